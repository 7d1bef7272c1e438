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
 * palette must have its bone rows prepared ({@link JointPalette#prepare}).
 */
public final class ScalarStbsSkinner extends AbstractSkinner {
    private final float[] positions;
    private final float[] restNormals;
    private final int[] joints;
    private final float[] weights;
    private final int width;
    private final boolean dualQuaternionBlend;
    /**
     * Offsets in the per-thread scratch, after p' (0..2) and the normal matrix row-major (3..11):
     * one influence ({@link StbsInfluence}), its rotation matrix, and the blended 3x4 B of STBS_LBS
     * (its translation column unused).
     */
    private static final int T = 12, R = T + StbsInfluence.FLOATS, B = R + 9;
    private final ThreadLocal<float[]> scratch = ThreadLocal.withInitial(() -> new float[B + 12]);

    /**
     * A skinner that reads the geometry's arrays in place; its bones come from the palette's bone rows.
     *
     * @param method   {@link SkinningMethod#STBS_LBS} or {@link SkinningMethod#STBS_DQS}
     * @param geometry the geometry to skin
     * @param normals  how normals move; not {@link NormalTransform#NONE}
     * @throws IllegalArgumentException for another method, or under {@link NormalTransform#NONE}
     */
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

    /** STBS_LBS: {@code p' = B p}, {@code B = sum_k w_k [R(r_k) | x_k]}, the normal by B's cofactor or B. */
    private void deformLinear(JointPalette palette, int i, boolean exactNormals, float[] out) {
        final float[] rows = palette.boneRows();
        final float[] dq = palette.dualQuaternions();
        int o = width * i;
        int v = 3 * i;
        float px = positions[v], py = positions[v + 1], pz = positions[v + 2];
        float b0 = 0, b1 = 0, b2 = 0, b3 = 0, b4 = 0, b5 = 0, b6 = 0, b7 = 0, b8 = 0, b9 = 0, b10 = 0, b11 = 0;
        for (int k = 0; k < width; k++) {
            float w = weights[o + k];
            if (w == 0f && k > 0) {
                continue; // a padded influence: its transformation (a sin, a cos) is not needed
            }
            StbsInfluence.transform(rows, dq, joints[o + k], px, py, pz, out, T);
            SkinningSteps.rotationMatrix(out[T], out[T + 1], out[T + 2], out[T + 3], out, R);
            b0 += w * out[R];
            b1 += w * out[R + 1];
            b2 += w * out[R + 2];
            b3 += w * out[T + 4];
            b4 += w * out[R + 3];
            b5 += w * out[R + 4];
            b6 += w * out[R + 5];
            b7 += w * out[T + 5];
            b8 += w * out[R + 6];
            b9 += w * out[R + 7];
            b10 += w * out[R + 8];
            b11 += w * out[T + 6];
        }
        out[0] = b0 * px + b1 * py + b2 * pz + b3;
        out[1] = b4 * px + b5 * py + b6 * pz + b7;
        out[2] = b8 * px + b9 * py + b10 * pz + b11;
        out[B] = b0;
        out[B + 1] = b1;
        out[B + 2] = b2;
        out[B + 4] = b4;
        out[B + 5] = b5;
        out[B + 6] = b6;
        out[B + 8] = b8;
        out[B + 9] = b9;
        out[B + 10] = b10;
        if (exactNormals) {
            // Unsigned: a blend of rotations has a positive determinant unless it degenerates.
            SkinningSteps.signedCofactor(out, B, false, out, 3);
        } else {
            SkinningSteps.linearPart(out, B, out, 3);
        }
    }

    /**
     * STBS_DQS: each influence as the unit dual quaternion {@code (r_k, x_k r_k / 2)}, blended with
     * antipodality signs against the first influence's r and normalised (the signed blend of
     * {@link SkinningSteps#blendDualQuaternions}, over transformations made per point); then
     * {@code p' = R p + t}, the normal matrix R.
     */
    private void deformDualQuaternions(JointPalette palette, int i, float[] out) {
        final float[] rows = palette.boneRows();
        final float[] dq = palette.dualQuaternions();
        final int t = T;
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
        SkinningSteps.rotationMatrix(rx, ry, rz, rw, out, 3);
        out[0] = out[3] * px + out[4] * py + out[5] * pz + tx;
        out[1] = out[6] * px + out[7] * py + out[8] * pz + ty;
        out[2] = out[9] * px + out[10] * py + out[11] * pz + tz;
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
