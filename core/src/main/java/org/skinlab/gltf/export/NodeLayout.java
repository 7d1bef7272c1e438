package org.skinlab.gltf.export;

import java.io.IOException;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import org.joml.Matrix4f;
import org.skinlab.animation.LocalPose;
import org.skinlab.animation.Skeleton;
import org.skinlab.model.AssetInfo;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.model.TransformElement;
import org.skinlab.model.UpAxis;

import com.fasterxml.jackson.core.JsonGenerator;

/**
 * The glTF node tree: one node per model node (same order), and the nodes the export adds.
 *
 * <ul>
 * <li>A root ({@value #ROOT_NAME}) above the model's roots when the document is not Y-up in
 *     metres (its rotation and uniform scale are {@link AssetInfo#toYUpMeters}), when a skin needs a
 *     node that stays in the document's frame (COLLADA's joint -1, unweighted positions), or when
 *     skinned meshes' joints hang under several roots (glTF wants one hierarchy per skin).</li>
 * <li>Transforms: a glTF translation/rotation/scale stack is written as it is; every other node
 *     as the T, R and S of its rest matrix ({@link LocalPose}), or as its matrix when that has
 *     shear T*R*S cannot hold (such a node cannot be animated in glTF, and an animated one loses
 *     its shear as the runtime's blending does).</li>
 * <li>Nodes that hold meshes: see {@link #staticMeshNode} and {@link #skinnedMeshNode}.</li>
 * </ul>
 */
final class NodeLayout {
    static final String ROOT_NAME = "skinlab_root";
    /** Largest difference of a recomposed T*R*S from the rest matrix before the matrix is written instead. */
    private static final float SHEAR_TOLERANCE = 1e-6f;

    /** A glTF node being built. */
    static final class GltfNode {
        final String name;
        final List<Integer> children = new ArrayList<>();
        float[] translation;
        float[] rotation;
        float[] scale;
        /** Column-major, or null for TRS. */
        float[] matrix;
        int mesh = -1;
        int skin = -1;
        float[] weights;

        GltfNode(String name) {
            this.name = name;
        }
    }

    private final List<GltfNode> nodes = new ArrayList<>();
    private final List<Integer> sceneRoots = new ArrayList<>();
    private final Model model;
    private final int root;
    private final boolean[] holdsMesh;
    /** Per glTF node (those made from the model's): whether some clip animates it. */
    private final boolean[] animated;
    private int documentFrame = -1;

    /**
     * Lays out the model's nodes; {@code animated} marks the nodes some clip animates (written as
     * T, R and S), {@code needsRoot} whether a skin needs the added root anyway.
     */
    NodeLayout(Model model, Skeleton skeleton, boolean[] animated, boolean needsRoot) {
        this.model = model;
        AssetInfo asset = model.asset();
        boolean converts = asset != null && (asset.upAxis() != UpAxis.Y_UP || asset.unitMeter() != 1.0);
        int modelRoots = 0;
        for (Node n : model.nodes()) {
            modelRoots += n.parent() < 0 ? 1 : 0;
        }
        boolean skinned = model.instances().stream().anyMatch(i -> i.isSkinned());
        int offset = 0;
        if (converts || needsRoot || modelRoots > 1 && skinned) {
            GltfNode r = new GltfNode(ROOT_NAME);
            if (converts) {
                // AssetInfo.toYUpMeters: Z_UP is -90 degrees about X, X_UP +90 degrees about Z; the
                // quaternions written from their exact values, so they are unit to the last bit glTF checks.
                float h = (float) Math.sqrt(0.5);
                r.rotation = asset.upAxis() == UpAxis.Z_UP ? new float[] {-h, 0f, 0f, h}
                        : asset.upAxis() == UpAxis.X_UP ? new float[] {0f, 0f, h, h} : null;
                float s = (float) asset.unitMeter();
                r.scale = new float[] {s, s, s};
            }
            nodes.add(r);
            sceneRoots.add(0);
            offset = 1;
        }
        this.root = offset == 1 ? 0 : -1;
        float[] rest = skeleton.newLocalPose().array();
        for (Node n : model.nodes()) {
            GltfNode g = new GltfNode(n.name() != null ? n.name() : n.id());
            transform(n, animated[n.index()], rest, g);
            nodes.add(g);
            if (n.parent() < 0) {
                if (root >= 0) {
                    nodes.get(root).children.add(offset + n.index());
                } else {
                    sceneRoots.add(offset + n.index());
                }
            }
            for (int c : n.children()) {
                g.children.add(offset + c);
            }
        }
        this.holdsMesh = new boolean[nodes.size()];
        this.animated = new boolean[nodes.size()];
        for (Node n : model.nodes()) {
            this.animated[offset + n.index()] = animated[n.index()];
        }
    }

