package org.skinlab.gltf;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Deque;
import java.util.List;

import org.skinlab.model.Node;
import org.skinlab.model.TransformElement;

/**
 * Reads the scene ({@code scene}, else scene 0; without scenes, every root node with a warning)
 * into the model's depth-first node list. Only the scene's nodes are loaded; the others are left
 * out with a warning (and refused where a skin or animation needs them).
 *
 * <p>A node's transform is its {@code matrix} as one MATRIX element (glTF writes it column-major,
 * the model row-major), else the stack [TRANSLATE "translation", QUATERNION "rotation", SCALE
 * "scale"], always all three (defaults where absent) so animation channels find them by sid; a
 * rotation that is not a unit quaternion is normalised with a warning (the model's quaternion
 * element would scale by its squared length).
 * The node graph must be a forest: a node with two parents, a cycle, or a scene node that is some
 * node's child is refused with the path.
 */
final class SceneReader {
    static final String TRANSLATION = "translation";
    static final String ROTATION = "rotation";
    static final String SCALE = "scale";
    /** How far from 1 a rotation's length may be before it is normalised (and reported). */
    static final double UNIT_TOLERANCE = 1e-3;

    private final GltfContext ctx;
    private final JsonNode nodes;
    /** Per glTF node, its index in the model's node list, or -1 when not in the scene. */
    final int[] modelIndex;
    /** Per model node, its glTF index. */
    final List<Integer> gltfIndex = new ArrayList<>();
    final List<Node> result = new ArrayList<>();

    SceneReader(GltfContext ctx, JsonNode root) throws GltfException {
        this.ctx = ctx;
        this.nodes = root.get("nodes").arrayOrMissing();
        this.modelIndex = new int[nodes.size()];
        Arrays.fill(modelIndex, -1);
    }

    /** Reads the scene; {@code joints} marks the glTF nodes some skin uses as joints. */
    void read(JsonNode root, boolean[] joints) throws GltfException {
        int[] parent = parents();
        int[] roots = sceneRoots(root, parent);
        Deque<int[]> stack = new ArrayDeque<>(); // (glTF node, model parent)
        for (int r = roots.length - 1; r >= 0; r--) {
            stack.push(new int[] {roots[r], -1});
        }
        List<int[]> children = new ArrayList<>();
        while (!stack.isEmpty()) {
            int[] entry = stack.pop();
            int g = entry[0];
            JsonNode node = nodes.get(g);
            int index = gltfIndex.size();
            modelIndex[g] = index;
            gltfIndex.add(g);
            JsonNode kids = node.get("children");
            for (int c = kids.size() - 1; c >= 0; c--) {
                stack.push(new int[] {kids.get(c).index(nodes.size(), "nodes"), index});
            }
            children.add(new int[] {entry[1]});
        }
        for (int i = 0; i < gltfIndex.size(); i++) {
            int g = gltfIndex.get(i);
            JsonNode node = nodes.get(g);
            JsonNode kids = node.get("children");
            int[] childIndices = new int[kids.size()];
            for (int c = 0; c < childIndices.length; c++) {
                childIndices[c] = modelIndex[kids.get(c).index(nodes.size(), "nodes")];
            }
            result.add(new Node(i, children.get(i)[0], childIndices, null, null, node.get("name").string(null),
                    joints[g], false, transforms(ctx, node)));
        }
        int left = nodes.size() - result.size();
        if (left > 0) {
            ctx.warn(nodes.path(), left + " of " + nodes.size() + " nodes are not in the scene; they are not loaded");
        }
    }

    /** Each node's parent (-1 for none), refusing a second parent and cycles. */
    private int[] parents() throws GltfException {
        int[] parent = new int[nodes.size()];
        Arrays.fill(parent, -1);
        for (int n = 0; n < parent.length; n++) {
            JsonNode kids = nodes.get(n).get("children").arrayOrMissing();
            for (int c = 0; c < kids.size(); c++) {
                int child = kids.get(c).index(parent.length, "nodes");
                if (child == n) {
                    throw kids.get(c).error("node " + n + " is its own child");
                }
                if (parent[child] >= 0) {
                    throw kids.get(c).error("node " + child + " is already a child of node " + parent[child]
                            + " (the node graph must be a tree)");
                }
                parent[child] = n;
            }
        }
        // With one parent each, a cycle is a path upwards that comes back to itself: walk up from
        // each node until a root or a node already known to reach one (each node is walked once).
        byte[] state = new byte[parent.length]; // 0 unknown, 1 on the current walk, 2 reaches a root
        for (int n = 0; n < parent.length; n++) {
            int p = n;
            while (p >= 0 && state[p] == 0) {
                state[p] = 1;
                p = parent[p];
            }
            if (p >= 0 && state[p] == 1) {
                throw nodes.get(p).get("children").error("node " + p + " is its own ancestor (a cycle)");
            }
            for (int q = n; q >= 0 && state[q] == 1; q = parent[q]) {
                state[q] = 2;
            }
        }
        return parent;
    }

