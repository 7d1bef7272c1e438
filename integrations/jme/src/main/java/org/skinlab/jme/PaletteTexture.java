package org.skinlab.jme;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;

import com.jme3.texture.Image;
import com.jme3.texture.Texture;
import com.jme3.texture.Texture2D;
import com.jme3.texture.image.ColorSpace;
import com.jme3.util.BufferUtils;
import org.skinlab.skinning.JointPalette;

/**
 * The GPU path's joint palette: one RGBA32F texture, a row per palette joint of
 * {@link #TEXELS_PER_JOINT} texels (the Android app's layout, since both read it through
 * skinning.glsl's paletteRow/paletteRotation/paletteDual/boneRow): texels 0-2 the skinning matrix
 * M (row-major 3x4), 3-4 the dual quaternion (rotation, dual part), 5-7 the scale part S (identity
 * when no joint has scale), 8-13 the bone rows (for the methods that read bones). The control
 * fills it each frame; jME uploads it when the material binds it.
 */
final class PaletteTexture {
    static final int TEXELS_PER_JOINT = 14;
    static final int MATRIX_TEXEL = 0;
    static final int ROTATION_TEXEL = 3;
    static final int SCALE_TEXEL = 5;
    static final int BONE_TEXEL = 8;
    private static final float[] IDENTITY_ROWS = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};

    private final int joints;
    private final Image image;
    private final Texture2D texture;
    private final ByteBuffer bytes;
    private final FloatBuffer floats;
    private final float[] row = new float[4 * TEXELS_PER_JOINT];

    PaletteTexture(int joints) {
        this.joints = joints;
        bytes = BufferUtils.createByteBuffer(4 * 4 * TEXELS_PER_JOINT * joints);
        floats = bytes.asFloatBuffer();
        image = new Image(Image.Format.RGBA32F, TEXELS_PER_JOINT, joints, bytes, ColorSpace.Linear);
        texture = new Texture2D(image);
        // texelFetch reads exact texels; no mipmaps, so the texture is complete.
        texture.setMagFilter(Texture.MagFilter.Nearest);
        texture.setMinFilter(Texture.MinFilter.NearestNoMipMaps);
        texture.setWrap(Texture.WrapMode.EdgeClamp);
    }

    Texture2D texture() {
        return texture;
    }

    /**
     * Copies the palette (prepared for the method the shader runs) into the texture. Allocation-free.
     *
     * @param palette  this frame's palette
     * @param withBones whether the bone rows are current (the method reads bones)
     */
    void fill(JointPalette palette, boolean withBones) {
        float[] m = palette.matrices();
        float[] dq = palette.dualQuaternions();
        float[] s = palette.hasScale() ? palette.scales() : null;
        float[] bones = withBones ? palette.boneRows() : null;
        floats.clear();
        for (int j = 0; j < joints; j++) {
            System.arraycopy(m, 12 * j, row, 4 * MATRIX_TEXEL, 12);
            System.arraycopy(dq, 8 * j, row, 4 * ROTATION_TEXEL, 8);
            System.arraycopy(s != null ? s : IDENTITY_ROWS, s != null ? 12 * j : 0, row, 4 * SCALE_TEXEL, 12);
            if (bones != null) {
                System.arraycopy(bones, JointPalette.BONE_FLOATS * j, row, 4 * BONE_TEXEL, JointPalette.BONE_FLOATS);
            }
            floats.put(row);
        }
        bytes.rewind();
        image.setData(0, bytes);
    }
}
