package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.collada.Snippets.assertNoWarnings;
import static org.skinlab.collada.Snippets.assertRows;
import static org.skinlab.collada.Snippets.collada;
import static org.skinlab.collada.Snippets.geometry;
import static org.skinlab.collada.Snippets.identities;
import static org.skinlab.collada.Snippets.node;
import static org.skinlab.collada.Snippets.oneWarning;
import static org.skinlab.collada.Snippets.skin;

import java.util.List;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.model.ImportWarning;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.model.Skin;

/**
 * {@link SkinLoader} on hand-made skins: matrices change from COLLADA's row-major to JOML's
 * column-major order, every influence is kept as written, and the tolerated oddities (positions
 * without influences, weight sums other than one, skins on morphs) are kept with a warning.
 */
class SkinImportTest {
    /** Matrix entries are small integers or sums of a few decimals: float rounding only. */
    private static final float EPS = 1e-6f;

    // ------------------------------------------------------------------ bind shape and inverse binds

    @Test
    void bindShapeMatrixWrittenAsIdentityIsIdentity() {
        Model m = Fixtures.read("identity-bind-shape.dae", collada(
                "<library_geometries>" + geometry("g", 3) + "</library_geometries>",
                "<library_controllers>" + skin("c", "g", "Name_array", "j", "1", "1 1 1", "0 0 0 0 0 0")
                        + "</library_controllers>"));
        assertTrue(m.skins().get(0).bindShapeMatrix().equals(new Matrix4f(), 0f),
                () -> "bind shape " + m.skins().get(0).bindShapeMatrix());
        assertNoWarnings(m);
    }

    @Test
    void missingBindShapeMatrixIsIdentity() {
        Model m = Fixtures.read("no-bind-shape.dae", collada(
                "<library_geometries>" + geometry("g", 3) + "</library_geometries>",
                "<library_controllers>" + skin("c", "g", null, "Name_array", "j", identities(1), "1", "1 1 1",
                        "0 0 0 0 0 0") + "</library_controllers>"));
        assertTrue(m.skins().get(0).bindShapeMatrix().equals(new Matrix4f(), 0f));
    }

    @Test
    void bindShapeMatrixRowMajorValuesBecomeColumnMajor() {
        Skin s = Fixtures.resource("skin/seven-influences.dae").skins().get(0);
        // The file writes the rows (0 -1 0 10) (1 0 0 20) (0 0 2 30) (0 0 0 1): the translation in
        // values 3, 7, 11 must land in JOML's m30 m31 m32, the rotation must not be transposed.
        assertEquals(10f, s.bindShapeMatrix().m30(), EPS);
        assertEquals(20f, s.bindShapeMatrix().m31(), EPS);
        assertEquals(30f, s.bindShapeMatrix().m32(), EPS);
        assertEquals(-1f, s.bindShapeMatrix().m10(), EPS); // row 0, column 1
        assertEquals(1f, s.bindShapeMatrix().m01(), EPS); // row 1, column 0
        assertRows(new float[][] {{0, -1, 0, 10}, {1, 0, 0, 20}, {0, 0, 2, 30}}, s.bindShapeMatrix(), EPS);
        // By hand: (1 0 0) -> rotated to (0 1 0), then moved by (10 20 30); (0 0 1) -> (0 0 2) + t.
        Vector3f x = s.bindShapeMatrix().transformPosition(new Vector3f(1, 0, 0));
        assertEquals(new Vector3f(10, 21, 30), x);
        Vector3f z = s.bindShapeMatrix().transformPosition(new Vector3f(0, 0, 1));
        assertEquals(new Vector3f(10, 20, 32), z);
    }

