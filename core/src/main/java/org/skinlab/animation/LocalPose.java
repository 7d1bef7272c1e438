package org.skinlab.animation;

import org.joml.Matrix4f;
import org.joml.Quaternionf;

/**
 * Every node's local transform as translation, rotation and scale: the space where poses are
 * blended ({@code org.skinlab.mixer}), whatever transform stack the file wrote (COLLADA matrices,
 * {@code <rotate>}/{@code <translate>} elements, glTF TRS). {@link AnimationSampler#sampleLocal}
 * writes it, {@link Skeleton#evaluate(LocalPose, Pose)} turns it into world matrices
 * ({@code local = T * R * S}).
 *
 * <p>Layout: {@value #STRIDE} floats per node at {@code STRIDE * node}: translation x y z,
 * rotation quaternion x y z w (unit), scale x y z. A node's shear (a {@code <skew>}, a sheared
 * {@code <matrix>}) has no place in T*R*S and is dropped, as in every TRS-based runtime.
 */
public final class LocalPose {
    /** Floats per node. */
    public static final int STRIDE = 10;

    private final Skeleton skeleton;
    private final float[] trs;

    LocalPose(Skeleton skeleton, float[] rest) {
        this.skeleton = skeleton;
        this.trs = rest.clone();
    }

    /**
     * The skeleton this pose belongs to.
     *
     * @return the skeleton that made it
     */
    public Skeleton skeleton() {
        return skeleton;
    }

    /**
     * The transforms, {@value #STRIDE} floats per node as the class comment says.
     *
     * @return the live array (not a copy), {@code STRIDE * skeleton().nodeCount()} floats
     */
    public float[] array() {
        return trs;
    }

    /**
     * Copies {@code other}'s transforms into this pose.
     *
     * @param other a local pose of the same skeleton
     * @return this pose
     * @throws IllegalArgumentException when {@code other} belongs to another skeleton
     */
    public LocalPose set(LocalPose other) {
        if (other.skeleton != skeleton) {
            throw new IllegalArgumentException("a local pose of another skeleton");
        }
        System.arraycopy(other.trs, 0, trs, 0, trs.length);
        return this;
    }

    /**
     * Sets every node back to its rest transform (the file's, split into T, R and S).
     *
     * @return this pose
     */
    public LocalPose setRest() {
        System.arraycopy(skeleton.restLocal(), 0, trs, 0, trs.length);
        return this;
    }

    /**
     * Node {@code node}'s rotation.
     *
     * @param node the node index
     * @param dest receives the rotation
     * @return {@code dest}
     */
    public Quaternionf rotation(int node, Quaternionf dest) {
        int o = STRIDE * node + 3;
        return dest.set(trs[o], trs[o + 1], trs[o + 2], trs[o + 3]);
    }

    /**
     * Splits an affine matrix into T, R and S at {@code dest[offset]} in this class's layout,
     * without allocating: the rotation of the normalised columns (a reflection shows as a negative
     * x scale), the scale along the rotation's axes; shear is dropped.
     */
    static void split(Matrix4f m, Quaternionf scratch, float[] dest, int offset) {
        dest[offset] = m.m30();
        dest[offset + 1] = m.m31();
        dest[offset + 2] = m.m32();
        float flip = m.determinant3x3() < 0 ? -1f : 1f;
        if (flip < 0) {
            m.scale(-1f, 1f, 1f);
        }
        m.getUnnormalizedRotation(scratch).normalize();
        dest[offset + 3] = scratch.x;
        dest[offset + 4] = scratch.y;
        dest[offset + 5] = scratch.z;
        dest[offset + 6] = scratch.w;
        float x = scratch.x;
        float y = scratch.y;
        float z = scratch.z;
        float w = scratch.w;
        // Columns of R dotted with the columns of M: the scale along R's axes.
        float sx = (1 - 2 * (y * y + z * z)) * m.m00() + 2 * (x * y + w * z) * m.m01() + 2 * (x * z - w * y) * m.m02();
        float sy = 2 * (x * y - w * z) * m.m10() + (1 - 2 * (x * x + z * z)) * m.m11() + 2 * (y * z + w * x) * m.m12();
        float sz = 2 * (x * z + w * y) * m.m20() + 2 * (y * z - w * x) * m.m21() + (1 - 2 * (x * x + y * y)) * m.m22();
        dest[offset + 7] = flip * sx;
        dest[offset + 8] = sy;
        dest[offset + 9] = sz;
    }
}
