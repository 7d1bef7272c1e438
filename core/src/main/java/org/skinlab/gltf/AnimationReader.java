package org.skinlab.gltf;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.skinlab.model.AnimationChannel;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Interpolation;
import org.skinlab.model.KeyframeTrack;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.MorphWeightChannel;
import org.skinlab.model.Node;

/**
 * Reads {@code /animations}: each animation one clip (its name, else "animation_N"), from time 0
 * to its last key, each translation/rotation/scale channel a track on the node's TRS element of
 * that sid. LINEAR and STEP keep their names; CUBICSPLINE becomes BEZIER with control points a
 * third of each segment in: for segment k with {@code td = t[k+1] - t[k]}, key k's out-tangent is
 * {@code (t[k] + td/3, v[k] + b[k] td/3)} and key k+1's in-tangent {@code (t[k+1] - td/3,
 * v[k+1] - a[k+1] td/3)}, which is the specification's Hermite spline exactly. Rotation keys that
 * are not unit length are normalised (their tangents scaled alike) with a warning. Channels on
 * morph {@code weights} become {@link MorphWeightChannel}s on the node's mesh instance (one value
 * per morph target of the node's mesh per key, CUBICSPLINE as above per weight); channels on nodes
 * outside the scene (or whose mesh draws nothing) are skipped with a warning. Two channels on the same node and path in one
 * animation are refused.
 */
final class AnimationReader {
    private static final float UNIT_TOLERANCE = 1e-3f;
    static final String WEIGHTS = "weights";

    private final GltfContext ctx;
    private final Accessors accessors;
    private final SceneReader scene;
    private final JsonNode nodes;
    private final JsonNode meshes;
    private final List<MeshInstance> instances;

    AnimationReader(GltfContext ctx, Accessors accessors, SceneReader scene, List<MeshInstance> instances,
            JsonNode root) throws GltfException {
        this.ctx = ctx;
        this.instances = instances;
        this.accessors = accessors;
        this.scene = scene;
        this.nodes = root.get("nodes");
        this.meshes = root.get("meshes");
    }

    List<AnimationClip> read(JsonNode root) throws GltfException {
        JsonNode animations = root.get("animations").arrayOrMissing();
        List<AnimationClip> clips = new ArrayList<>();
        for (int a = 0; a < animations.size(); a++) {
            clips.add(clip(animations.get(a), a));
        }
        return clips;
    }

    private AnimationClip clip(JsonNode animation, int index) throws GltfException {
        JsonNode channels = animation.get("channels");
        JsonNode samplers = animation.get("samplers");
        if (channels.size() == 0 || samplers.size() == 0) {
            throw animation.error("an animation needs channels and samplers");
        }
        List<AnimationChannel> result = new ArrayList<>();
        List<MorphWeightChannel> weightChannels = new ArrayList<>();
        java.util.Set<String> targets = new java.util.HashSet<>();
        float end = 0f;
        for (int c = 0; c < channels.size(); c++) {
            JsonNode channel = channels.get(c);
            JsonNode target = channel.get("target");
            int sampler = channel.get("sampler").index(samplers.size(), "samplers of this animation");
            String path = target.get("path").string();
            JsonNode nodeRef = target.get("node");
            if (nodeRef.isMissing()) {
                ctx.warn(target.path(), "no target node (an extension's target); skipped");
                continue;
            }
            int gltfNode = nodeRef.index(nodes.size(), "nodes");
            if (!targets.add(gltfNode + "/" + path)) {
                throw target.error("a second channel on the " + path + " of node " + gltfNode + " in this animation");
            }
            int width = width(path, target.get("path"), gltfNode);
            KeyframeTrack track = track(samplers.get(sampler), path, width);
            int node = scene.modelIndex[gltfNode];
            if (path.equals(WEIGHTS)) {
                // The clip lasts as long as the file says, whether or not the node is drawn.
                end = Math.max(end, track.endTime());
                int instance = instanceAt(node);
                if (instance < 0) {
                    ctx.warn(channel.path(), "node " + gltfNode + " draws no morphed mesh in the scene; the channel is skipped");
                } else {
                    weightChannels.add(new MorphWeightChannel(instance, 0, track, channel.path()));
                }
                continue;
            }
            if (node < 0) {
                ctx.warn(channel.path(), "node " + gltfNode + " is not in the scene; the channel is skipped");
                continue;
            }
            Node n = scene.result.get(node);
            int element = n.transformIndex(path);
            if (element < 0) {
                throw nodeRef.error("node " + gltfNode + " has a matrix; its " + path + " cannot be animated");
            }
            end = Math.max(end, track.endTime());
            result.add(new AnimationChannel(node, element, 0, track, channel.path()));
        }
        String name = animation.get("name").string(null);
        return new AnimationClip(null, name != null ? name : "animation_" + index, 0f, end, result, weightChannels);
    }

    /** The mesh instance of model node {@code node} (glTF: at most one per node), or -1. */
    private int instanceAt(int node) {
        for (int i = 0; node >= 0 && i < instances.size(); i++) {
            if (instances.get(i).node() == node) {
                return i;
            }
        }
        return -1;
    }

    private int width(String path, JsonNode pathNode, int gltfNode) throws GltfException {
        switch (path) {
            case SceneReader.TRANSLATION:
            case SceneReader.SCALE:
                return 3;
            case SceneReader.ROTATION:
                return 4;
            case WEIGHTS: {
                JsonNode mesh = nodes.get(gltfNode).get("mesh");
                int targetCount = mesh.isMissing() ? 0
                        : meshes.get(mesh.index(meshes.size(), "meshes")).get("primitives").get(0).get("targets").size();
                if (targetCount == 0) {
                    throw pathNode.error("node " + gltfNode + " has no mesh with morph targets to weigh");
                }
                return targetCount;
            }
            default:
                throw pathNode.error("unknown animation path \"" + path + "\"");
        }
    }