    @Test
    void inverseBindMatricesAreConvertedToColumnMajor() {
        Skin s = Fixtures.resource("skin/seven-influences.dae").skins().get(0);
        Matrix4f ibm = new Matrix4f();
        for (int j = 0; j < 7; j++) {
            s.inverseBindMatrix(j, ibm);
            // Each is a translation by (0, -j, 0), written in value 7 of its 16.
            assertEquals(0f, ibm.m30(), EPS);
            assertEquals(-j, ibm.m31(), EPS, "joint " + j);
            assertEquals(0f, ibm.m32(), EPS);
        }
        // Joint 5 (armL) also rotates: rows (0 1 0 0) (-1 0 0 -5) (0 0 1 0).
        s.inverseBindMatrix(5, ibm);
        assertRows(new float[][] {{0, 1, 0, 0}, {-1, 0, 0, -5}, {0, 0, 1, 0}}, ibm, EPS);
        assertEquals(new Vector3f(0, -6, 0), ibm.transformPosition(new Vector3f(1, 0, 0)));
        // The flat copy is column-major too: m31 of joint 5 is float 13 of its 16.
        assertEquals(-5f, s.inverseBindMatrices()[16 * 5 + 13], EPS);
    }

    @Test
    void inverseBindMatrixWithAProjectiveBottomRowIsMadeAffineWithAWarning() {
        Model m = Fixtures.read("ibm-bottom-row.dae", collada(
                "<library_geometries>" + geometry("g", 3) + "</library_geometries>",
                "<library_controllers>" + skin("c", "g", "1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1", "Name_array", "j",
                        "1 0 0 4  0 1 0 0  0 0 1 0  0.5 0 0 2", "1", "1 1 1", "0 0 0 0 0 0")
                        + "</library_controllers>"));
        Matrix4f ibm = m.skins().get(0).inverseBindMatrix(0, new Matrix4f());
        assertRows(new float[][] {{1, 0, 0, 4}, {0, 1, 0, 0}, {0, 0, 1, 0}}, ibm, 0f);
        oneWarning(m, "inverse bind matrix of joint \"j\" has bottom row (0.5 0.0 0.0 2.0)");
    }

    // ------------------------------------------------------------------------------------ joints

    @Test
    void nameArrayJointsAreKeptAsNames() {
        Skin s = Fixtures.resource("skin/seven-influences.dae").skins().get(0);
        assertEquals(List.of("hip", "spine", "chest", "neck", "head", "armL", "armR"), s.jointNames());
        assertFalse(s.jointsAreIdrefs());
    }

    @Test
    void idrefArrayJointsAreKeptAsNodeIds() {
        Model m = Fixtures.resource("skin/two-skins-and-a-static-mesh.dae");
        Skin blade = m.skins().get(0);
        assertEquals("blade-skin", blade.controllerId());
        assertEquals(List.of("arm_root", "arm_tip"), blade.jointNames());
        assertTrue(blade.jointsAreIdrefs());
    }

    // -------------------------------------------------------------------------------- influences

    @Test
    void sevenInfluencesPerPositionAreAllKeptInFileOrder() {
        Model m = Fixtures.resource("skin/seven-influences.dae");
        Skin s = m.skins().get(0);
        assertEquals(7, s.maxInfluences());
        assertEquals(3, s.mesh().positionCount());
        assertEquals(7, s.influenceCount(0));
        assertEquals(1, s.influenceCount(1));
        assertEquals(2, s.influenceCount(2));
        assertEquals(10, s.influenceTotal());
        // <v> pairs (joint weight-index) of position 0: 6 0, 0 1, 3 2, 1 3, 5 4, 2 5, 4 6 with the
        // weights 0.3 0.2 0.15 0.1 0.1 0.1 0.05.
        int[] joints = {6, 0, 3, 1, 5, 2, 4};
        float[] weights = {0.3f, 0.2f, 0.15f, 0.1f, 0.1f, 0.1f, 0.05f};
        int first = s.influenceStart(0);
        for (int k = 0; k < 7; k++) {
            assertEquals(joints[k], s.influenceJoint(first + k), "influence " + k);
            assertEquals(weights[k], s.influenceWeight(first + k), 0f, "influence " + k);
        }
        assertEquals(2, s.influenceJoint(s.influenceStart(1)));
        assertEquals(1f, s.influenceWeight(s.influenceStart(1)), 0f);
        assertEquals(3, s.influenceJoint(s.influenceStart(2)));
        assertEquals(0.25f, s.influenceWeight(s.influenceStart(2)), 0f);
        assertEquals(4, s.influenceJoint(s.influenceStart(2) + 1));
        assertEquals(0.75f, s.influenceWeight(s.influenceStart(2) + 1), 0f);
        assertNoWarnings(m);
    }

