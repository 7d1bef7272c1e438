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
    /** The normal matrix of the scale phase without scale. */
    private static final float[] IDENTITY = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    /**
     * Offsets in the per-thread scratch, after p' (0..2) and the normal matrix (3..11): p1, c1, K of
     * step 1, the blended rotation (8 floats, of which the real part is used), R, the centre's
     * translation t, and the blended matrix: the scale phase's S and its K, or LBS's blend.
     */
    private static final int P1 = 12, C1 = 15, K = 18, ROTATION = 27, R = 35, T = 44, S = 47;
    private final ThreadLocal<float[]> scratch = ThreadLocal.withInitial(
            () -> new float[S + SkinningSteps.SCALE_PHASE_FLOATS]);

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
        int o = width * i;
        int v = 3 * i;
        scalePhase(palette, o, v, exactNormals, d);
        SkinningSteps.blendDualQuaternions(palette.dualQuaternions(), joints, weights, o, width, d, ROTATION);
        if (palette.hasScale()) {
            moveScaledCentre(palette.dualQuaternions(), o, d);
        } else {
            moveCentre(palette.matrices(), o, d);
        }
        SkinningSteps.rotationMatrix(d[ROTATION], d[ROTATION + 1], d[ROTATION + 2], d[ROTATION + 3], d, R);
        float ex = d[P1] - d[C1], ey = d[P1 + 1] - d[C1 + 1], ez = d[P1 + 2] - d[C1 + 2];
        d[0] = d[R] * ex + d[R + 1] * ey + d[R + 2] * ez + d[T];
        d[1] = d[R + 3] * ex + d[R + 4] * ey + d[R + 5] * ez + d[T + 1];
        d[2] = d[R + 6] * ex + d[R + 7] * ey + d[R + 8] * ez + d[T + 2];
        SkinningSteps.multiply3x3(d, R, d, K, d, 3);
    }

    /**
     * Step 1: p1 and c1 into {@code d[P1]} and {@code d[C1]}, the normal matrix K of the scale phase
     * into {@code d[K]} (the identity without scale).
     */
    private void scalePhase(JointPalette palette, int o, int v, boolean exactNormals, float[] d) {
        if (!palette.hasScale()) {
            System.arraycopy(positions, v, d, P1, 3);
            System.arraycopy(centres, v, d, C1, 3);
            System.arraycopy(IDENTITY, 0, d, K, 9);
            return;
        }
        SkinningSteps.scalePhase(palette.scales(), joints, weights, o, width, exactNormals, palette.mirrorsScales(), d, S);
        transformAffine(d, S, positions, v, d, P1);
        transformAffine(d, S, centres, v, d, C1);
        System.arraycopy(d, S + 12, d, K, 9);
    }

    /** {@code dest[dd..dd+3) = A x} for the 3x4 matrix A at {@code a[ao]} and the point x at {@code x[xo]}. */
    private static void transformAffine(float[] a, int ao, float[] x, int xo, float[] dest, int dd) {
        float px = x[xo], py = x[xo + 1], pz = x[xo + 2];
        dest[dd] = a[ao] * px + a[ao + 1] * py + a[ao + 2] * pz + a[ao + 3];
        dest[dd + 1] = a[ao + 4] * px + a[ao + 5] * py + a[ao + 6] * pz + a[ao + 7];
        dest[dd + 2] = a[ao + 8] * px + a[ao + 9] * py + a[ao + 10] * pz + a[ao + 11];
    }

    /** Step 3 without scale: D = M, so {@code t = (sum_k w_k M_(j_k)) c}, the blended matrix applied once. */
    private void moveCentre(float[] matrices, int o, float[] d) {
        SkinningSteps.blendMatrices(matrices, joints, weights, o, width, d, S);
        transformAffine(d, S, d, C1, d, T);
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
            SkinningSteps.transformPoint(dq, 8 * joints[o + k], cx, cy, cz, d, T);
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
