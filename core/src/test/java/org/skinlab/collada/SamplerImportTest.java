package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.collada.AnimationXml.animation;
import static org.skinlab.collada.AnimationXml.document;
import static org.skinlab.collada.AnimationXml.floatSource;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.model.AnimationChannel;
import org.skinlab.model.Interpolation;
import org.skinlab.model.KeyframeTrack;
import org.skinlab.model.Model;

/**
 * Samplers: key times, values, interpolations and tangents as the file writes them; the
 * interpolations read as LINEAR with a warning; and the samplers that are refused with a
 * {@link ColladaException} naming the file and the element.
 */
class SamplerImportTest {
    /** Exact comparison for values copied from the file. */
    private static final float EXACT = 0f;
    /**
     * For control points computed as a third of a key interval or of a tangent and added to a key:
     * two float roundings of values up to 8 (ulp 9.5e-7 at most).
     */
    private static final float THIRD = 2e-6f;

    private static final String NODE = """
                  <node id="N">
                    <translate sid="translate">0 0 0</translate>
                    <rotate sid="rotateX">1 0 0 0</rotate>
                    <matrix sid="transform">1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1</matrix>
                  </node>
            """;

    /**
     * An animation "a" with one channel and a sampler with INPUT, OUTPUT, and, when not null,
     * INTERPOLATION, IN_TANGENT and OUT_TANGENT sources ({@code tangentStride} values per key).
     */
    private static String curve(String target, String times, String values, int stride, String interpolations,
            String in, String out, int tangentStride) {
        return AnimationXml.curve("a", target, times, values, stride, interpolations, in, out, tangentStride);
    }

    private static KeyframeTrack onlyTrack(Model m) {
        List<AnimationChannel> c = m.clips().get(0).channels();
        assertEquals(1, c.size(), () -> c.toString());
        return c.get(0).track();
    }

    private static Interpolation[] interpolations(KeyframeTrack t) {
        Interpolation[] result = new Interpolation[t.keyCount()];
        for (int k = 0; k < result.length; k++) {
            result[k] = t.interpolation(k);
        }
        return result;
    }

    private static void assertNoWarnings(Model m) {
        assertEquals(List.of(), m.warnings());
    }

    // ------------------------------------------------------------------ times and LINEAR/STEP

    @Test
    void keyTimesAreSecondsAsWrittenAndLinearWhenNoInterpolationIsGiven() {
        // A 24 fps key (1/24 s written as 0.041666668) and two equal times (a jump) are kept.
        Model m = Fixtures.read("times.dae", document(NODE,
                animation("a", "N/translate.X", "0 0.041666668 1.5 1.5 2", "1 2 3 4 5", 1)));
        KeyframeTrack t = onlyTrack(m);
        assertArrayEquals(new float[] {0f, 0.041666668f, 1.5f, 1.5f, 2f}, t.times(), EXACT);
        assertArrayEquals(new float[] {1, 2, 3, 4, 5}, t.values(), EXACT);
        assertEquals(0f, t.startTime(), EXACT);
        assertEquals(2f, t.endTime(), EXACT);
        assertArrayEquals(new Interpolation[] {Interpolation.LINEAR, Interpolation.LINEAR, Interpolation.LINEAR,
            Interpolation.LINEAR, Interpolation.LINEAR}, interpolations(t));
        assertFalse(t.hasTangents());
        assertNoWarnings(m);
    }

    @Test
    void linearAndStepKeysAreReadAsWritten() {
        Model m = Fixtures.read("step.dae", document(NODE,
                animation("a", "N/rotateX.ANGLE", "0 1 2", "0 90 180", 1, "STEP STEP LINEAR")));
        KeyframeTrack t = onlyTrack(m);
        assertArrayEquals(new Interpolation[] {Interpolation.STEP, Interpolation.STEP, Interpolation.LINEAR},
                interpolations(t));
        assertFalse(t.hasTangents());
        assertNoWarnings(m);
    }

    // ---------------------------------------------------------------------------- tangents

