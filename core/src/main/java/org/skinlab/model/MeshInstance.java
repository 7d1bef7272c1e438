package org.skinlab.model;

import java.util.List;

/**
 * A mesh placed in the scene: an {@code <instance_geometry>} (static, {@link #skin()} null) or an
 * {@code <instance_controller>} (skinned), with the skin's joints resolved to scene nodes.
 *
 * <p>A static instance is placed by its node's world matrix. A skinned one is placed by its
 * joints alone ({@code world(joint) * inverse bind * bind shape}, see {@code SkinnedGeometry}):
 * its node's transform does not move it, as glTF 2.0 requires ("the transform of the node that
 * holds a skinned mesh is ignored") and COLLADA's skinning equation has it.
 *
 * <p>Joint resolution (COLLADA 1.4.1, skin and instance_controller): with {@code <skeleton>}
 * roots, a Name_array joint is the node whose sid matches under those roots (first root first,
 * depth-first); without roots, or when no sid matches, the node whose id and then whose name
 * matches. IDREF_array joints are node ids. A joint that matches nothing is an import error.
 */
public final class MeshInstance {
    private final int node;
    private final Mesh mesh;
    private final Skin skin;
    private final int[] jointNodes;
    private final int[] skeletonRoots;
    private final List<MaterialBinding> materials;

    /**
     * @param node          index of the node that holds the instance
     * @param mesh          the mesh drawn: a geometry's mesh or a morph's result; for a skinned instance the
     *                      skin's {@link Skin#mesh()}
     * @param skin          the skin for a controller instance, or null
     * @param jointNodes    per skin joint, the node index (empty when static)
     * @param skeletonRoots the {@code <skeleton>} root node indices, in file order
     * @param materials     the material bound to each symbol, in {@code <instance_material>} order
     * @throws IllegalArgumentException when the skin deforms another mesh than {@code mesh}, or
     *         {@code jointNodes} does not hold one node per skin joint
     */
    public MeshInstance(int node, Mesh mesh, Skin skin, int[] jointNodes, int[] skeletonRoots,
            List<MaterialBinding> materials) {
        if (skin != null && skin.mesh() != mesh) {
            throw new IllegalArgumentException("the skin deforms a different mesh");
        }
        if (jointNodes.length != (skin == null ? 0 : skin.jointCount())) {
            throw new IllegalArgumentException("need one node per skin joint");
        }
        this.node = node;
        this.mesh = mesh;
        this.skin = skin;
        this.jointNodes = jointNodes.clone();
        this.skeletonRoots = skeletonRoots.clone();
        this.materials = List.copyOf(materials);
    }

    /**
     * Index of the node holding the instance.
     *
     * @return the node's index in {@link Model#nodes()}
     */
    public int node() {
        return node;
    }

    /**
     * The mesh drawn, before skinning: for a skinned instance, the skin's {@link Skin#mesh()}.
     *
     * @return the mesh: a geometry's, or a morph's result
     */
    public Mesh mesh() {
        return mesh;
    }

    /**
     * The skin, or null for a static mesh.
     *
     * @return the skin, or null
     */
    public Skin skin() {
        return skin;
    }

    /**
     * Whether the instance is skinned (placed by its joints, not by its node).
     *
     * @return true when {@link #skin()} is not null
     */
    public boolean isSkinned() {
        return skin != null;
    }

    /**
     * Node index of skin joint {@code j}.
     *
     * @param j the skin's joint index, 0 to {@link Skin#jointCount()} - 1
     * @return the index in {@link Model#nodes()} of the node the joint resolved to
     */
    public int jointNode(int j) {
        return jointNodes[j];
    }

    /**
     * Node indices of all skin joints (a copy).
     *
     * @return a new array with, per skin joint, its index in {@link Model#nodes()}; empty for a static instance
     */
    public int[] jointNodes() {
        return jointNodes.clone();
    }

    /**
     * The {@code <skeleton>} roots (a copy; empty when the instance names none).
     *
     * @return a new array of node indices in file order (for glTF, the skin's {@code skeleton} node, if any)
     */
    public int[] skeletonRoots() {
        return skeletonRoots.clone();
    }

    /**
     * The materials bound to the instance's symbols, in {@code <instance_material>} order.
     *
     * @return an unmodifiable list, one binding per bound symbol
     */
    public List<MaterialBinding> materials() {
        return materials;
    }

    /**
     * What the triangles of a {@link MeshPart} with this material symbol are drawn with: the
     * bound material, or {@link Material#DEFAULT} (texture coordinate set -1) when the file binds
     * none to it.
     *
     * @param symbol a material symbol, as {@link MeshPart#material()} gives it; null (a part without one) gets
     *               the default
     * @return the bound material's binding, or a new binding of {@link Material#DEFAULT}; never null
     */
    public MaterialBinding material(String symbol) {
        for (MaterialBinding b : materials) {
            if (b.symbol().equals(symbol)) {
                return b;
            }
        }
        return new MaterialBinding(symbol, Material.DEFAULT, -1);
    }
}
