package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

/** The float-texture layout of a palette, by hand-made values. */
class PaletteTexelsTest {
    @Test
    void laysOutMatricesDualQuaternionsScalesAndBoneRows() {
        float[] m = new float[24];
        float[] dq = new float[16];
        for (int i = 0; i < m.length; i++) {
            m[i] = i;
        }
        for (int i = 0; i < dq.length; i++) {
            dq[i] = 100 + i;
        }
        float[] bones = new float[2 * JointPalette.BONE_FLOATS];
        for (int i = 0; i < bones.length; i++) {
            bones[i] = 1000 + i;
        }
        float[] dest = new float[PaletteTexels.floats(2)];
        PaletteTexels.pack(2, m, dq, null, bones, dest);
        int row = 4 * PaletteTexels.TEXELS_PER_JOINT;
        assertEquals(12, dest[row], "joint 1's first matrix row starts its texture row");
        assertEquals(108, dest[row + 12], "then its dual quaternion");
        assertArrayEquals(new float[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, java.util.Arrays.copyOfRange(dest, 20, 32),
                "no scale: identity rows");
        assertArrayEquals(java.util.Arrays.copyOfRange(bones, 24, 48),
                java.util.Arrays.copyOfRange(dest, row + 32, row + 56), "joint 1's six bone rows after its scale rows");
        assertEquals(row, 56, "14 texels a joint");
    }
}