    @Test
    void bezierTwoDimensionalTangentsAreKeptAsWritten() {
        // Maya style: (time, value) per key for a one-value channel.
        String in = "-0.3 0  0.7 12  1.6 -1";
        String out = "0.4 1  1.2 8  2 -1";
        Model m = Fixtures.read("bezier-2d.dae", document(NODE,
                curve("N/rotateX.ANGLE", "0 1 2", "0 10 -1", 1, "BEZIER BEZIER BEZIER", in, out, 2)));
        KeyframeTrack t = onlyTrack(m);
        assertTrue(t.hasTangents());
        assertArrayEquals(new float[] {-0.3f, 0, 0.7f, 12, 1.6f, -1}, t.inTangents(), EXACT);
        assertArrayEquals(new float[] {0.4f, 1, 1.2f, 8, 2, -1}, t.outTangents(), EXACT);
        assertArrayEquals(new Interpolation[] {Interpolation.BEZIER, Interpolation.BEZIER, Interpolation.BEZIER},
                interpolations(t));
        assertNoWarnings(m);
    }

    @Test
    void hermiteTwoDimensionalTangentsBecomeControlPointsAThirdOfTheDerivativeFromTheirKey() {
        // HERMITE tangents are derivatives T = (dt/ds, dv/ds); the track keeps the equivalent Bezier
        // control points P + T/3 (out) and P - T/3 (in), 2 * (k * 3 + c) per (time, value).
        // Keys P0 = (0; 0 0 0), P1 = (1; 1 2 3).
        //   in, key 0:  T = (0, 1) (0, 2) (0, 3)        -> (0, -1/3) (0, -2/3) (0, -1)
        //   in, key 1:  T = (0.5, 4) (0.5, 5) (0.5, 6)  -> (5/6, 1 - 4/3) (5/6, 2 - 5/3) (5/6, 3 - 2)
        //   out, key 0: T = (0.5, 7) (0.5, 8) (0.5, 9)  -> (1/6, 7/3) (1/6, 8/3) (1/6, 3)
        //   out, key 1: T = (1, 10) (1, 11) (1, 12)     -> (4/3, 1 + 10/3) (4/3, 2 + 11/3) (4/3, 3 + 4)
        String in = "0 1 0 2 0 3   0.5 4 0.5 5 0.5 6";
        String out = "0.5 7 0.5 8 0.5 9   1 10 1 11 1 12";
        Model m = Fixtures.read("hermite-2d.dae", document(NODE,
                curve("N/translate", "0 1", "0 0 0  1 2 3", 3, "HERMITE HERMITE", in, out, 6)));
        KeyframeTrack t = onlyTrack(m);
        assertEquals(3, t.width());
        assertArrayEquals(new float[] {0, -1f / 3, 0, -2f / 3, 0, -1, 5f / 6, -1f / 3, 5f / 6, 1f / 3, 5f / 6, 1},
                t.inTangents(), THIRD);
        assertArrayEquals(new float[] {1f / 6, 7f / 3, 1f / 6, 8f / 3, 1f / 6, 3, 4f / 3, 13f / 3, 4f / 3, 17f / 3,
            4f / 3, 7}, t.outTangents(), THIRD);
        // Key 1, component z (c = 2): out-tangent value at 2 * (1 * 3 + 2) + 1 = 11.
        assertEquals(7f, t.outTangents()[11], THIRD);
        assertArrayEquals(new Interpolation[] {Interpolation.HERMITE, Interpolation.HERMITE}, interpolations(t));
        assertNoWarnings(m);
    }

    @Test
    void oneDimensionalHermiteTangentsAreDerivativesWithTimeLinearInTheSegment() {
        // 1-D: time is linear in s, so dt/ds is the segment's length and the control times sit at
        // thirds; dv/ds = T, so the values are v + T/3 (out) and v - T/3 (in). Keys at 0, 1, 4 s
        // with values 0 3 6; in-tangents 3 6 9, out-tangents -3 -6 -9.
        //   in:  (0, 0 - 1) (2/3, 3 - 2) (3, 6 - 3)       (key 0 has no previous segment: its own time)
        //   out: (1/3, 0 - 1) (2, 3 - 2) (4, 6 - 3)       (the last key has no next segment)
        Model m = Fixtures.read("hermite-1d.dae", document(NODE,
                curve("N/rotateX.ANGLE", "0 1 4", "0 3 6", 1, "HERMITE HERMITE HERMITE", "3 6 9", "-3 -6 -9", 1)));
        KeyframeTrack t = onlyTrack(m);
        assertArrayEquals(new float[] {0, -1, 2f / 3, 1, 3, 3}, t.inTangents(), THIRD);
        assertArrayEquals(new float[] {1f / 3, -1, 2, 1, 4, 3}, t.outTangents(), THIRD);
        assertNoWarnings(m);
    }

