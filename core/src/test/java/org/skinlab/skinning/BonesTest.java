package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;

/**
 * Bones derived from joints, and the palette's bone rows, on a hand-derived chain: joint 0 at
 * the origin, joint 1 at (0, 1, 0) (its child, along joint 0's Y axis), points up to y = 2.
 */
class BonesTest {
    private static final float EPS = 1e-6f;

    /** Two joints on the Y axis, points at y = 0.5 (joint 0) and 1.5, 2 (joint 1); joint 2 a sibling off-axis. */
    private static SkinnedGeometry chain() {
        float[] positions = {0.2f, 0.5f, 0f, 0.2f, 1.5f, 0f, 0f, 2f, 0.1f, 1f, 0.5f, 0f};
        float[] normals = new float[positions.length];
        int[] joints = {0, 1, 1, 2};
        float[] weights = {1, 1, 1, 1};
        float[] bind = new float[48];
        new Matrix4f().get(bind, 0);
        new Matrix4f().translation(0, -1, 0).get(bind, 16);
        // A sibling child of joint 0 at (1, 0.5, 0): less along joint 0's Y axis than joint 1.
        new Matrix4f().translation(-1, -0.5f, 0).get(bind, 32);
        return SkinnedGeometry.fromArrays(positions, normals, 1, joints, weights, bind, new int[] {-1, 0, 0});
    }

    @Test
    void aJointPointsAtTheChildAlongItsAxisAndALeafAsFarAsItsPointsReach() {
        Bones bones = chain().bones();
        assertEquals(1, bones.tailJoint(0));
        assertEquals(-1, bones.tailJoint(1));
        assertEquals(1f, bones.length(0), EPS);
        // Joint 1's farthest dominated point is at y = 2, one unit along its axis.
        assertEquals(1f, bones.length(1), EPS);
        assertEquals(2f, bones.tail(1, 1), EPS);
        // Joint 2 dominates only (1, 0.5, 0), its own head: a point-like bone.
        assertEquals(0f, bones.length(2), EPS);
        assertEquals(0, bones.parent(2));
    }

    @Test
    void withoutANodeTreeEveryJointIsALeaf() {
        SkinnedGeometry g = chain();
        SkinnedGeometry flat = SkinnedGeometry.fromArrays(g.positionArray(), g.normalArray(), 1, g.jointArray(),
                g.weightArray(), g.bindMatrixArray());
        assertEquals(-1, flat.bones().tailJoint(0));
        assertEquals(-1, flat.bones().parent(1));
    }

    @Test
    void aChildTwistedAboutItsBoneHasThatTwistAndAStretchedOneItsOffset() {
        SkinnedGeometry g = chain();
        JointPalette palette = g.newPalette();
        // Joint 1 turned 90 degrees about its own axis (Y through (0, 1, 0)), then scaled 1.5 along it.
        Matrix4f m = new Matrix4f().translation(0, 1, 0).rotateY((float) (Math.PI / 2)).scale(1f, 1.5f, 1f)
                .translate(0, -1, 0);
        palette.setMatrix(1, m);
        palette.prepareAll();
        float[] rows = palette.boneRows();
        int b = JointPalette.BONE_FLOATS;
        assertEquals((float) (Math.PI / 2), rows[b + 3], 1e-5f, "twist");
        assertArrayEquals(new float[] {0f, 2.5f, 0f, 1.5f}, slice(rows, b + 4), 1e-5f, "posed tail, stretch");
        assertArrayEquals(new float[] {0f, 0.5f, 0f, 0f}, slice(rows, b + 8), 1e-5f, "stretch offset");
        assertArrayEquals(new float[] {0f, 1f, 0f, 0f}, slice(rows, b + 12), 1e-5f, "posed axis");
        assertArrayEquals(new float[] {0f, 1f, 0f, 1f}, slice(rows, b + 16), 1e-6f, "rest head, length");
        assertArrayEquals(new float[] {0f, 2f, 0f, 0f}, slice(rows, b + 20), 1e-6f, "rest tail, parent");
        assertEquals(0f, rows[3], "a root has no twist");
        assertEquals(-1f, rows[23], "a root has no parent");
    }

    @Test
    void aPaletteWithoutBonesSaysSo() {
        JointPalette palette = JointPalette.withoutBindFrames(2);
        palette.prepare(SkinningMethod.DQS);
        assertThrows(IllegalStateException.class, () -> palette.prepare(SkinningMethod.SPLINE));
        assertThrows(IllegalStateException.class, palette::boneRows);
    }

    @Test
    void methodKeysRoundTrip() {
        for (SkinningMethod m : SkinningMethod.values()) {
            assertEquals(m, SkinningMethod.fromKey(m.key()));
        }
        assertEquals("stbs-dqs", SkinningMethod.STBS_DQS.key());
        assertEquals(SkinningMethod.STBS_LBS, SkinningMethod.fromKey("STBS_LBS"));
    }

    private static float[] slice(float[] a, int from) {
        return java.util.Arrays.copyOfRange(a, from, from + 4);
    }
}
