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

    /** Position in {@link Model#nodes()}. */
    public int index() {
        return index;
    }

    /** Index of the parent node, or -1 for a root of the visual scene. */
    public int parent() {
        return parent;
    }

    /** Indices of the child nodes (a copy). */
    public int[] children() {
        return children.clone();
    }

    public int childCount() {
        return children.length;
    }

    public int child(int i) {
        return children[i];
    }

    /** The node's id, or null. */
    public String id() {
        return id;
    }

    /** The node's sid (what Name_array joints refer to), or null. */
    public String sid() {
        return sid;
    }

    /** The node's name, or null. */
    public String name() {
        return name;
    }

    /** True for {@code type="JOINT"}. Skins may still use plain nodes as joints. */
    public boolean isJoint() {
        return joint;
    }

    /** True when this node is a copy made for an {@code <instance_node>}. */
    public boolean instanced() {
        return instanced;
    }

    /** The node's transform stack in document order. */
    public List<TransformElement> transforms() {
        return transforms;
    }

    /** Index of the transform element with the given sid, or -1. */
    public int transformIndex(String transformSid) {
        for (int i = 0; i < transforms.size(); i++) {
            if (transformSid.equals(transforms.get(i).sid())) {
                return i;
            }
        }
        return -1;
    }

    /** The product of the transform stack: the node's local matrix at rest (read-only view). */
    public Matrix4fc localMatrix() {
        return localMatrix;
    }

    /** A short label for messages: id, else name, else sid, else the index. */
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
