package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.testing.TestPaths;

/**
 * The centres of rotation against a second, deliberately plain implementation of the paper's
 * formula and its subdivision (dense weight vectors, every ordered joint pair j != k, every
 * triangle, sub-triangles built from their grid vertices, double precision, no code shared with
 * {@link CentresOfRotation}), against an exact centre derived by hand, and against what they mean: on the cylinders the centre of a
 * point in the blend region lies on the axis, at about the point's height (the rings of equal
 * weights around it).
 */
class CentresOfRotationTest {
    private static SkinnedGeometry geometry(String asset) throws Exception {
        return SkinnedModel.of(ColladaImporter.read(TestPaths.asset(asset))).geometries().get(0);
    }

    /**
     * Le and Hodgins 2016, eq. 5 and 4, written out as printed, over the mesh subdivided as the
     * paper integrates: each triangle into the n x n grid of sub-triangles, n the fewest segments
     * that keep every sub-edge's weight difference within epsilon; each sub-triangle built from
     * its three grid vertices (position and dense weight vector interpolated), its area from its
     * own cross product.
     */
    private static double[] reference(SkinnedGeometry g, int point, double sigma, double epsilon) {
        int joints = g.jointCount();
        int k = g.influencesPerPoint();
        double[][] w = new double[g.vertexCount()][joints];
        for (int v = 0; v < g.vertexCount(); v++) {
            for (int a = 0; a < k; a++) {
                w[v][g.jointArray()[k * v + a]] += g.weightArray()[k * v + a];
            }
        }
        double[] wp = new double[joints];
        for (int a = 0; a < k; a++) {
            wp[g.jointArray()[k * point + a]] += g.weightArray()[k * point + a];
        }
        int[] tri = g.mesh().triangles();
        float[] x = g.positionArray();
        double[] num = new double[3];
        double[] den = new double[1];
        for (int t = 0; t < tri.length; t += 3) {
            double[][] p = new double[3][3];
            for (int corner = 0; corner < 3; corner++) {
                for (int d = 0; d < 3; d++) {
                    p[corner][d] = x[3 * tri[t + corner] + d];
                }
            }
            double[][] cw = {w[tri[t]], w[tri[t + 1]], w[tri[t + 2]]};
            double longest = Math.max(distance(cw[0], cw[1]), Math.max(distance(cw[1], cw[2]), distance(cw[2], cw[0])));
            int n = Math.max(1, (int) Math.ceil(longest / epsilon));
            for (int i = 0; i < n; i++) {
                for (int j = 0; i + j < n; j++) {
                    addSubTriangle(p, cw, n, new int[][] {{i, j}, {i + 1, j}, {i, j + 1}}, wp, sigma, num, den);
                    if (i + j + 1 < n) {
                        addSubTriangle(p, cw, n, new int[][] {{i + 1, j}, {i, j + 1}, {i + 1, j + 1}}, wp, sigma, num, den);
                    }
                }
            }
        }
        if (den[0] == 0) {
            return new double[] {x[3 * point], x[3 * point + 1], x[3 * point + 2]};
        }
        return new double[] {num[0] / den[0], num[1] / den[0], num[2] / den[0]};
    }

    private static double distance(double[] a, double[] b) {
        double s = 0;
        for (int j = 0; j < a.length; j++) {
            s += (a[j] - b[j]) * (a[j] - b[j]);
        }
        return Math.sqrt(s);
    }

    /** One sub-triangle with grid vertices (i, j) = a + i/n (b - a) + j/n (c - a). */
    private static void addSubTriangle(double[][] p, double[][] cw, int n, int[][] grid, double[] wp, double sigma,
            double[] num, double[] den) {
        int joints = wp.length;
        double[][] q = new double[3][3];
        double[] wt = new double[joints];
        double[] c = new double[3];
        for (int v = 0; v < 3; v++) {
            double bi = grid[v][0] / (double) n;
            double bj = grid[v][1] / (double) n;
            for (int d = 0; d < 3; d++) {
                q[v][d] = p[0][d] + bi * (p[1][d] - p[0][d]) + bj * (p[2][d] - p[0][d]);
                c[d] += q[v][d] / 3;
            }
            for (int j = 0; j < joints; j++) {
                wt[j] += (cw[0][j] + bi * (cw[1][j] - cw[0][j]) + bj * (cw[2][j] - cw[0][j])) / 3;
            }
        }
        double s = 0;
        for (int j = 0; j < joints; j++) {
            for (int l = 0; l < joints; l++) {
                if (j != l) {
                    double e = wp[j] * wt[l] - wp[l] * wt[j];
                    s += wp[j] * wp[l] * wt[j] * wt[l] * Math.exp(-e * e / (sigma * sigma));
                }
            }
        }
        double[] ab = new double[3];
        double[] ac = new double[3];
        for (int d = 0; d < 3; d++) {
            ab[d] = q[1][d] - q[0][d];
            ac[d] = q[2][d] - q[0][d];
        }
        double cx = ab[1] * ac[2] - ab[2] * ac[1];
        double cy = ab[2] * ac[0] - ab[0] * ac[2];
        double cz = ab[0] * ac[1] - ab[1] * ac[0];
        double area = 0.5 * Math.sqrt(cx * cx + cy * cy + cz * cz);
        for (int d = 0; d < 3; d++) {
            num[d] += s * area * c[d];
        }
        den[0] += s * area;
    }