    private int[] sceneRoots(JsonNode root, int[] parent) throws GltfException {
        JsonNode scenes = root.get("scenes").arrayOrMissing();
        JsonNode sceneNode = root.get("scene");
        if (scenes.size() == 0) {
            if (!sceneNode.isMissing()) {
                throw sceneNode.error("names a scene but the document has none");
            }
            List<Integer> roots = new ArrayList<>();
            for (int n = 0; n < parent.length; n++) {
                if (parent[n] < 0) {
                    roots.add(n);
                }
            }
            if (!roots.isEmpty()) {
                ctx.warn("", "no scenes; every root node is loaded");
            }
            return roots.stream().mapToInt(Integer::intValue).toArray();
        }
        int s = sceneNode.isMissing() ? 0 : sceneNode.index(scenes.size(), "scenes");
        JsonNode list = scenes.get(s).get("nodes").arrayOrMissing();
        int[] roots = new int[list.size()];
        boolean[] listed = new boolean[parent.length];
        for (int i = 0; i < roots.length; i++) {
            roots[i] = list.get(i).index(parent.length, "nodes");
            if (parent[roots[i]] >= 0) {
                throw list.get(i).error("node " + roots[i] + " is a child of node " + parent[roots[i]]
                        + "; a scene lists root nodes only");
            }
            if (listed[roots[i]]) {
                throw list.get(i).error("node " + roots[i] + " is listed twice");
            }
            listed[roots[i]] = true;
        }
        return roots;
    }

    private static List<TransformElement> transforms(GltfContext ctx, JsonNode node) throws GltfException {
        JsonNode matrix = node.get("matrix");
        if (!matrix.isMissing()) {
            for (String trs : new String[] {TRANSLATION, ROTATION, SCALE}) {
                if (node.has(trs)) {
                    throw node.get(trs).error("a node has either a matrix or " + trs + ", not both");
                }
            }
            float[] m = matrix.floats(16, null);
            if (m[3] != 0f || m[7] != 0f || m[11] != 0f || m[15] != 1f) {
                ctx.warn(matrix.path(), "the last row is not (0 0 0 1); read as if it were");
            }
            return List.of(new TransformElement(TransformElement.Kind.MATRIX, "matrix", rowMajor(m)));
        }
        float[] q = node.get(ROTATION).floats(4, new float[] {0, 0, 0, 1});
        double length = Math.sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
        if (Math.abs(length - 1) > UNIT_TOLERANCE) {
            // The model's quaternion element is homogeneous (|q|^2 scales); glTF's rotations are unit.
            if (length == 0) {
                throw node.get(ROTATION).error("the zero quaternion is no rotation");
            }
            ctx.warn(node.get(ROTATION).path(), "not a unit quaternion (length " + (float) length + "); normalised");
            for (int c = 0; c < 4; c++) {
                q[c] = (float) (q[c] / length);
            }
        }
        return List.of(
                new TransformElement(TransformElement.Kind.TRANSLATE, TRANSLATION,
                        node.get(TRANSLATION).floats(3, new float[3])),
                new TransformElement(TransformElement.Kind.QUATERNION, ROTATION, q),
                new TransformElement(TransformElement.Kind.SCALE, SCALE,
                        node.get(SCALE).floats(3, new float[] {1, 1, 1})));
    }

    /** glTF's column-major 4x4 matrix in the model's row-major order. */
    static float[] rowMajor(float[] columnMajor) {
        float[] r = new float[16];
        for (int row = 0; row < 4; row++) {
            for (int col = 0; col < 4; col++) {
                r[4 * row + col] = columnMajor[4 * col + row];
            }
        }
        return r;
    }
}
