package org.skinlab.skinning;

/**
 * Dual Quaternion Skinning in plain Java, any number of influences (Kavan et al. 2008, with the
 * two-phase scale split of {@link JointPalette}). Per point:
 * <ol>
 * <li>if any joint is scaled this frame, {@code S = sum_k w_k S_(j_k)}, {@code p1 = S p}, the
 *     normal by {@link NormalTransform} applied to S (under INVERSE_TRANSPOSE times the sign of
 *     det S, so that a mirroring scale keeps normals outward);</li>
 * <li>{@code b = sum_k s_k w_k q_(j_k)} with {@code s_k = sign(q_(j_0) . q_(j_k))} on the real
 *     parts, j_0 the dominant influence: antipodal quaternions (the same rotation) are flipped
 *     onto the pivot's hemisphere so the blend takes the short way (Kavan et al. 2008, section
 *     4). The sign comes from {@code Math.copySign}, not a branch: with joints in random order a
 *     branch mispredicts about half the time. Its argument is {@code dot + 0}, so a dot of -0
 *     (orthogonal rotations) counts as +0, as in a lane compare {@code dot < 0}: the SIMD kernels
 *     then pick the same sign in that tie;</li>
 * <li>normalise b by its real part and apply it: rotate p1 and the normal, translate p1; under
 *     INVERSE_TRANSPOSE the normal is then scaled to unit length, as LBS's is.</li>
 * </ol>
 * Since every flipped term has a non-negative dot with the pivot, |b.real| >= w_0 > 0: the
 * normalisation never divides by zero.
 */
public final class ScalarDqsSkinner extends AbstractSkinner {
    private final float[] positions;
    private final float[] restNormals;
    private final int[] joints;
    private final float[] weights;
    private final int width;
    /**
     * Per thread: the blended dual quaternion (floats 0..7), the blended scale part (8..19,
     * row-major 3x4) and the normal matrix of the scale part (20..28, row-major 3x3).
     */
    private final ThreadLocal<float[]> blended = ThreadLocal.withInitial(() -> new float[29]);

