package org.skinlab.skinning;

import org.joml.Matrix3f;
import org.joml.Matrix4f;
import org.joml.Quaternionf;
import org.skinlab.animation.AnimationHelper;
import org.skinlab.animation.DualQuaternion;

/**
 * One frame's joint data for a skinner: the skinning matrices, and what DQS derives from them once
 * per joint per frame (not per vertex, as the thesis did).
 *
 * <p>{@link #matrices()}: per joint a 3x4 affine matrix, row-major (r00 r01 r02 tx, r10 ...), the
 * layout of the shared benchmark reference. Filled by
 * {@link org.skinlab.animation.Skeleton#skinningMatrices}.
 *
 * <p><b>DQS with scale: the two-phase split.</b> A dual quaternion holds only rotation and
 * translation. Following Kavan et al. 2008 (section 4, "scale and shear") each skinning matrix is
 * split into {@code M = D * S}, D rigid and S a scale/shear; per vertex the S are blended
 * linearly (unscaled joints contribute the identity), the D as dual quaternions, and the vertex
 * goes through the blended S first. Where S is centred matters once blended; we centre it on the
 * joint's bind frame, as Blender's armature modifier does with "preserve volume" (its
 * {@code mat4_to_dquat} uses the bone's rest matrix), so that scaling a bone along its own axis
 * scales the skin about that bone. Concretely, with {@code B} the rigid part of the joint's bind
 * frame {@code inverse(INV_BIND * BIND_SHAPE)}: {@code X = M B} is the joint's posed frame;
 * {@code X = [R|t] S0}; then {@code S = B S0 B^-1} and {@code D = [R|t] B^-1}. Joints whose posed
 * frame has unit columns (within 1e-4, Blender's threshold) and no reflection skip the split: S
 * is the identity and D = M.
 *
 * <p>Which rotation R a scaled frame has is a convention once the frame is sheared (a child of a
 * non-uniformly scaled joint is). We take Blender 3.4's: keep the frame's Y axis (the bone axis
 * in Blender's rigs and in files exported from them) and orthogonalise the others to it
 * ({@code orthogonalize_m4(m, 1)}), so our DQS agrees with Blender's to float precision on our
 * own assets; the polar rotation would differ by 0.7% of the tentacle's size (see
 * docs/references.md). Frames without a usable Y axis fall back to the polar rotation.
 */
public final class JointPalette {
    private final int joints;
    private final float[] matrices;
    private final float[] dualQuaternions;
    private final float[] scales;
    private final float[] pivots;
    private final float[] pivotInverses;
    private boolean scaled;

    private final Matrix4f m = new Matrix4f();
    private final Matrix4f x = new Matrix4f();
    private final Matrix4f t = new Matrix4f();
    private final Quaternionf q = new Quaternionf();
    private final Matrix3f r3 = new Matrix3f();
    private final DualQuaternion dq = new DualQuaternion();

    /**
     * @param bindMatrices per joint 16 floats column-major, the matrix that takes bind-shape
     *                     coordinates into the joint's frame (INV_BIND * BIND_SHAPE)
     */
    public JointPalette(float[] bindMatrices) {
        if (bindMatrices.length % 16 != 0) {
            throw new IllegalArgumentException("bind matrices need 16 floats each");
        }
        joints = bindMatrices.length / 16;
        matrices = new float[12 * joints];
        dualQuaternions = new float[8 * joints];
        scales = new float[12 * joints];
        pivots = new float[16 * joints];
        pivotInverses = new float[16 * joints];
        Matrix4f bind = new Matrix4f();
        Matrix4f base = new Matrix4f();
        Quaternionf r = new Quaternionf();
        for (int j = 0; j < joints; j++) {
            bind.set(bindMatrices, 16 * j);
            bind.invert(base);
            if (!base.isFinite()) {
                base.identity(); // a singular bind matrix: the importer warned; centre scale at the origin
            }
            AnimationHelper.rotationOf(base, r);
            Matrix4f pivot = new Matrix4f().translationRotate(base.m30(), base.m31(), base.m32(), r);
            pivot.get(pivots, 16 * j);
            pivot.invertAffine().get(pivotInverses, 16 * j);
            setIdentity3x4(matrices, 12 * j);
        }
    }

    /** A palette of {@code joints} joints whose bind frames are at the origin (e.g. benchmarks). */
    public static JointPalette withoutBindFrames(int joints) {
        float[] identities = new float[16 * joints];
        for (int j = 0; j < joints; j++) {
            identities[16 * j] = identities[16 * j + 5] = identities[16 * j + 10] = identities[16 * j + 15] = 1f;
        }
        return new JointPalette(identities);
    }

    public int jointCount() {
        return joints;
    }

    /** Per joint 12 floats, row-major 3x4 skinning matrix. Written by the skeleton, read by skinners. */
    public float[] matrices() {
        return matrices;
    }

