package org.skinlab.collada;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.skinlab.model.AnimationChannel;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.KeyframeTrack;
import org.skinlab.model.Morph;
import org.skinlab.model.MorphWeightChannel;
import org.skinlab.model.Node;
import org.skinlab.model.TransformElement;

/**
 * Reads {@code <library_animations>} (nested {@code <animation>}s included) into channels that
 * drive transform values of scene nodes, and groups them into clips: one per
 * {@code <animation_clip>}, or one clip over all channels when the file has none.
 *
 * <p>Target syntax handled: {@code node/sid} (the whole element), {@code node/sid.X|Y|Z|ANGLE}
 * (also {@code .W}), {@code node/sid(i)} and, for matrices, {@code node/sid(i)(j)}, which selects
 * column i of row j (the reading of three.js and assimp; the value index in the row-major element
 * is {@code 4 * j + i}).
 *
 * <p>A target that names a morph controller's MORPH_WEIGHT source ({@code smile-weights(1)}, no
 * slash) animates morph weights instead ({@link MorphWeightTargets}).
 *
 * <p>Lenient (with a warning): channels whose target is not a transform of a scene node (a
 * material, a node outside the visual scene, an unknown sid or member) and channels whose sampler
 * has no keys are skipped. Refused: dangling sampler or clip references.
 *
 * <p>Samplers are read by {@link SamplerReader} (keys, interpolations and what it tolerates and
 * refuses), their tangents turned into Bezier control points by {@link CurveTangents}, which also
 * recognises Blender's radian rotation tangents (one warning per file).
 */
final class AnimationLoader {
    private final ImportContext ctx;
    private final List<Node> nodes;
    private final Map<String, IntList> nodesById;
    private final Map<XmlElement, Channels> channelsByAnimation = new IdentityHashMap<>();
    private final CurveTangents tangents;
    private final SamplerReader samplers;
    private final MorphWeightTargets weightTargets;

    /** One animation's channels: on node transforms and on morph weights. */
    private static final class Channels {
        final List<AnimationChannel> nodes = new ArrayList<>();
        final List<MorphWeightChannel> weights = new ArrayList<>();

        void addAll(Channels other) {
            nodes.addAll(other.nodes);
            weights.addAll(other.weights);
        }

        float start() {
            float start = Float.POSITIVE_INFINITY;
            for (AnimationChannel c : nodes) {
                start = Math.min(start, c.track().startTime());
            }
            for (MorphWeightChannel c : weights) {
                start = Math.min(start, c.track().startTime());
            }
            return start;
        }

        float end() {
            float end = Float.NEGATIVE_INFINITY;
            for (AnimationChannel c : nodes) {
                end = Math.max(end, c.track().endTime());
            }
            for (MorphWeightChannel c : weights) {
                end = Math.max(end, c.track().endTime());
            }
            return end;
        }

        boolean isEmpty() {
            return nodes.isEmpty() && weights.isEmpty();
        }
    }

    /**
     * @param authoringTool the document's authoring tool as {@code ColladaImporter} read it from
     *                      {@code <asset>} ({@code AssetInfo.authoringTool()}), or null
     * @param morphs        the morphs and their loader, for channels on morph weights
     * @param scene         the visual scene: its nodes and the instances that draw morphs
     */
    AnimationLoader(ImportContext ctx, SceneLoader.Result scene, Map<XmlElement, Morph> morphsByController,
            MorphLoader morphs, String authoringTool) {
        this.ctx = ctx;
        this.nodes = scene.nodes;
        this.nodesById = scene.nodesById;
        this.tangents = new CurveTangents(ctx, authoringTool);
        this.samplers = new SamplerReader(ctx, tangents);
        this.weightTargets = new MorphWeightTargets(ctx, morphsByController, morphs, scene.instances, samplers);
    }

