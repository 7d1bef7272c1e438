package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.collada.Snippets.assertNoWarnings;
import static org.skinlab.collada.Snippets.collada;
import static org.skinlab.collada.Snippets.geometry;
import static org.skinlab.collada.Snippets.node;
import static org.skinlab.collada.Snippets.oneWarning;
import static org.skinlab.collada.Snippets.skin;

import java.util.Arrays;

import org.junit.jupiter.api.Test;
import org.skinlab.model.AnimationChannel;
import org.skinlab.model.ImportWarning;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.model.Node;

/**
 * How {@code <instance_controller>} resolves skin joints to scene nodes (MeshInstance's rules):
 * by sid under the {@code <skeleton>} roots, first root first; by id, then name, when there are
 * no roots; refused when nothing matches.
 */
class JointResolutionTest {
    /** A three-position mesh "g" skinned by controller "c" with the given Name_array joints. */
    private static String library(String joints) {
        int n = joints.trim().split("\\s+").length;
        // Position p is bound to joint min(p, n - 1) with weight 1.
        StringBuilder v = new StringBuilder();
        for (int p = 0; p < 3; p++) {
            v.append(Math.min(p, n - 1)).append(" 0 ");
        }
        return "<library_geometries>" + geometry("g", 3) + "</library_geometries>\n"
                + "<library_controllers>" + skin("c", "g", "Name_array", joints, "1", "1 1 1", v.toString().trim())
                + "</library_controllers>";
    }

    private static String scene(String nodes) {
        return "<library_visual_scenes><visual_scene id=\"s\">\n" + nodes
                + "\n</visual_scene></library_visual_scenes>\n<scene><instance_visual_scene url=\"#s\"/></scene>";
    }

    private static int[] indices(Model m, String... ids) {
        return Arrays.stream(ids).mapToInt(id -> node(m, id).index()).toArray();
    }

    @Test
    void twoCharactersWithTheSameSidsEachGetTheirOwnJoints() {
        Model m = Fixtures.resource("scene/two-characters-same-sids.dae");
        assertEquals(2, m.instances().size());
        MeshInstance bob = m.instances().get(0);
        MeshInstance alice = m.instances().get(1);
        assertEquals("bob_body", m.node(bob.node()).id());
        assertEquals("alice_body", m.node(alice.node()).id());
        assertSame(bob.skin(), alice.skin());
        assertArrayEquals(indices(m, "bob_root", "bob_arm", "bob_hand"), bob.jointNodes());
        assertArrayEquals(indices(m, "alice_root", "alice_arm", "alice_hand"), alice.jointNodes());
        assertArrayEquals(indices(m, "bob_root"), bob.skeletonRoots());
        assertArrayEquals(indices(m, "alice_root"), alice.skeletonRoots());
        assertNoWarnings(m);
    }

    @Test
    void instancedCharacterCopiesEachResolveToTheirOwnCopyOfTheSkeleton() {
        // One library node holds a skeleton and the skinned mesh naming it as <skeleton>; the scene
        // instantiates it twice, so ids, sids and names all occur twice.
        Model m = Fixtures.read("instanced-characters.dae", collada(library("root arm hand"), """
                <library_nodes>
                  <node id="character">
                    <node id="rig_root" sid="root" type="JOINT">
                      <node id="rig_arm" sid="arm" type="JOINT"><node id="rig_hand" sid="hand" type="JOINT"/></node>
                    </node>
                    <node id="skinned"><instance_controller url="#c"><skeleton>#rig_root</skeleton></instance_controller></node>
                  </node>
                </library_nodes>
                """, scene("""
                <node id="p1"><translate>-2 0 0</translate><instance_node url="#character"/></node>
                <node id="p2"><translate>2 0 0</translate><instance_node url="#character"/></node>
                """)));
        // Depth-first: p1 character rig_root rig_arm rig_hand skinned p2 character rig_root ...
        assertEquals(12, m.nodes().size());
        assertEquals(2, m.instances().size());
        MeshInstance first = m.instances().get(0);
        MeshInstance second = m.instances().get(1);
        assertEquals(5, first.node());
        assertEquals(11, second.node());
        assertArrayEquals(new int[] {2, 3, 4}, first.jointNodes());
        assertArrayEquals(new int[] {8, 9, 10}, second.jointNodes());
        assertArrayEquals(new int[] {2}, first.skeletonRoots());
        assertArrayEquals(new int[] {8}, second.skeletonRoots());
        assertTrue(m.node(8).instanced());
        assertNoWarnings(m);
    }