    @Test
    void oneDimensionalBezierTangentsAreControlValuesRelativeToTheirKeyAThirdOfTheWayToTheNeighbour() {
        // Keys at 0, 1 and 4 s with values 0 3 6. The control time of key k's in-tangent is
        // t[k] - (t[k] - t[k-1]) / 3 (key 0 has no previous key: its own time), of its
        // out-tangent t[k] + (t[k+1] - t[k]) / 3 (the last key: its own time), so in-times 0, 2/3,
        // 3 and out-times 1/3, 2, 4. The control value is the key's value minus the in-tangent and
        // plus the out-tangent (FCollada 1.x, see CurveTangents.controlPoints):
        //   in:  0 - 0.5, 3 - 1.5, 6 - 2.5;  out: 0 - 0.5, 3 - 1.5, 6 - 2.5.
        Model m = Fixtures.read("bezier-1d.dae", document(NODE,
                curve("N/rotateX.ANGLE", "0 1 4", "0 3 6", 1, "BEZIER BEZIER BEZIER", "0.5 1.5 2.5",
                        "-0.5 -1.5 -2.5", 1)));
        KeyframeTrack t = onlyTrack(m);
        assertArrayEquals(new float[] {0, -0.5f, 2f / 3f, 1.5f, 3, 3.5f}, t.inTangents(), THIRD);
        assertArrayEquals(new float[] {1f / 3f, -0.5f, 2, 1.5f, 4, 3.5f}, t.outTangents(), THIRD);
        assertNoWarnings(m);
    }

    @Test
    void oneDimensionalTangentsOfAThreeValueChannelShareTheKeyTimes() {
        // Keys at 0.5 and 2 s: key 0 out-time 0.5 + 1.5 / 3 = 1, key 1 in-time 2 - 0.5 = 1.5,
        // for all three components; values relative to each component's key value:
        //   in:  key 0 (0 0 0) - (1 2 3), key 1 (1 2 3) - (4 5 6)
        //   out: key 0 (0 0 0) + (7 8 9), key 1 (1 2 3) + (10 11 12)
        Model m = Fixtures.read("bezier-1d-xyz.dae", document(NODE,
                curve("N/translate", "0.5 2", "0 0 0  1 2 3", 3, "BEZIER BEZIER", "1 2 3  4 5 6", "7 8 9  10 11 12",
                        3)));
        KeyframeTrack t = onlyTrack(m);
        assertArrayEquals(new float[] {0.5f, -1, 0.5f, -2, 0.5f, -3, 1.5f, -3, 1.5f, -3, 1.5f, -3}, t.inTangents(),
                THIRD);
        assertArrayEquals(new float[] {1, 7, 1, 8, 1, 9, 2, 11, 2, 13, 2, 15}, t.outTangents(), THIRD);
        assertNoWarnings(m);
    }

    @Test
    void mixedInterpolationsAreKeptPerKey() {
        String in = "0 0  1 1  2 2  3 3";
        String out = "0 0  1 1  2 2  3 3";
        Model m = Fixtures.read("mixed.dae", document(NODE,
                curve("N/translate.Y", "0 1 2 3", "0 1 2 3", 1, "LINEAR STEP BEZIER HERMITE", in, out, 2)));
        KeyframeTrack t = onlyTrack(m);
        assertArrayEquals(new Interpolation[] {Interpolation.LINEAR, Interpolation.STEP, Interpolation.BEZIER,
            Interpolation.HERMITE}, interpolations(t));
        assertTrue(t.hasTangents());
        assertNoWarnings(m);
    }

    // ------------------------------------------------------------ Blender's radian tangents

    /** A document as {@link AnimationXml#document} writes it, but authored by {@code tool}. */
    private static String authoredBy(String tool, String nodes, String animations) {
        return document(nodes, animations).replace("<asset>",
                "<asset><contributor><authoring_tool>" + tool + "</authoring_tool></contributor>");
    }

