package org.skinlab.skinning;

/**
 * The per-point records the scalar kernels write: the deformation of {@link Skinner#skinDeformations}
 * (16 floats: two columns of the normal matrix N, the deformed position, N's last column, each
 * padded to four) and the point of {@link Skinner#skin}. Both start from what every kernel computes
 * per point, its deformed position {@code d[0..3)} and normal matrix {@code d[3..12)}. Plain Java.
 */
final class Deformations {
    private Deformations() {
    }

    /**
     * Writes the deformation at {@code f[o]} from a point's deformed position {@code d[e..e+3)} and
     * normal matrix {@code d[e+3..e+12)} (row-major), as the kernels compute them.
     */
    static void put(float[] f, int o, float[] d, int e) {
        f[o] = d[e + 3];
        f[o + 1] = d[e + 6];
        f[o + 2] = d[e + 9];
        f[o + 3] = 0f;
        f[o + 4] = d[e + 4];
        f[o + 5] = d[e + 7];
        f[o + 6] = d[e + 10];
        f[o + 7] = 0f;
        f[o + 8] = d[e];
        f[o + 9] = d[e + 1];
        f[o + 10] = d[e + 2];
        f[o + 11] = 0f;
        f[o + 12] = d[e + 5];
        f[o + 13] = d[e + 8];
        f[o + 14] = d[e + 11];
        f[o + 15] = 0f;
    }

    /**
     * Writes the deformation at {@code f[o]}: position {@code (px, py, pz)} and the normal matrix of
     * the row-major linear part {@code a}: with {@code cofactor}, its cofactor matrix, times the sign
     * of its determinant when {@code signed} (the palette mirrors: see
     * {@link JointPalette#mirrorsMatrices()}), otherwise {@code a} itself. For
     * {@link ScalarLbsSkinner}, which keeps its blend in locals (its class comment says why):
     * {@link SkinningSteps#signedCofactor}'s formula on values. Split in three so that each part
     * stays within the bytecode size C2 inlines into a hot loop (325 bytes,
     * {@code -XX:FreqInlineSize}): a call per point with 16 floats as arguments costs more than the
     * point's stores.
     */
    static void putCofactor(float[] f, int o, boolean cofactor, boolean signed, float a00, float a01, float a02,
            float a10, float a11, float a12, float a20, float a21, float a22, float px, float py, float pz) {
        if (cofactor) {
            putSignedCofactor(f, o, signed, a00, a01, a02, a10, a11, a12, a20, a21, a22);
        } else {
            putNormalMatrix(f, o, a00, a01, a02, a10, a11, a12, a20, a21, a22);
        }
        f[o + 8] = px;
        f[o + 9] = py;
        f[o + 10] = pz;
        f[o + 11] = 0f;
    }

    /** The normal matrix of {@link #putCofactor} with {@code cofactor}: a's signed cofactor matrix. */
    private static void putSignedCofactor(float[] f, int o, boolean signed, float a00, float a01, float a02,
            float a10, float a11, float a12, float a20, float a21, float a22) {
        float c00 = a11 * a22 - a21 * a12, c01 = a12 * a20 - a22 * a10, c02 = a10 * a21 - a20 * a11;
        float c10 = a21 * a02 - a01 * a22, c11 = a22 * a00 - a02 * a20, c12 = a20 * a01 - a00 * a21;
        float c20 = a01 * a12 - a11 * a02, c21 = a02 * a10 - a12 * a00, c22 = a00 * a11 - a10 * a01;
        float s = signed ? Math.copySign(1f, a00 * c00 + a01 * c01 + a02 * c02) : 1f;
        putNormalMatrix(f, o, s * c00, s * c01, s * c02, s * c10, s * c11, s * c12, s * c20, s * c21, s * c22);
    }

    /**
     * The row-major normal matrix n into the deformation at {@code f[o]}: its columns, each padded
     * to four, at 0, 4 and 12 (the position's place, 8, is left to the caller).
     */
    private static void putNormalMatrix(float[] f, int o, float n00, float n01, float n02, float n10, float n11,
            float n12, float n20, float n21, float n22) {
        f[o] = n00;
        f[o + 1] = n10;
        f[o + 2] = n20;
        f[o + 3] = 0f;
        f[o + 4] = n01;
        f[o + 5] = n11;
        f[o + 6] = n21;
        f[o + 7] = 0f;
        f[o + 12] = n02;
        f[o + 13] = n12;
        f[o + 14] = n22;
        f[o + 15] = 0f;
    }

    /**
     * Writes point i from its deformed position {@code d[0..3)} and normal matrix {@code d[3..12)}
     * (row-major, applied to the rest normal): the normal renormalised when {@code renormalise}
     * (exact normals).
     */
    static void putPoint(float[] d, float[] restNormals, int i, boolean renormalise, float[] outPositions,
            float[] outNormals) {
        int v = 3 * i;
        outPositions[v] = d[0];
        outPositions[v + 1] = d[1];
        outPositions[v + 2] = d[2];
        float nx = restNormals[v], ny = restNormals[v + 1], nz = restNormals[v + 2];
        float mx = d[3] * nx + d[4] * ny + d[5] * nz;
        float my = d[6] * nx + d[7] * ny + d[8] * nz;
        float mz = d[9] * nx + d[10] * ny + d[11] * nz;
        if (renormalise) {
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