    @Test
    void severalSkeletonRootsEachContributeTheirJoints() {
        // Like Blender's control-bone rigs: the skin's joints hang under two roots; a node outside
        // the roots carries the same sid "foot" earlier in the document and must not be taken.
        Model m = Fixtures.read("many-roots.dae", collada(library("upper lower foot"), scene("""
                <node id="armature">
                  <node id="decoy"><node id="decoy_foot" sid="foot"/></node>
                  <node id="leg_upper" sid="upper" type="JOINT"><node id="leg_lower" sid="lower" type="JOINT"/></node>
                  <node id="leg_control" sid="control" type="JOINT"><node id="leg_foot" sid="foot" type="JOINT"/></node>
                  <node id="leg_pole" sid="pole" type="JOINT"/>
                </node>
                <node id="leg"><instance_controller url="#c">
                  <skeleton>#leg_upper</skeleton><skeleton>#leg_control</skeleton>
                </instance_controller></node>
                """)));
        MeshInstance leg = m.instances().get(0);
        assertArrayEquals(indices(m, "leg_upper", "leg_lower", "leg_foot"), leg.jointNodes());
        assertArrayEquals(indices(m, "leg_upper", "leg_control"), leg.skeletonRoots());
        assertNoWarnings(m);
    }

    @Test
    void theFirstSkeletonRootWinsWhenSeveralHoldTheSid() {
        String nodes = """
                <node id="a_root" sid="root"><node id="a_arm" sid="arm"/></node>
                <node id="b_root" sid="root"><node id="b_arm" sid="arm"/></node>
                <node id="ab"><instance_controller url="#c"><skeleton>#a_root</skeleton><skeleton>#b_root</skeleton></instance_controller></node>
                <node id="ba"><instance_controller url="#c"><skeleton>#b_root</skeleton><skeleton>#a_root</skeleton></instance_controller></node>
                """;
        Model m = Fixtures.read("first-root.dae", collada(library("arm"), scene(nodes)));
        assertArrayEquals(indices(m, "a_arm"), m.instances().get(0).jointNodes());
        assertArrayEquals(indices(m, "b_arm"), m.instances().get(1).jointNodes());
    }

    @Test
    void withoutSkeletonRootsJointsAreFoundByIdThenByName() {
        // "j_hip" is a node id (its sid is "hip"); "knee" is only a node name; "elbow" is the name
        // of one node and, later in the document, the id of another: the id wins.
        Model m = Fixtures.read("no-roots.dae", collada(library("j_hip knee elbow"), scene("""
                <node id="j_hip" sid="hip" type="JOINT">
                  <node id="n_knee" name="knee" sid="k" type="JOINT"/>
                  <node id="n_named_elbow" name="elbow" type="JOINT"/>
                  <node id="elbow" name="arm" type="JOINT"/>
                </node>
                <node id="body"><instance_controller url="#c"/></node>
                """)));
        MeshInstance body = m.instances().get(0);
        assertArrayEquals(indices(m, "j_hip", "n_knee", "elbow"), body.jointNodes());
        assertEquals(0, body.skeletonRoots().length);
        assertNoWarnings(m);
    }

