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
 * object per vertex; each position's hash is kept, so only vertices of equal hash are compared.
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
        positionOfVertex = new int[n];
        int[] first = new int[n];
        int[] hashes = new int[n];
        // Sized for a quarter as many positions as vertices (a closed surface's split vertices),
        // doubled whenever it is half full: a small table stays in cache.
        int[] table = emptyTable(Math.max(16, Integer.highestOneBit(Math.max(1, n / 4)) << 1));
        int positions = 0;
        for (int v = 0; v < n; v++) {
            int hash = hash(v);
            int slot = slot(table, hashes, first, hash, v);
            if (table[slot] < 0) {
                if (2 * (positions + 1) > table.length) {
                    table = rehash(table.length * 2, hashes, positions);
                    slot = slot(table, hashes, first, hash, v);
                }
                table[slot] = positions;
                hashes[positions] = hash;
                first[positions++] = v;
            }
            positionOfVertex[v] = table[slot];
        }
        firstVertex = Arrays.copyOf(first, positions);
    }

    /** The slot of the position vertex {@code v} has (same hash, {@link #same}), else the free slot for it. */
    private int slot(int[] table, int[] hashes, int[] first, int hash, int v) {
        int mask = table.length - 1;
        int h = hash & mask;
        for (int p; (p = table[h]) >= 0; h = (h + 1) & mask) {
            if (hashes[p] == hash && same(first[p], v)) {
                break;
            }
        }
        return h;
    }

    private static int[] emptyTable(int capacity) {
        int[] table = new int[capacity];
        Arrays.fill(table, -1);
        return table;
    }

    /** A table of {@code capacity} slots holding positions {@code [0, positions)} by their hashes. */
    private static int[] rehash(int capacity, int[] hashes, int positions) {
        int[] table = emptyTable(capacity);
        int mask = capacity - 1;
        for (int p = 0; p < positions; p++) {
            int h = hashes[p] & mask;
            while (table[h] >= 0) {
                h = (h + 1) & mask;
            }
            table[h] = p;
        }
        return table;
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

    /**
     * A hash of everything {@link #same} compares (of the position alone, a file with many
     * vertices at one point weighted differently would make probing quadratic). MurmurHash3's
     * mixing: floats on a grid differ only in their high bits, and the table is indexed by the
     * low ones.
     */
    private int hash(int v) {
        int h = mix(mix(mix(0, Float.floatToRawIntBits(xyz[3 * v])), Float.floatToRawIntBits(xyz[3 * v + 1])),
                Float.floatToRawIntBits(xyz[3 * v + 2]));
        for (int i = start[v], end = start[v + 1]; i < end; i++) {
            h = mix(h, joints[i] ^ Float.floatToRawIntBits(weights[i]) * 31);
        }
        for (float[] t : targets) {
            h = mix(mix(mix(h, Float.floatToRawIntBits(t[3 * v])), Float.floatToRawIntBits(t[3 * v + 1])),
                    Float.floatToRawIntBits(t[3 * v + 2]));
        }
        h ^= h >>> 16;
        h *= 0x85ebca6b;
        h ^= h >>> 13;
        h *= 0xc2b2ae35;
        return h ^ (h >>> 16);
    }

    private static int mix(int h, int value) {
        return Integer.rotateLeft(h ^ value * 0xcc9e2d51, 15) * 0x1b873593;
    }

    private boolean same(int a, int b) {
        for (int c = 0; c < 3; c++) {
            if (Float.floatToRawIntBits(xyz[3 * a + c]) != Float.floatToRawIntBits(xyz[3 * b + c])) {
                return false;
            }
        }
        int n = start[a + 1] - start[a];
        if (n != start[b + 1] - start[b]) {
            return false;
        }
        for (int i = 0; i < n; i++) {
            if (joints[start[a] + i] != joints[start[b] + i]
                    || Float.floatToRawIntBits(weights[start[a] + i]) != Float.floatToRawIntBits(weights[start[b] + i])) {
                return false;
            }
        }
        for (float[] t : targets) {
            for (int c = 0; c < 3; c++) {
                if (Float.floatToRawIntBits(t[3 * a + c]) != Float.floatToRawIntBits(t[3 * b + c])) {
                    return false;
                }
            }
        }
        return true;
    }
}