    // Keys 0 and 90 degrees at 0 and 1 s; handles a third of the way, with values 0.5 and 1.2 in
    // radians (28.6 and 68.8 degrees), the way Blender 3.4 writes a bone's rotation.
    private static final String RADIAN_IN = "-0.333 0  0.667 1.2";
    private static final String RADIAN_OUT = "0.333 0.5  1.333 1.5707964";

    @Test
    void blenderRotationTangentsInRadiansAreConvertedToDegreesWithOneWarning() {
        Model m = Fixtures.read("blender-radians.dae", authoredBy("Blender 3.4.1", NODE,
                curve("N/rotateX.ANGLE", "0 1", "0 90", 1, "BEZIER BEZIER", RADIAN_IN, RADIAN_OUT, 2)));
        KeyframeTrack t = onlyTrack(m);
        // Times untouched; values times 180/pi: 1.2 rad = 68.754936 degrees, 0.5 rad = 28.647890.
        assertArrayEquals(new float[] {-0.333f, 0, 0.667f, 68.754936f}, t.inTangents(), 1e-4f);
        assertArrayEquals(new float[] {0.333f, 28.647890f, 1.333f, 90}, t.outTangents(), 1e-4f);
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
        String w = m.warnings().get(0).message();
        assertTrue(w.startsWith("1 BEZIER track(s)") && w.contains("radians") && w.contains("Blender"), w);
        assertTrue(m.warnings().get(0).element().contains("a-sampler"), m.warnings()::toString);
    }

    @Test
    void theRadianRuleAlsoReadsTheAngleByIndexAndWarnsOncePerFile() {
        // rotateX(3) is the same value as rotateX.ANGLE; two such tracks, one warning counting both.
        String nodes = NODE.replace("<rotate sid=\"rotateX\">1 0 0 0</rotate>",
                "<rotate sid=\"rotateX\">1 0 0 0</rotate><rotate sid=\"rotateY\">0 1 0 0</rotate>");
        String two = curve("N/rotateX(3)", "0 1", "0 90", 1, "BEZIER BEZIER", RADIAN_IN, RADIAN_OUT, 2)
                + curve("N/rotateY.ANGLE", "0 1", "0 90", 1, "BEZIER BEZIER", RADIAN_IN, RADIAN_OUT, 2)
                        .replace("\"a", "\"b").replace("#a", "#b");
        Model m = Fixtures.read("blender-radians-two.dae", authoredBy("Blender 2.93.1", nodes, two));
        for (AnimationChannel c : m.clips().get(0).channels()) {
            assertEquals(68.754936f, c.track().inTangents()[3], 1e-4f, c.target());
        }
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
        assertTrue(m.warnings().get(0).message().startsWith("2 BEZIER track(s)"), m.warnings()::toString);
    }

    @Test
    void blenderTangentsAlreadyInDegreesAreLeftAlone() {
        // An object's rotation (Blender converts those) or a fixed exporter: handle values 28.6 and
        // 68.8 lie nearer the keys 0 and 90 than 0 and pi/2.
        Model m = Fixtures.read("blender-degrees.dae", authoredBy("Blender 3.4.1", NODE,
                curve("N/rotateX.ANGLE", "0 1", "0 90", 1, "BEZIER BEZIER", "-0.333 0  0.667 68.8",
                        "0.333 28.6  1.333 90", 2)));
        KeyframeTrack t = onlyTrack(m);
        assertArrayEquals(new float[] {-0.333f, 0, 0.667f, 68.8f}, t.inTangents(), EXACT);
        assertArrayEquals(new float[] {0.333f, 28.6f, 1.333f, 90}, t.outTangents(), EXACT);
        assertNoWarnings(m);
    }

