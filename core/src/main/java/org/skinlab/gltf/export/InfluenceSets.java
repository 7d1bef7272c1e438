package org.skinlab.gltf.export;

import java.util.Map;

import org.skinlab.skinning.SkinnedGeometry;

/**
 * A skinned geometry's influences as glTF's {@code JOINTS_n}/{@code WEIGHTS_n} sets: the
 * geometry's slots (heaviest first, so slot 0, the DQS pivot, is the heaviest), four per set, as
 * many sets as the vertex with the most non-zero weights needs. Weights are divided by their sum in
 * double and the float rounding left over is added to the heaviest, so each vertex's float weights
 * sum to one as closely as floats can; empty slots are joint 0, weight 0.
 */
final class InfluenceSets {
    private final int sets;
    private final int[] joints;
    private final float[] weights;
    private final int jointCount;

    InfluenceSets(SkinnedGeometry geometry, int vertexCount) {
        int k = geometry.influencesPerPoint();
        int[] srcJoints = geometry.jointArray();
        float[] srcWeights = geometry.weightArray();
        int needed = 1;
        for (int v = 0; v < vertexCount; v++) {
            int n = 0;
            for (int a = 0; a < k; a++) {
                n += srcWeights[k * v + a] > 0f ? 1 : 0;
            }
            needed = Math.max(needed, n);
        }
        this.sets = (needed + 3) / 4;
        this.jointCount = geometry.jointCount();
        int width = 4 * sets;
        joints = new int[width * vertexCount];
        weights = new float[width * vertexCount];
        for (int v = 0; v < vertexCount; v++) {
            double sum = 0;
            int n = 0;
            for (int a = 0; a < k; a++) {
                float w = srcWeights[k * v + a];
                if (w > 0f) {
                    joints[width * v + n] = srcJoints[k * v + a];
                    weights[width * v + n] = w;
                    sum += w;
                    n++;
                }
            }
            if (n == 0) {
                // The geometry gives every point a weight; keep the point on its first slot's joint.
                joints[width * v] = srcJoints[k * v];
                weights[width * v] = 1f;
                continue;
            }
            double floatSum = 0;
            for (int a = 0; a < n; a++) {
                weights[width * v + a] = (float) (weights[width * v + a] / sum);
                floatSum += weights[width * v + a];
            }
            weights[width * v] = (float) (weights[width * v] + (1.0 - floatSum));
        }
    }

    /** Adds the sets' accessors to {@code attributes}. */
    void write(BinaryChunk bin, Map<String, Integer> attributes) {
        int count = weights.length / (4 * sets);
        int type = jointCount <= 256 ? BinaryChunk.UNSIGNED_BYTE : BinaryChunk.UNSIGNED_SHORT;
        for (int s = 0; s < sets; s++) {
            int[] j = new int[4 * count];
            float[] w = new float[4 * count];
            for (int v = 0; v < count; v++) {
                System.arraycopy(joints, 4 * (sets * v + s), j, 4 * v, 4);
                System.arraycopy(weights, 4 * (sets * v + s), w, 4 * v, 4);
            }
            attributes.put("JOINTS_" + s, bin.ints(j, "VEC4", 4, type, BinaryChunk.ARRAY_BUFFER));
            attributes.put("WEIGHTS_" + s, bin.floats(w, "VEC4", 4, BinaryChunk.ARRAY_BUFFER, false));
        }
    }
}