    /** The sampler's track: {@code width} values per key (for morph weights, one per target). */
    private KeyframeTrack track(JsonNode sampler, String path, int width) throws GltfException {
        String interpolation = sampler.get("interpolation").string("LINEAR");
        boolean cubic = interpolation.equals("CUBICSPLINE");
        if (!cubic && !interpolation.equals("LINEAR") && !interpolation.equals("STEP")) {
            throw sampler.get("interpolation").error("unknown interpolation \"" + interpolation + "\"");
        }
        JsonNode inputRef = sampler.get("input");
        int input = accessors.resolve(inputRef);
        accessors.expect(input, inputRef.path(), "SCALAR", "5126");
        float[] times = accessors.floats(input);
        int repeated = 0;
        for (int k = 0; k < times.length; k++) {
            if (times[k] < 0f || k > 0 && times[k] < times[k - 1]) {
                throw accessors.node(input).error("key time " + k + " is " + times[k]
                        + ": times must be non-negative and increase");
            }
            repeated += k > 0 && times[k] == times[k - 1] ? 1 : 0;
        }
        if (repeated > 0) {
            // The model reads a repeated time as a jump; glTF asks for strictly increasing times.
            ctx.warn(inputRef.path(), repeated + " key times repeat the one before; read as jumps");
        }
        JsonNode outputRef = sampler.get("output");
        int output = accessors.resolve(outputRef);
        int keys = times.length;
        boolean weights = path.equals(WEIGHTS);
        // Morph weights are scalars, one per target per key; TRS values one VEC3/VEC4 per key.
        accessors.expect(output, outputRef.path(), weights ? "SCALAR" : width == 4 ? "VEC4" : "VEC3",
                outputFormats(path));
        long expected = (long) (weights ? width : 1) * (cubic ? 3 : 1) * keys;
        if (accessors.elementCount(output) != expected) {
            throw outputRef.error("accessor " + output + " has " + accessors.elementCount(output) + " elements but "
                    + keys + " keys " + (weights ? "of " + width + " targets " : "") + "need " + expected);
        }
        float[] out = accessors.floats(output);
        return cubic ? cubic(times, out, width, path, outputRef) : linear(times, out, width, path, outputRef,
                interpolation.equals("STEP") ? Interpolation.STEP : Interpolation.LINEAR);
    }

    private static String[] outputFormats(String path) {
        if (path.equals(SceneReader.ROTATION) || path.equals(WEIGHTS)) {
            return new String[] {"5126", "5120n", "5121n", "5122n", "5123n"};
        }
        // KHR_mesh_quantization widens translation and scale outputs to every integer type.
        return new String[] {"5126", "5120", "5120n", "5121", "5121n", "5122", "5122n", "5123", "5123n"};
    }

    private KeyframeTrack linear(float[] times, float[] values, int width, String path, JsonNode ref,
            Interpolation interpolation) {
        float[] v = values.clone();
        if (path.equals(SceneReader.ROTATION)) {
            normalise(v, null, null, ref);
        }
        Interpolation[] kinds = new Interpolation[times.length];
        Arrays.fill(kinds, interpolation);
        return new KeyframeTrack(times, v, width, kinds, null, null);
    }

    /** CUBICSPLINE (in-tangent, value, out-tangent per key) as BEZIER control points. */
    private KeyframeTrack cubic(float[] times, float[] out, int width, String path, JsonNode ref) {
        int keys = times.length;
        float[] values = new float[keys * width];
        float[] inT = new float[2 * keys * width];
        float[] outT = new float[2 * keys * width];
        for (int k = 0; k < keys; k++) {
            float before = k > 0 ? (times[k] - times[k - 1]) / 3f : 0f;
            float after = k + 1 < keys ? (times[k + 1] - times[k]) / 3f : 0f;
            for (int c = 0; c < width; c++) {
                float a = out[(3 * k) * width + c];
                float v = out[(3 * k + 1) * width + c];
                float b = out[(3 * k + 2) * width + c];
                int i = k * width + c;
                values[i] = v;
                inT[2 * i] = times[k] - before;
                inT[2 * i + 1] = v - a * before;
                outT[2 * i] = times[k] + after;
                outT[2 * i + 1] = v + b * after;
            }
        }
        if (path.equals(SceneReader.ROTATION)) {
            normalise(values, inT, outT, ref);
        }
        Interpolation[] kinds = new Interpolation[keys];
        Arrays.fill(kinds, Interpolation.BEZIER);
        return new KeyframeTrack(times, values, width, kinds, inT, outT);
    }

    /** Makes each key's quaternion unit length, scaling its tangent control values alike. */
    private void normalise(float[] q, float[] inT, float[] outT, JsonNode ref) {
        int off = 0;
        for (int k = 0; k < q.length / 4; k++) {
            double len = Math.sqrt(q[4 * k] * q[4 * k] + q[4 * k + 1] * q[4 * k + 1] + q[4 * k + 2] * q[4 * k + 2]
                    + q[4 * k + 3] * q[4 * k + 3]);
            if (Math.abs(len - 1) > UNIT_TOLERANCE) {
                off++;
            }
            float s = len > 0 ? (float) (1 / len) : 1f;
            for (int c = 0; c < 4; c++) {
                q[4 * k + c] *= s;
                if (inT != null) {
                    inT[2 * (4 * k + c) + 1] *= s;
                    outT[2 * (4 * k + c) + 1] *= s;
                }
            }
        }
        if (off > 0) {
            ctx.warn(ref.path(), off + " rotation keys are not unit quaternions; normalised");
        }
    }
}
