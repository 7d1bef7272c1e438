package org.skinlab.skinning;

/**
 * Skinning with optimized centres of rotation (Le and Hodgins 2016, section 5) in plain Java, any
 * number of influences. Per point p with centre c ({@link SkinnedGeometry#centresOfRotation()}):
 * <ol>
 * <li>if any joint is scaled this frame, the scale phase of DQS first ({@link ScalarDqsSkinner}):
 *     {@code S = sum_k w_k S_(j_k)}, {@code p1 = S p}, {@code c1 = S c}, the normal by S's
 *     cofactor matrix (times the sign of det S) or by S itself; otherwise p1 = p, c1 = c;</li>
 * <li>the rotations' blend {@code q = sum_k s_k w_k r_(j_k)}, flipped onto the dominant
 *     influence's side as in DQS, normalised: R;</li>
 * <li>the centre moved by LBS of the joints' rigid parts D (from the palette's dual quaternions;
 *     D = M for unscaled joints): {@code t = sum_k w_k D_(j_k) c1};</li>
 * <li>{@code p' = R (p1 - c1) + t}, the normal turned by R.</li>
 * </ol>
 * Without scale this is the paper's formula, {@code p' = R (p - c) + LBS(c)}: rigid parts move
 * rigidly (every influence the same D gives p' = D p), the rotation is blended as in DQS (no
 * candy wrapper) and the translation is LBS's at the centre, which lies inside the mesh among the
 * points of similar weights (no bulge at bent joints). A point without a centre (one influence)
 * has c = p and moves by LBS. The palette must have its dual quaternions prepared.
 */
public final class ScalarCorSkinner extends AbstractSkinner {
    private final float[] positions;
    private final float[] restNormals;
    private final float[] centres;
    private final int[] joints;
    private final float[] weights;
    private final int width;
    /** Per thread: p' (0..2), the normal matrix row-major (3..11). */
    private final ThreadLocal<float[]> scratch = ThreadLocal.withInitial(() -> new float[12]);

