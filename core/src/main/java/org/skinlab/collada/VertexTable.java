package org.skinlab.collada;

import java.util.Arrays;

/**
 * The distinct vertices of a mesh being built. A vertex's key is its position index followed by
 * the bits of its attribute values (normal, colour, texture coordinates), {@code keyWidth} ints
 * in all: corners merge when their values agree, even where an exporter wrote a separate index
 * per corner (Blender writes one UV index per polygon corner, which would otherwise triple the
 * vertex count). Open addressing over a power-of-two table, no object per vertex.
 */
final class VertexTable {
    private final int keyWidth;
    private int[] keys = new int[0];
    private int vertexCount;
    private int[] table = new int[1 << 10]; // vertex index + 1, 0 = empty

    VertexTable(int keyWidth) {
        this.keyWidth = keyWidth;
    }

    /** The number of distinct vertices so far. */
    int count() {
        return vertexCount;
    }

    /** Int {@code i} of vertex {@code v}'s key. */
    int key(int v, int i) {
        return keys[v * keyWidth + i];
    }

    /** The vertex with this key, created when new (open addressing over the key table). */
    int vertexFor(int[] key) {
        int h = 1;
        for (int k : key) {
            h = 31 * h + k;
        }
        h ^= h >>> 16;
        h *= 0x85EBCA6B;
        h ^= h >>> 13;
        int mask = table.length - 1;
        int slot = h & mask;
        while (true) {
            int v = table[slot] - 1;
            if (v < 0) {
                break;
            }
            int off = v * keyWidth;
            boolean same = true;
            for (int i = 0; i < keyWidth; i++) {
                if (keys[off + i] != key[i]) {
                    same = false;
                    break;
                }
            }
            if (same) {
                return v;
            }
            slot = (slot + 1) & mask;
        }
        int v = vertexCount++;
        if ((v + 1) * keyWidth > keys.length) {
            keys = Arrays.copyOf(keys, Math.max(keyWidth * 64, keys.length * 2));
        }
        System.arraycopy(key, 0, keys, v * keyWidth, keyWidth);
        table[slot] = v + 1;
        if (2 * vertexCount > table.length) {
            rehash();
        }
        return v;
    }

    private void rehash() {
        int[] bigger = new int[table.length * 2];
        int mask = bigger.length - 1;
        for (int v = 0; v < vertexCount; v++) {
            int h = 1;
            int off = v * keyWidth;
            for (int i = 0; i < keyWidth; i++) {
                h = 31 * h + keys[off + i];
            }
            h ^= h >>> 16;
            h *= 0x85EBCA6B;
            h ^= h >>> 13;
            int slot = h & mask;
            while (bigger[slot] != 0) {
                slot = (slot + 1) & mask;
            }
            bigger[slot] = v + 1;
        }
        table = bigger;
    }
}