    private static void assertMatchesReference(String asset, int step, double epsilon) throws Exception {
        SkinnedGeometry g = geometry(asset);
        float[] c = CentresOfRotation.compute(g, new CentresOfRotation.Parameters(0.1, epsilon),
                CentresOfRotation.Progress.NONE);
        assertEquals(3 * g.pointCount(), c.length);
        for (int p = 0; p < g.vertexCount(); p += step) {
            double[] r = reference(g, p, 0.1, epsilon);
            for (int d = 0; d < 3; d++) {
                // Float output of a double sum: a few float ulps of a model about 2 units tall.
                assertEquals(r[d], c[3 * p + d], 2e-6, asset + " point " + p + " axis " + d);
            }
        }
    }

    @Test
    void theBendCylinderMatchesThePlainFormula() throws Exception {
        // Dense rings at the joint: no edge's weights differ by 0.1, nothing is subdivided.
        assertMatchesReference("cylinders/cylinder-bend.dae", 7, 0.1);
    }

    @Test
    void theCoarseTwistCylinderMatchesThePlainFormulaSubdividedOrNot() throws Exception {
        // Rings 0.118 m apart across the joint: weights jump by up to 0.2 along an edge.
        SkinnedGeometry g = geometry("cylinders/cylinder-twist-low.dae");
        assertTrue(CentresOfRotation.integrationTriangles(g, CentresOfRotation.Parameters.DEFAULT)
                > 2L * g.mesh().triangleCount(), "the coarse rings are subdivided");
        assertMatchesReference("cylinders/cylinder-twist-low.dae", 3, 0.1);
        assertMatchesReference("cylinders/cylinder-twist-low.dae", 3, Double.POSITIVE_INFINITY);
    }

    @Test
    void theTentacleMatchesThePlainFormula() throws Exception {
        // Eight joints along a chain, three influences per position.
        assertMatchesReference("creatures/tentacle-wave.dae", 5, 0.1);
    }

    @Test
    void theDefaultCharacterMatchesThePlainFormula() throws Exception {
        // 19 joints, up to 4 influences, weights from 0 to 1 across single edges.
        assertMatchesReference("characters/humanoid-walk.dae", 29, 0.1);
    }

    /**
     * A hand-derived case: a rectangle of 2 triangles, x in [0, 2], y in [0, 1], its weights
     * linear in x from (1, 0) to (0, 1), and a point weighted (0.3, 0.7) that lies on no triangle.
     * Along x the similarity is {@code s(xi) = 2 * 0.21 xi (1 - xi) exp(-(xi - 0.7)^2 / sigma^2)}
     * (xi = x / 2; the weights' cross term 0.3 xi - 0.7 (1 - xi) = xi - 0.7), constant along y,
     * so the exact centre is {@code x* = 2 int xi s / int s}, {@code y* = 0.5}: a one-dimensional
     * quadrature, no triangles involved. Subdivided at the paper's epsilon (15 segments per edge)
     * the sub-triangles' centroids are a midpoint rule, whose error for an integrand that nearly
     * vanishes with its slope at both ends is far below the float the centre is returned in
     * (observed 2e-8, at epsilon 0.02 too: the float's rounding); allowed 1e-6. The two triangles
     * alone put the centre 0.17 off.
     */
    @Test
    void subdivisionIntegratesALinearWeightRampToItsExactCentre() {
        float[] positions = {0, 0, 0, 2, 0, 0, 0, 1, 0, 2, 1, 0, 5, 5, 5};
        int[] joints = {0, 1, 0, 1, 0, 1, 0, 1, 0, 1};
        float[] weights = {1, 0, 0, 1, 1, 0, 0, 1, 0.3f, 0.7f};
        float[] identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        float[] bind = new float[32];
        System.arraycopy(identity, 0, bind, 0, 16);
        System.arraycopy(identity, 0, bind, 16, 16);
        SkinnedGeometry g = SkinnedGeometry.fromArrays(positions, new float[15], 2, joints, weights, bind);
        int[] triangles = {0, 1, 2, 1, 3, 2};

        double sigma = 0.1;
        int steps = 200_000; // Simpson's rule, far finer than the Gaussian
        double num = 0;
        double den = 0;
        for (int i = 0; i <= steps; i++) {
            double xi = i / (double) steps;
            double s = 0.42 * xi * (1 - xi) * Math.exp(-(xi - 0.7) * (xi - 0.7) / (sigma * sigma));
            double simpson = i == 0 || i == steps ? 1 : i % 2 == 1 ? 4 : 2;
            num += simpson * s * 2 * xi;
            den += simpson * s;
        }
        double exact = num / den;

        double[] error = new double[3];
        double[] epsilons = {Double.POSITIVE_INFINITY, 0.1, 0.02};
        for (int e = 0; e < 3; e++) {
            float[] c = CentresOfRotation.compute(g, triangles, new CentresOfRotation.Parameters(sigma, epsilons[e]),
                    CentresOfRotation.Progress.NONE);
            error[e] = Math.hypot(c[12] - exact, c[13] - 0.5);
            assertEquals(0, c[14], 1e-6);
        }
        System.out.printf("ramp: exact x %.6f; errors: no subdivision %.2e, epsilon 0.1 %.2e, 0.02 %.2e%n", exact,
                error[0], error[1], error[2]);
        assertTrue(error[0] > 0.1, "the two triangles alone: " + error[0]);
        assertTrue(error[1] < 1e-6, "epsilon 0.1: " + error[1] + " from the exact (" + exact + ", 0.5)");
        assertTrue(error[2] < 1e-6, "epsilon 0.02: " + error[2] + " from the exact (" + exact + ", 0.5)");
    }

