package org.skinlab.animation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.Arrays;

import org.junit.jupiter.api.Test;
import org.skinlab.collada.AnimationXml;
import org.skinlab.collada.Fixtures;
import org.skinlab.model.Model;

/**
 * BEZIER and HERMITE curves from file to sampled value, against values derived by hand from the
 * formulas (docs/animation.md, "Curves between keys"): the Hermite basis
 * {@code P(s) = h00 P0 + h10 T0 + h01 P1 + h11 T1} with {@code h00 = 2s^3 - 3s^2 + 1},
 * {@code h10 = s^3 - 2s^2 + s}, {@code h01 = -2s^3 + 3s^2}, {@code h11 = s^3 - s^2}, and the cubic
 * Bezier {@code B(s) = (1-s)^3 P0 + 3(1-s)^2 s C0 + 3(1-s) s^2 C1 + s^3 P1}, s in [0, 1].
 *
 * <p>Each test imports a small document (the importer turns every tangent form into Bezier control
 * points) and samples it with {@link AnimationSampler}, so what is checked is the whole path. The
 * node {@code N} has the stack translate (element 0), rotate (1), matrix (2).
 */
class CurveInterpolationTest {
    /** Values up to 43 from float control points and a float time: a few ulps. */
    private static final double VALUE = 2e-5;

    private static final String NODE = """
                  <node id="N">
                    <translate sid="translate">0 0 0</translate>
                    <rotate sid="rotateZ">0 0 1 0</rotate>
                    <matrix sid="transform">1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1</matrix>
                  </node>
            """;

    private static final int TRANSLATE = 0;
    private static final int MATRIX = 2;

    /** One curve channel in a document, imported and ready to sample. */
    private static final class Curve {
        final Skeleton skeleton;
        final AnimationSampler sampler;
        final Pose pose;

        Curve(String target, String times, String values, int stride, String interpolations, String in, String out,
                int tangentStride) {
            Model m = Fixtures.read("curve.dae", AnimationXml.document(NODE,
                    AnimationXml.curve("a", target, times, values, stride, interpolations, in, out, tangentStride)));
            assertEquals(0, m.warnings().size(), m.warnings()::toString);
            skeleton = Skeleton.of(m);
            sampler = new AnimationSampler(skeleton, m.clips().get(0));
            pose = skeleton.newPose();
        }

        /** The values of element {@code element} at {@code time}. */
        float[] at(double time, int element) {
            sampler.sample((float) time, RotationInterpolation.SLERP, pose);
            int o = skeleton.valueOffset(0, element);
            return Arrays.copyOfRange(pose.values(), o, o + skeleton.kind(0, element).size());
        }

        /** translate.X at {@code time}. */
        double x(double time) {
            return at(time, TRANSLATE)[0];
        }
    }

    // -------------------------------------------------------------------------------- HERMITE

    /**
     * Keys (0 s, 0) and (2 s, 10), 1-D HERMITE tangents T0 = 30 (out of key 0), T1 = -6 (in of
     * key 1). Time is linear in s (t = 2s), so P(s) = 30 h10 + 10 h01 - 6 h11
     * = 30s - 24s^2 + 4s^3, i.e. v(t) = 15t - 6t^2 + t^3/2.
     */
    private static Curve hermite1d() {
        return new Curve("N/translate.X", "0 2", "0 10", 1, "HERMITE HERMITE", "0 -6", "30 0", 1);
    }

    @Test
    void oneDimensionalHermiteFollowsTheHermiteBasis() {
        Curve c = hermite1d();
        // s = 1/4: h10 = 9/64, h01 = 5/32, h11 = -3/64: 30 * 9/64 + 10 * 5/32 + 6 * 3/64 = 6.0625
        assertEquals(6.0625, c.x(0.5), VALUE);
        // s = 1/2: h10 = 1/8, h01 = 1/2, h11 = -1/8: 3.75 + 5 + 0.75 = 9.5
        assertEquals(9.5, c.x(1), VALUE);
        // s = 3/4: h10 = 3/64, h01 = 27/32, h11 = -9/64: 1.40625 + 8.4375 + 0.84375 = 10.6875 (past 10)
        assertEquals(10.6875, c.x(1.5), VALUE);
        assertEquals(2.764, c.x(0.2), VALUE); // 15 * 0.2 - 6 * 0.04 + 0.004
        assertEquals(0, c.x(0), 0);
        assertEquals(10, c.x(2), 0);
    }

