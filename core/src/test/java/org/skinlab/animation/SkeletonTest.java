package org.skinlab.animation;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.animation.MathAssertions.assertMatrixEquals;
import static org.skinlab.animation.MathAssertions.rows;

import java.util.Arrays;

import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.junit.jupiter.api.Test;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.collada.Fixtures;
import org.skinlab.model.Model;
import org.skinlab.model.TransformElement;
import org.skinlab.testing.TestPaths;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * {@link Skeleton} on {@code fixtures/animation/skeleton-chain.dae} (the hierarchy is drawn in its
 * header): world matrices of joints and of the non-joint nodes between them, skinning matrices
 * {@code world * INV_BIND_MATRIX * BIND_SHAPE_MATRIX} with a bind shape matrix that does not
 * commute with the inverse bind matrices, the bind-shape pseudo-joint, and an animated control
 * node that moves the joint below it.
 *
 * <p>Every expected matrix is multiplied out by hand in the comments, column by column: a rotation
 * written as "e0 -> 2e1" sends the X axis to twice the Y axis.
 */
class SkeletonTest {
    /** Right angles, scales 0.5 to 3, translations up to 13: float rounding of sin/cos(90) only. */
    private static final double EPS = 1e-5;

    private static final Model MODEL = Fixtures.resource("animation/skeleton-chain.dae");

    private static int node(String id) {
        return MODEL.nodeById(id).orElseThrow().index();
    }

    // Rest-pose world matrices, derived in restWorldMatricesFollowTheHierarchy.
    private static final Matrix4fc ARMATURE = rows(2, 0, 0, 1, 0, 2, 0, 2, 0, 0, 2, 3);
    private static final Matrix4fc ROOT = rows(0, -2, 0, 1, 2, 0, 0, 4, 0, 0, 2, 3);
    private static final Matrix4fc HELPER = rows(0, 0, 2, 1, 2, 0, 0, 6, 0, 2, 0, 3);
    private static final Matrix4fc MID = rows(0, -6, 0, 3, 2, 0, 0, 6, 0, 0, 2, 3);
    private static final Matrix4fc TIP = rows(0, -2, 0, 1, 2, 0, 0, 6, 0, 0, 2, 3);

    @Test
    void restWorldMatricesFollowTheHierarchy() {
        Skeleton skeleton = Skeleton.of(MODEL);
        Pose pose = skeleton.newPose();
        // Armature: T(1 2 3) S(2).
        assertMatrixEquals(ARMATURE, pose.world(node("Armature"), new Matrix4f()), EPS);
        // Root: Armature * T(0 1 0) Rz(90). Rotation 2 Rz(90): e0 -> 2e1, e1 -> -2e0, e2 -> 2e2;
        // translation 2 (0 1 0) + (1 2 3) = (1 4 3).
        assertMatrixEquals(ROOT, pose.world(node("Root"), new Matrix4f()), EPS);
        // Helper (not a joint): Root * T(1 0 0) Rx(90). Rx(90): e0 -> e0, e1 -> e2, e2 -> -e1; so
        // e0 -> 2e1, e1 -> 2e2, e2 -> 2e0; translation Root(1 0 0) = (0 2 0) + (1 4 3) = (1 6 3).
        assertMatrixEquals(HELPER, pose.world(node("Helper"), new Matrix4f()), EPS);
        // Mid: Helper * T(0 0 1) Rx(-90) S(1 3 1). Rx(-90) S: e0 -> e0, e1 -> -3e2, e2 -> e1; then
        // Helper: e0 -> 2e1, e1 -> -6e0, e2 -> 2e2; translation Helper(0 0 1) = (2 0 0) + (1 6 3).
        assertMatrixEquals(MID, pose.world(node("Mid"), new Matrix4f()), EPS);
        // Control at rest translates by 0: Root's matrix. Tip: Root * T(1 0 0), translation
        // (0 2 0) + (1 4 3) = (1 6 3).
        assertMatrixEquals(ROOT, pose.world(node("Control"), new Matrix4f()), EPS);
        assertMatrixEquals(TIP, pose.world(node("Tip"), new Matrix4f()), EPS);
        // The skinned mesh's node has no transform.
        assertMatrixEquals(new Matrix4f(), pose.world(node("body"), new Matrix4f()), 0);
    }

    @Test
    void worldMatricesAreTheProductOfTheImportedLocalMatricesDownTheChain() {
        // Cross-check with the importer's own local matrices (Node.localMatrix), multiplied here
        // root to leaf.
        Skeleton skeleton = Skeleton.of(MODEL);
        Pose pose = skeleton.newPose();
        for (int i = 0; i < skeleton.nodeCount(); i++) {
            Matrix4f expected = new Matrix4f();
            for (int n = i; n >= 0; n = MODEL.node(n).parent()) {
                expected.mulLocal(MODEL.node(n).localMatrix());
            }
            assertMatrixEquals(expected, pose.world(i, new Matrix4f()), EPS);
        }
    }

