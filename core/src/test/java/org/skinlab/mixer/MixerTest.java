package org.skinlab.mixer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.LocalPose;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.Skeleton;
import org.skinlab.mixer.ReferenceMixer.Entry;
import org.skinlab.mixer.ReferenceMixer.RefLayer;

/**
 * The mixer against {@link ReferenceMixer}, a plain double-precision implementation of its rules
 * written from the formulas on the rig's keys. Tolerance: 2e-5 in translation and scale (metres;
 * the rig is about 2 m tall) and 2e-5 rad in rotation: the keys are stored as floats and the
 * mixer samples and blends in float.
 */
class MixerTest {
    static final double TOLERANCE = 2e-5;
    static final double[] TIMES = {0, 0.0625, 0.3, 0.4375, 0.59, 0.71, 0.999};

    private final MixerRig rig = new MixerRig();
    private final ReferenceMixer reference = new ReferenceMixer(rig);
    private final Skeleton skeleton = Skeleton.of(rig.model);

    private Mixer mixer() {
        return new Mixer(rig.model, skeleton);
    }

    private static Map<String, Double> weights(Object... clipsAndWeights) {
        Map<String, Double> m = new LinkedHashMap<>();
        for (int i = 0; i < clipsAndWeights.length; i += 2) {
            m.put((String) clipsAndWeights[i], ((Number) clipsAndWeights[i + 1]).doubleValue());
        }
        return m;
    }

    static void assertPose(double[][] expected, LocalPose actual, String what) {
        float[] a = actual.array();
        for (int j = 0; j < expected.length; j++) {
            int o = LocalPose.STRIDE * j;
            for (int c : new int[] {0, 1, 2, 7, 8, 9}) {
                int node = j;
                int comp = c;
                assertEquals(expected[j][c], a[o + c], TOLERANCE, () -> what + ": node " + node + " component " + comp);
            }
            double minus = 0;
            double plus = 0;
            for (int c = 3; c < 7; c++) {
                minus += (expected[j][c] - a[o + c]) * (expected[j][c] - a[o + c]);
                plus += (expected[j][c] + a[o + c]) * (expected[j][c] + a[o + c]);
            }
            // The angle between the rotations from the chord between the quaternions (acos loses it near 1).
            double angle = 4 * Math.asin(Math.min(1, Math.sqrt(Math.min(minus, plus)) / 2));
            int node = j;
            assertTrue(angle < TOLERANCE, () -> what + ": node " + node + " rotation off by " + angle + " rad");
        }
    }

    private double[][] evaluate(Mixer mixer) {
        LocalPose pose = skeleton.newLocalPose();
        mixer.evaluate(RotationInterpolation.SLERP, pose);
        return toDouble(pose);
    }

    private static double[][] toDouble(LocalPose pose) {
        double[][] r = new double[pose.array().length / LocalPose.STRIDE][LocalPose.STRIDE];
        for (int i = 0; i < r.length; i++) {
            for (int c = 0; c < LocalPose.STRIDE; c++) {
                r[i][c] = pose.array()[LocalPose.STRIDE * i + c];
            }
        }
        return r;
    }

    private void check(Mixer mixer, List<RefLayer> expected, String what) {
        LocalPose pose = skeleton.newLocalPose();
        mixer.evaluate(RotationInterpolation.SLERP, pose);
        assertPose(reference.evaluate(expected), pose, what);
    }

    @Test
    void oneClipIsTheClip() {
        for (String clip : List.of("walk", "run", "turn", "wave", "lean")) {
            for (double t : TIMES) {
                Mixer m = mixer();
                m.base().play(clip);
                m.base().setTime(t);
                check(m, List.of(new RefLayer(false, 1, null, 0, List.of(new Entry(clip, 1, m.base().time())))),
                        clip + " at " + t);
            }
        }
    }