    @Test
    void theRadianRuleNeedsBlenderAndARotationAngle() {
        // The same numbers from another tool, and on a translation from Blender: read as written.
        Model other = Fixtures.read("maya-radians.dae", authoredBy("Maya 2019 | OpenCOLLADA", NODE,
                curve("N/rotateX.ANGLE", "0 1", "0 90", 1, "BEZIER BEZIER", RADIAN_IN, RADIAN_OUT, 2)));
        assertArrayEquals(new float[] {-0.333f, 0, 0.667f, 1.2f}, onlyTrack(other).inTangents(), EXACT);
        assertNoWarnings(other);
        Model translate = Fixtures.read("blender-translate.dae", authoredBy("Blender 3.4.1", NODE,
                curve("N/translate.X", "0 1", "0 90", 1, "BEZIER BEZIER", RADIAN_IN, RADIAN_OUT, 2)));
        assertArrayEquals(new float[] {-0.333f, 0, 0.667f, 1.2f}, onlyTrack(translate).inTangents(), EXACT);
        assertNoWarnings(translate);
    }

    @Test
    void keysThatAreAllZeroFollowTheExporterAndAreConverted() {
        // With every key at 0, radians and degrees fit equally well; the rule then follows what the
        // exporter's code does for bone rotations: radians. A bump of 0.5 rad becomes 28.6 degrees.
        Model m = Fixtures.read("blender-zero.dae", authoredBy("Blender 3.4.1", NODE,
                curve("N/rotateX.ANGLE", "0 1", "0 0", 1, "BEZIER BEZIER", "-0.333 0  0.667 0.5",
                        "0.333 0.5  1.333 0", 2)));
        assertEquals(28.647890f, onlyTrack(m).outTangents()[1], 1e-4f);
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
    }

    // ------------------------------------------------------------ lenient: read with a warning

    @Test
    void cardinalAndBsplineAreReadAsLinearWithOneWarning() {
        Model m = Fixtures.read("cardinal.dae", document(NODE,
                animation("a", "N/translate.X", "0 1 2 3", "0 1 2 3", 1, "CARDINAL CARDINAL BSPLINE STEP")));
        KeyframeTrack t = onlyTrack(m);
        assertArrayEquals(new Interpolation[] {Interpolation.LINEAR, Interpolation.LINEAR, Interpolation.LINEAR,
            Interpolation.STEP}, interpolations(t));
        // One warning for the sampler, naming both unsupported interpolations, not one per key.
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
        String w = m.warnings().get(0).message();
        assertTrue(w.contains("CARDINAL") && w.contains("BSPLINE") && w.contains("LINEAR"), w);
    }

    @Test
    void bezierWithoutTangentsIsReadAsLinearWithAWarning() {
        Model m = Fixtures.read("bezier-no-tangents.dae", document(NODE,
                animation("a", "N/translate.X", "0 1 2", "0 1 2", 1, "STEP BEZIER HERMITE")));
        KeyframeTrack t = onlyTrack(m);
        assertArrayEquals(new Interpolation[] {Interpolation.STEP, Interpolation.LINEAR, Interpolation.LINEAR},
                interpolations(t));
        assertFalse(t.hasTangents());
        assertNull(t.inTangents());
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
        assertTrue(m.warnings().get(0).element().contains("a-sampler"), m.warnings()::toString);
    }

    @Test
    void keyedMatrixWithABottomRowOtherThan0001KeepsItsValuesWithAWarning() {
        // Key 1 has bottom row (0.5 0 0 2); key 0 has (0 0 0 0.9999999), which is float noise
        // within RowMajor.BOTTOM_ROW_TOLERANCE and not warned about.
        String key0 = "1 0 0 1  0 1 0 2  0 0 1 3  0 0 0 0.9999999";
        String key1 = "1 0 0 4  0 1 0 5  0 0 1 6  0.5 0 0 2";
        Model m = Fixtures.read("bottom-row.dae", document(NODE,
                animation("a", "N/transform", "0 1", key0 + " " + key1, 16)));
        KeyframeTrack t = onlyTrack(m);
        assertEquals(0.9999999f, t.value(0, 15), EXACT);
        assertEquals(0.5f, t.value(1, 12), EXACT);
        assertEquals(2f, t.value(1, 15), EXACT);
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
        assertTrue(m.warnings().get(0).message().contains("bottom row"), m.warnings()::toString);
    }

    // ----------------------------------------------------------------------------- refused

    /** The refusal names the file and the element; returns it for checks on the problem. */
    private static ColladaException refused(String name, String animations, String elementPart) {
        ColladaException e = Fixtures.error(name, document(NODE, animations));
        assertEquals(name, e.file());
        assertTrue(e.element().contains(elementPart), () -> "element: " + e.element());
        assertTrue(e.getMessage().startsWith(name + ": "), e::getMessage);
        return e;
    }

