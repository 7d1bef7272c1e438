package org.skinlab.skinning;

/**
 * Dual Quaternion Skinning in plain Java, any number of influences (Kavan et al. 2008, with the
 * two-phase scale split of {@link JointPalette}). Per point:
 * <ol>
 * <li>if any joint is scaled this frame, the scale phase ({@link SkinningSteps#scalePhase}):
 *     {@code S = sum_k w_k S_(j_k)}, {@code p1 = S p}, the normal by {@link NormalTransform}
 *     applied to S (under INVERSE_TRANSPOSE by its cofactor times the sign of det S, so that a
 *     mirroring scale keeps normals outward, and scaled to unit length);</li>
 * <li>the blend {@code b = sum_k s_k w_k q_(j_k)}, antipodal quaternions flipped onto the first
 *     influence's hemisphere, normalised by its real part
 *     ({@link SkinningSteps#blendDualQuaternions});</li>
 * <li>b applied: p1 rotated and translated, the normal rotated
 *     ({@link SkinningSteps#transformPoint}, {@link SkinningSteps#rotate}); under
 *     INVERSE_TRANSPOSE the normal is then scaled to unit length, as LBS's is.</li>
 * </ol>
 * The SIMD kernels flip the same terms (a dot of -0 included) and are tested against this one.
 * Positions only ({@link NormalTransform#NONE}) take a loop of their own, {@link #skinPositions},
 * chosen once per call: the same steps without the normal's (the scale phase's blend of S without
 * its cofactor), so the same bits.
 */
public final class ScalarDqsSkinner extends AbstractSkinner {
    private final float[] positions;
    private final float[] restNormals;
    private final int[] joints;
    private final float[] weights;
    private final int width;
    /**
     * Per thread: the blended dual quaternion (0..7), the scale phase's S and K (8..28,
     * {@link SkinningSteps#scalePhase}) and the scaled point (29..31); in {@link #skin} the scaled
     * normal (32..34); in {@link #skinDeformations} R (32..40) and the deformation, position
     * (41..43) and normal matrix (44..52).
     */
    private final ThreadLocal<float[]> blended = ThreadLocal.withInitial(() -> new float[53]);

