package org.skinlab.gltf.export;

import java.io.IOException;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;

import org.skinlab.animation.AnimationSampler;
import org.skinlab.animation.LocalPose;
import org.skinlab.animation.MorphWeightSampler;
import org.skinlab.animation.Pose;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.Skeleton;
import org.skinlab.model.AnimationChannel;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Interpolation;
import org.skinlab.model.KeyframeTrack;
import org.skinlab.model.Model;
import org.skinlab.model.MorphWeightChannel;
import org.skinlab.model.Node;
import org.skinlab.model.TransformElement;

import com.fasterxml.jackson.core.JsonGenerator;

/**
 * Animation clips as glTF animations, each from time 0 (the clip's start) to its duration.
 *
 * <ul>
 * <li><b>Copied</b>: a track on a glTF translation, rotation or scale, or on a morph's weights, of a
 *     clip that starts at 0, with one interpolation for all its keys (LINEAR, STEP, or BEZIER which
 *     is written back as CUBICSPLINE) and strictly increasing times within the clip.</li>
 * <li><b>Resampled</b>: every other animated node (COLLADA matrices, angles, transform stacks)
 *     becomes LINEAR translation, rotation and scale sampled with
 *     {@link AnimationSampler#sampleLocal} (rotations by SLERP, as glTF's LINEAR is) at the clip's
 *     start and end and every key time of the node's channels between; where that is not exact
 *     between keys (anything but one LINEAR whole matrix that is its node's one transform), also
 *     every 1/{@value #RATE} s. A node whose channels are all STEP keeps STEP at its key times. Morph weights that are not copied are resampled alike with
 *     {@link MorphWeightSampler}.</li>
 * </ul>
 */
final class ClipExport {
    /** Samples per second where a resampled track is not exact between keys. */
    static final float RATE = 60f;

    private record Sampler(int input, int output, String interpolation) {
    }

    private record Channel(int sampler, int node, String path) {
    }

    private record Animation(String name, List<Sampler> samplers, List<Channel> channels) {
    }

    private final Model model;
    private final Skeleton skeleton;
    private final NodeLayout nodes;
    private final int[] instanceNodes;
    private final BinaryChunk bin;
    private final List<String> warnings;
    private final List<Animation> animations = new ArrayList<>();

    /** {@code instanceNodes}: per mesh instance, the glTF node that draws it. */
    ClipExport(Model model, Skeleton skeleton, NodeLayout nodes, int[] instanceNodes, BinaryChunk bin,
            List<String> warnings) {
        this.model = model;
        this.skeleton = skeleton;
        this.nodes = nodes;
        this.instanceNodes = instanceNodes;
        this.bin = bin;
        this.warnings = warnings;
    }

    int clipCount() {
        return animations.size();
    }

    /** Per model node, whether some clip animates it. */
    static boolean[] animatedNodes(Model model) {
        boolean[] animated = new boolean[model.nodes().size()];
        for (AnimationClip clip : model.clips()) {
            for (AnimationChannel c : clip.channels()) {
                animated[c.node()] = true;
            }
        }
        return animated;
    }

    void clip(AnimationClip clip) {
        Animation a = new Animation(clip.name(), new ArrayList<>(), new ArrayList<>());
        Map<Integer, List<AnimationChannel>> byNode = new LinkedHashMap<>();
        for (AnimationChannel c : clip.channels()) {
            byNode.computeIfAbsent(c.node(), k -> new ArrayList<>()).add(c);
        }
        AnimationSampler sampler = null;
        Pose values = null;
        LocalPose local = null;
        for (Map.Entry<Integer, List<AnimationChannel>> e : byNode.entrySet()) {
            int node = e.getKey();
            List<AnimationChannel> channels = e.getValue();
            if (copyable(clip, node, channels)) {
                for (AnimationChannel c : channels) {
                    String path = model.node(node).transforms().get(c.transformIndex()).sid();
                    add(a, c.track(), nodes.node(node), path);
                }
                continue;
            }
            if (sampler == null) {
                sampler = new AnimationSampler(skeleton, clip);
                values = skeleton.newPose();
                local = skeleton.newLocalPose();
            }
            resample(a, clip, node, channels, sampler, values, local);
        }
        morphWeights(a, clip);
        if (a.channels.isEmpty()) {
            warnings.add("clip " + clip.name() + " animates nothing that is exported; left out");
            return;
        }
        animations.add(a);
    }

    private boolean copyable(AnimationClip clip, int node, List<AnimationChannel> channels) {
        Node n = model.node(node);
        if (!NodeLayout.isTrsStack(n.transforms()) || clip.start() != 0f) {
            return false;
        }
        boolean[] seen = new boolean[3];
        for (AnimationChannel c : channels) {
            TransformElement.Kind kind = n.transforms().get(c.transformIndex()).kind();
            if (c.valueOffset() != 0 || c.valueCount() != kind.size() || seen[c.transformIndex()]
                    || !copyable(c.track(), clip)) {
                return false;
            }
            seen[c.transformIndex()] = true;
        }
        return true;
    }

