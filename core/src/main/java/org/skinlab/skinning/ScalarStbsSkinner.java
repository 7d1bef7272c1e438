package org.skinlab.skinning;

/**
 * Stretchable and twistable bones (Jacobson and Sorkine 2011) in plain Java, any number of
 * influences, on top of LBS ({@link SkinningMethod#STBS_LBS}) or DQS
 * ({@link SkinningMethod#STBS_DQS}). Per point p each influence k contributes the rigid
 * transformation {@code T_k(p) = H + R(r_k) (p - h) + e_k s} of {@link StbsInfluence} (its
 * bone's twist and stretch taken in proportion to the point's endpoint weight e_k); then
 * <ul>
 * <li>STBS_LBS: {@code p' = (sum_k w_k [R(r_k) | x_k]) p}, the normal by the cofactor of the
 *     blended linear part (or by that part itself), as {@link ScalarLbsSkinner} does;</li>
 * <li>STBS_DQS: the influences as unit dual quaternions {@code (r_k, x_k r_k / 2)}, blended with
 *     antipodality signs against the dominant influence's r and normalised, as
 *     {@link ScalarDqsSkinner} does; the normal turned by the blended rotation.</li>
 * </ul>
 * The joints' scale beyond the bone's stretch (a radial squash, shear) is not applied: each
 * influence is rigid plus the stretch along its bone (docs/skinning.md, "Stretchable and twistable
 * bones"). Normals ignore the change of e across the surface, as CoR's ignore the centre's. The
 * palette must have its bone rows prepared ({@link JointPalette#prepareBones()}).
 */
public final class ScalarStbsSkinner extends AbstractSkinner {
    private final float[] positions;
    private final float[] restNormals;
    private final int[] joints;
    private final float[] weights;
    private final int width;
    private final boolean dualQuaternionBlend;
    /** Per thread: p' (0..2), the normal matrix row-major (3..11), one influence (12..18). */
    private final ThreadLocal<float[]> scratch = ThreadLocal.withInitial(() -> new float[12 + StbsInfluence.FLOATS]);

    /** @param method {@link SkinningMethod#STBS_LBS} or {@link SkinningMethod#STBS_DQS} */
    public ScalarStbsSkinner(SkinningMethod method, SkinnedGeometry geometry, NormalTransform normals) {
        super(method, "scalar", geometry, normals);
        if (method != SkinningMethod.STBS_LBS && method != SkinningMethod.STBS_DQS) {
            throw new IllegalArgumentException("not a stretchable-bones method: " + method);
        }
        this.dualQuaternionBlend = method == SkinningMethod.STBS_DQS;
        this.positions = geometry.positionArray();
        this.restNormals = geometry.normalArray();
        this.joints = geometry.jointArray();
        this.weights = geometry.weightArray();
        this.width = geometry.influencesPerPoint();
    }

    /** Point i's position into {@code out[0..3)}, its normal matrix (row-major) into {@code out[3..12)}. */
    private void deform(JointPalette palette, int i, boolean exactNormals, float[] out) {
        if (dualQuaternionBlend) {
            deformDualQuaternions(palette, i, out);
        } else {
            deformLinear(palette, i, exactNormals, out);
        }
    }

    private void deformLinear(JointPalette palette, int i, boolean exactNormals, float[] out) {
        final float[] rows = palette.boneRows();
        final float[] dq = palette.dualQuaternions();
        final int t = 12;
        int o = width * i;
        int v = 3 * i;
        float px = positions[v], py = positions[v + 1], pz = positions[v + 2];
        float b0 = 0, b1 = 0, b2 = 0, b3 = 0, b4 = 0, b5 = 0, b6 = 0, b7 = 0, b8 = 0, b9 = 0, b10 = 0, b11 = 0;
        for (int k = 0; k < width; k++) {
            float w = weights[o + k];
            if (w == 0f && k > 0) {
                continue; // a padded influence: its transformation (a sin, a cos) is not needed
            }
            StbsInfluence.transform(rows, dq, joints[o + k], px, py, pz, out, t);
            float x = out[t], y = out[t + 1], z = out[t + 2], s = out[t + 3];
            b0 += w * (1 - 2 * (y * y + z * z));
            b1 += w * (2 * (x * y - z * s));
            b2 += w * (2 * (x * z + y * s));
            b3 += w * out[t + 4];
            b4 += w * (2 * (x * y + z * s));
            b5 += w * (1 - 2 * (x * x + z * z));
            b6 += w * (2 * (y * z - x * s));
            b7 += w * out[t + 5];
            b8 += w * (2 * (x * z - y * s));
            b9 += w * (2 * (y * z + x * s));
            b10 += w * (1 - 2 * (x * x + y * y));
            b11 += w * out[t + 6];
        }
        out[0] = b0 * px + b1 * py + b2 * pz + b3;
        out[1] = b4 * px + b5 * py + b6 * pz + b7;
        out[2] = b8 * px + b9 * py + b10 * pz + b11;
        if (exactNormals) {
            // The cofactor: a blend of rotations has a positive determinant unless it degenerates.
            out[3] = b5 * b10 - b9 * b6;
            out[4] = b6 * b8 - b10 * b4;
            out[5] = b4 * b9 - b8 * b5;
            out[6] = b9 * b2 - b1 * b10;
            out[7] = b10 * b0 - b2 * b8;
            out[8] = b8 * b1 - b0 * b9;
            out[9] = b1 * b6 - b5 * b2;
            out[10] = b2 * b4 - b6 * b0;
            out[11] = b0 * b5 - b4 * b1;
        } else {
            out[3] = b0;
            out[4] = b1;
            out[5] = b2;
            out[6] = b4;
            out[7] = b5;
            out[8] = b6;
            out[9] = b8;
            out[10] = b9;
            out[11] = b10;
        }
    }

