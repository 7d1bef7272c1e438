package org.skinlab.animation;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;
import org.skinlab.collada.Fixtures;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * The bind pose on a hand-made skeleton whose transforms as written differ from the pose it was
 * bound in (fixtures/skin/bind-pose-apart-from-rest.dae: joint "arm" written at x = 3, bound at
 * x = 1; a static triangle on a child of arm at y = 1). Expected positions by hand from the
 * file's numbers; float products of small integers and halves are exact, so the tolerance is 1e-6.
 */
class BindPoseTest {
    private static final Model MODEL = Fixtures.resource("skin/bind-pose-apart-from-rest.dae");
    private static final float TOLERANCE = 1e-6f;

    /** The positions of the geometry drawing mesh {@code meshId} in the current pose, skinned by {@code method}. */
    private static float[] skinned(SkinnedModel m, String meshId, SkinningMethod method) {
        for (int g = 0; g < m.geometries().size(); g++) {
            if (m.geometries().get(g).mesh().id().equals(meshId)) {
                int n = m.geometries().get(g).pointCount();
                float[] positions = new float[3 * n];
                m.skin(g, method, positions, new float[3 * n]);
                return positions;
            }
        }
        throw new AssertionError("no mesh " + meshId);
    }

    @Test
    void theTransformsAsWrittenPlaceTheArmAtThree() {
        SkinnedModel m = SkinnedModel.of(MODEL);
        // arm's skinning matrix translate(3) * translate(-1) = translate(2); the third corner half of it.
        assertArrayEquals(new float[] {3, 0, 0.5f, 4, 0, 0.5f, 2, 1, 0.5f}, skinned(m, "sleeve", SkinningMethod.LBS),
                TOLERANCE);
        assertArrayEquals(new float[] {3, 1, 0, 3.5f, 1, 0, 3, 1.5f, 0}, skinned(m, "glove", SkinningMethod.LBS),
                TOLERANCE);
    }

    @Test
    void theBindPoseGivesTheBindShapeAndMovesNodesBelowAJointWithIt() {
        SkinnedModel m = SkinnedModel.of(MODEL);
        m.poseBind();
        for (SkinningMethod method : new SkinningMethod[] {SkinningMethod.LBS, SkinningMethod.DQS}) {
            // The mesh's positions moved by the bind shape matrix alone, whatever the weights.
            assertArrayEquals(new float[] {1, 0, 0.5f, 2, 0, 0.5f, 1, 1, 0.5f}, skinned(m, "sleeve", method),
                    TOLERANCE, method.key());
        }
        // hand = arm's bind frame translate(1) times its own translate(0, 1, 0).
        assertArrayEquals(new float[] {1, 1, 0, 1.5f, 1, 0, 1, 1.5f, 0}, skinned(m, "glove", SkinningMethod.LBS),
                TOLERANCE);
        // Posing the clip again leaves the bind pose.
        m.pose(0f, RotationInterpolation.SLERP);
        assertArrayEquals(new float[] {3, 0, 0.5f, 4, 0, 0.5f, 2, 1, 0.5f}, skinned(m, "sleeve", SkinningMethod.LBS),
                TOLERANCE);
    }

    @Test
    void onlyTheSkinsJointsAreBound() {
        BindPose bind = BindPose.of(MODEL);
        Skeleton skeleton = Skeleton.of(MODEL);
        int bound = 0;
        for (int i = 0; i < skeleton.nodeCount(); i++) {
            String id = skeleton.node(i).id();
            boolean joint = id.equals("root") || id.equals("arm");
            assertEquals(joint, bind.bound(i), id);
            bound += bind.bound(i) ? 1 : 0;
        }
        assertEquals(2, bound);
        Skeleton other = Skeleton.of(Fixtures.resource("skin/two-skins-and-a-static-mesh.dae"));
        assertThrows(IllegalArgumentException.class, () -> bind.apply(other, other.newPose()));
    }
}