    @Test
    void weightedSetsAccumulateAsThreeJsAndTheRestFillsTheRemainder() {
        Object[][] sets = {{"walk", 0.3, "run", 0.7}, {"walk", 0.5, "run", 0.5}, {"walk", 0.25, "run", 0.25},
            {"walk", 0.2, "run", 0.3, "turn", 0.9}, {"walk", 1, "wave", 1}, {"wave", 0.4, "lean", 0.3},
            {"walk", 0, "run", 1}, {"walk", 2, "run", 3}};
        for (Object[] set : sets) {
            for (double t : TIMES) {
                Mixer m = mixer();
                m.base().setClipWeights(weights(set));
                m.base().setTime(t);
                List<Entry> entries = new java.util.ArrayList<>();
                for (int i = 0; i < set.length; i += 2) {
                    String c = (String) set[i];
                    entries.add(new Entry(c, ((Number) set[i + 1]).doubleValue(),
                            t % rig.clip(c).duration()));
                }
                check(m, List.of(new RefLayer(false, 1, null, 0, entries)), java.util.Arrays.toString(set) + " at " + t);
            }
        }
    }

    @Test
    void overrideLayersWithMasksAndAdditiveLayers() {
        double[] upper = {0, 0, 1, 1, 0};
        double[] explicit = {0, 0, 0.5, 0.25, 0};
        for (double t : TIMES) {
            Mixer m = mixer();
            m.base().setClipWeights(weights("walk", 0.6, "run", 0.4));
            Layer wave = m.addLayer("wave");
            wave.play("run");
            wave.setMask(JointMask.subtree(skeleton, "spine"));
            wave.setWeight(0.7);
            Layer lean = m.addLayer("lean");
            lean.play("lean");
            lean.setAdditive(0);
            lean.setWeight(0.8);
            lean.setMask(JointMask.of(skeleton, Map.of("spine", 0.5f, "arm", 0.25f)));
            Layer waveAdd = m.addLayer("wave additive");
            waveAdd.play("wave");
            waveAdd.setAdditive(0.25);
            waveAdd.setWeight(0.5);
            for (Layer l : m.layers()) {
                l.setTime(t);
            }
            List<RefLayer> expected = List.of(
                    new RefLayer(false, 1, null, 0, List.of(new Entry("walk", 0.6, t), new Entry("run", 0.4, t % 0.6))),
                    new RefLayer(false, 0.7, upper, 0, List.of(new Entry("run", 1, t % 0.6))),
                    new RefLayer(true, 0.8, explicit, 0, List.of(new Entry("lean", 1, t))),
                    new RefLayer(true, 0.5, null, 0.25, List.of(new Entry("wave", 1, t))));
            check(m, expected, "four layers at " + t);
        }
    }

    @Test
    void aLayerAtWeightZeroOrWithoutClipsChangesNothing() {
        Mixer m = mixer();
        m.base().play("walk");
        m.base().setTime(0.3);
        double[][] before = evaluate(m);
        Layer l = m.addLayer("nothing yet");
        assertPoseEquals(before, evaluate(m));
        l.play("run");
        l.setWeight(0);
        assertPoseEquals(before, evaluate(m));
        assertSame(rig.model.clips().get(0), m.soleClip());
        l.setWeight(0.5);
        assertNull(m.soleClip());
    }

    private static void assertPoseEquals(double[][] a, double[][] b) {
        for (int i = 0; i < a.length; i++) {
            for (int c = 0; c < a[i].length; c++) {
                assertEquals(a[i][c], b[i][c], 0.0);
            }
        }
    }