    List<AnimationClip> load(XmlElement collada) throws ColladaException {
        List<XmlElement> topLevel = new ArrayList<>();
        Channels all = new Channels();
        for (XmlElement library : collada.children("library_animations")) {
            topLevel.addAll(library.children("animation"));
        }
        for (XmlElement animation : topLevel) {
            for (XmlElement a : withNested(animation)) {
                Channels own = new Channels();
                for (XmlElement channel : a.children("channel")) {
                    readChannel(channel, own);
                }
                channelsByAnimation.put(a, own);
                all.addAll(own);
            }
        }
        tangents.warnRadianTangents();

        List<AnimationClip> clips = new ArrayList<>();
        List<XmlElement> clipElements = new ArrayList<>();
        for (XmlElement library : collada.children("library_animation_clips")) {
            clipElements.addAll(library.children("animation_clip"));
        }
        for (int i = 0; i < clipElements.size(); i++) {
            clips.add(readClip(clipElements.get(i), i));
        }
        if (clipElements.isEmpty() && !all.isEmpty()) {
            clips.add(new AnimationClip(null, AnimationClip.DEFAULT_NAME, all.start(), all.end(), all.nodes,
                    all.weights));
        }
        return clips;
    }

    /** The animation and all animations nested in it, in document order. */
    private static List<XmlElement> withNested(XmlElement animation) {
        List<XmlElement> result = new ArrayList<>();
        Deque<XmlElement> todo = new ArrayDeque<>();
        todo.push(animation);
        while (!todo.isEmpty()) {
            XmlElement a = todo.pop();
            result.add(a);
            List<XmlElement> nested = a.children("animation");
            for (int i = nested.size() - 1; i >= 0; i--) {
                todo.push(nested.get(i));
            }
        }
        return result;
    }

    private AnimationClip readClip(XmlElement clip, int ordinal) throws ColladaException {
        Channels channels = new Channels();
        // A clip may instance an animation and also one nested in it (or the same one twice);
        // each animation's channels go in once, or the clip would drive the same values twice.
        Set<XmlElement> included = Collections.newSetFromMap(new IdentityHashMap<>());
        for (XmlElement instance : clip.children("instance_animation")) {
            XmlElement animation = ctx.resolve(instance, "url", "animation");
            for (XmlElement a : withNested(animation)) {
                if (!included.add(a)) {
                    continue;
                }
                Channels own = channelsByAnimation.get(a);
                if (own == null) {
                    throw ctx.error(instance, "url=\"" + instance.attr("url")
                            + "\" refers to an <animation> outside <library_animations>");
                }
                channels.addAll(own);
            }
        }
        float start = clipTime(clip, "start");
        float end;
        if (clip.attr("end") != null) {
            end = clipTime(clip, "end");
        } else {
            end = Math.max(start, channels.end());
            ctx.warn(clip, "no end attribute; the clip ends at its last key (" + end + " s)");
        }
        if (end < start) {
            throw ctx.error(clip, "end=\"" + clip.attr("end") + "\" is before start=\"" + clip.attr("start") + "\"");
        }
        String name = clip.attr("name") != null ? clip.attr("name")
                : clip.id() != null ? clip.id() : "clip-" + (ordinal + 1);
        return new AnimationClip(clip.id(), name, start, end, channels.nodes, channels.weights);
    }

    /**
     * A clip's start or end (0 when absent). Finite as a double is not enough: start="1e39" would
     * become an infinite float and an infinite or NaN duration.
     */
    private float clipTime(XmlElement clip, String attribute) throws ColladaException {
        float t = (float) ctx.number(clip, attribute, 0.0);
        if (Float.isInfinite(t)) {
            throw ctx.error(clip, attribute + "=\"" + clip.attr(attribute) + "\" is out of float range");
        }
        return t;
    }

    // ------------------------------------------------------------------------------- channels

    private void readChannel(XmlElement channel, Channels channels) throws ColladaException {
        XmlElement sampler = ctx.resolve(channel, "source", "sampler");
        String target = ctx.attr(channel, "target");
        int slash = target.indexOf('/');
        if (slash < 0 && weightTargets.read(channel, target, sampler, channels.weights)) {
            return;
        }
        if (slash <= 0 || slash == target.length() - 1) {
            ctx.warn(channel, "target=\"" + target + "\" is not of the form node/sid; skipped");
            return;
        }
        String nodeId = target.substring(0, slash);
        String rest = target.substring(slash + 1);
        int selectorAt = selectorStart(rest);
        String sid = rest.substring(0, selectorAt);
        String selector = rest.substring(selectorAt);
        if (sid.contains("/")) {
            ctx.warn(channel, "target=\"" + target + "\" addresses a nested sid path; only node/sid is supported;"
                    + " skipped");
            return;
        }
        IntList copies = nodesById.get(nodeId);
        if (copies == null) {
            XmlElement e = ctx.byId(nodeId);
            String why = e == null ? "no element has id \"" + nodeId + "\""
                    : e.name().equals("node") ? "node \"" + nodeId + "\" is not part of the visual scene"
                    : "it animates a <" + e.name() + ">, not a node transform";
            ctx.warn(channel, "target=\"" + target + "\" skipped: " + why);
            return;
        }
        for (int i = 0; i < copies.size(); i++) {
            if (!readNodeChannel(channel, sampler, nodes.get(copies.get(i)), nodeId, sid, selector, channels.nodes)) {
                return;
            }
        }
    }