    @Test
    void aGeometryFromArraysGetsTheModelsCentresFromTheTrianglesGivenApart() throws Exception {
        // What an engine integration does (integrations/jme): its mesh's arrays and index buffer, no
        // skinlab Mesh. The model's own geometry shares positions and computes per position; the
        // arrays' one computes per point: the same integral, so the same centres up to rounding.
        SkinnedGeometry model = geometry("characters/humanoid-walk.dae");
        SkinnedGeometry arrays = SkinnedGeometry.fromArrays(model.positionArray(), model.normalArray(),
                model.influencesPerPoint(), model.jointArray(), model.weightArray(), model.bindMatrixArray());
        float[] expected = CentresOfRotation.compute(model, CentresOfRotation.Parameters.DEFAULT,
                CentresOfRotation.Progress.NONE);
        float[] actual = CentresOfRotation.compute(arrays, model.mesh().triangles(), CentresOfRotation.Parameters.DEFAULT,
                CentresOfRotation.Progress.NONE);
        double worst = 0;
        for (int i = 0; i < expected.length; i++) {
            worst = Math.max(worst, Math.abs(expected[i] - actual[i]));
        }
        // The character is 1.8 m tall: a micrometre is float rounding of sums in another order.
        assertTrue(worst < 1e-6, "worst difference " + worst + " m");
        assertThrows(IllegalArgumentException.class, () -> CentresOfRotation.compute(arrays,
                new int[] {0, 1, model.pointCount()}, CentresOfRotation.Parameters.DEFAULT, CentresOfRotation.Progress.NONE));
        assertThrows(IllegalArgumentException.class, () -> CentresOfRotation.compute(arrays, new int[] {0, 1},
                CentresOfRotation.Parameters.DEFAULT, CentresOfRotation.Progress.NONE));
    }

    @Test
    void blendedPointsTurnAboutTheAxis() throws Exception {
        // cylinder-twist-high: axis z from 0 to 2, joint at z = 1, radius 0.25 (assets/README.md).
        SkinnedGeometry g = geometry("cylinders/cylinder-twist-high.dae");
        float[] c = CentresOfRotation.compute(g, CentresOfRotation.Parameters.DEFAULT, CentresOfRotation.Progress.NONE);
        int blended = 0;
        int k = g.influencesPerPoint();
        for (int p = 0; p < g.vertexCount(); p++) {
            float w1 = k > 1 ? g.weightArray()[k * p + 1] : 0;
            float[] x = g.positionArray();
            if (w1 > 0.05f) {
                blended++;
                double off = Math.hypot(c[3 * p], c[3 * p + 1]);
                assertTrue(off < 0.02, "point " + p + ": centre " + off + " from the axis");
                // Triangles with similar weights form the rings around the point's own height.
                assertEquals(x[3 * p + 2], c[3 * p + 2], 0.05, "point " + p + " centre height");
            } else if (w1 == 0) {
                // One influence: no centre, the point itself (LBS there).
                assertEquals(x[3 * p], c[3 * p]);
                assertEquals(x[3 * p + 2], c[3 * p + 2]);
            }
        }
        assertTrue(blended > 100, "blended points " + blended);
    }

    @Test
    void progressReachesTheTotal() throws Exception {
        SkinnedGeometry g = geometry("cylinders/cylinder-twist-low.dae");
        AtomicInteger last = new AtomicInteger();
        int[] total = new int[1];
        CentresOfRotation.compute(g, CentresOfRotation.Parameters.DEFAULT, (done, all) -> {
            last.accumulateAndGet(done, Math::max);
            total[0] = all;
        });
        assertEquals(total[0], last.get());
    }

    @Test
    void parametersOutsideTheirRangeAreRefused() {
        assertThrows(IllegalArgumentException.class, () -> new CentresOfRotation.Parameters(0, 0.1));
        assertThrows(IllegalArgumentException.class, () -> new CentresOfRotation.Parameters(Double.NaN, 0.1));
        assertThrows(IllegalArgumentException.class, () -> new CentresOfRotation.Parameters(0.1, 0.001));
        assertThrows(IllegalArgumentException.class, () -> new CentresOfRotation.Parameters(0.1, Double.NaN));
        new CentresOfRotation.Parameters(0.1, Double.POSITIVE_INFINITY);
    }
}
