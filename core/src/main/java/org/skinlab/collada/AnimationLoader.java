package org.skinlab.collada;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Collections;
import java.util.Deque;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.skinlab.model.AnimationChannel;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Interpolation;
import org.skinlab.model.KeyframeTrack;
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
 * <p>Lenient (with a warning): channels whose target is not a transform of a scene node (a
 * material, a node outside the visual scene, an unknown sid or member) and channels whose sampler
 * has no keys are skipped; CARDINAL and BSPLINE keys and BEZIER/HERMITE keys without tangents are
 * read as LINEAR; a keyed matrix whose bottom row is not (0 0 0 1) keeps its values (the bottom
 * row is ignored when evaluated).
 * Refused: a sampler whose INPUT and OUTPUT disagree in key count, OUTPUT or tangent widths that
 * do not fit the target, decreasing key times, and dangling sampler or clip references.
 *
 * <p>Curves: IN_TANGENT/OUT_TANGENT become the control points of the cubic Bezier of each segment
 * ({@link #controlPoints}), whatever form the file uses (2-D or 1-D, BEZIER or HERMITE), so the
 * sampler has one evaluation path. Blender's exporter writes the tangents of bone rotation angles
 * in radians; such tracks are recognised and converted ({@link #blenderRadians}), with one warning
 * per file.
 */
final class AnimationLoader {
    private final ImportContext ctx;
    private final List<Node> nodes;
    private final Map<String, IntList> nodesById;
    private final Map<XmlElement, List<AnimationChannel>> channelsByAnimation = new IdentityHashMap<>();
    private final Map<XmlElement, Map<Integer, KeyframeTrack>> tracks = new IdentityHashMap<>();
    /** True when {@code <asset>} names Blender as the authoring tool (see {@link #blenderRadians}). */
    private final boolean fromBlender;
    /** Samplers whose tangent values were converted from radians to degrees (one warning for all). */
    private final List<XmlElement> radianTangentSamplers = new ArrayList<>();

    /**
     * @param authoringTool the document's authoring tool as {@code ColladaImporter} read it from
     *                      {@code <asset>} ({@code AssetInfo.authoringTool()}), or null
     */
    AnimationLoader(ImportContext ctx, List<Node> nodes, Map<String, IntList> nodesById, String authoringTool) {
        this.ctx = ctx;
        this.nodes = nodes;
        this.nodesById = nodesById;
        this.fromBlender = authoringTool != null && authoringTool.startsWith("Blender");
    }

    List<AnimationClip> load(XmlElement collada) throws ColladaException {
        List<XmlElement> topLevel = new ArrayList<>();
        List<AnimationChannel> all = new ArrayList<>();
        for (XmlElement library : collada.children("library_animations")) {
            topLevel.addAll(library.children("animation"));
        }
        for (XmlElement animation : topLevel) {
            for (XmlElement a : withNested(animation)) {
                List<AnimationChannel> own = new ArrayList<>();
                for (XmlElement channel : a.children("channel")) {
                    readChannel(channel, own);
                }
                channelsByAnimation.put(a, own);
                all.addAll(own);
            }
        }
        if (!radianTangentSamplers.isEmpty()) {
            ctx.warn(radianTangentSamplers.get(0), radianTangentSamplers.size() + " BEZIER track(s) of <rotate> angles"
                    + " have tangent values in radians while their OUTPUT is in degrees (Blender's exporter writes"
                    + " bone rotation tangents so); the tangent values were converted to degrees, as Blender plays"
                    + " them. Rule: authoring tool \"Blender...\", channel on a rotate's ANGLE, 2-D tangents whose"
                    + " values lie nearer OUTPUT * pi/180 than OUTPUT (docs/importer.md)");
        }

        List<AnimationClip> clips = new ArrayList<>();
        List<XmlElement> clipElements = new ArrayList<>();
        for (XmlElement library : collada.children("library_animation_clips")) {
            clipElements.addAll(library.children("animation_clip"));
        }
        for (int i = 0; i < clipElements.size(); i++) {
            clips.add(readClip(clipElements.get(i), i));
        }
        if (clipElements.isEmpty() && !all.isEmpty()) {
            float start = Float.POSITIVE_INFINITY;
            float end = Float.NEGATIVE_INFINITY;
            for (AnimationChannel c : all) {
                start = Math.min(start, c.track().startTime());
                end = Math.max(end, c.track().endTime());
            }
            clips.add(new AnimationClip(null, AnimationClip.DEFAULT_NAME, start, end, all));
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
        List<AnimationChannel> channels = new ArrayList<>();
        // A clip may instance an animation and also one nested in it (or the same one twice);
        // each animation's channels go in once, or the clip would drive the same values twice.
        Set<XmlElement> included = Collections.newSetFromMap(new IdentityHashMap<>());
        for (XmlElement instance : clip.children("instance_animation")) {
            XmlElement animation = ctx.resolve(instance, "url", "animation");
            for (XmlElement a : withNested(animation)) {
                if (!included.add(a)) {
                    continue;
                }
                List<AnimationChannel> own = channelsByAnimation.get(a);
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
            end = start;
            for (AnimationChannel c : channels) {
                end = Math.max(end, c.track().endTime());
            }
            ctx.warn(clip, "no end attribute; the clip ends at its last key (" + end + " s)");
        }
        if (end < start) {
            throw ctx.error(clip, "end=\"" + clip.attr("end") + "\" is before start=\"" + clip.attr("start") + "\"");
        }
        String name = clip.attr("name") != null ? clip.attr("name")
                : clip.id() != null ? clip.id() : "clip-" + (ordinal + 1);
        return new AnimationClip(clip.id(), name, start, end, channels);
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

    private void readChannel(XmlElement channel, List<AnimationChannel> out) throws ColladaException {
        XmlElement sampler = ctx.resolve(channel, "source", "sampler");
        String target = ctx.attr(channel, "target");
        int slash = target.indexOf('/');
        if (slash <= 0 || slash == target.length() - 1) {
            ctx.warn(channel, "target=\"" + target + "\" is not of the form node/sid; skipped");
            return;
        }
        String nodeId = target.substring(0, slash);
        String rest = target.substring(slash + 1);
        int selectorAt = rest.length();
        for (int i = 0; i < rest.length(); i++) {
            char c = rest.charAt(i);
            if (c == '.' || c == '(') {
                selectorAt = i;
                break;
            }
        }
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
            Node node = nodes.get(copies.get(i));
            int transformIndex = node.transformIndex(sid);
            if (transformIndex < 0) {
                ctx.warn(channel, "target=\"" + target + "\" skipped: node \"" + nodeId
                        + "\" has no transform element with sid \"" + sid + "\"");
                return;
            }
            TransformElement.Kind kind = node.transforms().get(transformIndex).kind();
            int[] range = select(kind, selector);
            if (range == null) {
                ctx.warn(channel, "target=\"" + target + "\" skipped: \"" + selector + "\" does not select values of a <"
                        + kind.elementName() + ">");
                return;
            }
            // The angle of a <rotate> (member ANGLE or index 3): where Blender's radian tangents can be.
            boolean angle = kind == TransformElement.Kind.ROTATE && range[0] == 3 && range[1] == 1;
            KeyframeTrack track = track(sampler, range[1], kind == TransformElement.Kind.MATRIX && range[1] == 16,
                    angle && fromBlender);
            if (track.keyCount() == 0) {
                // Nothing to evaluate, and its start and end (0) would stretch the default clip.
                ctx.warn(channel, "target=\"" + target + "\" skipped: its sampler has no keys");
                return;
            }
            out.add(new AnimationChannel(node.index(), transformIndex, range[0], track, target));
        }
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

    // ------------------------------------------------------------------------------- samplers

    /**
     * The track of a sampler read for a target of {@code width} values; cached, since several
     * channels (or copies of an instanced node) may share a sampler. {@code blenderAngle}: the
     * target is a rotate's angle in a file Blender wrote, which may change the tangents' reading.
     */
    private KeyframeTrack track(XmlElement sampler, int width, boolean matrix, boolean blenderAngle)
            throws ColladaException {
        Map<Integer, KeyframeTrack> byWidth = tracks.computeIfAbsent(sampler, s -> new HashMap<>());
        int key = blenderAngle ? -width : width; // the Blender-angle reading is cached apart from the plain one
        KeyframeTrack track = byWidth.get(key);
        if (track == null) {
            track = readSampler(sampler, width, matrix, blenderAngle);
            byWidth.put(key, track);
        }
        return track;
    }

    private KeyframeTrack readSampler(XmlElement sampler, int width, boolean matrix, boolean blenderAngle)
            throws ColladaException {
        XmlElement inputIn = null;
        XmlElement outputIn = null;
        XmlElement interpolationIn = null;
        XmlElement inTangentIn = null;
        XmlElement outTangentIn = null;
        for (XmlElement input : sampler.children("input")) {
            switch (ctx.attr(input, "semantic")) {
                case "INPUT": inputIn = input; break;
                case "OUTPUT": outputIn = input; break;
                case "INTERPOLATION": interpolationIn = input; break;
                case "IN_TANGENT": inTangentIn = input; break;
                case "OUT_TANGENT": outTangentIn = input; break;
                default: break;
            }
        }
        if (inputIn == null || outputIn == null) {
            throw ctx.error(sampler, "needs an INPUT and an OUTPUT input");
        }
        Source timeSource = ctx.inputSource(inputIn);
        float[] times = timeSource.floats(ctx, inputIn, 1, "INPUT");
        int keys = times.length;
        for (int k = 1; k < keys; k++) {
            if (times[k] < times[k - 1]) {
                throw ctx.error(timeSource.element, "key times decrease at key " + k + " (" + times[k - 1] + " then "
                        + times[k] + ")");
            }
        }
        float[] values = keyValues(outputIn, keys, width, "OUTPUT");
        if (matrix) {
            for (int k = 0; k < keys; k++) {
                if (!RowMajor.checkBottomRow(ctx, values, 16 * k, outputIn, "keyed matrix " + k)) {
                    break; // one warning per track is enough
                }
            }
        }

        Interpolation[] interpolations = new Interpolation[keys];
        java.util.Arrays.fill(interpolations, Interpolation.LINEAR);
        if (interpolationIn != null) {
            Source s = ctx.inputSource(interpolationIn);
            String[] names = s.names(ctx, interpolationIn, "INTERPOLATION");
            if (names.length != keys) {
                throw ctx.error(interpolationIn, "INTERPOLATION has " + names.length + " entries for " + keys + " keys");
            }
            // One warning per sampler, not per key: a long CARDINAL track would otherwise fill
            // the warning list (ImportContext.MAX_WARNINGS) and hide everything else.
            Set<String> unsupported = null;
            for (int k = 0; k < keys; k++) {
                Interpolation i = interpolation(names[k]);
                if (i == null) {
                    if (unsupported == null) {
                        unsupported = new LinkedHashSet<>();
                    }
                    unsupported.add(names[k]);
                    i = Interpolation.LINEAR;
                }
                interpolations[k] = i;
            }
            if (unsupported != null) {
                ctx.warn(interpolationIn, "interpolation " + String.join(", ", unsupported)
                        + " is not supported; read as LINEAR");
            }
        }
        boolean curved = false;
        for (Interpolation i : interpolations) {
            curved |= i == Interpolation.BEZIER || i == Interpolation.HERMITE;
        }
        float[] inTangents = null;
        float[] outTangents = null;
        if (curved) {
            if (inTangentIn == null || outTangentIn == null) {
                ctx.warn(sampler, "BEZIER/HERMITE keys without IN_TANGENT and OUT_TANGENT; read as LINEAR");
                for (int k = 0; k < keys; k++) {
                    if (interpolations[k] == Interpolation.BEZIER || interpolations[k] == Interpolation.HERMITE) {
                        interpolations[k] = Interpolation.LINEAR;
                    }
                }
            } else {
                float[] in = tangentValues(inTangentIn, keys, width);
                float[] out = tangentValues(outTangentIn, keys, width);
                if (blenderAngle && blenderRadians(in, out, values)) {
                    for (int i = 1; i < in.length; i += 2) {
                        in[i] = (float) Math.toDegrees(in[i]);
                        out[i] = (float) Math.toDegrees(out[i]);
                    }
                    radianTangentSamplers.add(sampler);
                }
                inTangents = controlPoints(in, times, values, width, interpolations, true);
                outTangents = controlPoints(out, times, values, width, interpolations, false);
            }
        }
        return new KeyframeTrack(times, values, width, interpolations, inTangents, outTangents);
    }

    /**
     * Whether the 2-D tangents of a one-value angle track from Blender hold radians. Blender's
     * COLLADA exporter (verified on 3.4.1; the same code is in the newest exporter source we read,
     * see docs/importer.md) writes the OUTPUT of a bone's rotation in degrees but the value
     * coordinate of its Bezier handles in radians: {@code AnimationExporter::collada_tangent_from_curve}
     * converts only when the channel name starts with "rotation", and for bone curves that name is
     * {@code ["Bone"].rotation_euler}. Handles sit near their keys, so the values say which unit
     * they are in: radians when {@code sum |h - v pi/180| <= sum |h - v|} over every handle h and
     * its key's value v. A file whose tangents are already in degrees (an object's rotation, which
     * Blender converts, or a fixed exporter) fails that test and is left alone. A tie (every key
     * value 0, where the file cannot tell) goes to radians, as the exporter's code writes them.
     * 1-D tangents (Blender never writes them) are never converted.
     */
    private static boolean blenderRadians(float[] in, float[] out, float[] values) {
        if (in.length != 2 * values.length || out.length != 2 * values.length) {
            return false;
        }
        double radians = 0;
        double degrees = 0;
        for (int k = 0; k < values.length; k++) {
            double v = values[k];
            double r = Math.toRadians(v);
            radians += Math.abs(in[2 * k + 1] - r) + Math.abs(out[2 * k + 1] - r);
            degrees += Math.abs(in[2 * k + 1] - v) + Math.abs(out[2 * k + 1] - v);
        }
        return radians <= degrees;
    }

    /** The interpolation of that name, or null when it is not supported (CARDINAL, BSPLINE, ...). */
    private static Interpolation interpolation(String name) {
        switch (name) {
            case "LINEAR": return Interpolation.LINEAR;
            case "STEP": return Interpolation.STEP;
            case "BEZIER": return Interpolation.BEZIER;
            case "HERMITE": return Interpolation.HERMITE;
            default: return null;
        }
    }

    /** {@code keys * width} values of an OUTPUT-like input, checked against the key count. */
    private float[] keyValues(XmlElement input, int keys, int width, String what) throws ColladaException {
        Source s = ctx.inputSource(input);
        s.requireFloats(ctx, input, what);
        if (s.count() != keys) {
            throw ctx.error(input, what + " source \"" + s.id() + "\" has " + s.count() + " entries for " + keys
                    + " keys");
        }
        if (s.width() != width) {
            throw ctx.error(input, what + " source \"" + s.id() + "\" has " + s.width()
                    + " values per key, but the channel's target takes " + width);
        }
        return s.floats(ctx, input, width, what);
    }

    /**
     * The values of an IN_TANGENT/OUT_TANGENT input as written: {@code 2 * width} per key for 2-D
     * (time, value) tangents, {@code width} per key for 1-D (value only) tangents.
     */
    private float[] tangentValues(XmlElement input, int keys, int width) throws ColladaException {
        Source s = ctx.inputSource(input);
        String semantic = input.attr("semantic");
        s.requireFloats(ctx, input, semantic);
        if (s.count() != keys) {
            throw ctx.error(input, semantic + " source \"" + s.id() + "\" has " + s.count() + " entries for " + keys
                    + " keys");
        }
        if (s.width() != 2 * width && s.width() != width) {
            throw ctx.error(input, semantic + " source \"" + s.id() + "\" has " + s.width()
                    + " values per key; expected " + (2 * width) + " (time, value per component) or " + width);
        }
        return s.floats(ctx, input, s.width(), semantic);
    }

    /**
     * Tangents as written, turned into the control points of the cubic Bezier of the segment that
     * uses them: {@code (time, value)}, 2 * width floats per key, the layout of
     * {@link KeyframeTrack}. Key k's out-tangent belongs to segment [k, k+1] and is read by key
     * k's interpolation; key k's in-tangent belongs to segment [k-1, k] and is read by key k-1's
     * interpolation (key 0's in-tangent, used by no segment, by key 0's). Per the COLLADA 1.4.1
     * release notes and the 1.5 specification ("Curve Interpolation", animation curves), with
     * P = (INPUT, OUTPUT) of a key:
     * <ul>
     * <li><b>BEZIER, 2-D</b>: the tangent is the control point: C0 = OUT_TANGENT[k],
     *     C1 = IN_TANGENT[k+1]. Kept as written.</li>
     * <li><b>HERMITE, 2-D</b>: the tangent T = (dt/ds, dv/ds) is the derivative of the segment's
     *     curve P(s), s in [0, 1], at its end. The Hermite cubic with P0, T0, P1, T1 is exactly the
     *     Bezier with C0 = P0 + T0/3 and C1 = P1 - T1/3 (both have the same end points and end
     *     derivatives, B'(0) = 3 (C0 - P0), B'(1) = 3 (P1 - C1)): one rounding in float.</li>
     * <li><b>1-D</b> (value only; older exporters, ColladaMaya/FCollada 1.x): time is linear in s,
     *     the control times sit a third of the way to the neighbouring key. HERMITE: T = dv/ds as
     *     above, so the values are P0 + T0/3 and P1 - T1/3. BEZIER: the tangent is the control
     *     value relative to its key, v0 + OUT_TANGENT[k] and v1 - IN_TANGENT[k+1], as FCollada 1.x,
     *     the library that wrote these files, evaluates them ({@code FCDAnimationCurve::Evaluate}).
     *     Reading them as absolute control values would turn the zero tangents of a peak (the CTS
     *     files' keys "0 50" with tangents "0 0") into spikes.</li>
     * </ul>
     * The end keys' unused tangents get a time offset of 0.
     */
    static float[] controlPoints(float[] tangents, float[] times, float[] values, int width,
            Interpolation[] interpolations, boolean in) {
        int keys = times.length;
        boolean twoD = tangents.length == 2 * keys * width;
        float[] out = new float[2 * keys * width];
        float sign = in ? -1f : 1f;
        for (int k = 0; k < keys; k++) {
            int segment = in ? Math.max(k - 1, 0) : k;
            boolean hermite = interpolations[segment] == Interpolation.HERMITE;
            // 1-D: the neighbouring interval (0 at the ends, where the tangent is unused).
            float span = in ? (k > 0 ? times[k] - times[k - 1] : 0f) : (k + 1 < keys ? times[k + 1] - times[k] : 0f);
            for (int c = 0; c < width; c++) {
                int o = 2 * (k * width + c);
                float v = values[k * width + c];
                if (twoD) {
                    float tt = tangents[o];
                    float tv = tangents[o + 1];
                    out[o] = hermite ? times[k] + sign * tt / 3f : tt;
                    out[o + 1] = hermite ? v + sign * tv / 3f : tv;
                } else {
                    float t = tangents[k * width + c];
                    out[o] = times[k] + sign * span / 3f;
                    out[o + 1] = v + sign * (hermite ? t / 3f : t);
                }
            }
        }
        return out;
    }
}