    @Test
    void theSlopeAtEachEndIsTheTangent() {
        // 1-D: dv/dt = (dv/ds) / (dt/ds) = T / 2 at the ends: 15 at t = 0 and -3 at t = 2. For the
        // cubic v(t) = 15t - 6t^2 + t^3/2 the one-sided differences over h are exactly
        // 15 - 6h + h^2/2 and -3 + 3h + h^2/2 (v'' = -12 + 3t, v''' = 3): with h = 0.01,
        // 14.94005 and -2.96995. Float values near 10 carry 1e-6, so 2e-4 over h.
        Curve c = hermite1d();
        double h = 0.01;
        assertEquals(14.94005, (c.x(h) - c.x(0)) / h, 2e-4);
        assertEquals(-2.96995, (c.x(2) - c.x(2 - h)) / h, 2e-4);

        // 2-D (below): dv/dt = T.v / T.t, 2 / 0.5 = 4 at the start and 0 / 1.5 = 0 at the end.
        // Over h = 0.001: v(h) / h = 3.988 (4 - 12h + O(h^2) from the closed form), and near the end
        // 1 - v = (1 - s)^2 with 1 - s = (1 - t) / 1.5, so (1 - v(1 - h)) / h = h / 2.25 = 4.4e-4.
        Curve d = hermite2d();
        double k = 1e-3;
        assertEquals(4, d.x(k) / k, 0.015);
        assertEquals(hermite2dValue(k) / k, d.x(k) / k, 1e-3);
        assertEquals(0, (d.x(1) - d.x(1 - k)) / k, 1e-3);
    }

    /**
     * Keys (0, 0) and (1, 1) with 2-D HERMITE tangents T0 = (0.5, 2), T1 = (1.5, 0), both
     * derivatives with respect to s. Time: t(s) = 0.5 h10 + h01 + 1.5 h11 = s^2/2 + s/2
     * (increasing); value: v(s) = 2 h10 + h01 = 2s - s^2.
     */
    private static Curve hermite2d() {
        return new Curve("N/translate.X", "0 1", "0 1", 1, "HERMITE HERMITE", "0 0  1.5 0", "0.5 2  0 0", 2);
    }

    /** The same curve solved in closed form: s = (sqrt(1 + 8t) - 1) / 2. */
    private static double hermite2dValue(double t) {
        double s = (Math.sqrt(1 + 8 * t) - 1) / 2;
        return 2 * s - s * s;
    }

    @Test
    void twoDimensionalHermiteTangentsAreDerivativesOfTimeAndValue() {
        Curve c = hermite2d();
        // s = 1/4: t = 1/32 + 1/8 = 0.15625, v = 1/2 - 1/16 = 0.4375
        assertEquals(0.4375, c.x(0.15625), VALUE);
        // s = 1/2: t = 0.375, v = 0.75;  s = 3/4: t = 0.65625, v = 0.9375
        assertEquals(0.75, c.x(0.375), VALUE);
        assertEquals(0.9375, c.x(0.65625), VALUE);
        for (double t = 0.05; t < 1; t += 0.1) {
            assertEquals(hermite2dValue(t), c.x(t), VALUE, "t " + t);
        }
    }

    @Test
    void aThreeValueHermiteChannelInterpolatesEachComponentOnItsOwnCurve() {
        // translate from (0 0 0) at 0 s to (1 2 3) at 1 s; 1-D tangents: out of key 0 (3 0 -3),
        // in of key 1 (0 6 3). Per component, with s = t:
        //   x = 3 h10 + h01          = s^3 - 3s^2 + 3s
        //   y = 2 h01 + 6 h11        = 2s^3
        //   z = -3 h10 + 3 h01 + 3 h11 = -6s^3 + 12s^2 - 3s
        Curve c = new Curve("N/translate", "0 1", "0 0 0  1 2 3", 3, "HERMITE HERMITE", "0 0 0  0 6 3",
                "3 0 -3  0 0 0", 3);
        float[] half = c.at(0.5, TRANSLATE);
        assertEquals(0.875, half[0], VALUE);
        assertEquals(0.25, half[1], VALUE);
        assertEquals(0.75, half[2], VALUE);
        float[] quarter = c.at(0.25, TRANSLATE);
        assertEquals(0.578125, quarter[0], VALUE);
        assertEquals(0.03125, quarter[1], VALUE);
        assertEquals(-0.09375, quarter[2], VALUE);
    }

