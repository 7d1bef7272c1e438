package org.skinlab.skinning;

import java.util.Arrays;

/**
 * The rest-pose surface over which {@link CentresOfRotation} integrates weight similarity: per
 * triangle its corners, area, the joints any corner weights (its support) with each corner's
 * weight on them, and how finely it is integrated.
 *
 * <p><b>Subdivision</b> (Le and Hodgins 2016: the mesh is subdivided until the weights of the two
 * ends of every edge are at most epsilon apart; the Radium Engine's implementation does the same). A triangle whose corners' weight
 * vectors differ by up to {@code d} (Euclidean distance, the largest of its three edges) is cut
 * into the {@code n x n} grid of congruent sub-triangles with {@code n = ceil(d / epsilon)}, so
 * every sub-edge's ends differ by at most epsilon; weights are linear over the triangle, so a
 * sub-triangle's mean weight is the weight at its centroid. Per triangle rather than by splitting
 * shared edges: the same integral, with no connectivity needed (docs/references.md compares the
 * two).
 *
 * <p><b>Candidates.</b> Similarity needs two joints that both the point and the triangle weight,
 * so {@link #candidates} lists, per point, only the triangles whose support shares two of the
 * point's joints (from a per-joint index): the work per point follows the triangles around its
 * joints, not the whole mesh.
 */
final class SimilarityTriangles {
    final int count;
    /** Corner positions a, b, c: 9 per triangle. */
    final double[] corners;
    /** Area of each sub-triangle: the triangle's area over n^2. */
    final double[] subArea;
    /** Segments per edge of each triangle's grid (1: the triangle itself). */
    final int[] segments;
    /** Per triangle {@code [start[t], start[t + 1])} indexes its support in the arrays below. */
    final int[] start;
    final int[] joints;
    /** Per support entry the three corners' weights: wa, wb, wc. */
    final float[] cornerWeights;
    final int maxSupport;
    /** Per joint, the triangles whose support has it: {@code [jointStart[j], jointStart[j + 1])} of jointTriangles. */
    private final int[] jointStart;
    private final int[] jointTriangles;

    SimilarityTriangles(SkinnedGeometry g, int[] triangles, double epsilon) {
        count = triangles.length / 3;
        corners = new double[9 * count];
        subArea = new double[count];
        segments = new int[count];
        start = new int[count + 1];
        int k = g.influencesPerPoint();
        int[] gj = g.jointArray();
        float[] gw = g.weightArray();
        float[] rest = g.positionArray();
        int[] supportJoints = new int[3 * k];
        float[] supportWeights = new float[9 * k];
        int[] allJoints = new int[3 * k * Math.max(1, count)];
        float[] allWeights = new float[9 * k * Math.max(1, count)];
        int used = 0;
        int most = 0;
        for (int t = 0; t < count; t++) {
            for (int corner = 0; corner < 3; corner++) {
                int v = triangles[3 * t + corner];
                for (int d = 0; d < 3; d++) {
                    corners[9 * t + 3 * corner + d] = rest[3 * v + d];
                }
            }
            subArea[t] = area(corners, 9 * t);
            // Merge the corners' influences: each distinct joint once, with each corner's weight.
            int m = 0;
            Arrays.fill(supportWeights, 0f);
            for (int corner = 0; corner < 3; corner++) {
                int v = triangles[3 * t + corner];
                for (int e = 0; e < k; e++) {
                    float w = gw[k * v + e];
                    if (w <= 0) {
                        continue;
                    }
                    int j = gj[k * v + e];
                    int q = 0;
                    while (q < m && supportJoints[q] != j) {
                        q++;
                    }
                    if (q == m) {
                        supportJoints[m++] = j;
                    }
                    supportWeights[3 * q + corner] += w;
                }
            }
            int n = segments(supportWeights, m, epsilon);
            segments[t] = n;
            subArea[t] /= (double) n * n;
            start[t] = used;
            System.arraycopy(supportJoints, 0, allJoints, used, m);
            System.arraycopy(supportWeights, 0, allWeights, 3 * used, 3 * m);
            used += m;
            most = Math.max(most, m);
        }
        start[count] = used;
        joints = Arrays.copyOf(allJoints, used);
        cornerWeights = Arrays.copyOf(allWeights, 3 * used);
        maxSupport = Math.max(1, most);

        jointStart = new int[g.jointCount() + 1];
        for (int e = 0; e < used; e++) {
            jointStart[joints[e] + 1]++;
        }
        for (int j = 0; j < g.jointCount(); j++) {
            jointStart[j + 1] += jointStart[j];
        }
        jointTriangles = new int[used];
        int[] fill = Arrays.copyOf(jointStart, g.jointCount());
        for (int t = 0; t < count; t++) {
            for (int e = start[t]; e < start[t + 1]; e++) {
                jointTriangles[fill[joints[e]]++] = t;
            }
        }
    }

    /** How many triangles are integrated over after subdivision (the sum of n^2). */
    long integrationTriangles() {
        long total = 0;
        for (int n : segments) {
            total += (long) n * n;
        }
        return total;
    }

    /**
     * The triangles sharing at least two of {@code pointJoints[0..size)} (distinct joints) with
     * their support, into {@code out}; returns how many. {@code hits} is the caller's scratch of
     * {@link #count} zeros, left as zeros.
     */
    int candidates(int[] pointJoints, int size, byte[] hits, int[] out) {
        int found = 0;
        for (int a = 0; a < size; a++) {
            int j = pointJoints[a];
            for (int e = jointStart[j]; e < jointStart[j + 1]; e++) {
                int t = jointTriangles[e];
                if (hits[t] < 2 && ++hits[t] == 2) {
                    out[found++] = t;
                }
            }
        }
        for (int a = 0; a < size; a++) {
            int j = pointJoints[a];
            for (int e = jointStart[j]; e < jointStart[j + 1]; e++) {
                hits[jointTriangles[e]] = 0;
            }
        }
        // Triangle order, so that the sums do not depend on the order of the point's joints.
        Arrays.sort(out, 0, found);
        return found;
    }

    /** Segments per edge so that no sub-edge's ends differ by more than epsilon. */
    private static int segments(float[] cornerWeights, int m, double epsilon) {
        double ab = 0;
        double bc = 0;
        double ca = 0;
        for (int q = 0; q < m; q++) {
            double a = cornerWeights[3 * q];
            double b = cornerWeights[3 * q + 1];
            double c = cornerWeights[3 * q + 2];
            ab += (a - b) * (a - b);
            bc += (b - c) * (b - c);
            ca += (c - a) * (c - a);
        }
        double d = Math.sqrt(Math.max(ab, Math.max(bc, ca)));
        return Math.max(1, (int) Math.ceil(d / epsilon));
    }

    private static double area(double[] c, int o) {
        double abx = c[o + 3] - c[o];
        double aby = c[o + 4] - c[o + 1];
        double abz = c[o + 5] - c[o + 2];
        double acx = c[o + 6] - c[o];
        double acy = c[o + 7] - c[o + 1];
        double acz = c[o + 8] - c[o + 2];
        double x = aby * acz - abz * acy;
        double y = abz * acx - abx * acz;
        double z = abx * acy - aby * acx;
        return 0.5 * Math.sqrt(x * x + y * y + z * z);
    }
}