    @Test
    void blendSpacesGiveTheFormulasWeightsAndKeepTheClipsInPhase() {
        BlendSpace line = BlendSpace.linear(weights("walk", 1.2, "run", 3.5));
        double[] w = new double[2];
        line.weights(2.0, 0, w);
        assertEquals((3.5 - 2.0) / 2.3, w[0], 1e-12);
        assertEquals((2.0 - 1.2) / 2.3, w[1], 1e-12);
        line.weights(0, 0, w);
        assertEquals(1, w[0], 0);
        line.weights(9, 0, w);
        assertEquals(1, w[1], 0);

        Mixer m = mixer();
        m.base().setBlendSpace(line, 2.0, 0);
        // Advance by 0.37 s in uneven steps: the phase moves at 1 / (weighted mean duration).
        double[] steps = {0.01, 0.1, 0.2, 0.06};
        for (double s : steps) {
            m.advance(s);
        }
        double wWalk = (3.5 - 2.0) / 2.3;
        double wRun = 1 - wWalk;
        double phase = 0.37 / (wWalk * 1.0 + wRun * 0.6);
        phase -= Math.floor(phase);
        check(m, List.of(new RefLayer(false, 1, null, 0, List.of(new Entry("walk", wWalk, phase * 1.0),
                new Entry("run", wRun, phase * 0.6)))), "1-D blend space");

        Map<String, double[]> points = new LinkedHashMap<>();
        points.put("walk", new double[] {0, 1.2});
        points.put("run", new double[] {0, 3.5});
        points.put("turn", new double[] {1, 1.2});
        points.put("wave", new double[] {-1, 0});
        BlendSpace plane = BlendSpace.planar(points);
        double[][] at = {{0, 1.2}, {0.3, 2}, {-0.5, 0.4}, {2, 5}, {-3, -3}, {0.5, 1.2}};
        double[] got = new double[4];
        for (double[] p : at) {
            plane.weights(p[0], p[1], got);
            double[] expected = gradientBands(points, p[0], p[1]);
            for (int i = 0; i < 4; i++) {
                assertEquals(expected[i], got[i], 1e-12, "weight " + i + " at " + java.util.Arrays.toString(p));
            }
        }
        plane.weights(1, 1.2, got);
        assertEquals(1, got[2], 1e-12, "on a clip's point it plays alone");
    }

    /** Johansen's gradient-band influences, normalised: written here from the paper's formula. */
    private static double[] gradientBands(Map<String, double[]> points, double x, double y) {
        List<double[]> p = List.copyOf(points.values());
        double[] h = new double[p.size()];
        double sum = 0;
        for (int i = 0; i < p.size(); i++) {
            double min = Double.POSITIVE_INFINITY;
            for (int j = 0; j < p.size(); j++) {
                if (i == j) {
                    continue;
                }
                double[] pij = {p.get(j)[0] - p.get(i)[0], p.get(j)[1] - p.get(i)[1]};
                double[] pip = {x - p.get(i)[0], y - p.get(i)[1]};
                min = Math.min(min, 1 - (pip[0] * pij[0] + pip[1] * pij[1]) / (pij[0] * pij[0] + pij[1] * pij[1]));
            }
            h[i] = Math.max(0, min);
            sum += h[i];
        }
        for (int i = 0; i < h.length; i++) {
            h[i] /= sum;
        }
        return h;
    }

    @Test
    void crossFadesMoveTheWeightsAndAFadeDuringAFadeDoesNotPop() {
        Mixer m = mixer();
        m.base().play("walk");
        m.advance(0.3);
        m.base().crossFade("run", 0.5, FadeCurve.LINEAR, false);
        m.advance(0.25);
        assertEquals(0.5, m.base().clipWeights().get("walk"), 1e-12);
        assertEquals(0.5, m.base().clipWeights().get("run"), 1e-12);
        check(m, List.of(new RefLayer(false, 1, null, 0, List.of(new Entry("walk", 0.5, 0.55),
                new Entry("run", 0.5, 0.25)))), "half way through a fade");
        double[][] before = evaluate(m);
        m.base().crossFade("turn", 1.0, FadeCurve.SMOOTH, false);
        assertPoseEquals(before, evaluate(m));
        m.advance(0.5);
        Map<String, Double> w = m.base().clipWeights();
        assertEquals(0.25, w.get("walk"), 1e-12);
        assertEquals(0.25, w.get("run"), 1e-12);
        assertEquals(0.5, w.get("turn"), 1e-12);
        m.advance(0.6);
        assertEquals(Map.of("turn", 1.0), m.base().clipWeights());
        assertSame(rig.model.clips().get(2), m.soleClip());
    }