    @Test
    void aHermiteMatrixChannelIsInterpolatedValueByValue() {
        // Whole-matrix keys with HERMITE (1-D tangents, 16 per key): each value on its own curve.
        // Key 0 the identity, key 1 the identity moved 4 along x (value 3, row 0 column 3). Every
        // tangent is 0 but key 0's out-tangent of that value, 6: it follows 6 h10(s) + 4 h01(s),
        // 1.46875 at s = 1/4 and 2.75 at s = 1/2, and every other value stays as it is.
        String identity = "1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1";
        String moved = "1 0 0 4  0 1 0 0  0 0 1 0  0 0 0 1";
        String zeros = String.join(" ", java.util.Collections.nCopies(16, "0"));
        String out = "0 0 0 6  0 0 0 0  0 0 0 0  0 0 0 0  " + zeros;
        Curve c = new Curve("N/transform", "0 1", identity + "  " + moved, 16, "HERMITE HERMITE", zeros + " " + zeros,
                out, 16);
        float[] m = c.at(0.25, MATRIX);
        assertEquals(1.46875, m[3], VALUE);
        float[] expected = {1, 0, 0, m[3], 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        for (int i = 0; i < 16; i++) {
            assertEquals(expected[i], m[i], 0f, "value " + i);
        }
        assertEquals(2.75, c.at(0.5, MATRIX)[3], VALUE);
    }

    // ------------------------------------------------------------------------ BEZIER, 1-D

    @Test
    void oneDimensionalBezierTangentsOfZeroMakeAFlatPeak() {
        // Keys (0, 0), (1, 43), (2, 0), 1-D BEZIER as ColladaMaya wrote them: 0 at the peak, 14 and
        // -14 at the ends. Control values relative to the keys: segment [0, 1] has 0, 14, 43, 43 with
        // control times at thirds (so s = t):
        //   B(1/2)  = 3/8 * 14 + 3/8 * 43 + 1/8 * 43 = 26.75
        //   B(0.9)  = 3 (0.1)^2 0.9 * 14 + 3 * 0.1 * 0.81 * 43 + 0.729 * 43 = 42.174
        //   B(0.99) = 42.991344: 43 - B = 0.0087, quadratic in 1 - s: the peak is flat, B'(1) = 0
        // and by symmetry the same on [1, 2]. (Read as absolute control values, the zero tangents
        // would pull the curve to 0 next to the peak.)
        Curve c = new Curve("N/translate.X", "0 1 2", "0 43 0", 1, "BEZIER BEZIER BEZIER", "0 0 -14", "14 0 0", 1);
        assertEquals(26.75, c.x(0.5), VALUE);
        assertEquals(42.174, c.x(0.9), VALUE);
        assertEquals(42.991344, c.x(0.99), VALUE);
        assertEquals(42.991344, c.x(1.01), VALUE);
        assertEquals(26.75, c.x(1.5), VALUE);
    }

    // --------------------------------------------------------------------- linear tangents

    @Test
    void tangentsAlongTheSegmentReproduceLinearInEveryForm() {
        // Keys (1 s, 10) and (3 s, 30): LINEAR is 10 + 10 (t - 1). The same line as a curve:
        //   HERMITE 1-D: T = dv/ds = 20;  HERMITE 2-D: T = (2, 20);
        //   BEZIER 1-D: control values v0 + 20/3 and v1 - 20/3 (tangent 20/3, relative to the key);
        //   BEZIER 2-D: control points (1 + 2/3, 10 + 20/3) and (3 - 2/3, 30 - 20/3).
        String third = Float.toString(20f / 3);
        Curve[] curves = {
            new Curve("N/translate.X", "1 3", "10 30", 1, "HERMITE HERMITE", "20 20", "20 20", 1),
            new Curve("N/translate.X", "1 3", "10 30", 1, "HERMITE HERMITE", "2 20  2 20", "2 20  2 20", 2),
            new Curve("N/translate.X", "1 3", "10 30", 1, "BEZIER BEZIER", third + " " + third, third + " " + third, 1),
            new Curve("N/translate.X", "1 3", "10 30", 1, "BEZIER BEZIER",
                    "0 0  " + (3 - 2f / 3) + " " + (30 - 20f / 3), (1 + 2f / 3) + " " + (10 + 20f / 3) + "  0 0", 2),
        };
        for (int i = 0; i < curves.length; i++) {
            for (double t : new double[] {1, 1.3, 2, 2.45, 2.9, 3}) {
                assertEquals(10 + 10 * (t - 1), curves[i].x(t), VALUE, "curve " + i + ", t " + t);
            }
        }
    }
}