    /**
     * A skinner that reads the geometry's arrays in place (a morphed rest shape is followed as is).
     *
     * @param geometry the geometry to skin
     * @param normals  how normals move, or {@link NormalTransform#NONE} for positions only
     */
    public ScalarDqsSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.DQS, "scalar", geometry, normals);
        this.positions = geometry.positionArray();
        this.restNormals = geometry.normalArray();
        this.joints = geometry.jointArray();
        this.weights = geometry.weightArray();
        this.width = geometry.influencesPerPoint();
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        if (normals == NormalTransform.NONE) {
            skinPositions(palette, outPositions, from, to);
            return;
        }
        final float[] dq = palette.dualQuaternions();
        final float[] sc = palette.scales();
        final boolean scaled = palette.hasScale();
        final boolean exactNormals = normals == NormalTransform.INVERSE_TRANSPOSE;
        final boolean mirror = exactNormals && palette.mirrorsScales();
        final float[] b = blended.get();
        for (int i = from; i < to; i++) {
            int o = width * i;
            SkinningSteps.blendDualQuaternions(dq, joints, weights, o, width, b, 0);
            int v = 3 * i;
            float[] p = positions;
            float[] n = restNormals;
            int pv = v;
            int nv = v;
            if (scaled) {
                SkinningSteps.scalePhase(sc, joints, weights, o, width, exactNormals, mirror, b, 8);
                scalePoint(b, v, exactNormals);
                p = b;
                n = b;
                pv = 29;
                nv = 32;
            }
            float rx = b[0], ry = b[1], rz = b[2], rw = b[3];
            SkinningSteps.transformPoint(rx, ry, rz, rw, b[4], b[5], b[6], b[7], p[pv], p[pv + 1], p[pv + 2],
                    outPositions, v);
            SkinningSteps.rotate(rx, ry, rz, rw, n[nv], n[nv + 1], n[nv + 2], outNormals, v);
            if (exactNormals) {
                // Unit length like every exact normal (the rest normals of a file need not be).
                float mx = outNormals[v], my = outNormals[v + 1], mz = outNormals[v + 2];
                float len2 = mx * mx + my * my + mz * mz;
                float scale = len2 > 0f ? 1f / (float) Math.sqrt(len2) : 0f;
                outNormals[v] = mx * scale;
                outNormals[v + 1] = my * scale;
                outNormals[v + 2] = mz * scale;
            }
        }
    }

    /** {@link #skin} without normals: the scale phase's {@code S p} where joints scale, then the blend applied. */
    private void skinPositions(JointPalette palette, float[] outPositions, int from, int to) {
        final float[] dq = palette.dualQuaternions();
        final float[] sc = palette.scales();
        final boolean scaled = palette.hasScale();
        final float[] b = blended.get();
        for (int i = from; i < to; i++) {
            int o = width * i;
            SkinningSteps.blendDualQuaternions(dq, joints, weights, o, width, b, 0);
            int v = 3 * i;
            float[] p = positions;
            int pv = v;
            if (scaled) {
                SkinningSteps.blendMatrices(sc, joints, weights, o, width, b, 8);
                SkinningSteps.transformAffine(b, 8, positions, v, b, 29);
                p = b;
                pv = 29;
            }
            SkinningSteps.transformPoint(b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7], p[pv], p[pv + 1], p[pv + 2],
                    outPositions, v);
        }
    }

    /**
     * The scale phase's point: {@code S p} into {@code b[29..32)} and {@code K n} into
     * {@code b[32..35)}, S and K from {@code b[8..29)}; under the exact rule K n is scaled to unit
     * length (K carries the sign of det S already).
     */
    private void scalePoint(float[] b, int v, boolean exactNormals) {
        SkinningSteps.transformAffine(b, 8, positions, v, b, 29);
        float nx = restNormals[v], ny = restNormals[v + 1], nz = restNormals[v + 2];
        float mx = b[20] * nx + b[21] * ny + b[22] * nz;
        float my = b[23] * nx + b[24] * ny + b[25] * nz;
        float mz = b[26] * nx + b[27] * ny + b[28] * nz;
        if (exactNormals) {
            float len2 = mx * mx + my * my + mz * mz;
            float inv = len2 > 0f ? (float) (1.0 / Math.sqrt(len2)) : 0f;
            mx *= inv;
            my *= inv;
            mz *= inv;
        }
        b[32] = mx;
        b[33] = my;
        b[34] = mz;
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        if (normals == NormalTransform.NONE) {
            throw noDeformationsWithoutNormals();
        }
        final float[] dq = palette.dualQuaternions();
        final float[] sc = palette.scales();
        final boolean scaled = palette.hasScale();
        final boolean exactNormals = normals == NormalTransform.INVERSE_TRANSPOSE;
        final boolean mirror = exactNormals && palette.mirrorsScales();
        final float[] b = blended.get();
        for (int i = from; i < to; i++) {
            int o = width * i;
            SkinningSteps.blendDualQuaternions(dq, joints, weights, o, width, b, 0);
            int v = 3 * i;
            float[] p = positions;
            int pv = v;
            if (scaled) {
                SkinningSteps.scalePhase(sc, joints, weights, o, width, exactNormals, mirror, b, 8);
                SkinningSteps.transformAffine(b, 8, positions, v, b, 29);
                p = b;
                pv = 29;
                // N = R K
                SkinningSteps.rotationMatrix(b[0], b[1], b[2], b[3], b, 32);
                SkinningSteps.multiply3x3(b, 32, b, 20, b, 44);
            } else {
                SkinningSteps.rotationMatrix(b[0], b[1], b[2], b[3], b, 44);
            }
            SkinningSteps.transformPoint(b[0], b[1], b[2], b[3], b[4], b[5], b[6], b[7], p[pv], p[pv + 1], p[pv + 2],
                    b, 41);
            Deformations.put(outDeformations, DEFORMATION_FLOATS * i, b, 41);
        }
    }
}
