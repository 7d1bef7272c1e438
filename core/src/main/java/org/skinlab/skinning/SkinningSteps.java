package org.skinlab.skinning;

/**
 * The formulas the scalar kernels are built from, each written once: the matrix blend of LBS,
 * the dual-quaternion blend of DQS, the scale phase of {@link JointPalette}'s two-phase split,
 * the signed cofactor of a normal matrix, and the rotations of a unit quaternion. The SIMD kernels
 * keep theirs written out in lanes and are tested against kernels made of these.
 *
 * <p>Allocation-free in JOML's style: arrays and offsets in, the result into the caller's
 * {@code dest} at an offset (a per-thread scratch array of the kernel). Matrices are row-major,
 * 3x4 (12 floats, the last column the translation) or 3x3 (9 floats). Plain Java; each step is a
 * small static method, so the JIT inlines it into the kernel's loop.
 */
final class SkinningSteps {
    /** Floats {@link #scalePhase} writes: the blended scale part S (3x4), then its normal matrix K (3x3). */
    static final int SCALE_PHASE_FLOATS = 21;

    private SkinningSteps() {
    }

    /**
     * The LBS blend {@code B = sum_k w_k M_(j_k)} over the {@code width} influences at {@code o}
     * (Kavan et al. 2008, eq. 1), 12 floats into {@code dest[d..d+12)}; {@code matrices} holds 12
     * floats per joint. The sum starts from the first influence's term.
     */
    static void blendMatrices(float[] matrices, int[] joints, float[] weights, int o, int width, float[] dest, int d) {
        float w = weights[o];
        int m = 12 * joints[o];
        float b0 = w * matrices[m], b1 = w * matrices[m + 1], b2 = w * matrices[m + 2], b3 = w * matrices[m + 3];
        float b4 = w * matrices[m + 4], b5 = w * matrices[m + 5], b6 = w * matrices[m + 6], b7 = w * matrices[m + 7];
        float b8 = w * matrices[m + 8], b9 = w * matrices[m + 9], b10 = w * matrices[m + 10];
        float b11 = w * matrices[m + 11];
        for (int k = 1; k < width; k++) {
            w = weights[o + k];
            m = 12 * joints[o + k];
            b0 += w * matrices[m];
            b1 += w * matrices[m + 1];
            b2 += w * matrices[m + 2];
            b3 += w * matrices[m + 3];
            b4 += w * matrices[m + 4];
            b5 += w * matrices[m + 5];
            b6 += w * matrices[m + 6];
            b7 += w * matrices[m + 7];
            b8 += w * matrices[m + 8];
            b9 += w * matrices[m + 9];
            b10 += w * matrices[m + 10];
            b11 += w * matrices[m + 11];
        }
        dest[d] = b0;
        dest[d + 1] = b1;
        dest[d + 2] = b2;
        dest[d + 3] = b3;
        dest[d + 4] = b4;
        dest[d + 5] = b5;
        dest[d + 6] = b6;
        dest[d + 7] = b7;
        dest[d + 8] = b8;
        dest[d + 9] = b9;
        dest[d + 10] = b10;
        dest[d + 11] = b11;
    }

