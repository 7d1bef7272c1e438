package org.skinlab.skinning;

/**
 * Skinning with optimized centres of rotation (Le and Hodgins 2016, section 5) in plain Java, any
 * number of influences. Per point p with centre c ({@link SkinnedGeometry#centresOfRotation()}):
 * <ol>
 * <li>if any joint is scaled this frame, the scale phase of DQS first
 *     ({@link SkinningSteps#scalePhase}): {@code S = sum_k w_k S_(j_k)}, {@code p1 = S p},
 *     {@code c1 = S c}, the normal by S's cofactor matrix (times the sign of det S) or by S itself;
 *     otherwise p1 = p, c1 = c;</li>
 * <li>the rotations' blend {@code q = sum_k s_k w_k r_(j_k)}, flipped onto the dominant
 *     influence's side and normalised, the real part of DQS's blend
 *     ({@link SkinningSteps#blendDualQuaternions}): R;</li>
 * <li>the centre moved by LBS of the joints' rigid parts D (from the palette's dual quaternions;
 *     D = M for unscaled joints, so the LBS blend of the matrices applies once):
 *     {@code t = sum_k w_k D_(j_k) c1};</li>
 * <li>{@code p' = R (p1 - c1) + t}, the normal matrix R K (K the scale phase's), or R without scale.</li>
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
    /**
     * Offsets in the per-thread scratch, after p' (0..2) and the normal matrix (3..11), of the steps
     * with scale: p1 and c1 of step 1, the blended rotation (8 floats, of which the real part is
     * used), R, the centre's translation t, and the scale phase's S and its K.
     */
    private static final int P1 = 12, C1 = 15, ROTATION = 18, R = 26, T = 35, S = 38;
    private final ThreadLocal<float[]> scratch = ThreadLocal.withInitial(
            () -> new float[S + SkinningSteps.SCALE_PHASE_FLOATS]);

    /**
     * A skinner for a geometry bound for CoR: it reads the geometry's arrays and centres in place.
     *
     * @param geometry the geometry to skin, with its centres of rotation
     *                 ({@link SkinnedGeometry#withCentresOfRotation()})
     * @param normals  how normals move; not {@link NormalTransform#NONE}
     * @throws IllegalStateException    when the geometry has no centres of rotation
     * @throws IllegalArgumentException under {@link NormalTransform#NONE}
     */
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
     * Point {@code i}: its deformed position into {@code d[0..3)} and its normal matrix (row-major
     * 3x3, to be applied to the rest normal) into {@code d[3..12)}, the steps of the class comment.
     */
    private void deform(JointPalette palette, int i, boolean exactNormals, float[] d) {
        if (!palette.hasScale()) {
            deformUnscaled(palette.dualQuaternions(), palette.matrices(), i, d);
            return;
        }
        int o = width * i;
        int v = 3 * i;
        float[] dq = palette.dualQuaternions();
        SkinningSteps.blendDualQuaternions(dq, joints, weights, o, width, d, ROTATION);
        SkinningSteps.rotationMatrix(d[ROTATION], d[ROTATION + 1], d[ROTATION + 2], d[ROTATION + 3], d, R);
        scalePhase(palette, o, v, exactNormals, d);
        moveScaledCentre(dq, o, d);
        turnAboutCentre(d, R, d, P1, d, C1, d);
        SkinningSteps.multiply3x3(d, R, d, S + 12, d, 3);
    }

    /**
     * Steps 2 to 4 without scale, in one pass over the influences: the rotations' blend q of
     * {@link SkinningSteps#blendDualQuaternions} (its real part) beside the matrices' blend B of
     * {@link SkinningSteps#blendMatrices}, then R of q as the normal matrix into {@code d[3..12)}
     * and {@code p' = R (p - c) + B c} into {@code d[0..3)}. Written in locals (the steps'
     * formulas in their order, so the same bits) because the two blends share the influences'
     * loads and loop: as two steps through the scratch, with the dual part DQS blends too, a frame
     * costs measurably more.
     */
    private void deformUnscaled(float[] dq, float[] mat, int i, float[] d) {
        int o = width * i;
        int j = joints[o];
        float w = weights[o];
        int q = 8 * j;
        float p0 = dq[q], p1 = dq[q + 1], p2 = dq[q + 2], p3 = dq[q + 3];
        float r0 = w * p0, r1 = w * p1, r2 = w * p2, r3 = w * p3;
        int m = 12 * j;
        float b0 = w * mat[m], b1 = w * mat[m + 1], b2 = w * mat[m + 2], b3 = w * mat[m + 3];
        float b4 = w * mat[m + 4], b5 = w * mat[m + 5], b6 = w * mat[m + 6], b7 = w * mat[m + 7];
        float b8 = w * mat[m + 8], b9 = w * mat[m + 9], b10 = w * mat[m + 10], b11 = w * mat[m + 11];
        for (int k = 1; k < width; k++) {
            j = joints[o + k];
            w = weights[o + k];
            q = 8 * j;
            float s = Math.copySign(w, p0 * dq[q] + p1 * dq[q + 1] + p2 * dq[q + 2] + p3 * dq[q + 3] + 0f);
            r0 += s * dq[q];
            r1 += s * dq[q + 1];
            r2 += s * dq[q + 2];
            r3 += s * dq[q + 3];
            m = 12 * j;
            b0 += w * mat[m];
            b1 += w * mat[m + 1];
            b2 += w * mat[m + 2];
            b3 += w * mat[m + 3];
            b4 += w * mat[m + 4];
            b5 += w * mat[m + 5];
            b6 += w * mat[m + 6];
            b7 += w * mat[m + 7];
            b8 += w * mat[m + 8];
            b9 += w * mat[m + 9];
            b10 += w * mat[m + 10];
            b11 += w * mat[m + 11];
        }
        float inv = (float) (1.0 / Math.sqrt(r0 * r0 + r1 * r1 + r2 * r2 + r3 * r3));
        // Without scale the normal matrix is R itself.
        SkinningSteps.rotationMatrix(inv * r0, inv * r1, inv * r2, inv * r3, d, 3);
        int v = 3 * i;
        float cx = centres[v], cy = centres[v + 1], cz = centres[v + 2];
        float ex = positions[v] - cx, ey = positions[v + 1] - cy, ez = positions[v + 2] - cz;
        d[0] = d[3] * ex + d[4] * ey + d[5] * ez + (b0 * cx + b1 * cy + b2 * cz + b3);
        d[1] = d[6] * ex + d[7] * ey + d[8] * ez + (b4 * cx + b5 * cy + b6 * cz + b7);
        d[2] = d[9] * ex + d[10] * ey + d[11] * ez + (b8 * cx + b9 * cy + b10 * cz + b11);
    }

    /**
     * Step 4: {@code p' = R (p1 - c1) + t} into {@code d[0..3)}, R at {@code d[r]}, p1 at
     * {@code p[pv]}, c1 at {@code c[cv]}, t at {@code d[T]}.
     */
    private static void turnAboutCentre(float[] d, int r, float[] p, int pv, float[] c, int cv, float[] out) {
        float ex = p[pv] - c[cv], ey = p[pv + 1] - c[cv + 1], ez = p[pv + 2] - c[cv + 2];
        out[0] = d[r] * ex + d[r + 1] * ey + d[r + 2] * ez + d[T];
        out[1] = d[r + 3] * ex + d[r + 4] * ey + d[r + 5] * ez + d[T + 1];
        out[2] = d[r + 6] * ex + d[r + 7] * ey + d[r + 8] * ez + d[T + 2];
    }

    /**
     * Step 1 with scale: S and its normal matrix K into {@code d[S..S+21)}, p1 = S p and c1 = S c
     * into {@code d[P1]} and {@code d[C1]}.
     */
    private void scalePhase(JointPalette palette, int o, int v, boolean exactNormals, float[] d) {
        SkinningSteps.scalePhase(palette.scales(), joints, weights, o, width, exactNormals, palette.mirrorsScales(), d,
                S);
        SkinningSteps.transformAffine(d, S, positions, v, d, P1);
        SkinningSteps.transformAffine(d, S, centres, v, d, C1);
    }

    /**
     * Step 3 with scale: {@code t = sum_k w_k D_(j_k) c1}, each rigid part D the palette's dual
     * quaternion ({@code D c = r c r* + t}).
     */
    private void moveScaledCentre(float[] dq, int o, float[] d) {
        float cx = d[C1], cy = d[C1 + 1], cz = d[C1 + 2];
        float tx = 0, ty = 0, tz = 0;
        for (int k = 0; k < width; k++) {
            float w = weights[o + k];
            int q = 8 * joints[o + k];
            SkinningSteps.transformPoint(dq[q], dq[q + 1], dq[q + 2], dq[q + 3], dq[q + 4], dq[q + 5], dq[q + 6],
                    dq[q + 7], cx, cy, cz, d, T);
            tx += w * d[T];
            ty += w * d[T + 1];
            tz += w * d[T + 2];
        }
        d[T] = tx;
        d[T + 1] = ty;
        d[T + 2] = tz;
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
