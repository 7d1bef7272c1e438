package org.skinlab.skinning;

/**
 * Linear Blend Skinning in plain Java, any number of influences: per point
 * {@code M = sum_k w_k M_(j_k)}, {@code p' = M p}, and the normal by {@link NormalTransform}.
 * The portable kernel (Android) and the reference the SIMD kernels are tested against.
 *
 * <p>{@link #skin} and {@link #skinDeformations} share the blend's and the normal matrix's
 * formulas, {@link SkinningSteps#blendMatrices} and {@link SkinningSteps#signedCofactor}, in the
 * same order (so the same bits); each writes the blend in locals in its own loop, and
 * {@link #skinDeformations} its record through {@link Deformations#putCofactor}. LBS does so little per point that passing the
 * 12 blended floats through a scratch array, as the other kernels do, costs a measurable share of
 * a frame, where in registers they cost nothing (Java has no other way to return several values
 * from a method); and one loop for both, choosing the output by a flag, leaves C2 one profile for
 * the two: whichever output a JVM asks for second runs measurably slower. For the same reason
 * positions only ({@link NormalTransform#NONE}) have a loop of their own, {@link #skinPositions},
 * chosen once per call: the same blend and position expressions, so the same bits.
 */
public final class ScalarLbsSkinner extends AbstractSkinner {
    private final float[] positions;
    private final float[] restNormals;
    private final int[] joints;
    private final float[] weights;
    private final int width;

    /**
     * A skinner that reads the geometry's arrays in place (a morphed rest shape is followed as is).
     *
     * @param geometry the geometry to skin
     * @param normals  how normals move, or {@link NormalTransform#NONE} for positions only
     */
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
        if (normals == NormalTransform.NONE) {
            skinPositions(palette.matrices(), positions, joints, weights, width, outPositions, from, to);
            return;
        }
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
            outPositions[v] = b0 * px + b1 * py + b2 * pz + b3;
            outPositions[v + 1] = b4 * px + b5 * py + b6 * pz + b7;
            outPositions[v + 2] = b8 * px + b9 * py + b10 * pz + b11;
            float nx = restNormals[v], ny = restNormals[v + 1], nz = restNormals[v + 2];
            if (exactNormals) {
                // Columns c0 = (b0 b4 b8), c1 = (b1 b5 b9), c2 = (b2 b6 b10); the inverse-transpose
                // times det has columns c1 x c2, c2 x c0, c0 x c1.
                float k00 = b5 * b10 - b9 * b6, k01 = b6 * b8 - b10 * b4, k02 = b4 * b9 - b8 * b5;
                float rx = k00 * nx + k01 * ny + k02 * nz;
                float ry = (b9 * b2 - b1 * b10) * nx + (b10 * b0 - b2 * b8) * ny + (b8 * b1 - b0 * b9) * nz;
                float rz = (b1 * b6 - b5 * b2) * nx + (b2 * b4 - b6 * b0) * ny + (b0 * b5 - b4 * b1) * nz;
                float len2 = rx * rx + ry * ry + rz * rz;
                // The cofactor is det times the inverse-transpose: under a mirroring blend (det < 0)
                // it would turn the normal inwards, so with a mirroring palette the sign of det goes
                // into the scale.
                float det = mirror ? b0 * k00 + b1 * k01 + b2 * k02 : 1f;
                float inv = len2 > 0f ? Math.copySign((float) (1.0 / Math.sqrt(len2)), det) : 0f;
                outNormals[v] = rx * inv;
                outNormals[v + 1] = ry * inv;
                outNormals[v + 2] = rz * inv;
            } else {
                outNormals[v] = b0 * nx + b1 * ny + b2 * nz;
                outNormals[v + 1] = b4 * nx + b5 * ny + b6 * nz;
                outNormals[v + 2] = b8 * nx + b9 * ny + b10 * nz;
            }
        }
    }

    /**
     * {@link #skin} without normals: {@code p' = (sum_k w_k M_(j_k)) p}, the normals not read. Static,
     * the arrays as arguments: compiled so, C2 on JDK 25 ran it a quarter faster in most runs than
     * the same loop as an instance method reading the fields.
     */
    private static void skinPositions(float[] mat, float[] positions, int[] joints, float[] weights, int width,
            float[] outPositions, int from, int to) {
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
            outPositions[v] = b0 * px + b1 * py + b2 * pz + b3;
            outPositions[v + 1] = b4 * px + b5 * py + b6 * pz + b7;
            outPositions[v + 2] = b8 * px + b9 * py + b10 * pz + b11;
        }
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        if (normals == NormalTransform.NONE) {
            throw noDeformationsWithoutNormals();
        }
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
            Deformations.putCofactor(outDeformations, DEFORMATION_FLOATS * i, exactNormals, mirror, b0, b1, b2, b4, b5,
                    b6, b8, b9, b10, b0 * px + b1 * py + b2 * pz + b3, b4 * px + b5 * py + b6 * pz + b7,
                    b8 * px + b9 * py + b10 * pz + b11);
        }
    }
}
