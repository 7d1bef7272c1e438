package org.skinlab.animation;

import java.util.List;

import org.joml.Matrix4f;
import org.joml.Quaternionf;
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
 * one place that turns COLLADA transforms into matrices; a stack of one {@code <matrix>} is read
 * the same way straight from its values), its world matrix the parent's world times that.
 * Non-joint nodes between joints (an armature node, a helper, a control bone that moves a joint)
 * are evaluated like any other, so their animation and rest transforms reach the joints below
 * them.
 *
 * <p>{@link #skinningMatrices} is the one place where skinning matrices are made:
 * {@code world(joint) * bind}, with bind = INV_BIND_MATRIX for points already in bind space
 * (see {@code SkinnedGeometry}): COLLADA's {@code world * INV_BIND_MATRIX * BIND_SHAPE_MATRIX}.
 *
 * <p>A skeleton is immutable and shared; all per-frame state lives in a {@link Pose}.
 */
public final class Skeleton {
    /** How {@link #mulAffine} reads its right operand. */
    private static final boolean ROW_MAJOR = true;
    private static final boolean COLUMN_MAJOR = false;
    /** The parent world matrix of a root. */
    private static final float[] IDENTITY = {1f, 0f, 0f, 0f, 0f, 1f, 0f, 0f, 0f, 0f, 1f, 0f, 0f, 0f, 0f, 1f};

    private final List<Node> nodes;
    private final int[] parents;
    private final int[] elementStart;
    private final TransformElement.Kind[] kinds;
    private final int[] valueOffsets;
    private final float[] restValues;
    /** Per node: its stack is one {@code <matrix>} (the common case), read straight from the values. */
    private final boolean[] singleMatrix;
    /**
     * Per node: its stack is glTF's translation, rotation quaternion, scale (each at most once,
     * in that order), so its {@link LocalPose} transform is its values, read without a matrix.
     */
    private final boolean[] trsStack;
    /** Every node's rest transform in {@link LocalPose}'s layout. */
    private final float[] restLocal;

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
        singleMatrix = new boolean[n];
        trsStack = new boolean[n];
        for (int i = 0; i < n; i++) {
            singleMatrix[i] = elementStart[i + 1] - elementStart[i] == 1
                    && kinds[elementStart[i]] == TransformElement.Kind.MATRIX;
            trsStack[i] = inTrsOrder(elementStart[i], elementStart[i + 1]);
        }
        restLocal = new float[LocalPose.STRIDE * n];
        Matrix4f m = new Matrix4f();
        Matrix4f scratch = new Matrix4f();
        Quaternionf q = new Quaternionf();
        for (int i = 0; i < n; i++) {
            toLocal(i, restValues, m, scratch, q, restLocal);
        }
    }

    /** Whether node {@code node}'s stack is glTF's translation, rotation, scale (each at most once, in order). */
    boolean isTrsStack(int node) {
        return trsStack[node];
    }

    private boolean inTrsOrder(int from, int to) {
        int last = -1;
        for (int e = from; e < to; e++) {
            int rank = kinds[e] == TransformElement.Kind.TRANSLATE ? 0
                    : kinds[e] == TransformElement.Kind.QUATERNION ? 1
                    : kinds[e] == TransformElement.Kind.SCALE ? 2 : -1;
            if (rank <= last) {
                return false;
            }
            last = rank;
        }
        return true;
    }

    /**
     * Writes node {@code i}'s local transform, made from its transform values in {@code values},
     * into {@code dest} in {@link LocalPose}'s layout: read straight from a glTF TRS stack (the
     * quaternion normalised), else the product of its stack split into T, R and S (shear dropped).
     * Allocation-free; {@code m}, {@code scratch} and {@code q} are overwritten.
     */
    void toLocal(int i, float[] values, Matrix4f m, Matrix4f scratch, Quaternionf q, float[] dest) {
        int o = LocalPose.STRIDE * i;
        if (trsStack[i]) {
            dest[o] = 0f;
            dest[o + 1] = 0f;
            dest[o + 2] = 0f;
            dest[o + 3] = 0f;
            dest[o + 4] = 0f;
            dest[o + 5] = 0f;
            dest[o + 6] = 1f;
            dest[o + 7] = 1f;
            dest[o + 8] = 1f;
            dest[o + 9] = 1f;
            for (int e = elementStart[i]; e < elementStart[i + 1]; e++) {
                int v = valueOffsets[e];
                switch (kinds[e]) {
                    case TRANSLATE:
                        System.arraycopy(values, v, dest, o, 3);
                        break;
                    case QUATERNION: {
                        double len = Math.sqrt((double) values[v] * values[v] + (double) values[v + 1] * values[v + 1]
                                + (double) values[v + 2] * values[v + 2] + (double) values[v + 3] * values[v + 3]);
                        if (len > 0) {
                            for (int c = 0; c < 4; c++) {
                                dest[o + 3 + c] = (float) (values[v + c] / len);
                            }
                        }
                        break;
                    }
                    default:
                        System.arraycopy(values, v, dest, o + 7, 3);
                        break;
                }
            }
            return;
        }
        m.identity();
        for (int e = elementStart[i]; e < elementStart[i + 1]; e++) {
            TransformElement.multiply(kinds[e], values, valueOffsets[e], m, scratch);
        }
        LocalPose.split(m, q, dest, o);
    }

    /**
     * A new local pose at rest: every node's rest transform split into T, R and S.
     *
     * @return a new local pose of this skeleton
     */
    public LocalPose newLocalPose() {
        return new LocalPose(this, restLocal);
    }

    float[] restLocal() {
        return restLocal;
    }

    /**
     * The skeleton of a model's visual scene.
     *
     * @param model the model whose {@link Model#nodes() nodes} become the skeleton's, in the same order
     * @return a new skeleton, its rest values copied from the nodes' transform elements
     */
    public static Skeleton of(Model model) {
        return new Skeleton(model.nodes());
    }

    /**
     * Number of nodes, joints or not: the size of {@link Model#nodes()}.
     *
     * @return the node count; node indices run from 0 to this minus 1
     */
    public int nodeCount() {
        return parents.length;
    }

    /**
     * Parent of node {@code i}, -1 for a root.
     *
     * @param i the node index, in [0, {@link #nodeCount()})
     * @return the parent's node index, always less than {@code i}, or -1 for a root
     */
    public int parent(int i) {
        return parents[i];
    }

    /**
     * Node {@code i} of the model, as imported.
     *
     * @param i the node index, in [0, {@link #nodeCount()})
     * @return the node, with its name, ids and rest transform elements
     */
    public Node node(int i) {
        return nodes.get(i);
    }

    /**
     * Number of floats in a pose's value array.
     *
     * @return the length of {@link Pose#values()}: the sizes of all nodes' transform elements summed
     */
    public int valueCount() {
        return restValues.length;
    }

    /**
     * Where the values of transform element {@code transformIndex} of node {@code node} start.
     *
     * @param node the node index, in [0, {@link #nodeCount()})
     * @param transformIndex the index of the element in the node's transform stack ({@link Node#transforms()})
     * @return the index in {@link Pose#values()} of the element's first value; {@link #kind} says how many follow
     * @throws IndexOutOfBoundsException when the node has no such element or there is no such node
     */
    public int valueOffset(int node, int transformIndex) {
        int e = elementStart[node] + transformIndex;
        if (transformIndex < 0 || e >= elementStart[node + 1]) {
            throw new IndexOutOfBoundsException("node " + node + " has no transform " + transformIndex);
        }
        return valueOffsets[e];
    }

    /**
     * The kind of transform element {@code transformIndex} of node {@code node}.
     *
     * @param node the node index, in [0, {@link #nodeCount()})
     * @param transformIndex the index of the element in the node's transform stack, in
     *     [0, {@code node(node).transforms().size()}); not checked against the node's own stack
     * @return the element's kind, which fixes the number and layout of its values
     */
    public TransformElement.Kind kind(int node, int transformIndex) {
        return kinds[elementStart[node] + transformIndex];
    }

    /**
     * A new pose at rest (values as written in the file), already evaluated.
     *
     * @return a new pose of this skeleton, with its own value and world arrays
     */
    public Pose newPose() {
        Pose pose = new Pose(this);
        evaluate(pose);
        return pose;
    }

    /**
     * Sets all transform values of the pose back to the rest values. The world matrices are left
     * as they were until the next {@link #evaluate}.
     *
     * @param pose a pose of this skeleton
     */
    public void reset(Pose pose) {
        System.arraycopy(restValues, 0, pose.values(), 0, restValues.length);
    }

    float[] restValues() {
        return restValues;
    }

    /**
     * Computes every node's world matrix from the pose's transform values. Allocation-free.
     *
     * <p>The products are written out on the arrays (see {@link #mulAffine}); a node whose stack
     * is one {@code <matrix>} is read straight from its values, others go through
     * {@link TransformElement#multiply}.
     *
     * @param pose a pose of this skeleton; its transform values are read, its world matrices overwritten
     */
    public void evaluate(Pose pose) {
        evaluate(pose, null, null);
    }

    /**
     * As {@link #evaluate(Pose)}, except that each node {@code i} with {@code given[i]} takes
     * {@code givenWorlds[16 i ..]} (column-major) as its world matrix instead of its parent's times
     * its own transforms; the nodes below it build on that ({@link BindPose}). Null arrays give
     * no node.
     */
    void evaluate(Pose pose, boolean[] given, float[] givenWorlds) {
        float[] values = pose.values();
        float[] world = pose.worldArray();
        Matrix4f local = pose.local;
        Matrix4f scratch = pose.scratch;
        for (int i = 0; i < parents.length; i++) {
            int w = 16 * i;
            int p = parents[i];
            if (given != null && given[i]) {
                System.arraycopy(givenWorlds, w, world, w, 16);
                continue;
            }
            if (singleMatrix[i]) {
                // The values are the local matrix, row-major (bottom row taken as 0 0 0 1).
                int o = valueOffsets[elementStart[i]];
                if (p >= 0) {
                    mulAffine(world, 16 * p, values, o, ROW_MAJOR, world, w);
                } else {
                    mulAffine(IDENTITY, 0, values, o, ROW_MAJOR, world, w);
                }
                continue;
            }
            local.identity();
            for (int e = elementStart[i]; e < elementStart[i + 1]; e++) {
                TransformElement.multiply(kinds[e], values, valueOffsets[e], local, scratch);
            }
            local.get(world, w);
            if (p >= 0) {
                mulAffine(world, 16 * p, world, w, COLUMN_MAJOR, world, w);
            }
        }
    }

    /**
     * Computes every node's world matrix from local transforms: {@code parent world * T * R * S}.
     * Allocation-free. The pose's transform values are not touched (they no longer describe its
     * world matrices until the next {@link #evaluate(Pose)}).
     *
     * @param local the nodes' local transforms, a local pose of this skeleton
     * @param pose a pose of this skeleton; its world matrices are overwritten
     * @throws IllegalArgumentException when either belongs to another skeleton
     */
    public void evaluate(LocalPose local, Pose pose) {
        if (local.skeleton() != this || pose.skeleton() != this) {
            throw new IllegalArgumentException("a pose of another skeleton");
        }
        float[] trs = local.array();
        float[] world = pose.worldArray();
        float[] rows = pose.localRows;
        for (int i = 0; i < parents.length; i++) {
            int o = LocalPose.STRIDE * i;
            AnimationHelper.composeRowMajor(trs[o], trs[o + 1], trs[o + 2], trs[o + 3], trs[o + 4], trs[o + 5],
                    trs[o + 6], trs[o + 7], trs[o + 8], trs[o + 9], rows, 0);
            int p = parents[i];
            mulAffine(p >= 0 ? world : IDENTITY, p >= 0 ? 16 * p : 0, rows, 0, ROW_MAJOR, world, 16 * i);
        }
    }

    /**
     * {@code dest = a * b} for affine matrices stored column-major, 16 floats each (bottom rows
     * taken as 0 0 0 1, not read), except that {@code b} may be row-major; {@code dest} may be
     * either operand. Each entry is summed in the order JOML's {@code Matrix4f.mulAffine} uses,
     * so the results equal JOML's products to the bit (up to the sign of a zero).
     */
    static void mulAffine(float[] a, int ao, float[] b, int bo, boolean bRowMajor, float[] dest, int d) {
        int rs = bRowMajor ? 4 : 1; // step between rows of b
        int cs = bRowMajor ? 1 : 4; // step between columns of b
        float a00 = a[ao];
        float a01 = a[ao + 1];
        float a02 = a[ao + 2];
        float a10 = a[ao + 4];
        float a11 = a[ao + 5];
        float a12 = a[ao + 6];
        float a20 = a[ao + 8];
        float a21 = a[ao + 9];
        float a22 = a[ao + 10];
        float a30 = a[ao + 12];
        float a31 = a[ao + 13];
        float a32 = a[ao + 14];
        // bCR: column C, row R (JOML's naming).
        float b00 = b[bo];
        float b01 = b[bo + rs];
        float b02 = b[bo + 2 * rs];
        float b10 = b[bo + cs];
        float b11 = b[bo + cs + rs];
        float b12 = b[bo + cs + 2 * rs];
        float b20 = b[bo + 2 * cs];
        float b21 = b[bo + 2 * cs + rs];
        float b22 = b[bo + 2 * cs + 2 * rs];
        float b30 = b[bo + 3 * cs];
        float b31 = b[bo + 3 * cs + rs];
        float b32 = b[bo + 3 * cs + 2 * rs];
        dest[d] = a00 * b00 + (a10 * b01 + a20 * b02);
        dest[d + 1] = a01 * b00 + (a11 * b01 + a21 * b02);
        dest[d + 2] = a02 * b00 + (a12 * b01 + a22 * b02);
        dest[d + 3] = 0f;
        dest[d + 4] = a00 * b10 + (a10 * b11 + a20 * b12);
        dest[d + 5] = a01 * b10 + (a11 * b11 + a21 * b12);
        dest[d + 6] = a02 * b10 + (a12 * b11 + a22 * b12);
        dest[d + 7] = 0f;
        dest[d + 8] = a00 * b20 + (a10 * b21 + a20 * b22);
        dest[d + 9] = a01 * b20 + (a11 * b21 + a21 * b22);
        dest[d + 10] = a02 * b20 + (a12 * b21 + a22 * b22);
        dest[d + 11] = 0f;
        dest[d + 12] = a00 * b30 + (a10 * b31 + (a20 * b32 + a30));
        dest[d + 13] = a01 * b30 + (a11 * b31 + (a21 * b32 + a31));
        dest[d + 14] = a02 * b30 + (a12 * b31 + (a22 * b32 + a32));
        dest[d + 15] = 1f;
    }

    /**
     * Skinning matrices for one geometry's palette: per joint
     * {@code world(jointNodes[j]) * bindMatrices[j]}, where a bind matrix is
     * INV_BIND_MATRIX for points in bind space (see {@code SkinnedGeometry}) and a node of -1 means no
     * node (identity world, the bind-shape pseudo-joint). Bind matrices are affine (their bottom
     * rows are not read). Written as row-major 3x4 matrices, 12 floats per joint, the layout
     * skinning kernels read. The pose must have been evaluated.
     *
     * @param pose an evaluated pose of this skeleton, whose world matrices are read
     * @param jointNodes per joint of the palette, its node index, or -1 for the identity world
     * @param bindMatrices per joint, its bind matrix as 16 floats column-major at {@code 16 j}
     * @param dest receives per joint a row-major 3x4 matrix at {@code 12 j}; at least {@code 12 * jointNodes.length}
     *     floats
     */
    public void skinningMatrices(Pose pose, int[] jointNodes, float[] bindMatrices, float[] dest) {
        float[] world = pose.worldArray();
        float[] product = pose.product;
        for (int j = 0; j < jointNodes.length; j++) {
            int node = jointNodes[j];
            if (node >= 0) {
                mulAffine(world, 16 * node, bindMatrices, 16 * j, COLUMN_MAJOR, product, 0);
                AnimationHelper.putRowMajor3x4(product, 0, dest, 12 * j);
            } else {
                AnimationHelper.putRowMajor3x4(bindMatrices, 16 * j, dest, 12 * j);
            }
        }
    }
}
