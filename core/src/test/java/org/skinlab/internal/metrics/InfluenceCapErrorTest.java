package org.skinlab.internal.metrics;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.collada.Fixtures;
import org.skinlab.model.Model;
import org.skinlab.model.Skin;
import org.skinlab.testing.TestPaths;
import org.skinlab.skinning.InfluenceView;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * {@link InfluenceCapError} against a direct computation written here from the formulas, in
 * double: each position's influences read from the {@link Skin} as the file wrote them (divided
 * by their sum; capped to the k heaviest, equal weights in file order, divided by the kept sum
 * when weight was lost), and per sample time LBS {@code sum w M p} and DQS (Kavan et al. 2008:
 * blended scale part, dual quaternions flipped onto the dominant influence's hemisphere,
 * normalised, applied) from the same palette the model computes (skinning matrices, and the
 * palette's dual quaternions and scale parts for DQS). It shares nothing with our skinners,
 * {@link SkinnedGeometry}'s influence arrays or {@link InfluenceView}.
 *
 * <p>Tolerance: {@value #TOLERANCE} of the rest size between the reported and the direct largest
 * distance, and between the direct distance at the reported position and time and the direct
 * largest (so the reported place is a worst one). Ours is two float skinnings subtracted (about
 * 1e-7 of the size each); the deviations measured are at most 1.1e-7 of the size.
 */
class InfluenceCapErrorTest {
    /** The methods this test is about (CoR has its own tests: CorSkinningTest). */
    private static final SkinningMethod[] LBS_AND_DQS = {SkinningMethod.LBS, SkinningMethod.DQS};

    static final double TOLERANCE = 2e-6;

    @Test
    void sampleTimesAreThirtyPerSecondFromTheStartThenTheEnd() {
        float[] one = InfluenceCapError.sampleTimes(0f, 1f);
        assertEquals(31, one.length);
        for (int i = 0; i < 30; i++) {
            assertEquals((float) (i / 30.0), one[i], 0f);
        }
        assertEquals(1f, one[30], 0f);
        // 0.1 s: 0, 1/30, 2/30, and 3/30 is the end itself (as a float), so it comes once.
        assertArrayEquals(new float[] {0f, (float) (1 / 30.0), (float) (2 / 30.0), 0.1f},
                InfluenceCapError.sampleTimes(0f, 0.1f), 0f);
        assertArrayEquals(new float[] {2f, (float) (2 + 1 / 30.0), 2.05f}, InfluenceCapError.sampleTimes(2f, 2.05f), 0f);
        assertArrayEquals(new float[] {0.5f}, InfluenceCapError.sampleTimes(0.5f, 0.5f), 0f);
    }

    @Test
    void handMadeChainAgreesWithTheDirectComputation() {
        Model model = Fixtures.resource("skin/capped-chain.dae");
        assertEquals(List.of(), model.warnings());
        List<String> lines = check(model, new int[] {1, 2, 3, 4, 5, 8});
        lines.forEach(System.out::println);
    }

    @Test
    void corpusCowboyAgreesWithTheDirectComputation() throws Exception {
        Path file = TestPaths.corpusFileOrSkip("S01_cowboy.dae");
        Model model = ColladaImporter.read(file);
        List<String> lines = check(model, new int[] {1, 2, 4, 6, 8});
        lines.forEach(System.out::println);
    }

    /**
     * What lets {@link InfluenceCapError} skip a view that drops no weight: skinned, it gives the
     * geometry's own positions bit for bit (LBS and DQS, scale phase included), at every sample.
     */
    @Test
    void aViewThatDropsNothingDeformsBitForBitAsTheGeometry() throws Exception {
        List<Model> models = new ArrayList<>(List.of(Fixtures.resource("skin/capped-chain.dae")));
        Optional<Path> cowboy = TestPaths.corpusFile("S01_cowboy.dae");
        if (cowboy.isPresent()) {
            models.add(ColladaImporter.read(cowboy.get()));
        } else {
            System.out.println("corpus absent: the cowboy not checked");
        }
        for (Model model : models) {
            SkinnedModel skinned = SkinnedModel.of(model);
            SkinnedGeometry g = skinned.geometries().get(0);
            for (int k : new int[] {g.influencesPerPoint(), g.influencesPerPoint() + 3}) {
                InfluenceView view = InfluenceView.of(g, k);
                assertEquals(0, view.cappedPointCount());
                SkinnedGeometry capped = SkinnedGeometry.fromArrays(g.positionArray(), g.normalArray(), k,
                        view.jointIndicesAsInts(), view.weights(), g.bindMatrixArray());
                for (float t : InfluenceCapError.sampleTimes(skinned.sampler().start(), skinned.sampler().end())) {
                    skinned.pose(t, RotationInterpolation.SLERP);
                    JointPalette palette = skinned.palette(0);
                    palette.prepareAll();
                    for (SkinningMethod m : LBS_AND_DQS) {
                        float[] a = new float[3 * g.pointCount()];
                        float[] b = new float[3 * g.pointCount()];
                        float[] normals = new float[3 * g.pointCount()];
                        Skinners.scalar(m, g, NormalTransform.BLENDED_MATRIX).skinAll(palette, a, normals);
                        Skinners.scalar(m, capped, NormalTransform.BLENDED_MATRIX).skinAll(palette, b, normals);
                        assertArrayEquals(a, b, 0f, model.source() + " k " + k + " " + m + " at " + t);
                    }
                }
            }
        }
    }

    /**
     * Measures the model's first clip with {@link InfluenceCapError} and directly, for each cap,
     * and checks they agree; returns one printable line per geometry and cap.
     */
    private static List<String> check(Model model, int[] caps) {
        SkinnedModel skinned = SkinnedModel.of(model);
        List<List<InfluenceCapError.Result>> measured = InfluenceCapError.measure(skinned, caps);
        SkinnedModel atRest = new SkinnedModel(model, null, NormalTransform.INVERSE_TRANSPOSE);
        List<String> lines = new ArrayList<>();
        boolean anyCapped = false;
        for (int g = 0; g < skinned.geometries().size(); g++) {
            Skin skin = skinned.geometries().get(g).instance().skin();
            if (skin == null) {
                continue;
            }
            Direct direct = new Direct(skin, skinned, atRest, g, caps);
            for (int c = 0; c < caps.length; c++) {
                InfluenceCapError.Result r = measured.get(g).get(c);
                String where = skin.controllerId() + ", k " + caps[c];
                assertEquals(caps[c], r.cap(), where);
                assertEquals(skin.maxInfluences(), r.influences(), where);
                assertEquals(direct.times.length, r.samples(), where);
                assertEquals(direct.size, r.size(), 1e-6 * direct.size, where + ": rest size");
                assertEquals(direct.cappedPositions[c], r.cappedPositions(), where);
                assertEquals(direct.maxDropped[c], r.maxDroppedWeight(), 3e-7, where);
                for (int m = 0; m < 2; m++) {
                    InfluenceCapError.Worst w = m == 0 ? r.lbs() : r.dqs();
                    String what = where + (m == 0 ? " LBS" : " DQS");
                    double largest = direct.largest(c, m);
                    if (caps[c] >= skin.maxInfluences()) {
                        // Nothing is dropped: both sides deform exactly alike.
                        assertEquals(0.0, largest, 0.0, what);
                        assertEquals(0.0, w.distance(), 0.0, what);
                        assertEquals(-1, w.position(), what);
                        assertTrue(Float.isNaN(w.time()), what);
                        continue;
                    }
                    anyCapped = true;
                    assertEquals(largest, w.distance(), TOLERANCE * direct.size, what);
                    assertEquals(w.distance() / r.size(), w.relative(), 1e-12, what);
                    assertEquals(largest, direct.at(c, m, w.position(), w.time()), TOLERANCE * direct.size,
                            what + ": the reported position " + w.position() + " at " + w.time() + " s");
                    lines.add(String.format(Locale.ROOT, "%s %s: %.6g, %.3g of %.4g, position %d at %.4f s;"
                            + " direct %.6g (off by %.1e of the size)", model.source(), what, w.distance(), w.relative(),
                            r.size(), w.position(), w.time(), largest, Math.abs(largest - w.distance()) / r.size()));
                }
            }
        }
        assertTrue(anyCapped, "no cap below the influence count: nothing was compared");
        return lines;
    }

    /** The direct computation for one geometry: every distance, per cap, method, time and position. */
    private static final class Direct {
        final float[] times;
        final double size;
        /** [cap][method][time][position] */
        final double[][][][] distances;
        /** Per cap: positions that lose weight, and the most weight one loses (of a sum of 1). */
        final int[] cappedPositions;
        final double[] maxDropped;

        Direct(Skin skin, SkinnedModel model, SkinnedModel atRest, int g, int[] caps) {
            int positions = skin.mesh().positionCount();
            float[] rest = skin.mesh().positions();
            int pseudo = skin.jointCount(); // the palette's bind-shape joint, when the geometry has one
            double[][][] full = new double[positions][][];
            double[][][][] capped = new double[caps.length][positions][][];
            for (int p = 0; p < positions; p++) {
                full[p] = influences(skin, p, pseudo, Integer.MAX_VALUE);
                for (int c = 0; c < caps.length; c++) {
                    capped[c][p] = influences(skin, p, pseudo, caps[c]);
                }
            }
            cappedPositions = new int[caps.length];
            maxDropped = new double[caps.length];
            for (int c = 0; c < caps.length; c++) {
                for (int p = 0; p < positions; p++) {
                    double dropped = droppedWeight(skin, p, caps[c]);
                    cappedPositions[c] += dropped != 0 ? 1 : 0;
                    maxDropped[c] = Math.max(maxDropped[c], dropped);
                }
            }
            times = times(model.sampler().start(), model.sampler().end());
            size = restSize(rest, full, atRest.palette(g).matrices());
            distances = new double[caps.length][2][times.length][positions];
            for (int t = 0; t < times.length; t++) {
                model.pose(times[t], RotationInterpolation.SLERP);
                JointPalette palette = model.palette(g);
                palette.prepareAll();
                for (int p = 0; p < positions; p++) {
                    double[] lbs = lbs(palette.matrices(), full[p], rest, p);
                    double[] dqs = dqs(palette, full[p], rest, p);
                    for (int c = 0; c < caps.length; c++) {
                        distances[c][0][t][p] = distance(lbs, lbs(palette.matrices(), capped[c][p], rest, p));
                        distances[c][1][t][p] = distance(dqs, dqs(palette, capped[c][p], rest, p));
                    }
                }
            }
        }

        double largest(int cap, int method) {
            double max = 0;
            for (double[] perTime : distances[cap][method]) {
                for (double d : perTime) {
                    max = Math.max(max, d);
                }
            }
            return max;
        }

        double at(int cap, int method, int position, float time) {
            for (int t = 0; t < times.length; t++) {
                if (times[t] == time) {
                    return distances[cap][method][t][position];
                }
            }
            throw new AssertionError("time " + time + " is no sample time");
        }

        /** The rule, written again: start + i/30 while before the end, then the end. */
        static float[] times(float start, float end) {
            List<Float> list = new ArrayList<>();
            for (int i = 0; (float) (start + i / 30.0) < end; i++) {
                list.add((float) (start + i / 30.0));
            }
            list.add(end);
            float[] a = new float[list.size()];
            for (int i = 0; i < a.length; i++) {
                a[i] = list.get(i);
            }
            return a;
        }

        /**
         * Position p's influences as {palette joint, weight} pairs, heaviest first (file order among
         * equals), at most {@code cap}, divided by the sum of those kept when some weight was lost
         * and by the sum of all otherwise. No weight at all: the bind shape (the pseudo-joint).
         */
        static double[][] influences(Skin skin, int p, int pseudo, int cap) {
            int start = skin.influenceStart(p);
            int n = skin.influenceCount(p);
            List<Integer> order = new ArrayList<>();
            double all = 0;
            for (int e = start; e < start + n; e++) {
                order.add(e);
                all += skin.influenceWeight(e);
            }
            if (n == 0 || all == 0) {
                return new double[][] {{pseudo, 1}};
            }
            order.sort((a, b) -> Float.compare(skin.influenceWeight(b), skin.influenceWeight(a))); // stable
            int kept = Math.min(cap, n);
            double keptSum = 0;
            boolean lost = false;
            for (int s = 0; s < n; s++) {
                if (s < kept) {
                    keptSum += skin.influenceWeight(order.get(s));
                } else {
                    lost |= skin.influenceWeight(order.get(s)) != 0f;
                }
            }
            double divisor = lost ? keptSum : all;
            double[][] result = new double[kept][];
            for (int s = 0; s < kept; s++) {
                int j = skin.influenceJoint(order.get(s));
                result[s] = new double[] {j < 0 ? pseudo : j, skin.influenceWeight(order.get(s)) / divisor};
            }
            return result;
        }

        /** The weight, of a sum of 1, that position p loses beyond its {@code cap} heaviest influences. */
        static double droppedWeight(Skin skin, int p, int cap) {
            List<Float> weights = new ArrayList<>();
            double all = 0;
            for (int e = skin.influenceStart(p); e < skin.influenceStart(p + 1); e++) {
                weights.add(skin.influenceWeight(e));
                all += skin.influenceWeight(e);
            }
            weights.sort((a, b) -> Float.compare(b, a));
            double dropped = 0;
            for (int s = cap; s < weights.size(); s++) {
                dropped += weights.get(s);
            }
            return all == 0 ? 0 : dropped / all;
        }

        /** LBS: (sum w M) p with the palette's row-major 3x4 matrices. */
        static double[] lbs(float[] matrices, double[][] influences, float[] rest, int p) {
            double x = rest[3 * p], y = rest[3 * p + 1], z = rest[3 * p + 2];
            double[] out = new double[3];
            for (double[] jw : influences) {
                int m = 12 * (int) jw[0];
                for (int r = 0; r < 3; r++) {
                    out[r] += jw[1] * (matrices[m + 4 * r] * x + matrices[m + 4 * r + 1] * y
                            + matrices[m + 4 * r + 2] * z + matrices[m + 4 * r + 3]);
                }
            }
            return out;
        }

        /**
         * DQS: p1 = (sum w S) p; b = sum s w q with s the sign of the real parts' dot with the
         * dominant (first) influence's; b / |b.real|; p' = r p1 r* + t, t = 2 vec(d r*).
         */
        static double[] dqs(JointPalette palette, double[][] influences, float[] rest, int p) {
            float[] scales = palette.scales();
            float[] dq = palette.dualQuaternions();
            double[] p1 = lbs(scales, influences, rest, p);
            double[] b = new double[8];
            int q0 = 8 * (int) influences[0][0];
            for (double[] jw : influences) {
                int q = 8 * (int) jw[0];
                double dot = 0;
                for (int i = 0; i < 4; i++) {
                    dot += (double) dq[q0 + i] * dq[q + i];
                }
                double w = dot < 0 ? -jw[1] : jw[1];
                for (int i = 0; i < 8; i++) {
                    b[i] += w * dq[q + i];
                }
            }
            double norm = Math.sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2] + b[3] * b[3]);
            double[] r = {b[0] / norm, b[1] / norm, b[2] / norm, b[3] / norm};
            double[] d = {b[4] / norm, b[5] / norm, b[6] / norm, b[7] / norm};
            // r p1 r*, as quaternion products (x y z w)
            double[] rotated = vector(multiply(multiply(r, new double[] {p1[0], p1[1], p1[2], 0}), conjugate(r)));
            double[] t = vector(multiply(d, conjugate(r)));
            return new double[] {rotated[0] + 2 * t[0], rotated[1] + 2 * t[1], rotated[2] + 2 * t[2]};
        }

        static double[] multiply(double[] a, double[] b) {
            return new double[] {
                a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
                a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
                a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
                a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
        }

        static double[] conjugate(double[] q) {
            return new double[] {-q[0], -q[1], -q[2], q[3]};
        }

        static double[] vector(double[] q) {
            return new double[] {q[0], q[1], q[2]};
        }

        static double distance(double[] a, double[] b) {
            return Math.sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
        }

        /** Diagonal of the bounding box of the positions skinned (LBS, all influences) at rest. */
        static double restSize(float[] rest, double[][][] full, float[] restMatrices) {
            double[] min = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
            double[] max = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
            for (int p = 0; p < full.length; p++) {
                double[] v = lbs(restMatrices, full[p], rest, p);
                for (int a = 0; a < 3; a++) {
                    min[a] = Math.min(min[a], v[a]);
                    max[a] = Math.max(max[a], v[a]);
                }
            }
            return Math.sqrt((max[0] - min[0]) * (max[0] - min[0]) + (max[1] - min[1]) * (max[1] - min[1])
                    + (max[2] - min[2]) * (max[2] - min[2]));
        }
    }
}