    @Test
    void positionsWithoutInfluencesAreKeptWithAWarning() {
        // vcount 1 0 1: position 1 has no influence at all.
        Model m = Fixtures.read("zero-influences.dae", collada(
                "<library_geometries>" + geometry("g", 3) + "</library_geometries>",
                "<library_controllers>" + skin("c", "g", "Name_array", "a b", "1", "1 0 1", "0 0  1 0")
                        + "</library_controllers>"));
        Skin s = m.skins().get(0);
        assertEquals(3, s.mesh().positionCount());
        assertEquals(1, s.influenceCount(0));
        assertEquals(0, s.influenceCount(1));
        assertEquals(1, s.influenceCount(2));
        assertEquals(1, s.influenceJoint(s.influenceStart(2)));
        ImportWarning w = oneWarning(m, "have no influences");
        assertTrue(w.message().startsWith("1 of 3 positions"), w::toString);
        assertTrue(w.element().startsWith("<vertex_weights> in <controller id=\"c\">"), w::toString);
    }

    @Test
    void weightsThatDoNotSumToOneAreKeptAsWrittenWithAWarning() {
        // Position 0: 0.5 + 0.2 = 0.7; position 1: 0.6 + 0.6 = 1.2; position 2: 1.
        Model m = Fixtures.read("bad-sums.dae", collada(
                "<library_geometries>" + geometry("g", 3) + "</library_geometries>",
                "<library_controllers>" + skin("c", "g", "Name_array", "a b", "0.5 0.2 0.6 1", "2 2 1",
                        "0 0 1 1  0 2 1 2  1 3") + "</library_controllers>"));
        Skin s = m.skins().get(0);
        assertEquals(0.5f, s.influenceWeight(0), 0f);
        assertEquals(0.2f, s.influenceWeight(1), 0f);
        assertEquals(0.6f, s.influenceWeight(2), 0f);
        assertEquals(0.6f, s.influenceWeight(3), 0f);
        assertEquals(1f, s.influenceWeight(4), 0f);
        ImportWarning w = oneWarning(m, "do not sum to 1");
        // The worst sum is the one furthest from 1: 0.7 (0.3 away) rather than 1.2 (0.2 away).
        assertTrue(w.message().startsWith("2 of 3 positions have weights that do not sum to 1 (worst 0.7"),
                w::toString);
    }

    @Test
    void jointIndexMinusOneIsKeptAsTheBindShapeReference() {
        // Position 0: (-1, 0.5) (0, 0.5); COLLADA's index -1 means the bind shape itself.
        Model m = Fixtures.read("minus-one.dae", collada(
                "<library_geometries>" + geometry("g", 3) + "</library_geometries>",
                "<library_controllers>" + skin("c", "g", "Name_array", "a", "0.5 1", "2 1 1",
                        "-1 0  0 0  0 1  0 1") + "</library_controllers>"));
        Skin s = m.skins().get(0);
        assertEquals(2, s.influenceCount(0));
        assertEquals(-1, s.influenceJoint(0));
        assertEquals(0.5f, s.influenceWeight(0), 0f);
        assertEquals(0, s.influenceJoint(1));
        assertNoWarnings(m);
    }