    @Test
    void skeletonNamingAMissingNodeIsIgnoredWithAWarningAndJointsStillResolve() {
        Model m = Fixtures.read("missing-root.dae", collada(library("hip knee"), scene("""
                <node id="hip" sid="hip" type="JOINT"><node id="knee" sid="knee" type="JOINT"/></node>
                <node id="body"><instance_controller url="#c"><skeleton>#no_such_node</skeleton></instance_controller></node>
                """)));
        MeshInstance body = m.instances().get(0);
        assertArrayEquals(indices(m, "hip", "knee"), body.jointNodes());
        assertEquals(0, body.skeletonRoots().length);
        ImportWarning w = oneWarning(m, "skeleton root \"#no_such_node\" is not a node of the scene; ignored");
        assertTrue(w.element().startsWith("<skeleton> in <node id=\"body\">"), w::toString);
    }

    @Test
    void jointFoundOnlyOutsideTheSkeletonRootsIsTakenWithAWarning() {
        // The root is "upper", but "foot" hangs under "control", which the instance does not name.
        Model m = Fixtures.read("outside-roots.dae", collada(library("upper foot"), scene("""
                <node id="upper" sid="upper" type="JOINT"/>
                <node id="control" sid="control" type="JOINT"><node id="foot" sid="foot" type="JOINT"/></node>
                <node id="leg"><instance_controller url="#c"><skeleton>#upper</skeleton></instance_controller></node>
                """)));
        assertArrayEquals(indices(m, "upper", "foot"), m.instances().get(0).jointNodes());
        oneWarning(m, "some joints matched no sid under the <skeleton> roots");
    }

    @Test
    void jointThatMatchesNothingIsRefusedNamingTheControllerAndTheJoint() {
        ColladaException e = Fixtures.error("ghost-joint.dae", collada(library("hip ghost"), scene("""
                <node id="hip" sid="hip" type="JOINT"/>
                <node id="body"><instance_controller url="#c"><skeleton>#hip</skeleton></instance_controller></node>
                """)));
        assertEquals("ghost-joint.dae", e.file());
        assertTrue(e.element().startsWith("<instance_controller> in <node id=\"body\">"), e::getMessage);
        assertTrue(e.problem().startsWith("joint \"ghost\" of controller \"c\" matches no node"), e::getMessage);
    }

    @Test
    void animatedControlBonesOutsideTheSkinStayNodesAndKeepTheirChannels() {
        // upper > lower deform the mesh; ik_target is a JOINT the skin does not use, animated.
        Model m = Fixtures.read("control-bone.dae", collada(library("upper lower"), """
                <library_animations><animation id="ik">
                  <source id="ik-in"><float_array id="ik-in-array" count="2">0 1</float_array>
                    <technique_common><accessor source="#ik-in-array" count="2"><param name="TIME" type="float"/></accessor></technique_common></source>
                  <source id="ik-out"><float_array id="ik-out-array" count="6">0 0 0  0 1 0</float_array>
                    <technique_common><accessor source="#ik-out-array" count="2" stride="3"><param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/></accessor></technique_common></source>
                  <sampler id="ik-sampler"><input semantic="INPUT" source="#ik-in"/><input semantic="OUTPUT" source="#ik-out"/></sampler>
                  <channel source="#ik-sampler" target="ik_target/location"/>
                </animation></library_animations>
                """, scene("""
                <node id="armature">
                  <node id="upper" sid="upper" type="JOINT"><node id="lower" sid="lower" type="JOINT"/></node>
                  <node id="ik_target" sid="ik_target" type="JOINT"><translate sid="location">0 0 0</translate></node>
                </node>
                <node id="leg"><instance_controller url="#c"><skeleton>#upper</skeleton></instance_controller></node>
                """)));
        Node ik = node(m, "ik_target");
        MeshInstance leg = m.instances().get(0);
        assertArrayEquals(indices(m, "upper", "lower"), leg.jointNodes());
        assertFalse(Arrays.stream(leg.jointNodes()).anyMatch(j -> j == ik.index()));
        assertEquals(5, m.nodes().size());
        assertEquals(1, m.clips().size());
        assertEquals(1, m.clips().get(0).channels().size());
        AnimationChannel channel = m.clips().get(0).channels().get(0);
        assertEquals(ik.index(), channel.node());
        assertEquals(0, channel.transformIndex());
        assertEquals(1f, channel.track().value(1, 1), 0f);
        assertNoWarnings(m);
    }
}
