package org.skinlab.skinning;

import org.joml.Matrix4f;
import org.joml.Quaternionf;
import org.skinlab.animation.AnimationHelper;
import org.skinlab.animation.DualQuaternion;

/**
 * DQS's derivation from a palette's skinning matrices, once per pose: each matrix split into its
 * rigid part D and its scale part S ({@code M = D S}, centred on the joint's bind frame, with
 * Blender's choice of rotation; {@link JointPalette}'s class comment defines both), and D as a
 * dual quaternion. Works in the arrays of one palette, which it is given once; owns the joints'
 * bind-frame pivots and its scratch. Allocation-free (except for a posed frame without a usable Y
 * axis, see {@link #boneAxisFrame}).
 */
final class ScaleSplit {
    private final int joints;
    private final float[] matrices;
    private final float[] rigidParts;
    private final float[] scales;
    private final float[] dualQuaternions;
    /** Per joint the rigid part B of its bind frame, row-major 3x4 (rotation, then translation). */
    private final float[] pivots;

    private final DualQuaternion dq = new DualQuaternion();
    /** Scratch for the rare frame without a usable Y axis (see {@link #boneAxisFrame}). */
    private final Matrix4f fallbackFrame = new Matrix4f();
    private final Quaternionf fallbackRotation = new Quaternionf();
    /**
     * Per-frame scratch: a posed frame's rotation R (row-major 3x3, from {@link #boneAxisFrame})
     * and a quaternion (x y z w, from {@link #quaternionOf}).
     */
    private final float[] rotation = new float[9];
    private final float[] quaternion = new float[4];

    /**
     * @param bindMatrices    per joint 16 floats column-major (INV_BIND), for the pivots
     * @param matrices        the palette's skinning matrices, read
     * @param rigidParts      where D goes, 12 floats per joint
     * @param scales          where S goes, 12 floats per joint
     * @param dualQuaternions where D's dual quaternion goes, 8 floats per joint
     */
    ScaleSplit(float[] bindMatrices, float[] matrices, float[] rigidParts, float[] scales, float[] dualQuaternions) {
        this.joints = bindMatrices.length / 16;
        this.matrices = matrices;
        this.rigidParts = rigidParts;
        this.scales = scales;
        this.dualQuaternions = dualQuaternions;
        this.pivots = new float[12 * joints];
        Matrix4f bind = new Matrix4f();
        Matrix4f base = new Matrix4f();
        Quaternionf r = new Quaternionf();
        Matrix4f pivot = new Matrix4f();
        for (int j = 0; j < joints; j++) {
            bind.set(bindMatrices, 16 * j);
            bind.invert(base);
            if (!base.isFinite()) {
                base.identity(); // a singular bind matrix: the importer warned; centre scale at the origin
            }
            AnimationHelper.rotationOf(base, r);
            pivot.translationRotate(base.m30(), base.m31(), base.m32(), r);
            AnimationHelper.putRowMajor3x4(pivot, pivots, 12 * j);
        }
    }

    /** Per joint the rigid part of its bind frame, row-major 3x4 (read-only). */
    float[] pivots() {
        return pivots;
    }

    /**
     * Splits every joint's matrix and writes the dual quaternions; returns whether some joint has a
     * scale part.
     *
     * <p>Two passes: the first splits every matrix into its rigid part D and scale part S, the
     * second turns the D into dual quaternions. Each pass has a long chain of dependent square
     * roots and divisions per joint; apart, the loops are short enough for the processor to
     * overlap the chains of neighbouring joints (measured in docs/benchmarks.md).
     */
    boolean run() {
        boolean anyScale = false;
        for (int j = 0; j < joints; j++) {
            anyScale |= split(j);
        }
        float[] d = rigidParts;
        float[] q = quaternion;
        for (int j = 0; j < joints; j++) {
            int o = 12 * j;
            quaternionOf(d[o], d[o + 1], d[o + 2], d[o + 4], d[o + 5], d[o + 6], d[o + 8], d[o + 9], d[o + 10], q);
            dq.set(q[0], q[1], q[2], q[3], d[o + 3], d[o + 7], d[o + 11]).get(dualQuaternions, 8 * j);
        }
        return anyScale;
    }