    @Test
    void vertexWeightsJointSourceOtherThanTheJointsIsRemappedByName() {
        // <joints> lists a b c; <vertex_weights> indexes its own name source "c a b", so its
        // index 0 is joint c (2), 1 is a (0) and 2 is b (1).
        Model m = Fixtures.read("remap.dae", collada(
                "<library_geometries>" + geometry("g", 3) + "</library_geometries>",
                """
                <library_controllers><controller id="c"><skin source="#g">
                  <source id="joints"><Name_array id="joints-array" count="3">a b c</Name_array>
                    <technique_common><accessor source="#joints-array" count="3"><param name="JOINT" type="name"/></accessor></technique_common></source>
                  <source id="weight-joints"><Name_array id="weight-joints-array" count="3">c a b</Name_array>
                    <technique_common><accessor source="#weight-joints-array" count="3"><param name="JOINT" type="name"/></accessor></technique_common></source>
                  <source id="ibm"><float_array id="ibm-array" count="48">%s</float_array>
                    <technique_common><accessor source="#ibm-array" count="3" stride="16"><param name="TRANSFORM" type="float4x4"/></accessor></technique_common></source>
                  <source id="w"><float_array id="w-array" count="1">1</float_array>
                    <technique_common><accessor source="#w-array" count="1"><param name="WEIGHT" type="float"/></accessor></technique_common></source>
                  <joints><input semantic="JOINT" source="#joints"/><input semantic="INV_BIND_MATRIX" source="#ibm"/></joints>
                  <vertex_weights count="3">
                    <input semantic="JOINT" source="#weight-joints" offset="0"/><input semantic="WEIGHT" source="#w" offset="1"/>
                    <vcount>1 1 1</vcount><v>0 0  1 0  2 0</v>
                  </vertex_weights>
                </skin></controller></library_controllers>
                """.formatted(identities(3))));
        Skin s = m.skins().get(0);
        assertEquals(List.of("a", "b", "c"), s.jointNames());
        assertEquals(2, s.influenceJoint(0));
        assertEquals(0, s.influenceJoint(1));
        assertEquals(1, s.influenceJoint(2));
    }

    @Test
    void remappedJointIndexBeyondItsOwnNameSourceIsRefusedNamingTheElement() {
        // <vertex_weights> indexes "c a" (two names); index 2 is out of that source's range even
        // though the skin has three joints.
        ColladaException e = Fixtures.error("remap-range.dae", collada(
                "<library_geometries>" + geometry("g", 3) + "</library_geometries>",
                """
                <library_controllers><controller id="c"><skin source="#g">
                  <source id="joints"><Name_array id="joints-array" count="3">a b c</Name_array>
                    <technique_common><accessor source="#joints-array" count="3"><param name="JOINT" type="name"/></accessor></technique_common></source>
                  <source id="weight-joints"><Name_array id="weight-joints-array" count="2">c a</Name_array>
                    <technique_common><accessor source="#weight-joints-array" count="2"><param name="JOINT" type="name"/></accessor></technique_common></source>
                  <source id="ibm"><float_array id="ibm-array" count="48">%s</float_array>
                    <technique_common><accessor source="#ibm-array" count="3" stride="16"><param name="TRANSFORM" type="float4x4"/></accessor></technique_common></source>
                  <source id="w"><float_array id="w-array" count="1">1</float_array>
                    <technique_common><accessor source="#w-array" count="1"><param name="WEIGHT" type="float"/></accessor></technique_common></source>
                  <joints><input semantic="JOINT" source="#joints"/><input semantic="INV_BIND_MATRIX" source="#ibm"/></joints>
                  <vertex_weights count="3">
                    <input semantic="JOINT" source="#weight-joints" offset="0"/><input semantic="WEIGHT" source="#w" offset="1"/>
                    <vcount>1 1 1</vcount><v>0 0  1 0  2 0</v>
                  </vertex_weights>
                </skin></controller></library_controllers>
                """.formatted(identities(3))));
        assertTrue(e.element().startsWith("<v> in <controller id=\"c\">"), e::getMessage);
        assertTrue(e.problem().contains("joint index 2"), e::getMessage);
        assertTrue(e.problem().contains("weight-joints"), e::getMessage);
    }

    // ------------------------------------------------------------------- several skins per file