    /** Where the member selector ({@code .X}, {@code (3)}) of a target's sid part starts, or its length. */
    private static int selectorStart(String sidAndSelector) {
        for (int i = 0; i < sidAndSelector.length(); i++) {
            char c = sidAndSelector.charAt(i);
            if (c == '.' || c == '(') {
                return i;
            }
        }
        return sidAndSelector.length();
    }

    /**
     * Adds the channel of one copy of the target node to {@code out}; returns false, having warned,
     * when the channel is skipped (it is then skipped for every copy).
     */
    private boolean readNodeChannel(XmlElement channel, XmlElement sampler, Node node, String nodeId, String sid,
            String selector, List<AnimationChannel> out) throws ColladaException {
        String target = channel.attr("target");
        int transformIndex = node.transformIndex(sid);
        if (transformIndex < 0) {
            ctx.warn(channel, "target=\"" + target + "\" skipped: node \"" + nodeId
                    + "\" has no transform element with sid \"" + sid + "\"");
            return false;
        }
        TransformElement.Kind kind = node.transforms().get(transformIndex).kind();
        int[] range = select(kind, selector);
        if (range == null) {
            ctx.warn(channel, "target=\"" + target + "\" skipped: \"" + selector + "\" does not select values of a <"
                    + kind.elementName() + ">");
            return false;
        }
        // The angle of a <rotate> (member ANGLE or index 3): where Blender's radian tangents can be.
        boolean angle = kind == TransformElement.Kind.ROTATE && range[0] == 3 && range[1] == 1;
        KeyframeTrack track = samplers.track(sampler, range[1],
                kind == TransformElement.Kind.MATRIX && range[1] == 16, angle && tangents.fromBlender());
        if (track.keyCount() == 0) {
            // Nothing to evaluate, and its start and end (0) would stretch the default clip.
            ctx.warn(channel, "target=\"" + target + "\" skipped: its sampler has no keys");
            return false;
        }
        out.add(new AnimationChannel(node.index(), transformIndex, range[0], track, target));
        return true;
    }

    /** {offset, width} of the values a selector picks from an element of the given kind, or null. */
    static int[] select(TransformElement.Kind kind, String selector) {
        if (selector.isEmpty()) {
            return new int[] {0, kind.size()};
        }
        if (selector.charAt(0) == '.') {
            String member = selector.substring(1);
            int index;
            switch (member) {
                case "X": index = 0; break;
                case "Y": index = 1; break;
                case "Z": index = 2; break;
                case "W": index = 3; break;
                case "ANGLE": index = kind == TransformElement.Kind.ROTATE ? 3 : -1; break;
                default: index = -1; break;
            }
            if (index < 0 || kind == TransformElement.Kind.MATRIX || index >= kind.size()) {
                return null;
            }
            return new int[] {index, 1};
        }
        // Array syntax: (i) or (i)(j).
        List<Integer> indices = new ArrayList<>(2);
        int i = 0;
        while (i < selector.length()) {
            if (selector.charAt(i) != '(') {
                return null;
            }
            int close = selector.indexOf(')', i);
            if (close < 0) {
                return null;
            }
            try {
                indices.add(Integer.parseInt(selector.substring(i + 1, close).trim()));
            } catch (NumberFormatException e) {
                return null;
            }
            i = close + 1;
        }
        int index;
        if (indices.size() == 1) {
            index = indices.get(0);
        } else if (indices.size() == 2 && kind == TransformElement.Kind.MATRIX) {
            int column = indices.get(0);
            int row = indices.get(1);
            if (column < 0 || column > 3 || row < 0 || row > 3) {
                return null;
            }
            index = 4 * row + column;
        } else {
            return null;
        }
        return index < 0 || index >= kind.size() ? null : new int[] {index, 1};
    }
}
