package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.testing.TestPaths;

/**
 * The stretch and twist assets (assets/README.md, made by assets/src/make_limb.py) deliver what
 * the bone methods read, in both files: bones of length 1 m along a chain, and at the key times
 * the README names the middle bone's stretch (1.25 at 0.5 s, 1.5 at 1 s, the end bone carried
 * unstretched to the stretched tail) and the forearm's twist relative to the upper arm (90
 * degrees at 0.5 s, 170 at 0.875 s, a half turn at 1 s, whose sign a relative rotation cannot
 * tell, so only its size is checked). Tolerance 1e-4: the files hold 6-7 significant digits.
 */
class LimbAssetsTest {
    private static final double EPS = 1e-4;

    private static final int HEAD = 0;
    private static final int TAIL = 1;

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"stretch/limb-stretch.dae", "stretch/limb-stretch.glb"})
    void theMiddleBoneStretchesToOneAndAHalfAndTheEndBoneIsCarriedUnstretched(String asset) throws Exception {
        Limb limb = new Limb(asset);
        int root = limb.joint("root");
        int middle = limb.joint("middle");
        int end = limb.joint("end");
        Bones bones = limb.geometry().bones();
        assertEquals(middle, bones.tailJoint(root));
        assertEquals(end, bones.tailJoint(middle));
        for (int j : new int[] {root, middle, end}) {
            assertEquals(1.0, bones.length(j), EPS, "bone length");
        }
        float[] rows = limb.rowsAt(0.5f);
        assertEquals(1.25, stretch(rows, middle), EPS);
        rows = limb.rowsAt(1f);
        assertEquals(1.0, stretch(rows, root), EPS);
        assertEquals(1.5, stretch(rows, middle), EPS);
        assertEquals(1.0, stretch(rows, end), EPS);
        // end's head sits on middle's stretched tail, 2.5 m above root's head, and end keeps its length
        assertEquals(2.5, distance(rows, root, HEAD, end, HEAD), EPS);
        assertEquals(0.0, distance(rows, middle, TAIL, end, HEAD), EPS);
        assertEquals(1.0, distance(rows, end, HEAD, end, TAIL), EPS);
        for (int j : new int[] {root, middle, end}) {
            assertEquals(0.0, twist(rows, j), EPS, "no twist");
        }
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"twist/arm-twist.dae", "twist/arm-twist.glb"})
    void theForearmTwistsTo90And170AndAHalfTurnAboutItsAxis(String asset) throws Exception {
        Limb limb = new Limb(asset);
        int upper = limb.joint("upper_arm");
        int forearm = limb.joint("forearm");
        int hand = limb.joint("hand");
        Bones bones = limb.geometry().bones();
        assertEquals(forearm, bones.tailJoint(upper));
        assertEquals(hand, bones.tailJoint(forearm));
        assertEquals(1.0, bones.length(upper), EPS);
        assertEquals(1.0, bones.length(forearm), EPS);
        assertEquals(0.4, bones.length(hand), EPS);
        float[] rows = limb.rowsAt(0.5f);
        assertEquals(Math.toRadians(90), twist(rows, forearm), EPS);
        rows = limb.rowsAt(0.875f);
        assertEquals(Math.toRadians(170), twist(rows, forearm), EPS);
        assertEquals(0.0, twist(rows, hand), EPS, "the hand turns with the forearm");
        assertEquals(1.0, stretch(rows, forearm), EPS);
        rows = limb.rowsAt(1f);
        assertEquals(Math.PI, Math.abs(twist(rows, forearm)), EPS);
    }

    private static double twist(float[] rows, int j) {
        return rows[JointPalette.BONE_FLOATS * j + 3];
    }

    private static double stretch(float[] rows, int j) {
        return rows[JointPalette.BONE_FLOATS * j + 7];
    }

    /** Distance between row {@code ra} (0 posed head, 1 posed tail) of joint a and row rb of joint b. */
    private static double distance(float[] rows, int a, int ra, int b, int rb) {
        int oa = JointPalette.BONE_FLOATS * a + 4 * ra;
        int ob = JointPalette.BONE_FLOATS * b + 4 * rb;
        double dx = rows[oa] - rows[ob];
        double dy = rows[oa + 1] - rows[ob + 1];
        double dz = rows[oa + 2] - rows[ob + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** One asset's single skinned mesh, posed through SkinnedModel. */
    private static final class Limb {
        private final Model model;
        private final SkinnedModel skinned;

        Limb(String asset) throws Exception {
            model = ModelImporter.read(TestPaths.asset(asset));
            skinned = SkinnedModel.of(model);
            assertEquals(1, skinned.geometries().size());
        }

        SkinnedGeometry geometry() {
            return skinned.geometries().get(0);
        }

        int joint(String name) {
            List<Node> nodes = model.nodes();
            for (int j = 0; j < geometry().jointCount(); j++) {
                if (nodes.get(geometry().jointNode(j)).name().equals(name)) {
                    return j;
                }
            }
            throw new AssertionError("no joint " + name);
        }

        float[] rowsAt(float t) {
            skinned.pose(t, RotationInterpolation.SLERP);
            return skinned.palette(0).prepareAll().boneRows();
        }
    }
}