    private static void transform(Node n, boolean animated, float[] rest, GltfNode g) {
        List<TransformElement> stack = n.transforms();
        if (isTrsStack(stack)) {
            g.translation = stack.get(0).values();
            g.rotation = stack.get(1).values();
            g.scale = stack.get(2).values();
            return;
        }
        int o = LocalPose.STRIDE * n.index();
        float[] t = {rest[o], rest[o + 1], rest[o + 2]};
        float[] r = {rest[o + 3], rest[o + 4], rest[o + 5], rest[o + 6]};
        float[] s = {rest[o + 7], rest[o + 8], rest[o + 9]};
        Matrix4f trs = new Matrix4f().translationRotateScale(t[0], t[1], t[2], r[0], r[1], r[2], r[3], s[0], s[1], s[2]);
        if (!animated && !trs.equals(n.localMatrix(), SHEAR_TOLERANCE * Math.max(1f, maxAbs(n.localMatrix())))) {
            g.matrix = n.localMatrix().get(new float[16]);
            return;
        }
        g.translation = t;
        g.rotation = r;
        g.scale = s;
    }

    private static float maxAbs(org.joml.Matrix4fc m) {
        float[] v = m.get(new float[16]);
        float max = 0f;
        for (float f : v) {
            max = Math.max(max, Math.abs(f));
        }
        return max;
    }

    /** glTF's own stack as the importer makes it: translation, rotation, scale. */
    static boolean isTrsStack(List<TransformElement> stack) {
        return stack.size() == 3 && stack.get(0).kind() == TransformElement.Kind.TRANSLATE
                && "translation".equals(stack.get(0).sid()) && stack.get(1).kind() == TransformElement.Kind.QUATERNION
                && "rotation".equals(stack.get(1).sid()) && stack.get(2).kind() == TransformElement.Kind.SCALE
                && "scale".equals(stack.get(2).sid());
    }

    /** The glTF node of model node {@code modelNode}. */
    int node(int modelNode) {
        return modelNode + (root >= 0 ? 1 : 0);
    }

    GltfNode get(int gltfNode) {
        return nodes.get(gltfNode);
    }

    int size() {
        return nodes.size();
    }

    /** A node whose world matrix is the document's frame at all times (a child of the root). */
    int documentFrame() {
        if (documentFrame < 0) {
            if (root < 0) {
                throw new IllegalStateException("no root for the document frame");
            }
            documentFrame = add(root, "skinlab_document_frame");
        }
        return documentFrame;
    }

    /** A new identity node under {@code parent} (-1: a scene root). */
    int add(int parent, String name) {
        nodes.add(new GltfNode(name));
        int index = nodes.size() - 1;
        if (parent < 0) {
            sceneRoots.add(index);
        } else {
            nodes.get(parent).children.add(index);
        }
        return index;
    }

    /**
     * The node that draws a static instance of model node {@code modelNode}: the node itself for
     * its first mesh, an identity child for each further one (a glTF node holds one mesh).
     */
    int staticMeshNode(int modelNode, String name) {
        int g = node(modelNode);
        if (!holdsMesh[g]) {
            holdsMesh[g] = true;
            return g;
        }
        return add(g, name);
    }

    /**
     * The node that draws a skinned instance: glTF ignores its transform and warns when it is not
     * a root, so the model's node when it is a plain root of identity transform that holds no
     * other mesh, else a new scene root.
     */
    int skinnedMeshNode(int modelNode, String name) {
        Node n = model.node(modelNode);
        int g = node(modelNode);
        boolean plainRoot = root < 0 && n.parent() < 0 && !n.isJoint() && n.childCount() == 0
                && n.localMatrix().equals(new Matrix4f(), 0f);
        if (plainRoot && !holdsMesh[g]) {
            holdsMesh[g] = true;
            GltfNode node = nodes.get(g);
            node.translation = null;
            node.rotation = null;
            node.scale = null;
            node.matrix = null;
            return g;
        }
        return add(-1, name);
    }

