package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;
import org.skinlab.model.MorphWeightChannel;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * Channels on a morph controller's weights (docs/importer.md, "Morphs") become animated weights,
 * and the skinning path morphs before skinning. Expected positions are derived by hand from the
 * specification's NORMALIZED formula {@code P = (1 - sum w) B + sum w T}:
 * base B = (0,0,0) (0,1,0) (2,0,0); target A = B + (0,0,1); target C = B + (1,0,0).
 * Weight 0 is LINEAR 0 -> 1 over [0, 2] s ({@code smile-weights(0)}), weight 1 STEP 0 then 0.5 at
 * 1 s (through the float array's id, {@code smile-weights-array(1)}). So at t = 0.5: w = (0.25, 0),
 * P = B + 0.25 (0,0,1); at t = 1: w = (0.5, 0.5), P = 0.5 A + 0.5 C = B + (0.5, 0, 0.5).
 */
class MorphWeightAnimationTest {
    private static final float EPS = 1e-6f;

    private static String geometry(String id, String positions) {
        return "<geometry id=\"" + id + "\"><mesh>\n"
                + "  <source id=\"" + id + "-pos\"><float_array id=\"" + id + "-pos-array\" count=\"9\">" + positions
                + "</float_array>\n"
                + "    <technique_common><accessor source=\"#" + id + "-pos-array\" count=\"3\" stride=\"3\">"
                + "<param name=\"X\" type=\"float\"/><param name=\"Y\" type=\"float\"/><param name=\"Z\" type=\"float\"/>"
                + "</accessor></technique_common></source>\n"
                + "  <vertices id=\"" + id + "-vtx\"><input semantic=\"POSITION\" source=\"#" + id + "-pos\"/></vertices>\n"
                + "  <triangles count=\"1\"><input semantic=\"VERTEX\" source=\"#" + id + "-vtx\" offset=\"0\"/>"
                + "<p>0 1 2</p></triangles>\n</mesh></geometry>\n";
    }

    private static final String LIBRARIES = libraries(
            Snippets.skin("face-skin", "smile", "Name_array", "jaw", "1", "1 1 1", "0 0 0 0 0 0"));

    private static String libraries(String skin) {
        return "<library_geometries>" + geometry("base", "0 0 0 0 1 0 2 0 0")
            + geometry("up", "0 0 1 0 1 1 2 0 1") + geometry("right", "1 0 0 1 1 0 3 0 0") + "</library_geometries>\n"
            + """
            <library_controllers>
              <controller id="smile"><morph source="#base" method="NORMALIZED">
                <source id="smile-targets"><IDREF_array id="smile-targets-array" count="2">up right</IDREF_array>
                  <technique_common><accessor source="#smile-targets-array" count="2"><param name="IDREF" type="IDREF"/></accessor></technique_common></source>
                <source id="smile-weights"><float_array id="smile-weights-array" count="2">0 0</float_array>
                  <technique_common><accessor source="#smile-weights-array" count="2"><param name="MORPH_WEIGHT" type="float"/></accessor></technique_common></source>
                <targets><input semantic="MORPH_TARGET" source="#smile-targets"/><input semantic="MORPH_WEIGHT" source="#smile-weights"/></targets>
              </morph></controller>
            """ + skin + "</library_controllers>\n";
    }

    private static final String SCENE = """
                  <node id="jaw" sid="jaw" type="JOINT"/>
                  <node id="face"><instance_controller url="#face-skin"><skeleton>#jaw</skeleton></instance_controller></node>
                  <node id="plain"><instance_controller url="#smile"/></node>
            """;

    private static Model model(String animations) {
        return Fixtures.read("morph-weights.dae", AnimationXml.document(LIBRARIES, SCENE, animations, null));
    }

    /**
     * A skin on the morph whose bind shape mirrors, scales by 2 and moves x by 1, and whose inverse
     * bind matrix mirrors back (so the skinning path moves the common mirror into the points): the
     * morphed positions must go through both as the rest shape did. At t = 1 (w = (0.5, 0.5))
     * P = B + (0.5, 0, 0.5); the joint is at the origin, so the result is IBM BSM P with
     * IBM BSM = [2 0 0 -1; 0 2 0 0; 0 0 2 0]: (0, 0, 1), (0, 2, 1), (4, 0, 1).
     */
    @Test
    void aMirroringScalingBindShapeAppliesToTheMorphedPositions() {
        String skin = Snippets.skin("face-skin", "smile", "-2 0 0 1 0 2 0 0 0 0 2 0 0 0 0 1", "Name_array", "jaw",
                "-1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1", "1", "1 1 1", "0 0 0 0 0 0");
        Model m = Fixtures.read("morph-weights-bsm.dae", AnimationXml.document(libraries(skin), SCENE, PER_WEIGHT, null));
        SkinnedModel skinned = new SkinnedModel(m, m.clips().get(0), NormalTransform.INVERSE_TRANSPOSE);
        skinned.pose(1f, RotationInterpolation.SLERP);
        for (SkinningMethod method : SkinningMethod.values()) {
            float[] points = new float[3 * skinned.geometries().get(0).pointCount()];
            skinned.skin(0, method, points, new float[points.length]);
            assertArrayEquals(new float[] {0, 0, 1, 0, 2, 1, 4, 0, 1},
                    skinned.geometries().get(0).positionsInSourceOrder(points, new float[9]), 1e-5f, method.toString());
        }
    }

    private static final String PER_WEIGHT = AnimationXml.animation("w0", "smile-weights(0)", "0 2", "0 1", 1)
            + AnimationXml.animation("w1", "smile-weights-array(1)", "0 1", "0 0.5", 1, "STEP STEP");

    @Test
    void channelsOnTheWeightsSourceAnimateEveryInstanceOfTheMorph() {
        Model m = model(PER_WEIGHT);
        assertEquals(List.of(), m.warnings());
        AnimationClip clip = m.clips().get(0);
        assertEquals(0, clip.channels().size());
        // Two instances draw the morph (one through the skin), two channels: four weight channels.
        List<MorphWeightChannel> weights = clip.morphWeights();
        assertEquals(4, weights.size());
        assertEquals(List.of(0, 1, 0, 1), weights.stream().map(MorphWeightChannel::instance).toList());
        assertEquals(List.of(0, 0, 1, 1), weights.stream().map(MorphWeightChannel::weightOffset).toList());
        assertEquals(0f, clip.start());
        assertEquals(2f, clip.end());
    }

    @Test
    void everyMethodSkinsTheMorphedShapeAtAndBetweenKeys() {
        Model m = model(PER_WEIGHT);
        SkinnedModel skinned = new SkinnedModel(m, m.clips().get(0), NormalTransform.INVERSE_TRANSPOSE);
        float[][] expected = {
            {0, 0, 0, 0, 1, 0, 2, 0, 0}, // t = 0: the base
            {0, 0, 0.25f, 0, 1, 0.25f, 2, 0, 0.25f}, // t = 0.5
            {0.5f, 0, 0.5f, 0.5f, 1, 0.5f, 2.5f, 0, 0.5f}, // t = 1
            {0.5f, 0, 1, 0.5f, 1, 1, 2.5f, 0, 1}, // t = 2: w = (1, 0.5), P = A + 0.5 (C - B)
        };
        float[] times = {0, 0.5f, 1, 2};
        for (int k = 0; k < times.length; k++) {
            skinned.pose(times[k], RotationInterpolation.SLERP);
            for (int g = 0; g < 2; g++) {
                assertTrue(skinned.morphs(g));
                for (SkinningMethod method : SkinningMethod.values()) {
                    float[] points = new float[3 * skinned.geometries().get(g).pointCount()];
                    skinned.skin(g, method, points, new float[points.length]);
                    float[] positions = skinned.geometries().get(g).positionsInSourceOrder(points, new float[9]);
                    assertArrayEquals(expected[k], positions, EPS, "t=" + times[k] + " geometry " + g + " " + method);
                }
            }
        }
    }

    @Test
    void theWholeWeightArrayCanBeOneChannel() {
        Model m = model(AnimationXml.animation("w", "smile-weights", "0 1", "0 0 1 0.5", 2));
        assertEquals(List.of(), m.warnings());
        assertEquals(2, m.clips().get(0).morphWeights().get(0).weightCount());
        SkinnedModel skinned = new SkinnedModel(m, m.clips().get(0), NormalTransform.INVERSE_TRANSPOSE);
        skinned.pose(1f, RotationInterpolation.SLERP);
        float[] points = new float[3 * skinned.geometries().get(1).pointCount()];
        skinned.skin(1, SkinningMethod.LBS, points, new float[points.length]);
        // w = (1, 0.5): (1 - 1.5) B + A + 0.5 C
        assertArrayEquals(new float[] {0.5f, 0, 1, 0.5f, 1, 1, 2.5f, 0, 1},
                skinned.geometries().get(1).positionsInSourceOrder(points, new float[9]), EPS);
    }

    /** The morph "smile" only as the base of another morph ("grin"), which the scene draws. */
    @Test
    void weightsOfAMorphUnderAnotherMorphAreSkippedWithAWarning() {
        String grin = """
                  <controller id="grin"><morph source="#smile" method="RELATIVE">
                    <source id="grin-targets"><IDREF_array id="grin-targets-array" count="1">up</IDREF_array>
                      <technique_common><accessor source="#grin-targets-array" count="1"><param name="IDREF" type="IDREF"/></accessor></technique_common></source>
                    <source id="grin-weights"><float_array id="grin-weights-array" count="1">0</float_array>
                      <technique_common><accessor source="#grin-weights-array" count="1"><param name="MORPH_WEIGHT" type="float"/></accessor></technique_common></source>
                    <targets><input semantic="MORPH_TARGET" source="#grin-targets"/><input semantic="MORPH_WEIGHT" source="#grin-weights"/></targets>
                  </morph></controller>
                """;
        Model m = Fixtures.read("morph-on-morph.dae", AnimationXml.document(libraries(grin),
                "      <node id=\"plain\"><instance_controller url=\"#grin\"/></node>\n",
                AnimationXml.animation("w", "smile-weights(0)", "0 1", "0 1", 1)
                        + AnimationXml.animation("g", "grin-weights(0)", "0 1", "0 1", 1), null));
        assertEquals(1, m.clips().get(0).morphWeights().size(), "grin's channel");
        assertEquals("grin-weights(0)", m.clips().get(0).morphWeights().get(0).target());
        assertTrue(m.warnings().stream().anyMatch(w -> w.toString().contains("smile-weights(0)")
                && w.toString().contains("no instance draws this morph")), m.warnings()::toString);
    }

    @Test
    void aWeightOutsideTheArrayIsSkippedWithAWarning() {
        Model m = model(AnimationXml.animation("w", "smile-weights(2)", "0 1", "0 1", 1));
        assertTrue(m.clips().isEmpty() || m.clips().get(0).morphWeights().isEmpty());
        assertTrue(m.warnings().stream().anyMatch(w -> w.toString().contains("smile-weights(2)")), m.warnings()::toString);
    }
}
