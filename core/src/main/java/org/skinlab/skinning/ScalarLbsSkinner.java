package org.skinlab.skinning;

/**
 * Linear Blend Skinning in plain Java, any number of influences: per point
 * {@code M = sum_k w_k M_(j_k)} ({@link SkinningSteps#blendMatrices}), {@code p' = M p}, and the
 * normal by {@link NormalTransform}: under INVERSE_TRANSPOSE by M's cofactor (det times the
 * inverse-transpose; with a mirroring palette times the sign of det, so the normal stays outward)
 * and scaled to unit length, else by M's linear part.
 * The portable kernel (Android) and the reference the SIMD kernels are tested against.
 */
public final class ScalarLbsSkinner extends AbstractSkinner {
    private final float[] positions;
    private final float[] restNormals;
    private final int[] joints;
    private final float[] weights;
    private final int width;
    /**
     * Per thread: in {@link #skin} the blend B (0..11) and its normal matrix (12..20); in
     * {@link #skinDeformations} the point's deformation, position (0..2) and normal matrix (3..11),
     * and B (12..23).
     */
    private final ThreadLocal<float[]> scratch = ThreadLocal.withInitial(() -> new float[24]);

    public ScalarLbsSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.LBS, "scalar", geometry, normals);
        this.positions = geometry.positionArray();
        this.restNormals = geometry.normalArray();
        this.joints = geometry.jointArray();
        this.weights = geometry.weightArray();
        this.width = geometry.influencesPerPoint();
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        final float[] mat = palette.matrices();
        final boolean exactNormals = normals == NormalTransform.INVERSE_TRANSPOSE;
        final boolean mirror = exactNormals && palette.mirrorsMatrices();
        final float[] b = scratch.get();
        for (int i = from; i < to; i++) {
            SkinningSteps.blendMatrices(mat, joints, weights, width * i, width, b, 0);
            int v = 3 * i;
            float px = positions[v], py = positions[v + 1], pz = positions[v + 2];
            float qx = b[0] * px + b[1] * py + b[2] * pz + b[3];
            float qy = b[4] * px + b[5] * py + b[6] * pz + b[7];
            float qz = b[8] * px + b[9] * py + b[10] * pz + b[11];
            float nx = restNormals[v], ny = restNormals[v + 1], nz = restNormals[v + 2];
            float mx;
            float my;
            float mz;
            if (exactNormals) {
                SkinningSteps.signedCofactor(b, 0, mirror, b, 12);
                mx = b[12] * nx + b[13] * ny + b[14] * nz;
                my = b[15] * nx + b[16] * ny + b[17] * nz;
                mz = b[18] * nx + b[19] * ny + b[20] * nz;
                float len2 = mx * mx + my * my + mz * mz;
                float inv = len2 > 0f ? (float) (1.0 / Math.sqrt(len2)) : 0f;
                mx *= inv;
                my *= inv;
                mz *= inv;
            } else {
                mx = b[0] * nx + b[1] * ny + b[2] * nz;
                my = b[4] * nx + b[5] * ny + b[6] * nz;
                mz = b[8] * nx + b[9] * ny + b[10] * nz;
            }
            // Written last: a store to another float[] would keep the JIT from reading b from registers.
            outPositions[v] = qx;
            outPositions[v + 1] = qy;
            outPositions[v + 2] = qz;
            outNormals[v] = mx;
            outNormals[v + 1] = my;
            outNormals[v + 2] = mz;
        }
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        final float[] mat = palette.matrices();
        final boolean exactNormals = normals == NormalTransform.INVERSE_TRANSPOSE;
        final boolean mirror = exactNormals && palette.mirrorsMatrices();
        final float[] b = scratch.get();
        for (int i = from; i < to; i++) {
            SkinningSteps.blendMatrices(mat, joints, weights, width * i, width, b, 12);
            int v = 3 * i;
            float px = positions[v], py = positions[v + 1], pz = positions[v + 2];
            b[0] = b[12] * px + b[13] * py + b[14] * pz + b[15];
            b[1] = b[16] * px + b[17] * py + b[18] * pz + b[19];
            b[2] = b[20] * px + b[21] * py + b[22] * pz + b[23];
            if (exactNormals) {
                SkinningSteps.signedCofactor(b, 12, mirror, b, 3);
            } else {
                SkinningSteps.linearPart(b, 12, b, 3);
            }
            Deformations.put(outDeformations, DEFORMATION_FLOATS * i, b, 0);
        }
    }
}
