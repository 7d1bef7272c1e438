package org.skinlab.jme;

import java.nio.FloatBuffer;
import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

import com.jme3.scene.Mesh;
import com.jme3.scene.VertexBuffer.Type;
import com.jme3.scene.mesh.IndexBuffer;

/**
 * Which of skinlab's per-POSITION outputs a jME vertex is: skinlab's glTF importer gives vertices
 * one position when their position and influences are bitwise equal, numbered in the order of their
 * first vertex (core's PositionWelder); jME keeps every vertex. The same rule over jME's bind
 * position and (sorted) influences gives the map.
 */
final class PositionOrder {
    private PositionOrder() {
    }

    /** Per jME vertex its skinlab position; the count of positions in the last entry. */
    static int[] positionOfVertex(Mesh mesh) {
        FloatBuffer p = (FloatBuffer) (mesh.getBuffer(Type.BindPosePosition) != null
                ? mesh.getBuffer(Type.BindPosePosition) : mesh.getBuffer(Type.Position)).getData();
        IndexBuffer joints = IndexBuffer.wrapIndexBuffer(mesh.getBuffer(Type.BoneIndex).getData());
        FloatBuffer weights = (FloatBuffer) mesh.getBuffer(Type.BoneWeight).getData();
        int n = mesh.getVertexCount();
        int[] map = new int[n + 1];
        Map<Key, Integer> seen = new HashMap<>();
        for (int v = 0; v < n; v++) {
            int[] k = new int[11];
            for (int c = 0; c < 3; c++) {
                k[c] = Float.floatToIntBits(p.get(3 * v + c));
            }
            for (int s = 0; s < 4; s++) {
                k[3 + s] = joints.get(4 * v + s);
                k[7 + s] = Float.floatToIntBits(weights.get(4 * v + s));
            }
            Integer known = seen.putIfAbsent(new Key(k), seen.size());
            map[v] = known != null ? known : seen.size() - 1;
        }
        map[n] = seen.size();
        return map;
    }

    private static final class Key {
        final int[] v;

        Key(int[] v) {
            this.v = v;
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof Key && Arrays.equals(v, ((Key) o).v);
        }

        @Override
        public int hashCode() {
            return Arrays.hashCode(v);
        }
    }
}
