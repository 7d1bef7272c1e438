package org.skinlab.skinning;

/**
 * The per-point frame record of {@link Skinner#skinDeformations} (16 floats: two columns of the normal
 * matrix N, the deformed position, N's last column, each padded to four) and the blends the scalar
 * kernels share. Plain Java.
 */
final class Deformations {
    private Deformations() {
    }

    /**
     * {@code b = sum_k w_k M_(j_k)} over the {@code width} influences at {@code o}: 12 floats,
     * row-major 3x4, into {@code b}. {@code matrices} holds 12 floats per joint.
     */
    static void blendMatrices(float[] matrices, int[] joints, float[] weights, int o, int width, float[] b, int bo) {
        float w = weights[o];
        int m = 12 * joints[o];
        for (int c = 0; c < 12; c++) {
            b[bo + c] = w * matrices[m + c];
        }
        for (int k = 1; k < width; k++) {
            w = weights[o + k];
            m = 12 * joints[o + k];
            for (int c = 0; c < 12; c++) {
                b[bo + c] += w * matrices[m + c];
            }
        }
    }

    /**
     * The normal matrix of the row-major 3x4 matrix at {@code a[ao]}: its cofactor matrix, times the
     * sign of its determinant when {@code signed}, row-major 3x3 into {@code out[oo..oo+9)}.
     */
    static void signedCofactor(float[] a, int ao, boolean signed, float[] out, int oo) {
        float a00 = a[ao], a01 = a[ao + 1], a02 = a[ao + 2];
        float a10 = a[ao + 4], a11 = a[ao + 5], a12 = a[ao + 6];
        float a20 = a[ao + 8], a21 = a[ao + 9], a22 = a[ao + 10];
        float c00 = a11 * a22 - a21 * a12, c01 = a12 * a20 - a22 * a10, c02 = a10 * a21 - a20 * a11;
        float s = signed ? Math.copySign(1f, a00 * c00 + a01 * c01 + a02 * c02) : 1f;
        out[oo] = s * c00;
        out[oo + 1] = s * c01;
        out[oo + 2] = s * c02;
        out[oo + 3] = s * (a21 * a02 - a01 * a22);
        out[oo + 4] = s * (a22 * a00 - a02 * a20);
        out[oo + 5] = s * (a20 * a01 - a00 * a21);
        out[oo + 6] = s * (a01 * a12 - a11 * a02);
        out[oo + 7] = s * (a02 * a10 - a12 * a00);
        out[oo + 8] = s * (a00 * a11 - a10 * a01);
    }

    /**
     * Writes the frame at {@code o}: position {@code (px, py, pz)} and the normal matrix of the
     * row-major linear part {@code a}: with {@code cofactor}, its cofactor matrix, times the sign of
     * its determinant when {@code signed} (the palette mirrors: see
     * {@link JointPalette#mirrorsMatrices()}), otherwise {@code a} itself.
     */
    static void put(float[] f, int o, boolean cofactor, boolean signed, float a00, float a01, float a02, float a10, float a11,
            float a12, float a20, float a21, float a22, float px, float py, float pz) {
        if (cofactor) {
            float c00 = a11 * a22 - a21 * a12, c01 = a12 * a20 - a22 * a10, c02 = a10 * a21 - a20 * a11;
            float c10 = a21 * a02 - a01 * a22, c11 = a22 * a00 - a02 * a20, c12 = a20 * a01 - a00 * a21;
            float c20 = a01 * a12 - a11 * a02, c21 = a02 * a10 - a12 * a00, c22 = a00 * a11 - a10 * a01;
            float s = signed ? Math.copySign(1f, a00 * c00 + a01 * c01 + a02 * c02) : 1f;
            a00 = s * c00;
            a01 = s * c01;
            a02 = s * c02;
            a10 = s * c10;
            a11 = s * c11;
            a12 = s * c12;
            a20 = s * c20;
            a21 = s * c21;
            a22 = s * c22;
        }
        f[o] = a00;
        f[o + 1] = a10;
        f[o + 2] = a20;
        f[o + 3] = 0f;
        f[o + 4] = a01;
        f[o + 5] = a11;
        f[o + 6] = a21;
        f[o + 7] = 0f;
        f[o + 8] = px;
        f[o + 9] = py;
        f[o + 10] = pz;
        f[o + 11] = 0f;
        f[o + 12] = a02;
        f[o + 13] = a12;
        f[o + 14] = a22;
        f[o + 15] = 0f;
    }

    /**
     * Writes point i from its deformed position {@code d[0..3)} and normal matrix {@code d[3..12)}
     * (row-major, applied to the rest normal), as the kernels that compute a per-point frame do in
     * {@link Skinner#skin}: the normal renormalised when {@code renormalise} (exact normals).
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