    @Test
    void severalSkinsAndAStaticMeshEachKeepTheirOwnMeshAndJoints() {
        Model m = Fixtures.resource("skin/two-skins-and-a-static-mesh.dae");
        assertEquals(3, m.meshes().size());
        assertEquals(2, m.skins().size());
        Skin blade = m.skins().get(0);
        Skin cloth = m.skins().get(1);
        assertSame(m.mesh("blade").orElseThrow(), blade.mesh());
        assertSame(m.mesh("cloth").orElseThrow(), cloth.mesh());
        assertEquals(List.of("pole", "flagTop", "flagBottom"), cloth.jointNames());
        // <v> of cloth: joints 0 2 1 0 for positions 0..3.
        assertEquals(2, cloth.influenceJoint(cloth.influenceStart(1)));
        assertEquals(1, cloth.influenceJoint(cloth.influenceStart(2)));
        assertEquals(2, blade.maxInfluences());
        assertEquals(1, cloth.maxInfluences());

        // Instances in node order: blade-node, cloth-node, rock-node.
        List<MeshInstance> instances = m.instances();
        assertEquals(3, instances.size());
        MeshInstance bladeInstance = instances.get(0);
        MeshInstance clothInstance = instances.get(1);
        MeshInstance rock = instances.get(2);
        assertSame(blade, bladeInstance.skin());
        assertSame(cloth, clothInstance.skin());
        assertEquals("blade-node", m.node(bladeInstance.node()).id());
        assertEquals("cloth-node", m.node(clothInstance.node()).id());
        // Each skin's joints are its own nodes: blade by id (IDREF_array), cloth by sid.
        assertEquals(node(m, "arm_root").index(), bladeInstance.jointNode(0));
        assertEquals(node(m, "arm_tip").index(), bladeInstance.jointNode(1));
        assertEquals(node(m, "flag_pole").index(), clothInstance.jointNode(0));
        assertEquals(node(m, "flag_top").index(), clothInstance.jointNode(1));
        assertEquals(node(m, "flag_bottom").index(), clothInstance.jointNode(2));

        // The static mesh: <instance_geometry> gives a MeshInstance without a skin.
        assertNull(rock.skin());
        assertFalse(rock.isSkinned());
        assertSame(m.mesh("rock").orElseThrow(), rock.mesh());
        assertEquals("rock-node", m.node(rock.node()).id());
        assertEquals(0, rock.jointNodes().length);
        assertNoWarnings(m);
    }

    // --------------------------------------------------------------------------- skin on a morph

    @Test
    void skinOnAMorphControllerSkinsTheMorphsResult() {
        Model m = Fixtures.read("skin-on-morph.dae", collada(
                "<library_geometries>" + geometry("base", 3) + geometry("smiling", 3) + "</library_geometries>",
                """
                <library_controllers>
                  <controller id="smile"><morph source="#base" method="NORMALIZED">
                    <source id="smile-targets"><IDREF_array id="smile-targets-array" count="1">smiling</IDREF_array>
                      <technique_common><accessor source="#smile-targets-array" count="1"><param name="IDREF" type="IDREF"/></accessor></technique_common></source>
                    <source id="smile-weights"><float_array id="smile-weights-array" count="1">0.5</float_array>
                      <technique_common><accessor source="#smile-weights-array" count="1"><param name="MORPH_WEIGHT" type="float"/></accessor></technique_common></source>
                    <targets><input semantic="MORPH_TARGET" source="#smile-targets"/><input semantic="MORPH_WEIGHT" source="#smile-weights"/></targets>
                  </morph></controller>
                """ + skin("face-skin", "smile", "Name_array", "jaw", "1", "1 1 1", "0 0 0 0 0 0")
                        + "</library_controllers>"));
        assertEquals(1, m.skins().size());
        Skin s = m.skins().get(0);
        // The morph's values are MorphImportTest's business; here: the skin deforms its result,
        // which the model lists after the geometries under the controller's id.
        assertSame(m.morphs().get(0).result(), s.mesh());
        assertSame(m.mesh("smile").orElseThrow(), s.mesh());
        assertEquals(3, m.meshes().size());
        assertEquals(List.of(), m.warnings());
    }
}