    /** Per joint 8 floats (real x y z w, dual x y z w): the rigid part D, after {@link #prepareDualQuaternions()}. */
    public float[] dualQuaternions() {
        return dualQuaternions;
    }

    /** Per joint 12 floats, row-major 3x4: the scale/shear part S, after {@link #prepareDualQuaternions()}. */
    public float[] scales() {
        return scales;
    }

    /** True when some joint has a scale part this frame (DQS must run its first phase). */
    public boolean hasScale() {
        return scaled;
    }

    /** Sets joint {@code j}'s skinning matrix from a JOML matrix (its affine part). */
    public void setMatrix(int j, Matrix4f matrix) {
        AnimationHelper.putRowMajor3x4(matrix, matrices, 12 * j);
    }

    /** Joint {@code j}'s skinning matrix as a JOML matrix. */
    public Matrix4f getMatrix(int j, Matrix4f dest) {
        return AnimationHelper.getRowMajor3x4(matrices, 12 * j, dest);
    }

    /**
     * Derives each joint's dual quaternion (and scale part) from {@link #matrices()}: once per
     * frame, before DQS skinning. See the class comment for the split.
     */
    public void prepareDualQuaternions() {
        boolean anyScale = false;
        for (int j = 0; j < joints; j++) {
            getMatrix(j, m);
            x.set(pivots, 16 * j);
            m.mul(x, x); // X = M B: the posed joint frame
            float l0 = x.m00() * x.m00() + x.m01() * x.m01() + x.m02() * x.m02() - 1f;
            float l1 = x.m10() * x.m10() + x.m11() * x.m11() + x.m12() * x.m12() - 1f;
            float l2 = x.m20() * x.m20() + x.m21() * x.m21() + x.m22() * x.m22() - 1f;
            // Blender compares |size - 1|^2 with 1e-8; |len^2 - 1| ~ 2 |len - 1| near one.
            boolean hasScale = l0 * l0 + l1 * l1 + l2 * l2 > 4 * 1e-8f || x.determinant3x3() < 0f;
            if (!hasScale) {
                // M is rigid to float noise: Shepperd's conversion, then renormalised.
                q.setFromNormalized(m).normalize();
                writeDualQuaternion(j, q, m.m30(), m.m31(), m.m32());
                setIdentity3x4(scales, 12 * j);
                continue;
            }
            anyScale = true;
            boneAxisRotation(x, q);
            // [R|t]^-1 X = S0 (pure linear), then S = B S0 B^-1.
            t.translationRotate(x.m30(), x.m31(), x.m32(), q).invertAffine().mul(x, t);
            t.m30(0f).m31(0f).m32(0f);
            x.set(pivots, 16 * j).mul(t, t);
            x.set(pivotInverses, 16 * j);
            t.mul(x);
            AnimationHelper.putRowMajor3x4(t, scales, 12 * j);
            // D = [R|t] B^-1 = M S^-1
            t.invertAffine();
            m.mul(t, t);
            // D is rigid to float noise (a rotation times the rigid pivot's inverse).
            q.setFromNormalized(t).normalize();
            writeDualQuaternion(j, q, t.m30(), t.m31(), t.m32());
        }
        scaled = anyScale;
    }

    /**
     * The rotation of a scaled frame that keeps its Y axis: y = Y/|Y|, z = X x y normalised,
     * x = y x z (Blender's {@code orthogonalize_m4} with axis 1).
     */
    private Quaternionf boneAxisRotation(Matrix4f frame, Quaternionf dest) {
        float yx = frame.m10();
        float yy = frame.m11();
        float yz = frame.m12();
        float yl = (float) Math.sqrt(yx * yx + yy * yy + yz * yz);
        float xx = frame.m00();
        float xy = frame.m01();
        float xz = frame.m02();
        if (yl > 1e-12f) {
            yx /= yl;
            yy /= yl;
            yz /= yl;
            float zx = xy * yz - xz * yy;
            float zy = xz * yx - xx * yz;
            float zz = xx * yy - xy * yx;
            float zl = (float) Math.sqrt(zx * zx + zy * zy + zz * zz);
            if (zl > 1e-12f) {
                zx /= zl;
                zy /= zl;
                zz /= zl;
                float ax = yy * zz - yz * zy;
                float ay = yz * zx - yx * zz;
                float az = yx * zy - yy * zx;
                return dest.setFromNormalized(r3.set(ax, ay, az, yx, yy, yz, zx, zy, zz)).normalize();
            }
        }
        return AnimationHelper.rotationOf(frame, dest);
    }

    private void writeDualQuaternion(int j, Quaternionf r, float tx, float ty, float tz) {
        dq.set(r.x, r.y, r.z, r.w, tx, ty, tz).get(dualQuaternions, 8 * j);
    }

    private static void setIdentity3x4(float[] a, int o) {
        java.util.Arrays.fill(a, o, o + 12, 0f);
        a[o] = 1f;
        a[o + 5] = 1f;
        a[o + 10] = 1f;
    }
}
