package org.skinlab.skinning;

/**
 * The second half of skinning each position once: derives a geometry's points from the
 * deformations of the positions they carry ({@link Skinner#skinDeformations}). Per point {@code i}
 * with deformation {@code f = deformationOfPoint[i]}: the position is the deformation's, the normal
 * is {@code N_f n_i} for the point's own rest normal, renormalised when asked (zero stays zero).
 * An expansion is bound to one geometry's mapping and rest normals (so it may keep them in
 * whatever layout suits it) and holds no per-call state: disjoint ranges may run on different
 * threads at once. Core's implementation is {@link #scalar}; a {@link SkinnerProvider} may offer a
 * faster one.
 */
public interface DeformationExpansion {
    /**
     * Writes 3 floats per point {@code [from, to)} into {@code outPositions} and {@code outNormals}
     * at {@code 3 * point}.
     *
     * @param deformations {@link Skinner#DEFORMATION_FLOATS} floats per deformation
     * @param normalise    scale each normal to unit length (the exact normal rule)
     * @param outPositions receives the deformed positions, 3 floats per point
     * @param outNormals   receives each point's rest normal moved by its deformation's normal matrix,
     *                     3 floats per point
     * @param from         the first point to write
     * @param to           one past the last point to write
     */
    void expand(float[] deformations, float[] outPositions, float[] outNormals, int from, int to, boolean normalise);

    /**
     * A short name for reports.
     *
     * @return the implementation's name, e.g. "scalar"
     */
    String implementation();

    /**
     * The plain-Java expansion (Android, and the reference for faster ones).
     *
     * @param deformationOfPoint the deformation of each point (read, not copied)
     * @param restNormals        3 floats per point (read, not copied)
     * @return a new expansion bound to these arrays
     */
    static DeformationExpansion scalar(int[] deformationOfPoint, float[] restNormals) {
        return new DeformationExpansion() {
            @Override
            public void expand(float[] deformations, float[] outPositions, float[] outNormals, int from, int to,
                    boolean normalise) {
                for (int i = from; i < to; i++) {
                    int f = Skinner.DEFORMATION_FLOATS * deformationOfPoint[i];
                    int v = 3 * i;
                    float nx = restNormals[v], ny = restNormals[v + 1], nz = restNormals[v + 2];
                    float x = deformations[f] * nx + deformations[f + 4] * ny + deformations[f + 12] * nz;
                    float y = deformations[f + 1] * nx + deformations[f + 5] * ny + deformations[f + 13] * nz;
                    float z = deformations[f + 2] * nx + deformations[f + 6] * ny + deformations[f + 14] * nz;
                    if (normalise) {
                        float len2 = x * x + y * y + z * z;
                        float inv = len2 > 0f ? (float) (1.0 / Math.sqrt(len2)) : 0f;
                        x *= inv;
                        y *= inv;
                        z *= inv;
                    }
                    outNormals[v] = x;
                    outNormals[v + 1] = y;
                    outNormals[v + 2] = z;
                    outPositions[v] = deformations[f + 8];
                    outPositions[v + 1] = deformations[f + 9];
                    outPositions[v + 2] = deformations[f + 10];
                }
            }

            @Override
            public String implementation() {
                return "scalar";
            }
        };
    }
}