    /**
     * Splits joint {@code j}'s matrix M into {@code rigidParts} (D) and {@code scales} (S);
     * returns whether it has a scale part.
     *
     * <p>A scaled joint's parts follow the definitions in the class comment, rearranged so that no
     * matrix is inverted: with X = M B = [R|x] S0 and B = [Bl|b] rigid (so its inverse is its
     * transpose), {@code D = [R|x] B^-1 = [R Bl^T | x - R Bl^T b]}, and, D being rigid,
     * {@code S = B S0 B^-1 = D^-1 M = [Dl^T Ml | Dl^T (m - d)]} with M = [Ml|m], D = [Dl|d].
     */
    private boolean split(int j) {
        float[] mat = matrices;
        float[] piv = pivots;
        int o = 12 * j;
        float m00 = mat[o], m01 = mat[o + 1], m02 = mat[o + 2];
        float m10 = mat[o + 4], m11 = mat[o + 5], m12 = mat[o + 6];
        float m20 = mat[o + 8], m21 = mat[o + 9], m22 = mat[o + 10];
        float b00 = piv[o], b01 = piv[o + 1], b02 = piv[o + 2];
        float b10 = piv[o + 4], b11 = piv[o + 5], b12 = piv[o + 6];
        float b20 = piv[o + 8], b21 = piv[o + 9], b22 = piv[o + 10];
        // Xl, the linear part of the posed joint frame X = M B (in locals: this runs per joint per frame).
        float x00 = m00 * b00 + (m01 * b10 + m02 * b20);
        float x10 = m10 * b00 + (m11 * b10 + m12 * b20);
        float x20 = m20 * b00 + (m21 * b10 + m22 * b20);
        float x01 = m00 * b01 + (m01 * b11 + m02 * b21);
        float x11 = m10 * b01 + (m11 * b11 + m12 * b21);
        float x21 = m20 * b01 + (m21 * b11 + m22 * b21);
        float x02 = m00 * b02 + (m01 * b12 + m02 * b22);
        float x12 = m10 * b02 + (m11 * b12 + m12 * b22);
        float x22 = m20 * b02 + (m21 * b12 + m22 * b22);
        if (isRigid(x00, x01, x02, x10, x11, x12, x20, x21, x22)) {
            keepRigid(o);
            return false;
        }
        boneAxisFrame(x00, x01, x02, x10, x11, x12, x20, x21, x22, rotation);
        putRigidPart(o, rotation);
        putScalePart(o);
        return true;
    }

    /**
     * Whether a posed frame's linear part (given row by row) has unit columns and no reflection,
     * to float noise: then the joint needs no scale part.
     */
    private static boolean isRigid(float x00, float x01, float x02, float x10, float x11, float x12, float x20,
            float x21, float x22) {
        float l0 = x00 * x00 + x10 * x10 + x20 * x20 - 1f;
        float l1 = x01 * x01 + x11 * x11 + x21 * x21 - 1f;
        float l2 = x02 * x02 + x12 * x12 + x22 * x22 - 1f;
        float det = (x00 * x11 - x10 * x01) * x22 + (x20 * x01 - x00 * x21) * x12 + (x10 * x21 - x20 * x11) * x02;
        // Blender compares |size - 1|^2 with 1e-8; |len^2 - 1| ~ 2 |len - 1| near one.
        return !(l0 * l0 + l1 * l1 + l2 * l2 > 4 * 1e-8f || det < 0f);
    }

    /** A joint whose matrix is rigid to float noise: D = M, S = I. */
    private void keepRigid(int o) {
        float[] d = rigidParts;
        float[] sc = scales;
        d[o] = matrices[o];
        d[o + 1] = matrices[o + 1];
        d[o + 2] = matrices[o + 2];
        d[o + 3] = matrices[o + 3];
        d[o + 4] = matrices[o + 4];
        d[o + 5] = matrices[o + 5];
        d[o + 6] = matrices[o + 6];
        d[o + 7] = matrices[o + 7];
        d[o + 8] = matrices[o + 8];
        d[o + 9] = matrices[o + 9];
        d[o + 10] = matrices[o + 10];
        d[o + 11] = matrices[o + 11];
        sc[o] = 1f;
        sc[o + 1] = 0f;
        sc[o + 2] = 0f;
        sc[o + 3] = 0f;
        sc[o + 4] = 0f;
        sc[o + 5] = 1f;
        sc[o + 6] = 0f;
        sc[o + 7] = 0f;
        sc[o + 8] = 0f;
        sc[o + 9] = 0f;
        sc[o + 10] = 1f;
        sc[o + 11] = 0f;
    }

