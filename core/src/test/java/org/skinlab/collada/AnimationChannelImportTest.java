package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.collada.AnimationXml.animation;
import static org.skinlab.collada.AnimationXml.document;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.model.AnimationChannel;
import org.skinlab.model.ImportWarning;
import org.skinlab.model.Model;
import org.skinlab.model.Node;

/**
 * Channel targets: which node, transform element and values each {@code <channel>} drives, for
 * every target syntax the issue lists, and the targets that are skipped with a warning. Values
 * and key counts below are the ones written in each fixture; offsets follow the value layouts of
 * {@code TransformElement} (matrix row-major; rotate = axis x y z, angle).
 */
class AnimationChannelImportTest {
    /** Exact float comparison: values are copied from the file, never computed. */
    private static final float EXACT = 0f;

    private static final String MATRIX_BONE = """
                  <node id="Bone" sid="Bone" type="JOINT">
                    <matrix sid="transform">1 0 0 0  0 1 0 0  0 0 1 0  0 0 0 1</matrix>
                  </node>
            """;

    private static List<AnimationChannel> channels(Model m) {
        assertEquals(1, m.clips().size(), "one default clip expected");
        return m.clips().get(0).channels();
    }

    private static AnimationChannel only(Model m) {
        List<AnimationChannel> c = channels(m);
        assertEquals(1, c.size(), () -> "channels: " + c);
        return c.get(0);
    }

    private static void assertNoWarnings(Model m) {
        assertEquals(List.of(), m.warnings());
    }

    // ------------------------------------------------------------------------------- matrices

    @Test
    void wholeMatrixChannelDrivesAllSixteenValuesRowMajorAsWritten() {
        // Two keys whose 16 values are all different, so any transposition or reordering shows.
        String key0 = "1 0 0 10  0 1 0 20  0 0 1 30  0 0 0 1";
        String key1 = "2 3 4 5  6 7 8 9  10 11 12 13  0 0 0 1";
        Model m = Fixtures.read("whole-matrix.dae", document(MATRIX_BONE,
                animation("a", "Bone/transform", "0 1", key0 + " " + key1, 16)));
        AnimationChannel c = only(m);
        assertEquals(m.nodeById("Bone").orElseThrow().index(), c.node());
        assertEquals(0, c.transformIndex());
        assertEquals(0, c.valueOffset());
        assertEquals(16, c.valueCount());
        assertEquals("Bone/transform", c.target());
        assertArrayEquals(new float[] {1, 0, 0, 10, 0, 1, 0, 20, 0, 0, 1, 30, 0, 0, 0, 1,
                2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 0, 0, 0, 1}, c.track().values(), EXACT);
        // Row-major: translation x of key 0 is value 3, translation z of key 1 is value 11.
        assertEquals(10f, c.track().value(0, 3), EXACT);
        assertEquals(13f, c.track().value(1, 11), EXACT);
        assertNoWarnings(m);
    }

    @Test
    void matrixElementColumnIOfRowJIsValueIndexFourJPlusI() {
        // (i)(j) = column i of row j => 4 * j + i: (3)(0) -> 3 (translation x), (3)(1) -> 7
        // (translation y), (0)(2) -> 8, (1)(3) -> 13.
        Model m = Fixtures.read("matrix-elements.dae", document(MATRIX_BONE,
                animation("tx", "Bone/transform(3)(0)", "0 1", "0.5 1.5", 1)
                + animation("ty", "Bone/transform(3)(1)", "0 1", "2 3", 1)
                + animation("m20", "Bone/transform(0)(2)", "0 1", "4 5", 1)
                + animation("m31", "Bone/transform(1)(3)", "0 1", "0 0", 1)));
        List<AnimationChannel> c = channels(m);
        assertEquals(4, c.size());
        int[] expectedOffsets = {3, 7, 8, 13};
        for (int i = 0; i < 4; i++) {
            assertEquals(expectedOffsets[i], c.get(i).valueOffset(), c.get(i).target());
            assertEquals(1, c.get(i).valueCount());
            assertEquals(0, c.get(i).transformIndex());
        }
        assertEquals(0.5f, c.get(0).track().value(0, 0), EXACT);
        assertNoWarnings(m);
    }

