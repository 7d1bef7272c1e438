package org.skinlab.skinning;

/**
 * A joint palette laid out for a float texture, for GPUs without texture buffers (OpenGL ES 3.0,
 * and engines that only bind textures): {@value #TEXELS_PER_JOINT} RGBA texels per joint, one row
 * per joint, read with {@code texelFetch(palette, ivec2(k, joint), 0)}: k = 0-2 the rows of the
 * 3x4 skinning matrix, 3-4 the dual quaternion (rotation x y z w, dual part), 5-7 the rows of the
 * scale part (DQS's and CoR's scale phase; identity rows when there is none), 8-13 the bone rows
 * ({@link JointPalette#boneRows}, for the methods that read bones). The Android app and the
 * jMonkeyEngine control both upload this layout; their shader headers take the k from these
 * constants.
 */
public final class PaletteTexels {
    /** Texels per joint. */
    public static final int TEXELS_PER_JOINT = 14;
    /** First texel of a joint's skinning matrix rows (3 texels). */
    public static final int MATRIX_TEXEL = 0;
    /** The texel of a joint's dual quaternion's rotation; its dual part is the next one. */
    public static final int ROTATION_TEXEL = 3;
    /** First texel of a joint's scale part rows (3 texels). */
    public static final int SCALE_TEXEL = 5;
    /** First texel of a joint's bone rows ({@link JointPalette#BONE_FLOATS} / 4 texels). */
    public static final int BONE_TEXEL = 8;
    private static final float[] IDENTITY_ROWS = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

    private PaletteTexels() {
    }

    /**
     * Floats needed for a palette.
     *
     * @param joints the palette's joint count
     * @return {@code 4 * TEXELS_PER_JOINT * joints}
     */
    public static int floats(int joints) {
        return 4 * TEXELS_PER_JOINT * joints;
    }

    /**
     * Packs a palette. Allocation-free.
     *
     * @param joints          how many joints
     * @param matrices        12 floats per joint (row-major 3x4)
     * @param dualQuaternions 8 floats per joint
     * @param scales          12 floats per joint, or null for identity rows
     * @param boneRows        {@link JointPalette#BONE_FLOATS} floats per joint, or null: their texels
     *                        are left as they are
     * @param dest            at least {@link #floats}{@code (joints)} floats
     */
    public static void pack(int joints, float[] matrices, float[] dualQuaternions, float[] scales, float[] boneRows,
            float[] dest) {
        for (int j = 0; j < joints; j++) {
            int o = 4 * TEXELS_PER_JOINT * j;
            System.arraycopy(matrices, 12 * j, dest, o + 4 * MATRIX_TEXEL, 12);
            System.arraycopy(dualQuaternions, 8 * j, dest, o + 4 * ROTATION_TEXEL, 8);
            if (scales != null) {
                System.arraycopy(scales, 12 * j, dest, o + 4 * SCALE_TEXEL, 12);
            } else {
                System.arraycopy(IDENTITY_ROWS, 0, dest, o + 4 * SCALE_TEXEL, 12);
            }
            if (boneRows != null) {
                System.arraycopy(boneRows, JointPalette.BONE_FLOATS * j, dest, o + 4 * BONE_TEXEL,
                        JointPalette.BONE_FLOATS);
            }
        }
    }

    /**
     * Packs a prepared palette: its matrices, dual quaternions, scale parts when it has any, and
     * its bone rows when asked. Allocation-free.
     *
     * @param palette   the palette, prepared for the method the shader runs
     * @param withBones whether to pack the bone rows (current only for a palette prepared with bones)
     * @param dest      at least {@link #floats}{@code (palette.jointCount())} floats
     */
    public static void pack(JointPalette palette, boolean withBones, float[] dest) {
        pack(palette.jointCount(), palette.matrices(), palette.dualQuaternions(),
                palette.hasScale() ? palette.scales() : null, withBones ? palette.boneRows() : null, dest);
    }
}
