package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.List;
import java.util.stream.Collectors;

import org.junit.jupiter.api.Test;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.model.Skin;
import org.skinlab.testing.TestPaths;

/**
 * Skins and scenes of third-party files in ../shared/corpus (skipped when it is absent).
 *
 * <p>The expected numbers were derived independently of the importer with a short Python
 * {@code xml.etree} script: it counted the {@code <geometry>}s holding a {@code <mesh>}, read
 * each {@code <controller><skin>}'s joint {@code Name_array}, its {@code <vertex_weights count>}
 * and the sum and maximum of its {@code <vcount>}, listed the visual scene's {@code <node>}s
 * depth-first with id, sid and parent, and the {@code <skeleton>}s of each
 * {@code <instance_controller>}.
 */
class CorpusSkinSceneTest {
    private static Model read(String name) throws Exception {
        return ColladaImporter.read(TestPaths.corpusFileOrSkip(name));
    }

    /** Every joint is the node whose sid (or, failing that, id) is the joint's name. */
    private static void assertJointsMatchByName(Model m, MeshInstance instance) {
        Skin skin = instance.skin();
        for (int j = 0; j < skin.jointCount(); j++) {
            String name = skin.jointNames().get(j);
            Node n = m.node(instance.jointNode(j));
            assertEquals(name, n.sid() != null ? n.sid() : n.id(), "joint " + j + " resolved to " + n);
        }
    }

    private static int[] indices(Model m, String... ids) {
        return Arrays.stream(ids).mapToInt(id -> m.nodeById(id).orElseThrow().index()).toArray();
    }

    private static void assertNoJointWarnings(Model m) {
        assertTrue(m.warnings().stream().noneMatch(w -> w.message().contains("skeleton")
                || w.message().contains("joint")), () -> m.warnings().toString());
    }

    @Test
    void twoSkinnedCubesResolveBothBonesUnderTheirTwoSkeletonRoots() throws Exception {
        Model m = read("S14_two_skinned_cubes.dae");
        // Script: 1 mesh (Cube_001-mesh), 1 skin with joints Bone Bone_001, 16 positions with one
        // influence each; nodes Armature > {Bone, Bone_001}, then Cube holding the instance with
        // <skeleton>#Bone and #Bone_001.
        assertEquals(1, m.meshes().size());
        assertEquals(1, m.skins().size());
        Skin skin = m.skins().get(0);
        assertEquals(List.of("Bone", "Bone_001"), skin.jointNames());
        assertEquals(16, skin.mesh().positionCount());
        assertEquals(1, skin.maxInfluences());
        assertEquals(4, m.nodes().size());
        assertEquals(1, m.instances().size());
        MeshInstance cube = m.instances().get(0);
        assertEquals("Cube", m.node(cube.node()).id());
        assertArrayEquals(indices(m, "Bone", "Bone_001"), cube.skeletonRoots());
        assertArrayEquals(indices(m, "Bone", "Bone_001"), cube.jointNodes());
        assertJointsMatchByName(m, cube);
        assertNoJointWarnings(m);
    }