    @Test
    void severalElementChannelsOnOneMatrixEachKeepAllTheirKeys() {
        // three.js merges element channels of one matrix and keeps only two keys; here each
        // channel keeps its own 4, 5 and 3 keys with their own times.
        Model m = Fixtures.read("matrix-element-keys.dae", document(MATRIX_BONE,
                animation("tx", "Bone/transform(3)(0)", "0 0.25 0.5 1", "1 2 3 4", 1)
                + animation("ty", "Bone/transform(3)(1)", "0 0.1 0.2 0.3 0.4", "5 6 7 8 9", 1)
                + animation("tz", "Bone/transform(3)(2)", "0.5 0.75 2", "10 11 12", 1)));
        List<AnimationChannel> c = channels(m);
        assertEquals(3, c.size());
        assertArrayEquals(new float[] {0, 0.25f, 0.5f, 1}, c.get(0).track().times(), EXACT);
        assertArrayEquals(new float[] {1, 2, 3, 4}, c.get(0).track().values(), EXACT);
        assertArrayEquals(new float[] {0, 0.1f, 0.2f, 0.3f, 0.4f}, c.get(1).track().times(), EXACT);
        assertArrayEquals(new float[] {5, 6, 7, 8, 9}, c.get(1).track().values(), EXACT);
        assertArrayEquals(new float[] {0.5f, 0.75f, 2}, c.get(2).track().times(), EXACT);
        assertArrayEquals(new float[] {10, 11, 12}, c.get(2).track().values(), EXACT);
        assertEquals(3, c.get(0).valueOffset());
        assertEquals(7, c.get(1).valueOffset());
        assertEquals(11, c.get(2).valueOffset());
    }

    // --------------------------------------------------------------- translate, rotate, scale

    private static final String TRS_NODE = """
                  <node id="N">
                    <translate sid="translate">1 2 3</translate>
                    <rotate sid="rotateX">1 0 0 10</rotate>
                    <rotate sid="rotateY">0 1 0 20</rotate>
                    <scale sid="scale">1 1 1</scale>
                  </node>
            """;

    @Test
    void wholeTranslateDrivesThreeValues() {
        Model m = Fixtures.read("translate.dae", document(TRS_NODE,
                animation("t", "N/translate", "0 1", "1 2 3  4 5 6", 3)));
        AnimationChannel c = only(m);
        assertEquals(0, c.transformIndex());
        assertEquals(0, c.valueOffset());
        assertEquals(3, c.valueCount());
        assertArrayEquals(new float[] {1, 2, 3, 4, 5, 6}, c.track().values(), EXACT);
        assertNoWarnings(m);
    }

    @Test
    void translateMembersXYZAreOffsetsZeroOneTwo() {
        Model m = Fixtures.read("translate-members.dae", document(TRS_NODE,
                animation("x", "N/translate.X", "0 1", "7 8", 1)
                + animation("y", "N/translate.Y", "0 1", "9 10", 1)
                + animation("z", "N/translate.Z", "0 1", "11 12", 1)));
        List<AnimationChannel> c = channels(m);
        assertEquals(3, c.size());
        for (int i = 0; i < 3; i++) {
            assertEquals(0, c.get(i).transformIndex());
            assertEquals(i, c.get(i).valueOffset());
            assertEquals(1, c.get(i).valueCount());
        }
        assertArrayEquals(new float[] {11, 12}, c.get(2).track().values(), EXACT);
        assertNoWarnings(m);
    }

