package org.skinlab.android.logic;

import org.skinlab.simulation.Frame;
import org.skinlab.skinning.JointPalette;

/**
 * One geometry's joint palette of a {@link Frame} laid out for an OpenGL ES 3.0 float texture
 * (ES 3.0 has no texture buffers): {@value #TEXELS_PER_JOINT} RGBA32F texels per joint in one row
 * per joint, read in the shader with {@code texelFetch(palette, ivec2(k, joint), 0)}: k = 0-2 the
 * rows of the 3x4 skinning matrix, 3-4 the dual quaternion (rotation x y z w, dual part), 5-7 the
 * rows of the scale part (DQS's and CoR's scale phase; identity rows when the frame has none),
 * 8-13 the bone rows ({@link Frame#boneRows}, for the methods that read bones). The shader's
 * header takes those k from the constants below ({@link GlesShaders}).
 *
 * <p>The bone rows are packed with every frame, whatever its method: the palette goes up as one
 * texture per geometry in one call, and leaving 6 of 14 texels out would take a second call and
 * an unpack row length to save 96 bytes per joint.
 */
public final class PaletteTexture {
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

    private PaletteTexture() {
    }

    /** Floats needed for {@code joints} joints. */
    public static int floats(int joints) {
        return 4 * TEXELS_PER_JOINT * joints;
    }

    /** Packs geometry {@code g}'s palette of {@code frame} into {@code dest} (at least {@link #floats}). */
    public static void pack(Frame frame, int g, float[] dest) {
        int joints = frame.palette(g).jointCount();
        float[] m = frame.palette(g).matrices();
        float[] dq = frame.palette(g).dualQuaternions();
        float[] sc = frame.palette(g).hasScale() ? frame.palette(g).scales() : null;
        pack(joints, m, dq, sc, frame.palette(g).boneRows(), dest);
    }

    /**
     * The packing itself: {@code matrices} 12 floats per joint (row-major 3x4), {@code dualQuaternions}
     * 8 per joint, {@code scales} 12 per joint or null (identity), {@code boneRows}
     * {@link JointPalette#BONE_FLOATS} per joint or null (their texels are left as they are).
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
}