    /** D = [R Bl^T | x - Dl b] into {@code rigidParts}, with x the translation of X = M B. */
    private void putRigidPart(int o, float[] r) {
        float[] mat = matrices;
        float[] piv = pivots;
        float[] d = rigidParts;
        float m00 = mat[o], m01 = mat[o + 1], m02 = mat[o + 2], mt0 = mat[o + 3];
        float m10 = mat[o + 4], m11 = mat[o + 5], m12 = mat[o + 6], mt1 = mat[o + 7];
        float m20 = mat[o + 8], m21 = mat[o + 9], m22 = mat[o + 10], mt2 = mat[o + 11];
        float b00 = piv[o], b01 = piv[o + 1], b02 = piv[o + 2], bt0 = piv[o + 3];
        float b10 = piv[o + 4], b11 = piv[o + 5], b12 = piv[o + 6], bt1 = piv[o + 7];
        float b20 = piv[o + 8], b21 = piv[o + 9], b22 = piv[o + 10], bt2 = piv[o + 11];
        float xt0 = m00 * bt0 + (m01 * bt1 + (m02 * bt2 + mt0));
        float xt1 = m10 * bt0 + (m11 * bt1 + (m12 * bt2 + mt1));
        float xt2 = m20 * bt0 + (m21 * bt1 + (m22 * bt2 + mt2));
        float d00 = r[0] * b00 + r[1] * b01 + r[2] * b02;
        float d01 = r[0] * b10 + r[1] * b11 + r[2] * b12;
        float d02 = r[0] * b20 + r[1] * b21 + r[2] * b22;
        float d10 = r[3] * b00 + r[4] * b01 + r[5] * b02;
        float d11 = r[3] * b10 + r[4] * b11 + r[5] * b12;
        float d12 = r[3] * b20 + r[4] * b21 + r[5] * b22;
        float d20 = r[6] * b00 + r[7] * b01 + r[8] * b02;
        float d21 = r[6] * b10 + r[7] * b11 + r[8] * b12;
        float d22 = r[6] * b20 + r[7] * b21 + r[8] * b22;
        d[o] = d00;
        d[o + 1] = d01;
        d[o + 2] = d02;
        d[o + 3] = xt0 - (d00 * bt0 + d01 * bt1 + d02 * bt2);
        d[o + 4] = d10;
        d[o + 5] = d11;
        d[o + 6] = d12;
        d[o + 7] = xt1 - (d10 * bt0 + d11 * bt1 + d12 * bt2);
        d[o + 8] = d20;
        d[o + 9] = d21;
        d[o + 10] = d22;
        d[o + 11] = xt2 - (d20 * bt0 + d21 * bt1 + d22 * bt2);
    }

    /** S = [Dl^T Ml | Dl^T (m - d)] into {@code scales}, from the rigid part D already put. */
    private void putScalePart(int o) {
        float[] mat = matrices;
        float[] d = rigidParts;
        float[] sc = scales;
        float m00 = mat[o], m01 = mat[o + 1], m02 = mat[o + 2];
        float m10 = mat[o + 4], m11 = mat[o + 5], m12 = mat[o + 6];
        float m20 = mat[o + 8], m21 = mat[o + 9], m22 = mat[o + 10];
        float d00 = d[o], d01 = d[o + 1], d02 = d[o + 2];
        float d10 = d[o + 4], d11 = d[o + 5], d12 = d[o + 6];
        float d20 = d[o + 8], d21 = d[o + 9], d22 = d[o + 10];
        float e0 = mat[o + 3] - d[o + 3];
        float e1 = mat[o + 7] - d[o + 7];
        float e2 = mat[o + 11] - d[o + 11];
        sc[o] = d00 * m00 + d10 * m10 + d20 * m20;
        sc[o + 1] = d00 * m01 + d10 * m11 + d20 * m21;
        sc[o + 2] = d00 * m02 + d10 * m12 + d20 * m22;
        sc[o + 3] = d00 * e0 + d10 * e1 + d20 * e2;
        sc[o + 4] = d01 * m00 + d11 * m10 + d21 * m20;
        sc[o + 5] = d01 * m01 + d11 * m11 + d21 * m21;
        sc[o + 6] = d01 * m02 + d11 * m12 + d21 * m22;
        sc[o + 7] = d01 * e0 + d11 * e1 + d21 * e2;
        sc[o + 8] = d02 * m00 + d12 * m10 + d22 * m20;
        sc[o + 9] = d02 * m01 + d12 * m11 + d22 * m21;
        sc[o + 10] = d02 * m02 + d12 * m12 + d22 * m22;
        sc[o + 11] = d02 * e0 + d12 * e1 + d22 * e2;
    }