    /** One interpolation of LINEAR, STEP, BEZIER for all keys, times strictly increasing within the clip. */
    private static boolean copyable(KeyframeTrack t, AnimationClip clip) {
        if (t.keyCount() == 0) {
            return false;
        }
        Interpolation first = t.interpolation(0);
        if (first == Interpolation.HERMITE || first == Interpolation.BEZIER && !t.hasTangents()) {
            return false;
        }
        for (int k = 0; k < t.keyCount(); k++) {
            if (t.interpolation(k) != first && k + 1 < t.keyCount() || k > 0 && t.time(k) <= t.time(k - 1)
                    || t.time(k) < 0f || t.time(k) > clip.end()) {
                return false;
            }
        }
        return true;
    }

    /** A copied track: its keys, and for BEZIER the control points back as CUBICSPLINE tangents. */
    private void add(Animation a, KeyframeTrack t, int gltfNode, String path) {
        boolean weights = path.equals("weights");
        String type = weights ? "SCALAR" : t.width() == 4 ? "VEC4" : "VEC3";
        int width = weights ? 1 : t.width();
        float[] times = t.times();
        int input = bin.floats(times, "SCALAR", 1, 0, true);
        Interpolation kind = t.interpolation(0);
        int output;
        String interpolation;
        if (kind == Interpolation.BEZIER) {
            interpolation = "CUBICSPLINE";
            output = bin.floats(cubicSpline(t), type, width, 0, false);
        } else {
            interpolation = kind == Interpolation.STEP ? "STEP" : "LINEAR";
            output = bin.floats(t.values(), type, width, 0, false);
        }
        a.samplers.add(new Sampler(input, output, interpolation));
        a.channels.add(new Channel(a.samplers.size() - 1, gltfNode, path));
    }

    /** In-tangent, value, out-tangent per key: the derivatives the Bezier control points a third in encode. */
    private static float[] cubicSpline(KeyframeTrack t) {
        int keys = t.keyCount();
        int w = t.width();
        float[] inT = t.inTangents();
        float[] outT = t.outTangents();
        float[] out = new float[3 * keys * w];
        for (int k = 0; k < keys; k++) {
            float before = k > 0 ? (t.time(k) - t.time(k - 1)) / 3f : 0f;
            float after = k + 1 < keys ? (t.time(k + 1) - t.time(k)) / 3f : 0f;
            for (int c = 0; c < w; c++) {
                int i = k * w + c;
                float v = t.value(k, c);
                out[3 * k * w + c] = before > 0f ? (v - inT[2 * i + 1]) / before : 0f;
                out[(3 * k + 1) * w + c] = v;
                out[(3 * k + 2) * w + c] = after > 0f ? (outT[2 * i + 1] - v) / after : 0f;
            }
        }
        return out;
    }

    private void resample(Animation a, AnimationClip clip, int node, List<AnimationChannel> channels,
            AnimationSampler sampler, Pose values, LocalPose local) {
        boolean step = true;
        boolean linear = true;
        boolean exact = channels.size() == 1 && model.node(node).transforms().size() == 1;
        List<KeyframeTrack> tracks = new ArrayList<>();
        for (AnimationChannel c : channels) {
            tracks.add(c.track());
            TransformElement.Kind kind = model.node(node).transforms().get(c.transformIndex()).kind();
            exact &= kind == TransformElement.Kind.MATRIX && c.valueOffset() == 0 && c.valueCount() == 16;
            // The last key's interpolation starts no segment.
            for (int k = 0; k + 1 < c.track().keyCount(); k++) {
                Interpolation i = c.track().interpolation(k);
                step &= i == Interpolation.STEP;
                linear &= i == Interpolation.LINEAR;
            }
        }
        // A STEP segment among LINEAR ones has no exact LINEAR form: the dense grid keeps its ramp short.
        float[] times = sampleTimes(tracks, clip, !(exact && linear) && !step);
        int n = times.length;
        float[] t = new float[3 * n];
        float[] r = new float[4 * n];
        float[] s = new float[3 * n];
        float[] trs = local.array();
        int o = LocalPose.STRIDE * node;
        for (int i = 0; i < n; i++) {
            sampler.sampleLocal(times[i] + clip.start(), RotationInterpolation.SLERP, values, local);
            System.arraycopy(trs, o, t, 3 * i, 3);
            System.arraycopy(trs, o + 3, r, 4 * i, 4);
            System.arraycopy(trs, o + 7, s, 3 * i, 3);
            if (i > 0 && r[4 * i] * r[4 * i - 4] + r[4 * i + 1] * r[4 * i - 3] + r[4 * i + 2] * r[4 * i - 2]
                    + r[4 * i + 3] * r[4 * i - 1] < 0f) {
                for (int c = 0; c < 4; c++) {
                    r[4 * i + c] = -r[4 * i + c]; // the same rotation, on the side of the previous key
                }
            }
        }
        int input = bin.floats(times, "SCALAR", 1, 0, true);
        String interpolation = step ? "STEP" : "LINEAR";
        int gltfNode = nodes.node(node);
        a.samplers.add(new Sampler(input, bin.floats(t, "VEC3", 3, 0, false), interpolation));
        a.channels.add(new Channel(a.samplers.size() - 1, gltfNode, "translation"));
        a.samplers.add(new Sampler(input, bin.floats(r, "VEC4", 4, 0, false), interpolation));
        a.channels.add(new Channel(a.samplers.size() - 1, gltfNode, "rotation"));
        a.samplers.add(new Sampler(input, bin.floats(s, "VEC3", 3, 0, false), interpolation));
        a.channels.add(new Channel(a.samplers.size() - 1, gltfNode, "scale"));
    }