    public ScalarCorSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.COR, "scalar", geometry, normals);
        this.positions = geometry.positionArray();
        this.restNormals = geometry.normalArray();
        this.centres = geometry.centresOfRotation();
        this.joints = geometry.jointArray();
        this.weights = geometry.weightArray();
        this.width = geometry.influencesPerPoint();
    }

    /**
     * Point {@code i}: its deformed position into {@code out[0..3)} and its normal matrix (row-major
     * 3x3, to be applied to the rest normal) into {@code out[3..12)}.
     */
    private void deform(JointPalette palette, int i, boolean exactNormals, float[] out) {
        final float[] dq = palette.dualQuaternions();
        int o = width * i;
        int v = 3 * i;
        float px = positions[v], py = positions[v + 1], pz = positions[v + 2];
        float cx = centres[v], cy = centres[v + 1], cz = centres[v + 2];
        // The normal matrix K of the scale phase (identity without scale).
        float k0 = 1, k1 = 0, k2 = 0, k3 = 0, k4 = 1, k5 = 0, k6 = 0, k7 = 0, k8 = 1;
        if (palette.hasScale()) {
            float[] sc = palette.scales();
            float s0 = 0, s1 = 0, s2 = 0, s3 = 0, s4 = 0, s5 = 0, s6 = 0, s7 = 0, s8 = 0, s9 = 0, s10 = 0, s11 = 0;
            for (int k = 0; k < width; k++) {
                int s = 12 * joints[o + k];
                float w = weights[o + k];
                s0 += w * sc[s];
                s1 += w * sc[s + 1];
                s2 += w * sc[s + 2];
                s3 += w * sc[s + 3];
                s4 += w * sc[s + 4];
                s5 += w * sc[s + 5];
                s6 += w * sc[s + 6];
                s7 += w * sc[s + 7];
                s8 += w * sc[s + 8];
                s9 += w * sc[s + 9];
                s10 += w * sc[s + 10];
                s11 += w * sc[s + 11];
            }
            float qx = s0 * px + s1 * py + s2 * pz + s3;
            float qy = s4 * px + s5 * py + s6 * pz + s7;
            float qz = s8 * px + s9 * py + s10 * pz + s11;
            px = qx;
            py = qy;
            pz = qz;
            qx = s0 * cx + s1 * cy + s2 * cz + s3;
            qy = s4 * cx + s5 * cy + s6 * cz + s7;
            qz = s8 * cx + s9 * cy + s10 * cz + s11;
            cx = qx;
            cy = qy;
            cz = qz;
            if (exactNormals) {
                // Cofactor matrix, times the sign of det S when the palette's scales mirror.
                k0 = s5 * s10 - s9 * s6;
                k1 = s6 * s8 - s10 * s4;
                k2 = s4 * s9 - s8 * s5;
                k3 = s9 * s2 - s1 * s10;
                k4 = s10 * s0 - s2 * s8;
                k5 = s8 * s1 - s0 * s9;
                k6 = s1 * s6 - s5 * s2;
                k7 = s2 * s4 - s6 * s0;
                k8 = s0 * s5 - s4 * s1;
                float det = s0 * k0 + s1 * k1 + s2 * k2;
                if (palette.mirrorsScales() && det < 0) {
                    k0 = -k0;
                    k1 = -k1;
                    k2 = -k2;
                    k3 = -k3;
                    k4 = -k4;
                    k5 = -k5;
                    k6 = -k6;
                    k7 = -k7;
                    k8 = -k8;
                }
            } else {
                k0 = s0;
                k1 = s1;
                k2 = s2;
                k3 = s4;
                k4 = s5;
                k5 = s6;
                k6 = s8;
                k7 = s9;
                k8 = s10;
            }
        }
        // Blend the rotations (antipodality against the dominant influence) and move the centre
        // by the rigid parts D: without scale D = M, and LBS of the centre is the blended matrix
        // applied once; with scale, D c = r c r* + t, t = 2 (rw d - dw r + r x d), per influence.
        int q = 8 * joints[o];
        float p0 = dq[q], p1 = dq[q + 1], p2 = dq[q + 2], p3 = dq[q + 3];
        float r0 = 0, r1 = 0, r2 = 0, r3 = 0;
        float tx = 0, ty = 0, tz = 0;
        if (!palette.hasScale()) {
            final float[] mat = palette.matrices();
            float a0 = 0, a1 = 0, a2 = 0, a3 = 0, a4 = 0, a5 = 0, a6 = 0, a7 = 0, a8 = 0, a9 = 0, a10 = 0, a11 = 0;
            for (int k = 0; k < width; k++) {
                int j = joints[o + k];
                float w = weights[o + k];
                q = 8 * j;
                float sw = Math.copySign(w, p0 * dq[q] + p1 * dq[q + 1] + p2 * dq[q + 2] + p3 * dq[q + 3] + 0f);
                r0 += sw * dq[q];
                r1 += sw * dq[q + 1];
                r2 += sw * dq[q + 2];
                r3 += sw * dq[q + 3];
                int m = 12 * j;
                a0 += w * mat[m];
                a1 += w * mat[m + 1];
                a2 += w * mat[m + 2];
                a3 += w * mat[m + 3];
                a4 += w * mat[m + 4];
                a5 += w * mat[m + 5];
                a6 += w * mat[m + 6];
                a7 += w * mat[m + 7];
                a8 += w * mat[m + 8];
                a9 += w * mat[m + 9];
                a10 += w * mat[m + 10];
                a11 += w * mat[m + 11];
            }
            tx = a0 * cx + a1 * cy + a2 * cz + a3;
            ty = a4 * cx + a5 * cy + a6 * cz + a7;
            tz = a8 * cx + a9 * cy + a10 * cz + a11;
        } else {
            for (int k = 0; k < width; k++) {
                q = 8 * joints[o + k];
                float w = weights[o + k];
                float ax = dq[q], ay = dq[q + 1], az = dq[q + 2], aw = dq[q + 3];
                float bx = dq[q + 4], by = dq[q + 5], bz = dq[q + 6], bw = dq[q + 7];
                float sw = Math.copySign(w, p0 * ax + p1 * ay + p2 * az + p3 * aw + 0f);
                r0 += sw * ax;
                r1 += sw * ay;
                r2 += sw * az;
                r3 += sw * aw;
                float ux = ay * cz - az * cy + aw * cx;
                float uy = az * cx - ax * cz + aw * cy;
                float uz = ax * cy - ay * cx + aw * cz;
                float dx = cx + 2 * (ay * uz - az * uy) + 2 * (aw * bx - bw * ax + (ay * bz - az * by));
                float dy = cy + 2 * (az * ux - ax * uz) + 2 * (aw * by - bw * ay + (az * bx - ax * bz));
                float dz = cz + 2 * (ax * uy - ay * ux) + 2 * (aw * bz - bw * az + (ax * by - ay * bx));
                tx += w * dx;
                ty += w * dy;
                tz += w * dz;
            }
        }
        float inv = (float) (1.0 / Math.sqrt(r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3));
        float x = r0 * inv, y = r1 * inv, z = r2 * inv, w = r3 * inv;
        // R as a matrix: applied to p1 - c1 here and to the normal matrix below.
        float m0 = 1 - 2 * (y * y + z * z), m1 = 2 * (x * y - z * w), m2 = 2 * (x * z + y * w);
        float m3 = 2 * (x * y + z * w), m4 = 1 - 2 * (x * x + z * z), m5 = 2 * (y * z - x * w);
        float m6 = 2 * (x * z - y * w), m7 = 2 * (y * z + x * w), m8 = 1 - 2 * (x * x + y * y);
        float ex = px - cx, ey = py - cy, ez = pz - cz;
        out[0] = m0 * ex + m1 * ey + m2 * ez + tx;
        out[1] = m3 * ex + m4 * ey + m5 * ez + ty;
        out[2] = m6 * ex + m7 * ey + m8 * ez + tz;
        out[3] = m0 * k0 + m1 * k3 + m2 * k6;
        out[4] = m0 * k1 + m1 * k4 + m2 * k7;
        out[5] = m0 * k2 + m1 * k5 + m2 * k8;
        out[6] = m3 * k0 + m4 * k3 + m5 * k6;
        out[7] = m3 * k1 + m4 * k4 + m5 * k7;
        out[8] = m3 * k2 + m4 * k5 + m5 * k8;
        out[9] = m6 * k0 + m7 * k3 + m8 * k6;
        out[10] = m6 * k1 + m7 * k4 + m8 * k7;
        out[11] = m6 * k2 + m7 * k5 + m8 * k8;
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        final boolean exactNormals = normals == NormalTransform.INVERSE_TRANSPOSE;
        final float[] d = scratch.get();
        for (int i = from; i < to; i++) {
            deform(palette, i, exactNormals, d);
            Deformations.putPoint(d, restNormals, i, exactNormals, outPositions, outNormals);
        }
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        final boolean exactNormals = normals == NormalTransform.INVERSE_TRANSPOSE;
        final float[] d = scratch.get();
        for (int i = from; i < to; i++) {
            deform(palette, i, exactNormals, d);
            Deformations.put(outDeformations, DEFORMATION_FLOATS * i, false, false, d[3], d[4], d[5], d[6], d[7], d[8], d[9], d[10], d[11],
                    d[0], d[1], d[2]);
        }
    }
}