    /**
     * The rotation R of a scaled frame (its linear part, row-major), as a row-major 3x3 into
     * {@code dest}: keep the frame's Y axis, y = Y/|Y|, z = (X x Y)/|X x Y|, x = y x z (Blender's
     * {@code orthogonalize_m4} with axis 1, which normalises Y before the cross product: the same
     * z, and the two square roots do not wait for each other). A frame without a usable Y axis
     * (zero, or parallel to X) falls back to the polar rotation ({@link AnimationHelper#rotationOf},
     * which allocates).
     */
    private void boneAxisFrame(float x00, float x01, float x02, float x10, float x11, float x12, float x20,
            float x21, float x22, float[] dest) {
        float yx = x01;
        float yy = x11;
        float yz = x21;
        float zx = x10 * yz - x20 * yy;
        float zy = x20 * yx - x00 * yz;
        float zz = x00 * yy - x10 * yx;
        float yl = (float) Math.sqrt(yx * yx + yy * yy + yz * yz);
        float zl = (float) Math.sqrt(zx * zx + zy * zy + zz * zz);
        // |X x Y| = |X x y| |Y|: the bound on X x y, scaled.
        if (yl > 1e-12f && zl > 1e-12f * yl) {
            yx /= yl;
            yy /= yl;
            yz /= yl;
            zx /= zl;
            zy /= zl;
            zz /= zl;
            // Columns x, y, z.
            dest[0] = yy * zz - yz * zy;
            dest[3] = yz * zx - yx * zz;
            dest[6] = yx * zy - yy * zx;
            dest[1] = yx;
            dest[4] = yy;
            dest[7] = yz;
            dest[2] = zx;
            dest[5] = zy;
            dest[8] = zz;
            return;
        }
        Matrix4f frame = fallbackFrame.set(x00, x10, x20, 0f, x01, x11, x21, 0f, x02, x12, x22, 0f, 0f, 0f, 0f, 1f);
        Quaternionf polar = AnimationHelper.rotationOf(frame, fallbackRotation);
        AnimationHelper.rotationMatrix(polar, frame);
        dest[0] = frame.m00();
        dest[1] = frame.m10();
        dest[2] = frame.m20();
        dest[3] = frame.m01();
        dest[4] = frame.m11();
        dest[5] = frame.m21();
        dest[6] = frame.m02();
        dest[7] = frame.m12();
        dest[8] = frame.m22();
    }

    /**
     * The unit quaternion (x y z w) of a rotation matrix given row by row, into {@code dest}:
     * Shepperd's method (the largest of w, x, y, z is found from the diagonal and divides the
     * rest, so no component loses precision), then normalised against float noise in the matrix.
     */
    static void quaternionOf(float r00, float r01, float r02, float r10, float r11, float r12, float r20, float r21,
            float r22, float[] dest) {
        float x;
        float y;
        float z;
        float w;
        float trace = r00 + r11 + r22;
        if (trace >= 0f) {
            float s = (float) Math.sqrt(trace + 1f);
            w = s * 0.5f;
            s = 0.5f / s;
            x = (r21 - r12) * s;
            y = (r02 - r20) * s;
            z = (r10 - r01) * s;
        } else if (r00 >= r11 && r00 >= r22) {
            float s = (float) Math.sqrt(r00 - (r11 + r22) + 1f);
            x = s * 0.5f;
            s = 0.5f / s;
            y = (r01 + r10) * s;
            z = (r02 + r20) * s;
            w = (r21 - r12) * s;
        } else if (r11 > r22) {
            float s = (float) Math.sqrt(r11 - (r22 + r00) + 1f);
            y = s * 0.5f;
            s = 0.5f / s;
            x = (r01 + r10) * s;
            z = (r12 + r21) * s;
            w = (r02 - r20) * s;
        } else {
            float s = (float) Math.sqrt(r22 - (r00 + r11) + 1f);
            z = s * 0.5f;
            s = 0.5f / s;
            x = (r02 + r20) * s;
            y = (r12 + r21) * s;
            w = (r10 - r01) * s;
        }
        float inverseLength = 1f / (float) Math.sqrt(x * x + (y * y + (z * z + w * w)));
        dest[0] = x * inverseLength;
        dest[1] = y * inverseLength;
        dest[2] = z * inverseLength;
        dest[3] = w * inverseLength;
    }
}