    @Test
    void rotateAngleMemberAndArrayIndexThreeBothDriveTheAngleInDegrees() {
        // rotateX is transform 1, rotateY transform 2; the angle is value 3 of a <rotate>.
        Model m = Fixtures.read("rotate.dae", document(TRS_NODE,
                animation("rx", "N/rotateX.ANGLE", "0 1", "90 -45.5", 1)
                + animation("ry", "N/rotateY(3)", "0 1", "180 370", 1)));
        List<AnimationChannel> c = channels(m);
        assertEquals(2, c.size());
        assertEquals(1, c.get(0).transformIndex());
        assertEquals(3, c.get(0).valueOffset());
        assertEquals(1, c.get(0).valueCount());
        assertArrayEquals(new float[] {90, -45.5f}, c.get(0).track().values(), EXACT);
        assertEquals(2, c.get(1).transformIndex());
        assertEquals(3, c.get(1).valueOffset());
        // Degrees as written, not wrapped and not converted to radians.
        assertArrayEquals(new float[] {180, 370}, c.get(1).track().values(), EXACT);
        assertNoWarnings(m);
    }

    @Test
    void wholeScaleAndScaleZ() {
        Model m = Fixtures.read("scale.dae", document(TRS_NODE,
                animation("s", "N/scale", "0 1", "1 1 1  2 3 4", 3)
                + animation("sz", "N/scale.Z", "0 1", "0.5 0.25", 1)));
        List<AnimationChannel> c = channels(m);
        assertEquals(2, c.size());
        assertEquals(3, c.get(0).transformIndex());
        assertEquals(0, c.get(0).valueOffset());
        assertEquals(3, c.get(0).valueCount());
        assertEquals(3, c.get(1).transformIndex());
        assertEquals(2, c.get(1).valueOffset());
        assertEquals(1, c.get(1).valueCount());
        assertArrayEquals(new float[] {0.5f, 0.25f}, c.get(1).track().values(), EXACT);
        assertNoWarnings(m);
    }

    // --------------------------------------------------------------- exporter styles (files)

    @Test
    void blenderDecomposedSidsLocationRotationAndScaleMembers() {
        // fixtures/animation/blender-decomposed.dae: Armature_Bone has location (0), rotationZ (1),
        // rotationY (2), rotationX (3), scale (4); four channels in document order.
        Model m = Fixtures.resource("animation/blender-decomposed.dae");
        List<AnimationChannel> c = channels(m);
        assertEquals(4, c.size());
        int bone = m.nodeById("Armature_Bone").orElseThrow().index();
        String[] targets = {"Armature_Bone/location.X", "Armature_Bone/location.Z", "Armature_Bone/rotationZ.ANGLE",
            "Armature_Bone/scale.Z"};
        int[] transforms = {0, 0, 1, 4};
        int[] offsets = {0, 2, 3, 2};
        int[] keys = {3, 2, 3, 2};
        for (int i = 0; i < 4; i++) {
            assertEquals(targets[i], c.get(i).target());
            assertEquals(bone, c.get(i).node(), targets[i]);
            assertEquals(transforms[i], c.get(i).transformIndex(), targets[i]);
            assertEquals(offsets[i], c.get(i).valueOffset(), targets[i]);
            assertEquals(1, c.get(i).valueCount(), targets[i]);
            assertEquals(keys[i], c.get(i).track().keyCount(), targets[i]);
        }
        assertArrayEquals(new float[] {0, 90, 180}, c.get(2).track().values(), EXACT);
        assertArrayEquals(new float[] {0.25f, 0.75f}, c.get(3).track().times(), EXACT);
        assertNoWarnings(m);
    }

