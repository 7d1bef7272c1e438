package org.skinlab.skinning;

import java.util.Arrays;
import java.util.List;

import org.joml.Matrix4f;
import org.skinlab.model.Node;

/**
 * The bones of a geometry's palette as segments in bind space (the points' space), for the
 * methods that deform relative to bones rather than joints ({@link SkinningMethod#usesBones()}).
 * A file stores joints (frames), not bones: each joint's bone is derived here once.
 *
 * <ul>
 * <li><b>Head</b>: the joint's origin in bind space, the translation of {@code inverse(bind)}.</li>
 * <li><b>Tail</b>: the head of the child joint that lies most nearly along the joint's bind-frame
 *     Y axis (the bone axis in Blender's rigs and in most files exported from them; a Blender
 *     bone's connected child sits exactly there). A joint with several children (hips, a hand)
 *     thus points at its main continuation, not at their average.</li>
 * <li><b>A leaf</b> (no child away from its head) points along its Y axis, as long as the
 *     farthest point it dominates (its heaviest influence) reaches along that axis; a leaf that
 *     dominates no point beyond its head has length 0, a point-like bone.</li>
 * </ul>
 * Without a node tree ({@link SkinnedGeometry#of(org.skinlab.model.MeshInstance)}) every joint
 * is a leaf. Immutable.
 */
public final class Bones {
    /** Below this length (bind-space units) a joint-to-child offset is not a direction. */
    private static final float MIN_LENGTH = 1e-6f;

    private final int[] parents;
    private final int[] tailJoints;
    /** Per joint: head xyz, tail xyz. */
    private final float[] segments;

    private Bones(int[] parents, int[] tailJoints, float[] segments) {
        this.parents = parents;
        this.tailJoints = tailJoints;
        this.segments = segments;
    }

    /**
     * The bones of a geometry's palette joints. Bind-time work, one pass over the points (for the
     * leaves' lengths); a geometry computes them once when it is built ({@link SkinnedGeometry#bones()}).
     *
     * @param geometry the geometry whose bind matrices, joint hierarchy and points give the bones
     * @return the bones, one per palette joint
     */
    public static Bones of(SkinnedGeometry geometry) {
        int joints = geometry.jointCount();
        int[] parents = new int[joints];
        for (int j = 0; j < joints; j++) {
            parents[j] = geometry.jointParent(j);
        }
        float[] heads = new float[3 * joints];
        float[] axes = new float[3 * joints];
        restHeadsAndAxes(geometry.bindMatrixArray(), heads, axes);
        int[] tailJoints = tailJoints(parents, heads, axes);
        float[] leafLengths = leafLengths(geometry, heads, axes, tailJoints);
        float[] segments = new float[6 * joints];
        for (int j = 0; j < joints; j++) {
            System.arraycopy(heads, 3 * j, segments, 6 * j, 3);
            int t = tailJoints[j];
            for (int a = 0; a < 3; a++) {
                segments[6 * j + 3 + a] = t >= 0 ? heads[3 * t + a] : heads[3 * j + a] + leafLengths[j] * axes[3 * j + a];
            }
        }
        return new Bones(parents, tailJoints, segments);
    }

    /**
     * Per joint its rest frame's origin (the head) and unit Y axis (the bone axis; +Y where the
     * frame has none), from its bind matrix: the frame is {@code inverse(bind)}, the identity
     * where that is singular.
     */
    private static void restHeadsAndAxes(float[] bind, float[] heads, float[] axes) {
        Matrix4f frame = new Matrix4f();
        for (int j = 0; j < heads.length / 3; j++) {
            frame.set(bind, 16 * j).invert();
            if (!frame.isFinite()) {
                frame.identity();
            }
            heads[3 * j] = frame.m30();
            heads[3 * j + 1] = frame.m31();
            heads[3 * j + 2] = frame.m32();
            float yx = frame.m10(), yy = frame.m11(), yz = frame.m12();
            float len = (float) Math.sqrt(yx * yx + yy * yy + yz * yz);
            if (len > 0f) {
                axes[3 * j] = yx / len;
                axes[3 * j + 1] = yy / len;
                axes[3 * j + 2] = yz / len;
            } else {
                axes[3 * j + 1] = 1f;
            }
        }
    }