    @Test
    void legWithControlBonesKeepsTheControlBonesAsNodesOutsideTheSkin() throws Exception {
        Model m = read("S15_leg_control_bones.dae");
        // Script: 1 skin with joints Upper_Leg_L Lower_Leg_L Foot_L Toe_L, 28 positions, 58
        // influences, at most 3 per position; 11 nodes: Armature > {Upper_Leg_L > Lower_Leg_L,
        // Leg_Control_L > {Foot_L > Toe_L, Foot_Roll_L > Leg_IK_L, Toe_Control_L},
        // Leg_Pole_Target_L}, then Cube; <skeleton>s Upper_Leg_L, Leg_Control_L, Leg_Pole_Target_L.
        assertEquals(1, m.skins().size());
        Skin skin = m.skins().get(0);
        assertEquals(List.of("Upper_Leg_L", "Lower_Leg_L", "Foot_L", "Toe_L"), skin.jointNames());
        assertEquals(28, skin.mesh().positionCount());
        assertEquals(58, skin.influenceTotal());
        assertEquals(3, skin.maxInfluences());
        assertEquals(11, m.nodes().size());
        MeshInstance cube = m.instances().get(0);
        assertEquals(1, m.instances().size());
        assertArrayEquals(indices(m, "Upper_Leg_L", "Leg_Control_L", "Leg_Pole_Target_L"), cube.skeletonRoots());
        assertArrayEquals(indices(m, "Upper_Leg_L", "Lower_Leg_L", "Foot_L", "Toe_L"), cube.jointNodes());
        assertJointsMatchByName(m, cube);
        // The five control bones are in the scene, with their parents, and not skin joints.
        List<String> control = List.of("Leg_Control_L", "Foot_Roll_L", "Leg_IK_L", "Toe_Control_L", "Leg_Pole_Target_L");
        for (String id : control) {
            Node n = m.nodeById(id).orElseThrow(() -> new AssertionError("no node " + id));
            assertTrue(n.isJoint(), id);
            assertFalse(Arrays.stream(cube.jointNodes()).anyMatch(j -> j == n.index()), id + " is a skin joint");
        }
        assertEquals(m.nodeById("Foot_Roll_L").orElseThrow().index(), m.nodeById("Leg_IK_L").orElseThrow().parent());
        assertEquals(m.nodeById("Leg_Control_L").orElseThrow().index(), m.nodeById("Foot_L").orElseThrow().parent());
        // 11 nodes = Armature + 4 skin joints + 5 control bones + Cube.
        List<String> unused = m.nodes().stream()
                .filter(n -> n.isJoint() && Arrays.stream(cube.jointNodes()).noneMatch(j -> j == n.index()))
                .map(Node::id).collect(Collectors.toList());
        assertEquals(control, unused);
        assertNoJointWarnings(m);
    }

    @Test
    void trionSceneHasThreeGeometriesOfWhichOnlyOneIsSkinned() throws Exception {
        Model m = read("S17_trion_scene.dae");
        // Script: meshes Cube_001-mesh, Cylinder-mesh, Cube-mesh; one skin (Guy_Cube-skin) on
        // Cube_001-mesh with 8 joints, 8 positions of one influence; 14 nodes (Camera, Lamp,
        // Guy > 8 joints, Cube, Culumn, House); Cube holds the controller with <skeleton>#Position,
        // Culumn and House hold <instance_geometry> of Cylinder-mesh and Cube-mesh.
        assertEquals(3, m.meshes().size());
        assertEquals(1, m.skins().size());
        Skin skin = m.skins().get(0);
        assertSame(m.mesh("Cube_001-mesh").orElseThrow(), skin.mesh());
        assertEquals(List.of("Position", "Torse", "Hand_r", "Hand_r_2", "Hand_l", "Hand_l_2", "Neck", "Head"),
                skin.jointNames());
        assertEquals(8, skin.mesh().positionCount());
        assertEquals(14, m.nodes().size());
        assertEquals(3, m.instances().size());
        List<MeshInstance> skinned = m.instances().stream().filter(MeshInstance::isSkinned).collect(Collectors.toList());
        assertEquals(1, skinned.size());
        MeshInstance guy = skinned.get(0);
        assertSame(skin, guy.skin());
        assertEquals("Cube", m.node(guy.node()).id());
        assertArrayEquals(indices(m, "Position"), guy.skeletonRoots());
        assertJointsMatchByName(m, guy);
        // The two static instances, in node order: Culumn (Cylinder-mesh), House (Cube-mesh).
        List<MeshInstance> fixed = m.instances().stream().filter(i -> !i.isSkinned()).collect(Collectors.toList());
        assertEquals(2, fixed.size());
        assertNull(fixed.get(0).skin());
        assertEquals("Culumn", m.node(fixed.get(0).node()).id());
        assertSame(m.mesh("Cylinder-mesh").orElseThrow(), fixed.get(0).mesh());
        assertEquals("House", m.node(fixed.get(1).node()).id());
        assertSame(m.mesh("Cube-mesh").orElseThrow(), fixed.get(1).mesh());
        assertNotNull(m.nodeById("Camera").orElse(null));
        assertNoJointWarnings(m);
    }
}