    /**
     * The DQS blend {@code b = sum_k copySign(w_k, q_0 . q_k + 0) q_k} over the influences at
     * {@code o}, normalised by the length of its real part (Kavan et al. 2008, section 4), 8 floats
     * (real x y z w, dual x y z w) into {@code dest[d..d+8)}; {@code dq} holds 8 floats per joint.
     * The sign flips an antipodal quaternion (the same rotation) onto the hemisphere of the first
     * influence q_0, so the blend takes the short way. It comes from {@code Math.copySign}, not a
     * branch (with joints in random order a branch mispredicts about half the time), of
     * {@code dot + 0}, so a dot of -0 counts as +0, as a lane compare {@code dot < 0} does. Every
     * flipped term has a non-negative dot with q_0, so |b.real| >= w_0 > 0: the normalisation
     * never divides by zero.
     */
    static void blendDualQuaternions(float[] dq, int[] joints, float[] weights, int o, int width, float[] dest, int d) {
        int q = 8 * joints[o];
        float w = weights[o];
        float p0 = dq[q], p1 = dq[q + 1], p2 = dq[q + 2], p3 = dq[q + 3];
        float r0 = w * p0, r1 = w * p1, r2 = w * p2, r3 = w * p3;
        float d0 = w * dq[q + 4], d1 = w * dq[q + 5], d2 = w * dq[q + 6], d3 = w * dq[q + 7];
        for (int k = 1; k < width; k++) {
            q = 8 * joints[o + k];
            w = Math.copySign(weights[o + k], p0 * dq[q] + p1 * dq[q + 1] + p2 * dq[q + 2] + p3 * dq[q + 3] + 0f);
            r0 += w * dq[q];
            r1 += w * dq[q + 1];
            r2 += w * dq[q + 2];
            r3 += w * dq[q + 3];
            d0 += w * dq[q + 4];
            d1 += w * dq[q + 5];
            d2 += w * dq[q + 6];
            d3 += w * dq[q + 7];
        }
        float inv = (float) (1.0 / Math.sqrt(r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3));
        dest[d] = r0 * inv;
        dest[d + 1] = r1 * inv;
        dest[d + 2] = r2 * inv;
        dest[d + 3] = r3 * inv;
        dest[d + 4] = d0 * inv;
        dest[d + 5] = d1 * inv;
        dest[d + 6] = d2 * inv;
        dest[d + 7] = d3 * inv;
    }

    /**
     * The scale phase of the two-phase split ({@link JointPalette}): the blend of the joints' scale
     * parts {@code S = sum_k w_k S_(j_k)} into {@code dest[d..d+12)}, and the normal matrix of S
     * into {@code dest[d+12..d+21)}: with {@code exactNormals} its {@linkplain #signedCofactor
     * signed cofactor} (signed when the palette's scales mirror, so normals stay outward), else
     * S's linear part.
     */
    static void scalePhase(float[] scales, int[] joints, float[] weights, int o, int width, boolean exactNormals,
            boolean mirrors, float[] dest, int d) {
        blendMatrices(scales, joints, weights, o, width, dest, d);
        if (exactNormals) {
            signedCofactor(dest, d, mirrors, dest, d + 12);
        } else {
            linearPart(dest, d, dest, d + 12);
        }
    }

    /**
     * The normal matrix of the 3x4 matrix at {@code a[ao]} under the exact rule: its cofactor matrix
     * (det times the inverse-transpose), times the sign of its determinant when {@code signed} (a
     * mirroring matrix would otherwise turn normals inwards), 9 floats into {@code dest[d..d+9)}.
     */
    static void signedCofactor(float[] a, int ao, boolean signed, float[] dest, int d) {
        float a00 = a[ao], a01 = a[ao + 1], a02 = a[ao + 2];
        float a10 = a[ao + 4], a11 = a[ao + 5], a12 = a[ao + 6];
        float a20 = a[ao + 8], a21 = a[ao + 9], a22 = a[ao + 10];
        float c00 = a11 * a22 - a21 * a12, c01 = a12 * a20 - a22 * a10, c02 = a10 * a21 - a20 * a11;
        float s = signed ? Math.copySign(1f, a00 * c00 + a01 * c01 + a02 * c02) : 1f;
        dest[d] = s * c00;
        dest[d + 1] = s * c01;
        dest[d + 2] = s * c02;
        dest[d + 3] = s * (a21 * a02 - a01 * a22);
        dest[d + 4] = s * (a22 * a00 - a02 * a20);
        dest[d + 5] = s * (a20 * a01 - a00 * a21);
        dest[d + 6] = s * (a01 * a12 - a11 * a02);
        dest[d + 7] = s * (a02 * a10 - a12 * a00);
        dest[d + 8] = s * (a00 * a11 - a10 * a01);
    }

    /** The linear part of the 3x4 matrix at {@code a[ao]}, 9 floats into {@code dest[d..d+9)}. */
    static void linearPart(float[] a, int ao, float[] dest, int d) {
        for (int row = 0; row < 3; row++) {
            dest[d + 3 * row] = a[ao + 4 * row];
            dest[d + 3 * row + 1] = a[ao + 4 * row + 1];
            dest[d + 3 * row + 2] = a[ao + 4 * row + 2];
        }
    }