    /** Per joint the child whose head lies most nearly along its axis (see the class comment), or -1. */
    private static int[] tailJoints(int[] parents, float[] heads, float[] axes) {
        int joints = parents.length;
        int[] tailJoints = new int[joints];
        Arrays.fill(tailJoints, -1);
        float[] bestCos = new float[joints];
        Arrays.fill(bestCos, Float.NEGATIVE_INFINITY);
        for (int c = 0; c < joints; c++) {
            int p = parents[c];
            if (p < 0) {
                continue;
            }
            float dx = heads[3 * c] - heads[3 * p];
            float dy = heads[3 * c + 1] - heads[3 * p + 1];
            float dz = heads[3 * c + 2] - heads[3 * p + 2];
            float len = (float) Math.sqrt(dx * dx + dy * dy + dz * dz);
            if (len < MIN_LENGTH) {
                continue;
            }
            float cos = (dx * axes[3 * p] + dy * axes[3 * p + 1] + dz * axes[3 * p + 2]) / len;
            if (cos > bestCos[p]) {
                bestCos[p] = cos;
                tailJoints[p] = c;
            }
        }
        return tailJoints;
    }

    /** Per leaf joint, how far along its axis the points it dominates reach (0 for none beyond the head). */
    private static float[] leafLengths(SkinnedGeometry geometry, float[] heads, float[] axes, int[] tailJoints) {
        float[] lengths = new float[tailJoints.length];
        float[] positions = geometry.positionArray();
        int[] joints = geometry.jointArray();
        float[] weights = geometry.weightArray();
        int width = geometry.influencesPerPoint();
        for (int i = 0; i < geometry.pointCount(); i++) {
            int j = joints[width * i];
            if (tailJoints[j] >= 0 || !(weights[width * i] > 0f)) {
                continue;
            }
            float along = (positions[3 * i] - heads[3 * j]) * axes[3 * j]
                    + (positions[3 * i + 1] - heads[3 * j + 1]) * axes[3 * j + 1]
                    + (positions[3 * i + 2] - heads[3 * j + 2]) * axes[3 * j + 2];
            if (along > lengths[j]) {
                lengths[j] = along;
            }
        }
        return lengths;
    }

    /** Per palette joint, the palette joint of its nearest ancestor node in the palette, else -1. */
    static int[] jointParents(int[] jointNodes, List<Node> nodes) {
        int[] parents = new int[jointNodes.length];
        Arrays.fill(parents, -1);
        if (nodes.isEmpty()) {
            return parents;
        }
        int[] jointOfNode = new int[nodes.size()];
        Arrays.fill(jointOfNode, -1);
        for (int j = jointNodes.length - 1; j >= 0; j--) {
            if (jointNodes[j] >= 0) {
                jointOfNode[jointNodes[j]] = j; // a node listed twice: its first joint
            }
        }
        for (int j = 0; j < jointNodes.length; j++) {
            int node = jointNodes[j] < 0 ? -1 : nodes.get(jointNodes[j]).parent();
            while (node >= 0 && jointOfNode[node] < 0) {
                node = nodes.get(node).parent();
            }
            parents[j] = node >= 0 && jointOfNode[node] != j ? jointOfNode[node] : -1;
        }
        return parents;
    }

    /**
     * Number of bones, one per palette joint.
     *
     * @return the geometry's {@link SkinnedGeometry#jointCount()}
     */
    public int jointCount() {
        return parents.length;
    }

    /**
     * Joint j's parent joint, or -1.
     *
     * @param j a palette joint, {@code [0, jointCount())}
     * @return the parent's palette index (lower than {@code j} for {@link SkinnedGeometry#fromArrays}),
     *         or -1 for a root or when no node tree was known
     */
    public int parent(int j) {
        return parents[j];
    }

    /**
     * The child joint whose head is joint j's tail, or -1 for a leaf.
     *
     * @param j a palette joint, {@code [0, jointCount())}
     * @return the child's palette index, or -1 when the tail lies along j's own Y axis
     */
    public int tailJoint(int j) {
        return tailJoints[j];
    }

    /**
     * Coordinate {@code axis} (0 x, 1 y, 2 z) of joint j's head in bind space.
     *
     * @param j    a palette joint, {@code [0, jointCount())}
     * @param axis 0, 1 or 2 for x, y or z
     * @return that coordinate of the joint's rest origin, in the points' units
     */
    public float head(int j, int axis) {
        return segments[6 * j + axis];
    }

    /**
     * Coordinate {@code axis} of joint j's tail in bind space.
     *
     * @param j    a palette joint, {@code [0, jointCount())}
     * @param axis 0, 1 or 2 for x, y or z
     * @return that coordinate of the bone's far end, in the points' units; the head's for a point-like leaf
     */
    public float tail(int j, int axis) {
        return segments[6 * j + 3 + axis];
    }

    /**
     * The bone's rest length (0 for a point-like leaf).
     *
     * @param j a palette joint, {@code [0, jointCount())}
     * @return the distance from head to tail in bind space, not negative
     */
    public float length(int j) {
        float dx = tail(j, 0) - head(j, 0);
        float dy = tail(j, 1) - head(j, 1);
        float dz = tail(j, 2) - head(j, 2);
        return (float) Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    @Override
    public String toString() {
        return "Bones[" + parents.length + " joints]";
    }
}