    public ScalarDqsSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.DQS, "scalar", geometry, normals);
        this.positions = geometry.positionArray();
        this.restNormals = geometry.normalArray();
        this.joints = geometry.jointArray();
        this.weights = geometry.weightArray();
        this.width = geometry.influencesPerPoint();
    }

    /**
     * {@code b = sum_k copySign(w_k, q_0 . q_k + 0) q_k} into {@code b[0..8)}, normalised by the
     * length of its real part (see the class comment for the sign).
     */
    private void blendDualQuaternion(float[] dq, int o, float[] b) {
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
        b[0] = r0 * inv;
        b[1] = r1 * inv;
        b[2] = r2 * inv;
        b[3] = r3 * inv;
        b[4] = d0 * inv;
        b[5] = d1 * inv;
        b[6] = d2 * inv;
        b[7] = d3 * inv;
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        final float[] dq = palette.dualQuaternions();
        final float[] sc = palette.scales();
        final boolean scaled = palette.hasScale();
        final boolean exactNormals = normals == NormalTransform.INVERSE_TRANSPOSE;
        final boolean mirror = exactNormals && palette.mirrorsScales();
        for (int i = from; i < to; i++) {
            int o = width * i;
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
            int v = 3 * i;
            float px = positions[v], py = positions[v + 1], pz = positions[v + 2];
            float nx = restNormals[v], ny = restNormals[v + 1], nz = restNormals[v + 2];
            if (scaled) {
                int s = 12 * joints[o];
                w = weights[o];
                float s0 = w * sc[s], s1 = w * sc[s + 1], s2 = w * sc[s + 2], s3 = w * sc[s + 3];
                float s4 = w * sc[s + 4], s5 = w * sc[s + 5], s6 = w * sc[s + 6], s7 = w * sc[s + 7];
                float s8 = w * sc[s + 8], s9 = w * sc[s + 9], s10 = w * sc[s + 10], s11 = w * sc[s + 11];
                for (int k = 1; k < width; k++) {
                    s = 12 * joints[o + k];
                    w = weights[o + k];
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
                float mx;
                float my;
                float mz;
                if (exactNormals) {
                    float k00 = s5 * s10 - s9 * s6, k01 = s6 * s8 - s10 * s4, k02 = s4 * s9 - s8 * s5;
                    mx = k00 * nx + k01 * ny + k02 * nz;
                    my = (s9 * s2 - s1 * s10) * nx + (s10 * s0 - s2 * s8) * ny + (s8 * s1 - s0 * s9) * nz;
                    mz = (s1 * s6 - s5 * s2) * nx + (s2 * s4 - s6 * s0) * ny + (s0 * s5 - s4 * s1) * nz;
                    float len2 = mx * mx + my * my + mz * mz;
                    // The sign of det S keeps normals outward under a mirroring scale part.
                    float det = mirror ? s0 * k00 + s1 * k01 + s2 * k02 : 1f;
                    float inv = len2 > 0f ? Math.copySign((float) (1.0 / Math.sqrt(len2)), det) : 0f;
                    mx *= inv;
                    my *= inv;
                    mz *= inv;
                } else {
                    mx = s0 * nx + s1 * ny + s2 * nz;
                    my = s4 * nx + s5 * ny + s6 * nz;
                    mz = s8 * nx + s9 * ny + s10 * nz;
                }
                nx = mx;
                ny = my;
                nz = mz;
            }
            float inv = (float) (1.0 / Math.sqrt(r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3));
            float rx = r0 * inv, ry = r1 * inv, rz = r2 * inv, rw = r3 * inv;
            float dx = d0 * inv, dy = d1 * inv, dz = d2 * inv, dw = d3 * inv;
            // t = 2 (rw d.xyz - dw r.xyz + r.xyz x d.xyz); v' = v + 2 r x (r x v + rw v) + t
            float tx = 2 * (rw * dx - dw * rx + (ry * dz - rz * dy));
            float ty = 2 * (rw * dy - dw * ry + (rz * dx - rx * dz));
            float tz = 2 * (rw * dz - dw * rz + (rx * dy - ry * dx));
            float cx = ry * pz - rz * py + rw * px;
            float cy = rz * px - rx * pz + rw * py;
            float cz = rx * py - ry * px + rw * pz;
            outPositions[v] = px + 2 * (ry * cz - rz * cy) + tx;
            outPositions[v + 1] = py + 2 * (rz * cx - rx * cz) + ty;
            outPositions[v + 2] = pz + 2 * (rx * cy - ry * cx) + tz;
            cx = ry * nz - rz * ny + rw * nx;
            cy = rz * nx - rx * nz + rw * ny;
            cz = rx * ny - ry * nx + rw * nz;
            float mx = nx + 2 * (ry * cz - rz * cy);
            float my = ny + 2 * (rz * cx - rx * cz);
            float mz = nz + 2 * (rx * cy - ry * cx);
            if (exactNormals) {
                // Unit length like every exact normal (the rest normals of a file need not be).
                float len2 = mx * mx + my * my + mz * mz;
                float scale = len2 > 0f ? 1f / (float) Math.sqrt(len2) : 0f;
                mx *= scale;
                my *= scale;
                mz *= scale;
            }
            outNormals[v] = mx;
            outNormals[v + 1] = my;
            outNormals[v + 2] = mz;
        }
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        final float[] dq = palette.dualQuaternions();
        final float[] sc = palette.scales();
        final boolean scaled = palette.hasScale();
        final boolean exactNormals = normals == NormalTransform.INVERSE_TRANSPOSE;
        final boolean mirror = exactNormals && palette.mirrorsScales();
        final float[] b = blended.get();
        for (int i = from; i < to; i++) {
            int o = width * i;
            blendDualQuaternion(dq, o, b);
            int v = 3 * i;
            float px = positions[v], py = positions[v + 1], pz = positions[v + 2];
            float rx = b[0], ry = b[1], rz = b[2], rw = b[3];
            float dx = b[4], dy = b[5], dz = b[6], dw = b[7];
            // The rotation of the unit quaternion r as a matrix, row-major.
            float r00 = 1 - 2 * (ry * ry + rz * rz), r01 = 2 * (rx * ry - rz * rw), r02 = 2 * (rx * rz + ry * rw);
            float r10 = 2 * (rx * ry + rz * rw), r11 = 1 - 2 * (rx * rx + rz * rz), r12 = 2 * (ry * rz - rx * rw);
            float r20 = 2 * (rx * rz - ry * rw), r21 = 2 * (ry * rz + rx * rw), r22 = 1 - 2 * (rx * rx + ry * ry);
            float n00 = r00, n01 = r01, n02 = r02, n10 = r10, n11 = r11, n12 = r12, n20 = r20, n21 = r21, n22 = r22;
            if (scaled) {
                Deformations.blendMatrices(sc, joints, weights, o, width, b, 8);
                float qx = b[8] * px + b[9] * py + b[10] * pz + b[11];
                float qy = b[12] * px + b[13] * py + b[14] * pz + b[15];
                float qz = b[16] * px + b[17] * py + b[18] * pz + b[19];
                px = qx;
                py = qy;
                pz = qz;
                int k = 20;
                if (exactNormals) {
                    Deformations.signedCofactor(b, 8, mirror, b, 20);
                } else {
                    for (int row = 0; row < 3; row++) {
                        System.arraycopy(b, 8 + 4 * row, b, 20 + 3 * row, 3);
                    }
                }
                // N = R K
                n00 = r00 * b[k] + r01 * b[k + 3] + r02 * b[k + 6];
                n01 = r00 * b[k + 1] + r01 * b[k + 4] + r02 * b[k + 7];
                n02 = r00 * b[k + 2] + r01 * b[k + 5] + r02 * b[k + 8];
                n10 = r10 * b[k] + r11 * b[k + 3] + r12 * b[k + 6];
                n11 = r10 * b[k + 1] + r11 * b[k + 4] + r12 * b[k + 7];
                n12 = r10 * b[k + 2] + r11 * b[k + 5] + r12 * b[k + 8];
                n20 = r20 * b[k] + r21 * b[k + 3] + r22 * b[k + 6];
                n21 = r20 * b[k + 1] + r21 * b[k + 4] + r22 * b[k + 7];
                n22 = r20 * b[k + 2] + r21 * b[k + 5] + r22 * b[k + 8];
            }
            // The position as skin() moves it, so both paths give the same bits.
            float tx = 2 * (rw * dx - dw * rx + (ry * dz - rz * dy));
            float ty = 2 * (rw * dy - dw * ry + (rz * dx - rx * dz));
            float tz = 2 * (rw * dz - dw * rz + (rx * dy - ry * dx));
            float cx = ry * pz - rz * py + rw * px;
            float cy = rz * px - rx * pz + rw * py;
            float cz = rx * py - ry * px + rw * pz;
            Deformations.put(outDeformations, Skinner.DEFORMATION_FLOATS * i, false, false, n00, n01, n02, n10, n11, n12, n20, n21, n22,
                    px + 2 * (ry * cz - rz * cy) + tx, py + 2 * (rz * cx - rx * cz) + ty,
                    pz + 2 * (rx * cy - ry * cx) + tz);
        }
    }
}