    /**
     * Times from the clip's start (0) to its end: the ends, every key strictly between, and with
     * {@code dense} every 1/RATE s; strictly increasing after the shift to 0.
     */
    static float[] sampleTimes(List<KeyframeTrack> tracks, AnimationClip clip, boolean dense) {
        float start = clip.start();
        float end = clip.end();
        TreeSet<Float> set = new TreeSet<>();
        set.add(start);
        set.add(end);
        for (KeyframeTrack t : tracks) {
            for (int k = 0; k < t.keyCount(); k++) {
                if (t.time(k) > start && t.time(k) < end) {
                    set.add(t.time(k));
                }
            }
        }
        if (dense) {
            int steps = (int) Math.floor((end - start) * RATE);
            for (int i = 1; i <= steps; i++) {
                set.add((float) (start + i / (double) RATE));
            }
        }
        float[] times = new float[set.size()];
        int n = 0;
        for (float f : set) {
            float shifted = f - start;
            if (f <= end && (n == 0 || shifted > times[n - 1])) {
                times[n++] = shifted;
            }
        }
        return Arrays.copyOf(times, n);
    }

    private void morphWeights(Animation a, AnimationClip clip) {
        Map<Integer, List<MorphWeightChannel>> byInstance = new LinkedHashMap<>();
        for (MorphWeightChannel c : clip.morphWeights()) {
            byInstance.computeIfAbsent(c.instance(), k -> new ArrayList<>()).add(c);
        }
        MorphWeightSampler sampler = null;
        float[][] weights = null;
        for (Map.Entry<Integer, List<MorphWeightChannel>> e : byInstance.entrySet()) {
            int instance = e.getKey();
            List<MorphWeightChannel> channels = e.getValue();
            int targets = model.morphOf(model.instances().get(instance)).get().targets().size();
            MorphWeightChannel first = channels.get(0);
            if (channels.size() == 1 && first.weightOffset() == 0 && first.weightCount() == targets
                    && clip.start() == 0f && copyable(first.track(), clip)) {
                add(a, first.track(), instanceNodes[instance], "weights");
                continue;
            }
            if (sampler == null) {
                sampler = new MorphWeightSampler(model, clip);
                weights = sampler.newWeights();
            }
            boolean linear = true;
            boolean step = true;
            List<KeyframeTrack> tracks = new ArrayList<>();
            for (MorphWeightChannel c : channels) {
                tracks.add(c.track());
                for (int k = 0; k + 1 < c.track().keyCount(); k++) {
                    Interpolation i = c.track().interpolation(k);
                    linear &= i == Interpolation.LINEAR;
                    step &= i == Interpolation.STEP;
                }
            }
            float[] times = sampleTimes(tracks, clip, !linear && !step);
            float[] out = new float[times.length * targets];
            for (int i = 0; i < times.length; i++) {
                sampler.sample(times[i] + clip.start(), weights);
                System.arraycopy(weights[instance], 0, out, i * targets, targets);
            }
            int input = bin.floats(times, "SCALAR", 1, 0, true);
            a.samplers.add(new Sampler(input, bin.floats(out, "SCALAR", 1, 0, false), step ? "STEP" : "LINEAR"));
            a.channels.add(new Channel(a.samplers.size() - 1, instanceNodes[instance], "weights"));
        }
    }

    void writeJson(JsonGenerator g) throws IOException {
        if (animations.isEmpty()) {
            return;
        }
        g.writeArrayFieldStart("animations");
        for (Animation a : animations) {
            g.writeStartObject();
            g.writeStringField("name", a.name);
            g.writeArrayFieldStart("channels");
            for (Channel c : a.channels) {
                g.writeStartObject();
                g.writeNumberField("sampler", c.sampler);
                g.writeObjectFieldStart("target");
                g.writeNumberField("node", c.node);
                g.writeStringField("path", c.path);
                g.writeEndObject();
                g.writeEndObject();
            }
            g.writeEndArray();
            g.writeArrayFieldStart("samplers");
            for (Sampler s : a.samplers) {
                g.writeStartObject();
                g.writeNumberField("input", s.input);
                g.writeStringField("interpolation", s.interpolation);
                g.writeNumberField("output", s.output);
                g.writeEndObject();
            }
            g.writeEndArray();
            g.writeEndObject();
        }
        g.writeEndArray();
    }
}
