package org.skinlab.skinning;

/**
 * Linear Blend Skinning in plain Java, any number of influences: per point
 * {@code M = sum_k w_k M_(j_k)}, {@code p' = M p}, and the normal by {@link NormalTransform}.
 * The portable kernel (Android) and the reference the SIMD kernels are tested against.
 *
 * <p>{@link #skin} and {@link #skinDeformations} share one loop ({@link #skinRange}): the blend
 * and {@code p'} once, then by a flag that does not change within the loop (C2 unswitches it into
 * two loops) either the point or the deformation. The blend is
 * {@link SkinningSteps#blendMatrices}'s formula and the normal matrix
 * {@link SkinningSteps#signedCofactor}'s, in the same order (so the same bits), written in locals:
 * LBS does so little per point that passing the 12 blended floats through a scratch array, as the
 * other kernels do, costs a measurable share of a frame, where in registers they cost nothing;
 * Java has no other way to return several values from a method.
 */
public final class ScalarLbsSkinner extends AbstractSkinner {
    private final float[] positions;
    private final float[] restNormals;
    private final int[] joints;
    private final float[] weights;
    private final int width;

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
        skinRange(palette, false, outPositions, outNormals, null, from, to);
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        skinRange(palette, true, null, null, outDeformations, from, to);
    }

    /**
     * Points {@code [from, to)}: the blend {@code B = sum_k w_k M_(j_k)} and {@code p' = B p},
     * then with {@code deformations} the deformation into {@code outDeformations}, else the
     * position and normal into {@code outPositions} and {@code outNormals}.
     */
    private void skinRange(JointPalette palette, boolean deformations, float[] outPositions, float[] outNormals,
            float[] outDeformations, int from, int to) {
        final float[] mat = palette.matrices();
        final boolean exactNormals = normals == NormalTransform.INVERSE_TRANSPOSE;
        final boolean mirror = exactNormals && palette.mirrorsMatrices();
        for (int i = from; i < to; i++) {
            int o = width * i;
            float w = weights[o];
            int m = 12 * joints[o];
            float b0 = w * mat[m], b1 = w * mat[m + 1], b2 = w * mat[m + 2], b3 = w * mat[m + 3];
            float b4 = w * mat[m + 4], b5 = w * mat[m + 5], b6 = w * mat[m + 6], b7 = w * mat[m + 7];
            float b8 = w * mat[m + 8], b9 = w * mat[m + 9], b10 = w * mat[m + 10], b11 = w * mat[m + 11];
            for (int k = 1; k < width; k++) {
                w = weights[o + k];
                m = 12 * joints[o + k];
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
            int v = 3 * i;
            float px = positions[v], py = positions[v + 1], pz = positions[v + 2];
            float x = b0 * px + b1 * py + b2 * pz + b3;
            float y = b4 * px + b5 * py + b6 * pz + b7;
            float z = b8 * px + b9 * py + b10 * pz + b11;
            if (deformations) {
                Deformations.putCofactor(outDeformations, DEFORMATION_FLOATS * i, exactNormals, mirror, b0, b1, b2, b4,
                        b5, b6, b8, b9, b10, x, y, z);
            } else {
                Deformations.putPointCofactor(outPositions, outNormals, v, restNormals, exactNormals, mirror, b0, b1,
                        b2, b4, b5, b6, b8, b9, b10, x, y, z);
            }
        }
    }
}
