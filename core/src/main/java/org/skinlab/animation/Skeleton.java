package org.skinlab.animation;

import java.util.List;

import org.joml.Matrix4f;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.model.TransformElement;

/**
 * The scene's node hierarchy as runtime data: every node, joint or not, in the model's depth-first
 * order, with its transform stack flattened into one array of values that animation overwrites.
 *
 * <p>Evaluation ({@link #evaluate}) runs once forward through the nodes, parents first: each
 * node's local matrix is the product of its transform elements (composed by
 * {@link TransformElement#multiply(TransformElement.Kind, float[], int, Matrix4f, Matrix4f)}, the
 * one place that turns COLLADA transforms into matrices), its world matrix the parent's world
 * times that. Non-joint nodes between joints (an armature node, a helper, a control bone that
 * moves a joint) are evaluated like any other, so their animation and rest transforms reach the
 * joints below them.
 *
 * <p>{@link #skinningMatrices} is the one place where skinning matrices are made:
 * {@code world(joint) * INV_BIND_MATRIX * BIND_SHAPE_MATRIX}.
 *
 * <p>A skeleton is immutable and shared; all per-frame state lives in a {@link Pose}.
 */
public final class Skeleton {
    private final List<Node> nodes;
    private final int[] parents;
    private final int[] elementStart;
    private final TransformElement.Kind[] kinds;
    private final int[] valueOffsets;
    private final float[] restValues;

    private Skeleton(List<Node> nodes) {
        this.nodes = nodes;
        int n = nodes.size();
        parents = new int[n];
        elementStart = new int[n + 1];
        int elements = 0;
        int values = 0;
        for (Node node : nodes) {
            elements += node.transforms().size();
            for (TransformElement t : node.transforms()) {
                values += t.kind().size();
            }
        }
        kinds = new TransformElement.Kind[elements];
        valueOffsets = new int[elements];
        restValues = new float[values];
        int e = 0;
        int v = 0;
        for (int i = 0; i < n; i++) {
            Node node = nodes.get(i);
            parents[i] = node.parent();
            elementStart[i] = e;
            for (TransformElement t : node.transforms()) {
                kinds[e] = t.kind();
                valueOffsets[e] = v;
                t.copyValues(restValues, v);
                v += t.kind().size();
                e++;
            }
        }
        elementStart[n] = e;
    }

    /** The skeleton of a model's visual scene. */
    public static Skeleton of(Model model) {
        return new Skeleton(model.nodes());
    }

    public int nodeCount() {
        return parents.length;
    }

    /** Parent of node {@code i}, -1 for a root. */
    public int parent(int i) {
        return parents[i];
    }

    public Node node(int i) {
        return nodes.get(i);
    }

    /** Number of floats in a pose's value array. */
    public int valueCount() {
        return restValues.length;
    }

    /** Where the values of transform element {@code transformIndex} of node {@code node} start. */
    public int valueOffset(int node, int transformIndex) {
        int e = elementStart[node] + transformIndex;
        if (transformIndex < 0 || e >= elementStart[node + 1]) {
            throw new IndexOutOfBoundsException("node " + node + " has no transform " + transformIndex);
        }
        return valueOffsets[e];
    }

    /** The kind of transform element {@code transformIndex} of node {@code node}. */
    public TransformElement.Kind kind(int node, int transformIndex) {
        return kinds[elementStart[node] + transformIndex];
    }

    /** A new pose at rest (values as written in the file), already evaluated. */
    public Pose newPose() {
        Pose pose = new Pose(this);
        evaluate(pose);
        return pose;
    }

    /** Sets all transform values of the pose back to the rest values. */
    public void reset(Pose pose) {
        System.arraycopy(restValues, 0, pose.values(), 0, restValues.length);
    }

    float[] restValues() {
        return restValues;
    }

    /** Computes every node's world matrix from the pose's transform values. Allocation-free. */
    public void evaluate(Pose pose) {
        float[] values = pose.values();
        float[] world = pose.worldArray();
        Matrix4f local = pose.local;
        Matrix4f scratch = pose.scratch;
        Matrix4f parentWorld = pose.parentWorld;
        for (int i = 0; i < parents.length; i++) {
            local.identity();
            for (int e = elementStart[i]; e < elementStart[i + 1]; e++) {
                TransformElement.multiply(kinds[e], values, valueOffsets[e], local, scratch);
            }
            int p = parents[i];
            if (p >= 0) {
                parentWorld.set(world, 16 * p).mul(local, local);
            }
            local.get(world, 16 * i);
        }
    }

    /**
     * Skinning matrices for one geometry's palette: per joint
     * {@code world(jointNodes[j]) * bindMatrices[j]}, where a bind matrix is
     * INV_BIND_MATRIX * BIND_SHAPE_MATRIX (see {@code SkinnedGeometry}) and a node of -1 means no
     * node (identity world, the bind-shape pseudo-joint). Written as row-major 3x4 matrices, 12
     * floats per joint, the layout skinning kernels read. The pose must have been evaluated.
     */
    public void skinningMatrices(Pose pose, int[] jointNodes, float[] bindMatrices, float[] dest) {
        float[] world = pose.worldArray();
        Matrix4f w = pose.local;
        Matrix4f b = pose.scratch;
        for (int j = 0; j < jointNodes.length; j++) {
            int node = jointNodes[j];
            if (node >= 0) {
                w.set(world, 16 * node);
            } else {
                w.identity();
            }
            w.mul(b.set(bindMatrices, 16 * j));
            AnimationHelper.putRowMajor3x4(w, dest, 12 * j);
        }
    }
}
