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
 * formula (dense weight vectors, every ordered joint pair j != k, double precision, no code shared
 * with {@link CentersOfRotation}), and against what they mean: on the cylinders the centre of a
 * point in the blend region lies on the axis, at about the point's height (the rings of equal
 * weights around it).
 */
class CentersOfRotationTest {
    private static SkinnedGeometry geometry(String asset) throws Exception {
        return SkinnedModel.of(ColladaImporter.read(TestPaths.asset(asset))).geometries().get(0);
    }

    /** Le and Hodgins 2016, eq. 5 and 4, written out as printed. */
    private static double[] reference(SkinnedGeometry g, int point, double sigma) {
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
        double den = 0;
        for (int t = 0; t < tri.length; t += 3) {
            double[] wt = new double[joints];
            double[] c = new double[3];
            for (int corner = 0; corner < 3; corner++) {
                for (int j = 0; j < joints; j++) {
                    wt[j] += w[tri[t + corner]][j] / 3;
                }
                for (int d = 0; d < 3; d++) {
                    c[d] += x[3 * tri[t + corner] + d] / 3.0;
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
                ab[d] = x[3 * tri[t + 1] + d] - x[3 * tri[t] + d];
                ac[d] = x[3 * tri[t + 2] + d] - x[3 * tri[t] + d];
            }
            double cx = ab[1] * ac[2] - ab[2] * ac[1];
            double cy = ab[2] * ac[0] - ab[0] * ac[2];
            double cz = ab[0] * ac[1] - ab[1] * ac[0];
            double area = 0.5 * Math.sqrt(cx * cx + cy * cy + cz * cz);
            for (int d = 0; d < 3; d++) {
                num[d] += s * area * c[d];
            }
            den += s * area;
        }
        if (den == 0) {
            return new double[] {x[3 * point], x[3 * point + 1], x[3 * point + 2]};
        }
        return new double[] {num[0] / den, num[1] / den, num[2] / den};
    }

    private static void assertMatchesReference(String asset, int step) throws Exception {
        SkinnedGeometry g = geometry(asset);
        float[] c = CentersOfRotation.compute(g, CentersOfRotation.DEFAULT_SIGMA, CentersOfRotation.Progress.NONE);
        assertEquals(3 * g.pointCount(), c.length);
        for (int p = 0; p < g.vertexCount(); p += step) {
            double[] r = reference(g, p, CentersOfRotation.DEFAULT_SIGMA);
            for (int d = 0; d < 3; d++) {
                // Float output of a double sum: a few float ulps of a model about 2 units tall.
                assertEquals(r[d], c[3 * p + d], 2e-6, asset + " point " + p + " axis " + d);
            }
        }
    }

    @Test
    void theBendCylinderMatchesThePlainFormula() throws Exception {
        assertMatchesReference("cylinders/cylinder-bend.dae", 7);
    }

    @Test
    void theTentacleMatchesThePlainFormula() throws Exception {
        // Eight joints along a chain, three influences per position.
        assertMatchesReference("creatures/tentacle-wave.dae", 5);
    }

    @Test
    void blendedPointsTurnAboutTheAxis() throws Exception {
        // cylinder-twist-high: axis z from 0 to 2, joint at z = 1, radius 0.25 (assets/README.md).
        SkinnedGeometry g = geometry("cylinders/cylinder-twist-high.dae");
        float[] c = CentersOfRotation.compute(g, CentersOfRotation.DEFAULT_SIGMA, CentersOfRotation.Progress.NONE);
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
        CentersOfRotation.compute(g, 0.1, (done, all) -> {
            last.accumulateAndGet(done, Math::max);
            total[0] = all;
        });
        assertEquals(total[0], last.get());
        assertThrows(IllegalArgumentException.class, () -> CentersOfRotation.compute(g, 0, CentersOfRotation.Progress.NONE));
    }
}