    @Test
    void valuesAreLaidOutPerNodeAndElement() {
        Skeleton skeleton = Skeleton.of(MODEL);
        // Armature 3+3, Root 3+4, Helper 16, Mid 3+4+3, Control 3, Tip 3, body none.
        assertEquals(45, skeleton.valueCount());
        assertEquals(6, skeleton.valueOffset(node("Root"), 0));
        assertEquals(9, skeleton.valueOffset(node("Root"), 1));
        assertEquals(TransformElement.Kind.MATRIX, skeleton.kind(node("Helper"), 0));
        Pose pose = skeleton.newPose();
        assertEquals(90f, pose.values()[skeleton.valueOffset(node("Root"), 1) + 3]);
        // Row-major as in the file: value 3 is the translation x of the matrix.
        assertEquals(1f, pose.values()[skeleton.valueOffset(node("Helper"), 0) + 3]);
        assertThrows(IndexOutOfBoundsException.class, () -> skeleton.valueOffset(node("Root"), 2));
        assertThrows(IndexOutOfBoundsException.class, () -> skeleton.valueOffset(node("body"), 0));
        assertEquals(-1, skeleton.parent(node("Armature")));
        assertEquals(node("Root"), skeleton.parent(node("Control")));
    }

    @Test
    void aMovedControlNodeCarriesTheJointBelowIt() {
        Skeleton skeleton = Skeleton.of(MODEL);
        Pose pose = skeleton.newPose();
        pose.values()[skeleton.valueOffset(node("Control"), 0)] = 2; // Control location.X = 2
        skeleton.evaluate(pose);
        // Control: Root * T(2 0 0): translation 2 * (0 2 0) + (1 4 3) = (1 8 3); Tip one more
        // (0 2 0): (1 10 3). Joints outside the moved branch stay.
        assertMatrixEquals(rows(0, -2, 0, 1, 2, 0, 0, 8, 0, 0, 2, 3), pose.world(node("Control"), new Matrix4f()), EPS);
        assertMatrixEquals(rows(0, -2, 0, 1, 2, 0, 0, 10, 0, 0, 2, 3), pose.world(node("Tip"), new Matrix4f()), EPS);
        assertMatrixEquals(MID, pose.world(node("Mid"), new Matrix4f()), EPS);
        assertMatrixEquals(ROOT, pose.world(node("Root"), new Matrix4f()), EPS);
        // reset() restores the file's values.
        skeleton.reset(pose);
        skeleton.evaluate(pose);
        assertMatrixEquals(TIP, pose.world(node("Tip"), new Matrix4f()), EPS);
    }

    @Test
    void theClipsAnimatedControlNodeMovesTheJoint() {
        // The same through the sampler: Control/location.X is 0 -> 4 over [0, 1], so 2 at 0.5.
        Skeleton skeleton = Skeleton.of(MODEL);
        Pose pose = skeleton.newPose();
        new AnimationSampler(skeleton, MODEL.clips().get(0)).sample(0.5f, RotationInterpolation.SLERP, pose);
        skeleton.evaluate(pose);
        assertMatrixEquals(rows(0, -2, 0, 1, 2, 0, 0, 10, 0, 0, 2, 3), pose.world(node("Tip"), new Matrix4f()), EPS);
    }