    /**
     * The rotation of the unit quaternion (x, y, z, w) as a 3x3 matrix into {@code dest[d..d+9)}:
     * {@code 1 - 2(y^2 + z^2), 2(xy - zw), 2(xz + yw)} and its cyclic permutations.
     */
    static void rotationMatrix(float x, float y, float z, float w, float[] dest, int d) {
        dest[d] = 1 - 2 * (y * y + z * z);
        dest[d + 1] = 2 * (x * y - z * w);
        dest[d + 2] = 2 * (x * z + y * w);
        dest[d + 3] = 2 * (x * y + z * w);
        dest[d + 4] = 1 - 2 * (x * x + z * z);
        dest[d + 5] = 2 * (y * z - x * w);
        dest[d + 6] = 2 * (x * z - y * w);
        dest[d + 7] = 2 * (y * z + x * w);
        dest[d + 8] = 1 - 2 * (x * x + y * y);
    }

    /** {@code A B} of the 3x3 matrices at {@code a[ao]} and {@code b[bo]}, into {@code dest[d..d+9)}. */
    static void multiply3x3(float[] a, int ao, float[] b, int bo, float[] dest, int d) {
        for (int row = 0; row < 3; row++) {
            float a0 = a[ao + 3 * row], a1 = a[ao + 3 * row + 1], a2 = a[ao + 3 * row + 2];
            dest[d + 3 * row] = a0 * b[bo] + a1 * b[bo + 3] + a2 * b[bo + 6];
            dest[d + 3 * row + 1] = a0 * b[bo + 1] + a1 * b[bo + 4] + a2 * b[bo + 7];
            dest[d + 3 * row + 2] = a0 * b[bo + 2] + a1 * b[bo + 5] + a2 * b[bo + 8];
        }
    }

    /**
     * The point (x, y, z) moved by the unit dual quaternion at {@code q[qo]} (real r, dual d), into
     * {@code dest[d..d+3)}: {@code v' = v + 2 r x (r x v + r_w v) + t}, with the translation
     * {@code t = 2 (r_w d - d_w r + r x d)} (Kavan et al. 2008, section 3).
     */
    static void transformPoint(float[] q, int qo, float x, float y, float z, float[] dest, int d) {
        float rx = q[qo], ry = q[qo + 1], rz = q[qo + 2], rw = q[qo + 3];
        float dx = q[qo + 4], dy = q[qo + 5], dz = q[qo + 6], dw = q[qo + 7];
        float tx = 2 * (rw * dx - dw * rx + (ry * dz - rz * dy));
        float ty = 2 * (rw * dy - dw * ry + (rz * dx - rx * dz));
        float tz = 2 * (rw * dz - dw * rz + (rx * dy - ry * dx));
        float cx = ry * z - rz * y + rw * x;
        float cy = rz * x - rx * z + rw * y;
        float cz = rx * y - ry * x + rw * z;
        dest[d] = x + 2 * (ry * cz - rz * cy) + tx;
        dest[d + 1] = y + 2 * (rz * cx - rx * cz) + ty;
        dest[d + 2] = z + 2 * (rx * cy - ry * cx) + tz;
    }

    /**
     * The vector (x, y, z) turned by the unit quaternion at {@code q[qo]}, into
     * {@code dest[d..d+3)}: {@code v' = v + 2 r x (r x v + r_w v)}.
     */
    static void rotate(float[] q, int qo, float x, float y, float z, float[] dest, int d) {
        float rx = q[qo], ry = q[qo + 1], rz = q[qo + 2], rw = q[qo + 3];
        float cx = ry * z - rz * y + rw * x;
        float cy = rz * x - rx * z + rw * y;
        float cz = rx * y - ry * x + rw * z;
        dest[d] = x + 2 * (ry * cz - rz * cy);
        dest[d + 1] = y + 2 * (rz * cx - rx * cz);
        dest[d + 2] = z + 2 * (rx * cy - ry * cx);
    }
}
