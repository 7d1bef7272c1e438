package org.skinlab.model;

import java.util.List;

import org.joml.Matrix4f;
import org.joml.Matrix4fc;

/**
 * A node of the instantiated visual scene. Nodes live in one flat list in depth-first order
 * ({@link Model#nodes()}), so a parent always comes before its children and a skeleton can be
 * evaluated in one forward pass; links are indices into that list.
 *
 * <p>A {@code <node>} pulled in by {@code <instance_node>} appears once per instance, each copy
 * keeping the library node's id, sid and name; {@link #instanced()} tells the copies apart from
 * nodes written in place.
 */
public final class Node {
    private final int index;
    private final int parent;
    private final int[] children;
    private final String id;
    private final String sid;
    private final String name;
    private final boolean joint;
    private final boolean instanced;
    private final List<TransformElement> transforms;
    private final Matrix4f localMatrix;

    /**
     * Creates a node and computes its {@link #localMatrix()} from the transform stack.
     *
     * @param index      the node's position in {@link Model#nodes()}
     * @param parent     the parent node's index (less than {@code index}), or -1 for a root of the visual scene
     * @param children   the child nodes' indices, in file order (copied)
     * @param id         the node's id, or null (always null for glTF)
     * @param sid        the node's sid, or null (always null for glTF)
     * @param name       the node's name, or null
     * @param joint      true for a COLLADA node of {@code type="JOINT"}, or a glTF node that a skin lists as a joint
     * @param instanced  true when the node is a copy made for an {@code <instance_node>}
     * @param transforms the transform stack in document order (copied)
     * @throws IllegalArgumentException when {@code parent} is not less than {@code index}
     */
    public Node(int index, int parent, int[] children, String id, String sid, String name, boolean joint,
            boolean instanced, List<TransformElement> transforms) {
        if (parent >= index) {
            throw new IllegalArgumentException("a parent must come before its child");
        }
        this.index = index;
        this.parent = parent;
        this.children = children.clone();
        this.id = id;
        this.sid = sid;
        this.name = name;
        this.joint = joint;
        this.instanced = instanced;
        this.transforms = List.copyOf(transforms);
        Matrix4f m = new Matrix4f();
        Matrix4f scratch = new Matrix4f();
        for (TransformElement t : this.transforms) {
            t.multiply(m, scratch);
        }
        this.localMatrix = m;
    }

    /**
     * Position in {@link Model#nodes()}.
     *
     * @return the node's index, greater than its parent's
     */
    public int index() {
        return index;
    }

    /**
     * Index of the parent node, or -1 for a root of the visual scene.
     *
     * @return the parent's index in {@link Model#nodes()}, or -1
     */
    public int parent() {
        return parent;
    }

    /**
     * Indices of the child nodes (a copy).
     *
     * @return a new array of indices into {@link Model#nodes()}, in file order; empty for a leaf
     */
    public int[] children() {
        return children.clone();
    }

    /**
     * Number of child nodes.
     *
     * @return the child count, 0 for a leaf
     */
    public int childCount() {
        return children.length;
    }

    /**
     * Index of the node's child {@code i}.
     *
     * @param i the child's place among the node's children, 0 to {@link #childCount()} - 1
     * @return the child's index in {@link Model#nodes()}
     */
    public int child(int i) {
        return children[i];
    }

    /**
     * The node's id, or null.
     *
     * @return the id, or null when the file gives none (always for glTF)
     */
    public String id() {
        return id;
    }

    /**
     * The node's sid (what Name_array joints refer to), or null.
     *
     * @return the sid, or null when the file gives none (always for glTF)
     */
    public String sid() {
        return sid;
    }

    /**
     * The node's name, or null.
     *
     * @return the name, or null when the file gives none
     */
    public String name() {
        return name;
    }

    /**
     * True for {@code type="JOINT"}. Skins may still use plain nodes as joints.
     *
     * @return true for a COLLADA node of {@code type="JOINT"}, or a glTF node that a skin lists as a joint
     */
    public boolean isJoint() {
        return joint;
    }

    /**
     * True when this node is a copy made for an {@code <instance_node>}.
     *
     * @return whether the node is such a copy (always false for glTF)
     */
    public boolean instanced() {
        return instanced;
    }

    /**
     * The node's transform stack in document order.
     *
     * @return an unmodifiable list of the transform elements, empty when the node has none
     */
    public List<TransformElement> transforms() {
        return transforms;
    }

    /**
     * Index of the transform element with the given sid, or -1.
     *
     * @param transformSid the element's sid, not null: e.g. {@code rotateX} in the COLLADA animation target
     *                     {@code node/rotateX.ANGLE}, or glTF's {@code translation}, {@code rotation}, {@code scale}
     * @return the index in {@link #transforms()} of the first element with that sid, or -1 when none has it
     */
    public int transformIndex(String transformSid) {
        for (int i = 0; i < transforms.size(); i++) {
            if (transformSid.equals(transforms.get(i).sid())) {
                return i;
            }
        }
        return -1;
    }

    /**
     * The product of the transform stack: the node's local matrix at rest (read-only view).
     *
     * @return the matrix from the node's frame to its parent's (the identity for an empty stack)
     */
    public Matrix4fc localMatrix() {
        return localMatrix;
    }

    /**
     * A short label for messages: id, else name, else sid, else the index.
     *
     * @return the label, never null; the index is written as {@code #} and the number
     */
    public String label() {
        if (id != null) {
            return id;
        }
        if (name != null) {
            return name;
        }
        return sid != null ? sid : "#" + index;
    }

    @Override
    public String toString() {
        return "Node[" + index + " " + label() + (joint ? " JOINT" : "") + "]";
    }
}
