package org.skinlab.skinning;

/**
 * The formulas the scalar kernels are built from, each written once: the matrix blend of LBS,
 * the dual-quaternion blend of DQS, the scale phase of {@link JointPalette}'s two-phase split,
 * the signed cofactor of a normal matrix, and the rotations of a unit quaternion. The SIMD kernels
 * keep theirs written out in lanes and are tested against kernels made of these.
 *
 * <p>Allocation-free in JOML's style: arrays and offsets in, the result into the caller's
 * {@code dest} at an offset (a per-thread scratch array of the kernel). Matrices are row-major,
 * 3x4 (12 floats, the last column the translation) or 3x3 (9 floats). Plain Java, static and
 * stateless. A kernel reads a step's result from its scratch before it writes to another float
 * array, so that the JIT can take the values from registers instead of memory.
 */
final class SkinningSteps {
    /** Floats {@link #scalePhase} writes: the blended scale part S (3x4), then its normal matrix K (3x3). */
    static final int SCALE_PHASE_FLOATS = 21;

    private SkinningSteps() {
    }

    /**
     * The LBS blend {@code B = sum_k w_k M_(j_k)} over the {@code width} influences at {@code o}
     * (Kavan et al. 2008, eq. 1), 12 floats into {@code dest[d..d+12)}; {@code matrices} holds 12
     * floats per joint. The sums start from -0, the identity of IEEE addition, so the first term
     * is kept exactly (also when it is -0).
     */
    static void blendMatrices(float[] matrices, int[] joints, float[] weights, int o, int width, float[] dest, int d) {
        float b0 = -0f, b1 = -0f, b2 = -0f, b3 = -0f, b4 = -0f, b5 = -0f;
        float b6 = -0f, b7 = -0f, b8 = -0f, b9 = -0f, b10 = -0f, b11 = -0f;
        for (int k = 0; k < width; k++) {
            float w = weights[o + k];
            int m = 12 * joints[o + k];
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
        put4(dest, d, 1f, b0, b1, b2, b3);
        put4(dest, d + 4, 1f, b4, b5, b6, b7);
        put4(dest, d + 8, 1f, b8, b9, b10, b11);
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
            w = hemisphereWeight(weights[o + k], p0, p1, p2, p3, dq, q);
            r0 += w * dq[q];
            r1 += w * dq[q + 1];
            r2 += w * dq[q + 2];
            r3 += w * dq[q + 3];
            d0 += w * dq[q + 4];
            d1 += w * dq[q + 5];
            d2 += w * dq[q + 6];
            d3 += w * dq[q + 7];
        }
        putNormalised(r0, r1, r2, r3, d0, d1, d2, d3, dest, d);
    }

    /**
     * {@code copySign(w, p . q + 0)} for the rotation quaternion p of the first influence and the
     * one at {@code dq[q]}: the weight of {@link #blendDualQuaternions}'s term, in a method of its
     * own so that the blend stays within the bytecode size C2 inlines into a hot loop (325 bytes,
     * {@code -XX:FreqInlineSize}).
     */
    private static float hemisphereWeight(float w, float p0, float p1, float p2, float p3, float[] dq, int q) {
        return Math.copySign(w, p0 * dq[q] + p1 * dq[q + 1] + p2 * dq[q + 2] + p3 * dq[q + 3] + 0f);
    }

    /**
     * The dual quaternion (real r, dual e) divided by |r| into {@code dest[d..d+8)}, {@code 1 / |r|}
     * with the square root and the division in double; a method of its own for the reason
     * {@link #hemisphereWeight} is.
     */
    private static void putNormalised(float r0, float r1, float r2, float r3, float e0, float e1, float e2, float e3,
            float[] dest, int d) {
        float inv = (float) (1.0 / Math.sqrt(r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3));
        put4(dest, d, inv, r0, r1, r2, r3);
        put4(dest, d + 4, inv, e0, e1, e2, e3);
    }

    /**
     * {@code s (a, b, c, e)} into {@code dest[d..d+4)}: the blends' stores, in a method of its own so
     * that {@link #blendMatrices} stays within the bytecode size C2 inlines into a hot loop (325
     * bytes, {@code -XX:FreqInlineSize}); times 1 is exact.
     */
    private static void put4(float[] dest, int d, float s, float a, float b, float c, float e) {
        dest[d] = s * a;
        dest[d + 1] = s * b;
        dest[d + 2] = s * c;
        dest[d + 3] = s * e;
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
     * {@code A x} for the 3x4 matrix A at {@code a[ao]} and the point x at {@code x[xo]}, into
     * {@code dest[d..d+3)}.
     */
    static void transformAffine(float[] a, int ao, float[] x, int xo, float[] dest, int d) {
        float px = x[xo], py = x[xo + 1], pz = x[xo + 2];
        dest[d] = a[ao] * px + a[ao + 1] * py + a[ao + 2] * pz + a[ao + 3];
        dest[d + 1] = a[ao + 4] * px + a[ao + 5] * py + a[ao + 6] * pz + a[ao + 7];
        dest[d + 2] = a[ao + 8] * px + a[ao + 9] * py + a[ao + 10] * pz + a[ao + 11];
    }

    /**
     * The point (x, y, z) moved by the unit dual quaternion (real r, dual d) into
     * {@code dest[o..o+3)}: {@code v' = v + 2 r x (r x v + r_w v) + t}, with the translation
     * {@code t = 2 (r_w d - d_w r + r x d)} (Kavan et al. 2008, section 3). The quaternion comes as
     * values, so a kernel reads it from its scratch once for the point and the normal.
     */
    static void transformPoint(float rx, float ry, float rz, float rw, float dx, float dy, float dz, float dw, float x,
            float y, float z, float[] dest, int o) {
        float tx = 2 * (rw * dx - dw * rx + (ry * dz - rz * dy));
        float ty = 2 * (rw * dy - dw * ry + (rz * dx - rx * dz));
        float tz = 2 * (rw * dz - dw * rz + (rx * dy - ry * dx));
        float cx = ry * z - rz * y + rw * x;
        float cy = rz * x - rx * z + rw * y;
        float cz = rx * y - ry * x + rw * z;
        dest[o] = x + 2 * (ry * cz - rz * cy) + tx;
        dest[o + 1] = y + 2 * (rz * cx - rx * cz) + ty;
        dest[o + 2] = z + 2 * (rx * cy - ry * cx) + tz;
    }

    /**
     * The vector (x, y, z) turned by the unit quaternion r into {@code dest[o..o+3)}:
     * {@code v' = v + 2 r x (r x v + r_w v)}.
     */
    static void rotate(float rx, float ry, float rz, float rw, float x, float y, float z, float[] dest, int o) {
        float cx = ry * z - rz * y + rw * x;
        float cy = rz * x - rx * z + rw * y;
        float cz = rx * y - ry * x + rw * z;
        dest[o] = x + 2 * (ry * cz - rz * cy);
        dest[o + 1] = y + 2 * (rz * cx - rx * cz);
        dest[o + 2] = z + 2 * (rx * cy - ry * cx);
    }
}