    @Test
    void everyRotationElementKeepsItsOwnChannel() {
        // fixtures/animation/max-three-rotations.dae: Bip01 = translate (0), rotateZ (1),
        // rotateY (2), rotateX (3), scale (4); the translation and all three angles are animated.
        // three.js applies only one of the rotation channels; all four must be here.
        Model m = Fixtures.resource("animation/max-three-rotations.dae");
        List<AnimationChannel> c = channels(m);
        assertEquals(4, c.size());
        assertEquals(0, c.get(0).transformIndex());
        assertEquals(3, c.get(0).valueCount());
        assertArrayEquals(new float[] {0, 0, 0, 1, 2, 3}, c.get(0).track().values(), EXACT);
        int[] transforms = {1, 2, 3};
        float[][] values = {{30, 60, 90}, {0, -10, -20, -40}, {5, 15}};
        for (int i = 0; i < 3; i++) {
            AnimationChannel r = c.get(i + 1);
            assertEquals(transforms[i], r.transformIndex(), r.target());
            assertEquals(3, r.valueOffset(), r.target());
            assertEquals(1, r.valueCount(), r.target());
            assertArrayEquals(values[i], r.track().values(), EXACT, r.target());
        }
        assertNoWarnings(m);
    }

    // ------------------------------------------------------------------ structure of the file

    @Test
    void channelsAreFoundInNestedAnimationsAtAnyDepth() {
        // outer (no channel) > middle (channel on translate.X) > inner (channel on translate.Y),
        // then a second top-level animation with a channel on translate.Z: three channels in
        // document order.
        String nested = "    <animation id=\"outer\">\n"
                + "    <animation id=\"middle\">\n"
                + animationBody("mid", "N/translate.X", "0 1", "5 6")
                + "    <animation id=\"inner\">\n"
                + animationBody("inner", "N/translate.Y", "0 1 2", "0 1 2")
                + "    </animation>\n"
                + "    </animation>\n"
                + "    </animation>\n"
                + animation("second", "N/translate.Z", "0 4", "8 9", 1);
        Model m = Fixtures.read("nested.dae", document(TRS_NODE, nested));
        List<AnimationChannel> c = channels(m);
        assertEquals(3, c.size(), () -> c.toString());
        assertEquals("N/translate.X", c.get(0).target());
        assertEquals("N/translate.Y", c.get(1).target());
        assertEquals("N/translate.Z", c.get(2).target());
        assertEquals(2, c.get(0).track().keyCount());
        assertEquals(3, c.get(1).track().keyCount());
        assertEquals(2, c.get(2).track().keyCount());
        assertNoWarnings(m);
    }

    /** Sources, sampler and channel of a one-channel animation, without the enclosing element. */
    private static String animationBody(String id, String target, String times, String values) {
        String full = animation(id, target, times, values, 1);
        return full.substring(full.indexOf('\n') + 1, full.lastIndexOf("    </animation>"));
    }

    @Test
    void aChannelOnANodeInstancedTwiceYieldsOneChannelPerCopy() {
        String library = """
                  <library_nodes>
                    <node id="Finger" name="Finger">
                      <rotate sid="rotateZ">0 0 1 0</rotate>
                    </node>
                  </library_nodes>
                """;
        String scene = """
                      <node id="LeftHand"><instance_node url="#Finger"/></node>
                      <node id="RightHand"><instance_node url="#Finger"/></node>
                """;
        Model m = Fixtures.read("instanced.dae", AnimationXml.document(library, scene,
                animation("bend", "Finger/rotateZ.ANGLE", "0 1", "0 45", 1), null));
        // Depth-first: LeftHand 0, Finger copy 1, RightHand 2, Finger copy 3.
        assertEquals(4, m.nodes().size());
        List<AnimationChannel> c = channels(m);
        assertEquals(2, c.size());
        assertEquals(1, c.get(0).node());
        assertEquals(3, c.get(1).node());
        for (AnimationChannel ch : c) {
            Node n = m.node(ch.node());
            assertEquals("Finger", n.id());
            assertTrue(n.instanced());
            assertEquals(0, ch.transformIndex());
            assertEquals(3, ch.valueOffset());
        }
        assertNotEquals(m.node(1).parent(), m.node(3).parent());
        // Both copies are driven by the same sampler, read once.
        assertSame(c.get(0).track(), c.get(1).track());
        assertNoWarnings(m);
    }

    // ---------------------------------------------------- lenient: skipped with one warning

