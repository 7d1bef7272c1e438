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
