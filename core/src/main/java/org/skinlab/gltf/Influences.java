package org.skinlab.gltf;

import java.util.Arrays;

/**
 * The skin influences of a mesh's positions, read from every JOINTS_n/WEIGHTS_n pair of each
 * block (all sets, not just the first, in set order), kept as written except that zero weights
 * are dropped: glTF pads unused slots with weight 0, and a zero weight moves nothing. Weights are
 * not renormalised here (the model keeps weights as written; the skinning path divides by their
 * sum, which the specification allows: sums must be 1 within tolerance, and normalising what is
 * already 1 changes nothing).
 */
final class Influences {
    private final Accessors accessors;
    private final int[] count;
    private int[] joints;
    private float[] weights;
    /** Per position, its influences in slots [4 * sets * p, ...), -1 joint for unused. */
    private final int[][] blockJoints;
    private final float[][] blockWeights;
    private final int[] blockStart;
    private int blocks;
    int maxJoint = -1;
    String maxJointPath;
    String withoutJoints;

    Influences(Accessors accessors, int positions) {
        this.accessors = accessors;
        this.count = new int[positions];
        this.blockJoints = new int[64][];
        this.blockWeights = new float[64][];
        this.blockStart = new int[64];
    }

    void read(JsonNode attributes, int start, int n) throws GltfException {
        if (!attributes.has("JOINTS_0") || !attributes.has("WEIGHTS_0")) {
            if (withoutJoints == null) {
                withoutJoints = attributes.path();
            }
            return;
        }
        for (int set = 0; attributes.has("JOINTS_" + set) || attributes.has("WEIGHTS_" + set); set++) {
            JsonNode jointsRef = attributes.get("JOINTS_" + set);
            JsonNode weightsRef = attributes.get("WEIGHTS_" + set);
            if (jointsRef.isMissing() || weightsRef.isMissing()) {
                throw attributes.error("JOINTS_" + set + " and WEIGHTS_" + set + " must come together");
            }
            int ja = accessors.resolve(jointsRef);
            int wa = accessors.resolve(weightsRef);
            accessors.expect(ja, jointsRef.path(), "VEC4", "5121", "5123");
            accessors.expect(wa, weightsRef.path(), "VEC4", "5126", "5121n", "5123n");
            if (accessors.elementCount(ja) != n || accessors.elementCount(wa) != n) {
                throw attributes.error("JOINTS_" + set + " or WEIGHTS_" + set + " does not have the " + n
                        + " elements POSITION has");
            }
            if (blocks == blockJoints.length) {
                throw attributes.error("more than " + blockJoints.length + " JOINTS/WEIGHTS sets in one mesh");
            }
            int[] j = accessors.ints(ja);
            float[] w = accessors.floats(wa);
            for (int i = 0; i < 4 * n; i++) {
                if (w[i] < 0f) {
                    throw weightsRef.error("weight " + i % 4 + " of vertex " + i / 4 + " is negative (" + w[i] + ")");
                }
                if (w[i] > 0f) {
                    count[start + i / 4]++;
                    if (j[i] > maxJoint) {
                        maxJoint = j[i];
                        maxJointPath = jointsRef.path();
                    }
                }
            }
            blockJoints[blocks] = j;
            blockWeights[blocks] = w;
            blockStart[blocks++] = start;
        }
    }

    int[] start() {
        int[] s = new int[count.length + 1];
        for (int p = 0; p < count.length; p++) {
            s[p + 1] = s[p] + count[p];
        }
        joints = new int[s[count.length]];
        weights = new float[joints.length];
        int[] fill = Arrays.copyOf(s, count.length);
        for (int b = 0; b < blocks; b++) {
            int[] j = blockJoints[b];
            float[] w = blockWeights[b];
            for (int i = 0; i < w.length; i++) {
                if (w[i] > 0f) {
                    int at = fill[blockStart[b] + i / 4]++;
                    joints[at] = j[i];
                    weights[at] = w[i];
                }
            }
        }
        return s;
    }

    int[] joints() {
        return joints;
    }

    float[] weights() {
        return weights;
    }
}