    /**
     * Imports a document with one good channel (N/translate.X) and one bad one; asserts that
     * the good one is imported, the bad one skipped, and exactly one warning names the target.
     */
    private static ImportWarning skippedWithWarning(String name, String libraries, String badTarget) {
        Model m = Fixtures.read(name, AnimationXml.document(libraries, TRS_NODE,
                animation("good", "N/translate.X", "0 1", "7 8", 1)
                + animation("bad", badTarget, "0 1", "1 2", 1), null));
        List<AnimationChannel> c = channels(m);
        assertEquals(1, c.size(), () -> c.toString());
        assertEquals("N/translate.X", c.get(0).target());
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
        ImportWarning w = m.warnings().get(0);
        assertTrue(w.message().contains(badTarget), w::toString);
        assertTrue(w.message().contains("skipped"), w::toString);
        assertTrue(w.element().startsWith("<channel"), w::toString);
        return w;
    }

    @Test
    void targetOnAnEffectParameterIsSkippedWithAWarning() {
        // Blender/Maya write material colour animation as effect/technique-sid/param-sid.
        String effects = """
                  <library_effects>
                    <effect id="Skin-effect"><profile_COMMON><technique sid="common"><lambert>
                      <diffuse><color sid="diffuse">1 1 1 1</color></diffuse>
                    </lambert></technique></profile_COMMON></effect>
                  </library_effects>
                """;
        skippedWithWarning("effect-target.dae", effects, "Skin-effect/common/diffuse");
    }

    @Test
    void targetOnAMaterialIsSkippedWithAWarningSayingSo() {
        String materials = """
                  <library_effects>
                    <effect id="Skin-effect"><profile_COMMON><technique sid="common"><lambert/></technique></profile_COMMON></effect>
                  </library_effects>
                  <library_materials>
                    <material id="Skin"><instance_effect url="#Skin-effect"/></material>
                  </library_materials>
                """;
        ImportWarning w = skippedWithWarning("material-target.dae", materials, "Skin/emission");
        assertTrue(w.message().contains("<material>"), w::toString);
    }

    @Test
    void targetNodeOutsideTheVisualSceneIsSkippedWithAWarning() {
        String library = """
                  <library_nodes>
                    <node id="Spare"><translate sid="translate">0 0 0</translate></node>
                  </library_nodes>
                """;
        ImportWarning w = skippedWithWarning("outside-scene.dae", library, "Spare/translate.X");
        assertTrue(w.message().contains("not part of the visual scene"), w::toString);
    }

    @Test
    void targetNodeThatDoesNotExistIsSkippedWithAWarning() {
        ImportWarning w = skippedWithWarning("no-such-node.dae", "", "Ghost/translate.X");
        assertTrue(w.message().contains("Ghost"), w::toString);
    }

    @Test
    void unknownSidIsSkippedWithAWarning() {
        ImportWarning w = skippedWithWarning("unknown-sid.dae", "", "N/rotateZ.ANGLE");
        assertTrue(w.message().contains("\"rotateZ\""), w::toString);
    }

    @Test
    void unknownMemberIsSkippedWithAWarning() {
        ImportWarning w = skippedWithWarning("unknown-member.dae", "", "N/translate.Q");
        assertTrue(w.message().contains(".Q"), w::toString);
    }

    @Test
    void angleMemberOfATranslateIsSkippedWithAWarning() {
        skippedWithWarning("angle-of-translate.dae", "", "N/translate.ANGLE");
    }

    @Test
    void matrixElementSyntaxOnARotateIsSkippedWithAWarning() {
        skippedWithWarning("matrix-index-on-rotate.dae", "", "N/rotateX(0)(1)");
    }

    @Test
    void nestedSidPathIsSkippedWithAWarning() {
        ImportWarning w = skippedWithWarning("nested-sid.dae", "", "N/inner/rotateX.ANGLE");
        assertTrue(w.message().contains("nested sid path"), w::toString);
    }
}