    @Test
    void skinningMatricesAreWorldTimesInverseBindTimesBindShape() {
        Skeleton skeleton = Skeleton.of(MODEL);
        Pose pose = skeleton.newPose();
        SkinnedGeometry geometry = SkinnedGeometry.of(MODEL.instances().get(0));
        // Palette: the skin's joints, then the pseudo-joint that position 2 (joint -1) needs.
        assertArrayEquals(new int[] {node("Root"), node("Mid"), node("Tip"), -1}, geometry.jointNodeArray());
        float[] m = new float[12 * geometry.jointCount()];
        skeleton.skinningMatrices(pose, geometry.jointNodeArray(), geometry.bindMatrixArray(), m);
        // The geometry holds its points in bind space (the bind shape matrix applied once), so its
        // skinning matrices are world * IBM; times the BSM they are COLLADA's world * IBM * BSM.
        m = timesBindShape(m, geometry.jointCount());
        // BSM = T(0 0 5) Rz(90).
        // Root: IBM T(-1 0 0), so IBM BSM = Rz(90) with translation (-1 0 5). Root's rotation
        // (e0 -> 2e1, e1 -> -2e0, e2 -> 2e2) after Rz(90) (e0 -> e1, e1 -> -e0): diag(-2 -2 2);
        // translation Root(-1 0 5) = (0 -2 10) + (1 4 3) = (1 2 13). The other order,
        // world * BSM * IBM, would put the translation at (3 4 13).
        assertRow12(new float[] {-2, 0, 0, 1, 0, -2, 0, 2, 0, 0, 2, 13}, m, 0);
        // Mid: IBM S(0.5): IBM BSM = 0.5 Rz(90), translation (0 0 2.5). Mid's rotation (e0 -> 2e1,
        // e1 -> -6e0, e2 -> 2e2) after it: e0 -> -3e0, e1 -> -e1, e2 -> e2; translation
        // Mid(0 0 2.5) = (0 0 5) + (3 6 3) = (3 6 8).
        assertRow12(new float[] {-3, 0, 0, 3, 0, -1, 0, 6, 0, 0, 1, 8}, m, 1);
        // Tip: IBM T(0 0 2) Rx(-90): IBM BSM rotation e0 -> -e2, e1 -> -e0, e2 -> e1, translation
        // Rx(-90)(0 0 5) + (0 0 2) = (0 5 2). Tip's rotation is Root's: e0 -> -2e2, e1 -> -2e1,
        // e2 -> -2e0; translation Tip(0 5 2) = (-10 0 4) + (1 6 3) = (-9 6 7).
        assertRow12(new float[] {0, 0, -2, -9, 0, -2, 0, 6, -2, 0, 0, 7}, m, 2);
        // The pseudo-joint: identity world and bind, so (times the BSM) the bind shape matrix itself.
        assertRow12(new float[] {0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 5}, m, 3);
    }

    @Test
    void skinningMatricesFollowTheAnimatedPose() {
        // Control location.X = 2 moves Tip by Root(2 0 0) = (0 4 0): its skinning matrix's
        // translation becomes (-9 10 7); the rotation part and the other joints do not change.
        Skeleton skeleton = Skeleton.of(MODEL);
        Pose pose = skeleton.newPose();
        pose.values()[skeleton.valueOffset(node("Control"), 0)] = 2;
        skeleton.evaluate(pose);
        SkinnedGeometry geometry = SkinnedGeometry.of(MODEL.instances().get(0));
        float[] m = new float[12 * geometry.jointCount()];
        skeleton.skinningMatrices(pose, geometry.jointNodeArray(), geometry.bindMatrixArray(), m);
        m = timesBindShape(m, geometry.jointCount());
        assertRow12(new float[] {-2, 0, 0, 1, 0, -2, 0, 2, 0, 0, 2, 13}, m, 0);
        assertRow12(new float[] {0, 0, -2, -9, 0, -2, 0, 10, -2, 0, 0, 7}, m, 2);
    }

    @Test
    void aJointWithoutANodeUsesTheIdentityAndTheLayoutIsRowMajor() {
        // Direct call: joint nodes {-1, Root} with bind matrices B0 = T(1 2 3) and B1 = identity.
        // Node -1 gives B0 itself, written row by row (translation in values 3, 7, 11).
        Skeleton skeleton = Skeleton.of(MODEL);
        Pose pose = skeleton.newPose();
        float[] bind = new float[32];
        new Matrix4f().translation(1, 2, 3).get(bind, 0);
        new Matrix4f().get(bind, 16);
        float[] m = new float[24];
        skeleton.skinningMatrices(pose, new int[] {-1, node("Root")}, bind, m);
        assertRow12(new float[] {1, 0, 0, 1, 0, 1, 0, 2, 0, 0, 1, 3}, m, 0);
        assertRow12(new float[] {0, -2, 0, 1, 2, 0, 0, 4, 0, 0, 2, 3}, m, 1);
    }

    @Test
    void evaluatingTwiceGivesTheSameMatrices() {
        // Evaluation must not feed on its own output (scratch matrices are reset per node).
        Skeleton skeleton = Skeleton.of(MODEL);
        Pose pose = skeleton.newPose();
        float[] first = pose.worldArray().clone();
        skeleton.evaluate(pose);
        assertArrayEquals(first, pose.worldArray(), 0f);
        // Skinning in between uses the pose's scratch matrices; evaluation is still unaffected.
        SkinnedGeometry geometry = SkinnedGeometry.of(MODEL.instances().get(0));
        skeleton.skinningMatrices(pose, geometry.jointNodeArray(), geometry.bindMatrixArray(),
                new float[12 * geometry.jointCount()]);
        skeleton.evaluate(pose);
        assertArrayEquals(first, pose.worldArray(), 0f);
        assertTrue(pose.skeleton() == skeleton);
    }

