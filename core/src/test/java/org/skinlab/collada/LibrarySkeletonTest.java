package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.collada.Snippets.oneWarning;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * Skeletons that live in {@code <library_nodes>} ({@code fixtures/quirks/library-skeleton.dae}):
 * named by a {@code <skeleton>} but placed nowhere, placed with {@code <instance_node>}, or only
 * found through the skin's joint names. In every case the rest pose must reproduce the bind shape
 * (so the skeleton stands where its inverse bind matrices say, not under the instance's node),
 * and the clip that turns J2 must reach it.
 */
class LibrarySkeletonTest {
    private static final String NAME = "quirks/library-skeleton.dae";
    private static final float[] BIND_SHAPE = {0, 1, 0, 1, 1, 0, 2, 1, 0};

    /** LBS positions of the first instance at clip time t. */
    private static float[] skinned(Model m, float t) {
        SkinnedModel s = SkinnedModel.of(m);
        s.pose(t, RotationInterpolation.SLERP);
        float[] points = new float[3 * s.geometries().get(0).pointCount()];
        s.skin(0, SkinningMethod.LBS, points, new float[points.length]);
        float[] positions = new float[9];
        for (int p = 0; p < 3; p++) {
            int q = s.geometries().get(0).pointOfPosition(p);
            System.arraycopy(points, 3 * q, positions, 3 * p, 3);
        }
        return positions;
    }

    private static void assertRestAndTurn(Model m) {
        assertArrayEquals(BIND_SHAPE, skinned(m, 0f), 1e-6f, "rest pose = bind shape");
        // At 1 s J2 has turned 90 degrees about Z at (1,1,0): position 2 (only J2) goes to (1,2,0),
        // position 1 (half J1, half J2) stays at its joint (1,1,0).
        assertArrayEquals(new float[] {0, 1, 0, 1, 1, 0, 1, 2, 0}, skinned(m, 1f), 1e-6f, "J2 turned");
    }

    @Test
    void aSkeletonRootPlacedNowhereBecomesARootOfTheScene() {
        Model m = Fixtures.resource(NAME);
        MeshInstance instance = m.instances().get(0);
        assertEquals("J1", m.node(instance.jointNode(0)).id());
        assertEquals(-1, m.node(instance.jointNode(0)).parent());
        assertEquals(3, m.nodes().size(), "holder, J1, J2");
        assertRestAndTurn(m);
        oneWarning(m, "skeleton root \"#J1\" lives in <library_nodes> and is placed nowhere in the scene;"
                + " instantiated as a root of the scene");
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
    }

    @Test
    void aSkeletonPlacedWithInstanceNodeIsFoundInItsCopy() {
        Model m = Fixtures.read("placed.dae", Fixtures.text(NAME).replace("<visual_scene id=\"scene\">",
                "<visual_scene id=\"scene\"><node id=\"rig\"><instance_node url=\"#J1\"/></node>"));
        assertEquals(4, m.nodes().size(), "rig, its copy of J1 and J2, holder");
        assertEquals("rig", m.node(m.node(m.instances().get(0).jointNode(0)).parent()).id());
        assertRestAndTurn(m);
        Snippets.assertNoWarnings(m);
    }

    @Test
    void jointsFoundOnlyInLibraryNodesBringTheirOutermostNode() {
        Model m = Fixtures.read("no-skeleton.dae", Fixtures.text(NAME).replace("<skeleton>#J1</skeleton>", ""));
        assertEquals(3, m.nodes().size());
        assertRestAndTurn(m);
        oneWarning(m, "joint \"J1\" lives in <library_nodes> under node \"J1\", which is placed nowhere in the scene;"
                + " that node is instantiated as a root of the scene");
        assertEquals(1, m.warnings().size(), () -> m.warnings().toString());
    }

    @Test
    void anInstancingBombInLibraryNodesIsStillRefused() {
        // J1 instancing a library node that instances itself: the cycle check covers the new roots.
        String text = Fixtures.text(NAME).replace("<rotate sid=\"rotateZ\">0 0 1 0</rotate>",
                "<rotate sid=\"rotateZ\">0 0 1 0</rotate><instance_node url=\"#J1\"/>");
        ColladaException e = Fixtures.error("cycle.dae", text);
        assertTrue(e.getMessage().contains("instantiates a node that contains it (a cycle)"), e::getMessage);
    }
}
