package org.skinlab.gltf;

import java.util.Arrays;

/**
 * Gives a glTF mesh the model's two index spaces: glTF stores one position per vertex, and
 * exporters split a point of the surface into several vertices wherever its normal or texture
 * coordinates differ (Blender along every seam and hard edge). Vertices whose position, skin
 * influences (joints and weights in the same order) and morph offsets are all bitwise equal
 * deform identically under every skinning method, so they share one model position, as
 * COLLADA's do: the skinning path then deforms each position once ({@code SkinnedGeometry}'s
 * shared positions, the thesis' vertex groups) and per-position output has the surface's points.
 * Positions come in the order of their first vertex. Open addressing over an int table: no
 * object per vertex.
 */
final class PositionWelder {
    /** Per vertex, its position. */
    final int[] positionOfVertex;
    /** Per position, its first vertex. */
    final int[] firstVertex;

    private final float[] xyz;
    private final int[] start;
    private final int[] joints;
    private final float[] weights;
    private final float[][] targets;

    /**
     * @param xyz     3 floats per vertex
     * @param start   influences per vertex (compressed rows into joints and weights)
     * @param targets per morph target, 3 offsets per vertex
     */
    PositionWelder(float[] xyz, int[] start, int[] joints, float[] weights, float[][] targets) {
        this.xyz = xyz;
        this.start = start;
        this.joints = joints;
        this.weights = weights;
        this.targets = targets;
        int n = xyz.length / 3;
        int capacity = Integer.highestOneBit(Math.max(1, n)) << 2; // load factor at most 1/2
        int[] table = new int[capacity];
        Arrays.fill(table, -1);
        positionOfVertex = new int[n];
        int[] first = new int[n];
        int positions = 0;
        for (int v = 0; v < n; v++) {
            int h = hash(v) & (capacity - 1);
            while (table[h] >= 0 && !same(first[table[h]], v)) {
                h = (h + 1) & (capacity - 1);
            }
            if (table[h] < 0) {
                table[h] = positions;
                first[positions++] = v;
            }
            positionOfVertex[v] = table[h];
        }
        firstVertex = Arrays.copyOf(first, positions);
    }

    /** Per-vertex values ({@code width} per vertex) reduced to one per position (its first vertex's). */
    float[] perPosition(float[] perVertex, int width) {
        float[] out = new float[width * firstVertex.length];
        for (int p = 0; p < firstVertex.length; p++) {
            System.arraycopy(perVertex, width * firstVertex[p], out, width * p, width);
        }
        return out;
    }

    /** The influence rows per position (compressed: positionCount + 1 offsets). */
    int[] influenceStart() {
        int[] s = new int[firstVertex.length + 1];
        for (int p = 0; p < firstVertex.length; p++) {
            int v = firstVertex[p];
            s[p + 1] = s[p] + start[v + 1] - start[v];
        }
        return s;
    }

    int[] influenceJoints(int[] positionStart) {
        int[] out = new int[positionStart[firstVertex.length]];
        for (int p = 0; p < firstVertex.length; p++) {
            int v = firstVertex[p];
            System.arraycopy(joints, start[v], out, positionStart[p], start[v + 1] - start[v]);
        }
        return out;
    }

    float[] influenceWeights(int[] positionStart) {
        float[] out = new float[positionStart[firstVertex.length]];
        for (int p = 0; p < firstVertex.length; p++) {
            int v = firstVertex[p];
            System.arraycopy(weights, start[v], out, positionStart[p], start[v + 1] - start[v]);
        }
        return out;
    }

    private int hash(int v) {
        int h = 1;
        for (int c = 0; c < 3; c++) {
            h = 31 * h + Float.floatToIntBits(xyz[3 * v + c]);
        }
        for (int i = start[v]; i < start[v + 1]; i++) {
            h = 31 * h + joints[i];
            h = 31 * h + Float.floatToIntBits(weights[i]);
        }
        for (float[] t : targets) {
            for (int c = 0; c < 3; c++) {
                h = 31 * h + Float.floatToIntBits(t[3 * v + c]);
            }
        }
        return h ^ (h >>> 16);
    }

    private boolean same(int a, int b) {
        for (int c = 0; c < 3; c++) {
            if (Float.floatToIntBits(xyz[3 * a + c]) != Float.floatToIntBits(xyz[3 * b + c])) {
                return false;
            }
        }
        int n = start[a + 1] - start[a];
        if (n != start[b + 1] - start[b]) {
            return false;
        }
        for (int i = 0; i < n; i++) {
            if (joints[start[a] + i] != joints[start[b] + i]
                    || Float.floatToIntBits(weights[start[a] + i]) != Float.floatToIntBits(weights[start[b] + i])) {
                return false;
            }
        }
        for (float[] t : targets) {
            for (int c = 0; c < 3; c++) {
                if (Float.floatToIntBits(t[3 * a + c]) != Float.floatToIntBits(t[3 * b + c])) {
                    return false;
                }
            }
        }
        return true;
    }
}