    private void deformDualQuaternions(JointPalette palette, int i, float[] out) {
        final float[] rows = palette.boneRows();
        final float[] dq = palette.dualQuaternions();
        final int t = 12;
        int o = width * i;
        int v = 3 * i;
        float px = positions[v], py = positions[v + 1], pz = positions[v + 2];
        float r0 = 0, r1 = 0, r2 = 0, r3 = 0, d0 = 0, d1 = 0, d2 = 0, d3 = 0;
        float p0 = 0, p1 = 0, p2 = 0, p3 = 0;
        for (int k = 0; k < width; k++) {
            if (weights[o + k] == 0f && k > 0) {
                continue;
            }
            StbsInfluence.transform(rows, dq, joints[o + k], px, py, pz, out, t);
            float x = out[t], y = out[t + 1], z = out[t + 2], s = out[t + 3];
            if (k == 0) {
                p0 = x;
                p1 = y;
                p2 = z;
                p3 = s;
            }
            // Antipodality against the dominant influence's rotation, as in ScalarDqsSkinner.
            float w = Math.copySign(weights[o + k], p0 * x + p1 * y + p2 * z + p3 * s + 0f);
            float ex = out[t + 4], ey = out[t + 5], ez = out[t + 6];
            r0 += w * x;
            r1 += w * y;
            r2 += w * z;
            r3 += w * s;
            // The dual part x r / 2 of the translation x.
            float hw = 0.5f * w;
            d0 += hw * (s * ex + (ey * z - ez * y));
            d1 += hw * (s * ey + (ez * x - ex * z));
            d2 += hw * (s * ez + (ex * y - ey * x));
            d3 -= hw * (ex * x + ey * y + ez * z);
        }
        float inv = (float) (1.0 / Math.sqrt(r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3));
        float rx = r0 * inv, ry = r1 * inv, rz = r2 * inv, rw = r3 * inv;
        float dx = d0 * inv, dy = d1 * inv, dz = d2 * inv, dw = d3 * inv;
        float tx = 2 * (rw * dx - dw * rx + (ry * dz - rz * dy));
        float ty = 2 * (rw * dy - dw * ry + (rz * dx - rx * dz));
        float tz = 2 * (rw * dz - dw * rz + (rx * dy - ry * dx));
        float m0 = 1 - 2 * (ry * ry + rz * rz), m1 = 2 * (rx * ry - rz * rw), m2 = 2 * (rx * rz + ry * rw);
        float m3 = 2 * (rx * ry + rz * rw), m4 = 1 - 2 * (rx * rx + rz * rz), m5 = 2 * (ry * rz - rx * rw);
        float m6 = 2 * (rx * rz - ry * rw), m7 = 2 * (ry * rz + rx * rw), m8 = 1 - 2 * (rx * rx + ry * ry);
        out[0] = m0 * px + m1 * py + m2 * pz + tx;
        out[1] = m3 * px + m4 * py + m5 * pz + ty;
        out[2] = m6 * px + m7 * py + m8 * pz + tz;
        out[3] = m0;
        out[4] = m1;
        out[5] = m2;
        out[6] = m3;
        out[7] = m4;
        out[8] = m5;
        out[9] = m6;
        out[10] = m7;
        out[11] = m8;
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
            Deformations.put(outDeformations, DEFORMATION_FLOATS * i, d, 0);
        }
    }
}