    @Test
    void aSynchronisedFadeStartsTheIncomingClipInPhase() {
        Mixer m = mixer();
        m.base().play("walk");
        m.advance(0.4);
        m.base().crossFade("run", 0.3, FadeCurve.SMOOTH, true);
        Map<String, Double> w = m.base().clipWeights();
        assertEquals(1.0, w.get("walk"));
        m.advance(0.1);
        // Both at the same phase, advancing at the weighted mean duration.
        double share = FadeCurve.SMOOTH.share(0.1 / 0.3);
        double phase = 0.4 + 0.1 / ((1 - share) * 1.0 + share * 0.6);
        check(m, List.of(new RefLayer(false, 1, null, 0, List.of(new Entry("walk", 1 - share, phase),
                new Entry("run", share, phase * 0.6)))), "synchronised fade");
    }

    @Test
    void badInputIsRefusedWithAMessageNamingIt() {
        Mixer m = mixer();
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> m.base().play("jog"));
        assertTrue(e.getMessage().contains("\"jog\"") && e.getMessage().contains("walk, run, turn, wave, lean"),
                e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> m.base().setClipWeights(weights("walk", -1)));
        assertTrue(e.getMessage().contains("\"walk\"") && e.getMessage().contains("-1"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> m.base().setClipWeights(weights("walk", Double.NaN)));
        assertTrue(e.getMessage().contains("NaN"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> m.base().setWeight(Double.NaN));
        assertTrue(e.getMessage().contains("base") && e.getMessage().contains("NaN"), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> JointMask.subtree(skeleton, "tail"));
        assertTrue(e.getMessage().contains("\"tail\"") && e.getMessage().contains("hips, spine, arm, leg"),
                e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> BlendSpace.linear(weights("walk", 1, "run", 1)));
        assertTrue(e.getMessage().contains("\"walk\" and \"run\""), e.getMessage());
        Map<String, double[]> same = new LinkedHashMap<>();
        same.put("walk", new double[] {0, 1});
        same.put("run", new double[] {0, 1});
        e = assertThrows(IllegalArgumentException.class, () -> BlendSpace.planar(same));
        assertTrue(e.getMessage().contains("\"walk\" and \"run\""), e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> m.base().crossFade("run", -1, FadeCurve.LINEAR, false));
        assertTrue(e.getMessage().contains("-1"), e.getMessage());
        assertThrows(IllegalArgumentException.class, () -> m.advance(Double.NaN));
        // A refused change changes nothing: the layer still plays what it played.
        m.base().play("walk");
        assertThrows(IllegalArgumentException.class, () -> m.base().setClipWeights(weights("run", 1, "jog", 1)));
        assertEquals(Map.of("walk", 1.0), m.base().clipWeights());
    }

    @Test
    void clipsThatAnimateDifferentJointsAreToldOnceAndNeverMakeNaN() {
        Mixer m = mixer();
        m.base().setClipWeights(weights("walk", 0.5, "wave", 0.5));
        m.base().setClipWeights(weights("walk", 0.5, "wave", 0.5));
        List<String> told = m.warnings();
        assertEquals(1, told.stream().filter(s -> s.contains("\"wave\"")).count(), told.toString());
        assertTrue(told.get(0).contains("hips") && told.get(0).contains("leg"), told.get(0));
        m.base().setClipWeights(weights("walk", 0, "wave", 0));
        LocalPose pose = skeleton.newLocalPose();
        m.advance(1e6);
        m.evaluate(RotationInterpolation.SLERP, pose);
        for (float v : pose.array()) {
            assertTrue(Float.isFinite(v));
        }
        assertPose(ReferenceMixer.rest(), pose, "all weights zero: the rest pose");
    }
}