    @Test
    void inputAndOutputKeyCountsThatDifferAreRefused() {
        // 3 times, 2 values.
        String a = curve("N/translate.X", "0 1 2", "5 6", 1, null, null, null, 0);
        ColladaException e = refused("count-mismatch.dae", a, "a-sampler");
        assertTrue(e.element().startsWith("<input"), e::getMessage);
        assertTrue(e.problem().contains("2 entries for 3 keys"), e::getMessage);
    }

    @Test
    void outputWidthThatDoesNotFitTheTargetIsRefused() {
        // Three values per key on an angle (one value).
        String a = curve("N/rotateX.ANGLE", "0 1", "1 2 3  4 5 6", 3, null, null, null, 0);
        ColladaException e = refused("width-angle.dae", a, "a-sampler");
        assertTrue(e.problem().contains("3 values per key") && e.problem().contains("takes 1"), e::getMessage);
    }

    @Test
    void outputOfTwelveValuesOnAWholeMatrixIsRefused() {
        String a = curve("N/transform", "0", "1 0 0 0  0 1 0 0  0 0 1 0", 12, null, null, null, 0);
        ColladaException e = refused("width-matrix.dae", a, "a-sampler");
        assertTrue(e.problem().contains("12 values per key") && e.problem().contains("takes 16"), e::getMessage);
    }

    @Test
    void tangentsOfTheWrongWidthAreRefused() {
        // A one-value channel takes 1 (value) or 2 (time, value) tangent values per key, not 3.
        String a = curve("N/translate.X", "0 1", "0 1", 1, "BEZIER BEZIER", "0 0 0  1 1 1", "0 0 0  1 1 1", 3);
        ColladaException e = refused("tangent-width.dae", a, "a-sampler");
        assertTrue(e.problem().contains("IN_TANGENT") && e.problem().contains("3 values per key"), e::getMessage);
    }

    @Test
    void tangentsWithTheWrongKeyCountAreRefused() {
        String a = curve("N/translate.X", "0 1 2", "0 1 2", 1, "BEZIER BEZIER BEZIER", "0 0  1 1", "0 0  1 1", 2);
        ColladaException e = refused("tangent-count.dae", a, "a-sampler");
        assertTrue(e.problem().contains("2 entries for 3 keys"), e::getMessage);
    }

    @Test
    void decreasingKeyTimesAreRefused() {
        String a = curve("N/translate.X", "0 1 0.5", "0 1 2", 1, null, null, null, 0);
        ColladaException e = refused("decreasing.dae", a, "<source id=\"a-input\">");
        assertTrue(e.problem().contains("decrease at key 2"), e::getMessage);
    }

    @Test
    void interpolationCountDifferentFromTheKeyCountIsRefused() {
        String a = curve("N/translate.X", "0 1 2", "0 1 2", 1, "LINEAR STEP", null, null, 0);
        ColladaException e = refused("interpolation-count.dae", a, "a-sampler");
        assertTrue(e.problem().contains("2 entries for 3 keys"), e::getMessage);
    }

    @Test
    void channelSourceThatRefersToNothingIsRefused() {
        String a = "    <animation id=\"a\">\n"
                + "      <channel source=\"#no-such-sampler\" target=\"N/translate.X\"/>\n"
                + "    </animation>\n";
        ColladaException e = refused("dangling-sampler.dae", a, "<channel");
        assertTrue(e.problem().contains("#no-such-sampler"), e::getMessage);
    }

    @Test
    void samplerWithoutOutputIsRefused() {
        String a = "    <animation id=\"a\">\n" + floatSource("a-input", "0 1", 1)
                + "      <sampler id=\"a-sampler\"><input semantic=\"INPUT\" source=\"#a-input\"/></sampler>\n"
                + "      <channel source=\"#a-sampler\" target=\"N/translate.X\"/>\n"
                + "    </animation>\n";
        ColladaException e = refused("no-output.dae", a, "<sampler id=\"a-sampler\">");
        assertTrue(e.problem().contains("OUTPUT"), e::getMessage);
    }
}