    /**
     * The skin's joints {@code joints} followed by the skeleton's non-joint ancestors when one of
     * them has a transform of its own (the up-axis root, an armature object), as joints no vertex
     * is bound to. A skinned mesh node is a scene root (see {@link #skinnedMeshNode}), and engines
     * differ in what they make of the skeleton's other ancestors: jMonkeyEngine's loader drops
     * their transforms, three.js binds the mesh at its own world matrix when it sits under them.
     * Every engine keeps a joint's transform.
     */
    int[] withTransformedAncestors(int[] joints) {
        int[] parents = new int[nodes.size()];
        java.util.Arrays.fill(parents, -1);
        for (int i = 0; i < nodes.size(); i++) {
            for (int c : nodes.get(i).children) {
                parents[c] = i;
            }
        }
        Set<Integer> jointSet = new HashSet<>();
        for (int j : joints) {
            jointSet.add(j);
        }
        // The deepest node on the first joint's path to the root that every joint's path passes through.
        List<Integer> path = new ArrayList<>();
        for (int a = joints.length > 0 ? joints[0] : -1; a >= 0; a = parents[a]) {
            path.add(a);
        }
        int common = 0;
        for (int j : joints) {
            Set<Integer> ancestors = new HashSet<>();
            for (int a = j; a >= 0; a = parents[a]) {
                ancestors.add(a);
            }
            while (common < path.size() && !ancestors.contains(path.get(common))) {
                common++;
            }
        }
        List<Integer> added = new ArrayList<>();
        boolean transformed = false;
        for (int i = common; i < path.size(); i++) {
            int a = path.get(i);
            if (!jointSet.contains(a)) {
                added.add(a);
                transformed |= !isIdentity(nodes.get(a), a);
            }
        }
        if (!transformed) {
            return joints;
        }
        int[] result = java.util.Arrays.copyOf(joints, joints.length + added.size());
        for (int i = 0; i < added.size(); i++) {
            result[joints.length + i] = added.get(i);
        }
        return result;
    }

    private boolean isIdentity(GltfNode n, int gltfNode) {
        if (n.matrix != null) {
            return new Matrix4f().set(n.matrix).equals(new Matrix4f(), 0f);
        }
        boolean t = n.translation == null || n.translation[0] == 0f && n.translation[1] == 0f && n.translation[2] == 0f;
        boolean r = n.rotation == null || n.rotation[0] == 0f && n.rotation[1] == 0f && n.rotation[2] == 0f;
        boolean s = n.scale == null || n.scale[0] == 1f && n.scale[1] == 1f && n.scale[2] == 1f;
        return t && r && s && (gltfNode >= animated.length || !animated[gltfNode]);
    }

    /** Distinct joint nodes for a skin: a node named twice gets an identity child for its second use. */
    int[] jointNodes(int[] gltfNodes) {
        Set<Integer> used = new HashSet<>();
        int[] result = gltfNodes.clone();
        for (int j = 0; j < result.length; j++) {
            if (!used.add(result[j])) {
                result[j] = add(result[j], nodes.get(result[j]).name + "_joint" + j);
            }
        }
        return result;
    }

    void writeJson(JsonGenerator g) throws IOException {
        g.writeNumberField("scene", 0);
        g.writeArrayFieldStart("scenes");
        g.writeStartObject();
        g.writeArrayFieldStart("nodes");
        for (int r : sceneRoots) {
            g.writeNumber(r);
        }
        g.writeEndArray();
        g.writeEndObject();
        g.writeEndArray();
        g.writeArrayFieldStart("nodes");
        for (GltfNode n : nodes) {
            g.writeStartObject();
            if (n.name != null) {
                g.writeStringField("name", n.name);
            }
            if (!n.children.isEmpty()) {
                g.writeArrayFieldStart("children");
                for (int c : n.children) {
                    g.writeNumber(c);
                }
                g.writeEndArray();
            }
            if (n.matrix != null) {
                BinaryChunk.writeFloats(g, "matrix", n.matrix);
            }
            writeUnlessDefault(g, "translation", n.translation, 0f, 0f, 0f);
            writeUnlessDefault(g, "rotation", n.rotation, 0f, 0f, 0f, 1f);
            writeUnlessDefault(g, "scale", n.scale, 1f, 1f, 1f);
            if (n.mesh >= 0) {
                g.writeNumberField("mesh", n.mesh);
            }
            if (n.skin >= 0) {
                g.writeNumberField("skin", n.skin);
            }
            if (n.weights != null) {
                BinaryChunk.writeFloats(g, "weights", n.weights);
            }
            g.writeEndObject();
        }
        g.writeEndArray();
    }

    private static void writeUnlessDefault(JsonGenerator g, String name, float[] v, float... identity)
            throws IOException {
        if (v != null && !java.util.Arrays.equals(v, identity)) {
            BinaryChunk.writeFloats(g, name, v);
        }
    }
}