    /** Row-major 3x4 matrices, each multiplied on the right by the model's bind shape matrix. */
    private static float[] timesBindShape(float[] rows, int joints) {
        Matrix4f bsm = new Matrix4f(MODEL.instances().get(0).skin().bindShapeMatrix());
        float[] out = new float[rows.length];
        Matrix4f m = new Matrix4f();
        for (int j = 0; j < joints; j++) {
            AnimationHelper.getRowMajor3x4(rows, 12 * j, m).mul(bsm);
            AnimationHelper.putRowMajor3x4(m, out, 12 * j);
        }
        return out;
    }

    @Test
    void theGeometryHoldsItsPointsInBindSpace() {
        // BSM = T(0 0 5) Rz(90) applied once to every point: position (x y z) -> (-y x z + 5).
        SkinnedGeometry geometry = SkinnedGeometry.of(MODEL.instances().get(0));
        float[] mesh = MODEL.instances().get(0).mesh().positions();
        for (int p = 0; p < geometry.positionCount(); p++) {
            int q = 3 * geometry.pointOfPosition(p);
            assertEquals(-mesh[3 * p + 1], geometry.positionArray()[q], EPS, "x of position " + p);
            assertEquals(mesh[3 * p], geometry.positionArray()[q + 1], EPS, "y of position " + p);
            assertEquals(mesh[3 * p + 2] + 5, geometry.positionArray()[q + 2], EPS, "z of position " + p);
        }
        assertFalse(geometry.windingMirrored(), "a rotation and a translation do not mirror");
    }

    @Test
    void worldAndSkinningMatricesEqualJomlsProductsToTheBit() throws Exception {
        // Evaluation multiplies on float arrays, in the order of JOML's Matrix4f.mul; so a pose of
        // the walking humanoid (one <matrix> per node) and of this file (mixed stacks) must give
        // JOML's own products root to leaf, and JOML's world * bind, exactly (== on each float,
        // so only the sign of a zero may differ).
        for (Model model : new Model[] {MODEL, ColladaImporter.read(TestPaths.asset("characters/humanoid-walk.dae"))}) {
            Skeleton skeleton = Skeleton.of(model);
            Pose pose = skeleton.newPose();
            AnimationSampler sampler = new AnimationSampler(skeleton, model.clips().get(0));
            SkinnedGeometry geometry = SkinnedGeometry.of(model.instances().get(0));
            int[] jointNodes = geometry.jointNodeArray();
            float[] bind = geometry.bindMatrixArray();
            float[] palette = new float[12 * jointNodes.length];
            for (float t : new float[] {0.1f, 0.37f, 0.5f, 0.93f}) {
                sampler.sample(t, RotationInterpolation.SLERP, pose);
                skeleton.evaluate(pose);
                skeleton.skinningMatrices(pose, jointNodes, bind, palette);
                Matrix4f[] world = new Matrix4f[skeleton.nodeCount()];
                Matrix4f scratch = new Matrix4f();
                for (int i = 0; i < world.length; i++) {
                    Matrix4f local = new Matrix4f();
                    for (int e = 0; e < model.node(i).transforms().size(); e++) {
                        TransformElement.multiply(skeleton.kind(i, e), pose.values(), skeleton.valueOffset(i, e), local,
                                scratch);
                    }
                    int p = skeleton.parent(i);
                    world[i] = p < 0 ? local : new Matrix4f(world[p]).mul(local);
                    float[] expected = world[i].get(new float[16]);
                    float[] actual = pose.world(i, new Matrix4f()).get(new float[16]);
                    assertArrayEquals(expected, actual, 0f, model.nodes().size() + " nodes: node " + i + " at " + t);
                }
                for (int j = 0; j < jointNodes.length; j++) {
                    Matrix4f w = jointNodes[j] < 0 ? new Matrix4f() : new Matrix4f(world[jointNodes[j]]);
                    float[] expected = new float[12];
                    AnimationHelper.putRowMajor3x4(w.mul(new Matrix4f().set(bind, 16 * j)), expected, 0);
                    assertArrayEquals(expected, Arrays.copyOfRange(palette, 12 * j, 12 * j + 12), 0f,
                            model.nodes().size() + " nodes: joint " + j + " at " + t);
                }
            }
        }
    }

    private static void assertRow12(float[] expected, float[] actual, int joint) {
        for (int i = 0; i < 12; i++) {
            assertEquals(expected[i], actual[12 * joint + i], EPS, "joint " + joint + ", row " + i / 4 + ", column " + i % 4);
        }
    }
}
