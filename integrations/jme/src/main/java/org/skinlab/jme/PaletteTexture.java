package org.skinlab.jme;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;

import com.jme3.texture.Image;
import com.jme3.texture.Texture;
import com.jme3.texture.Texture2D;
import com.jme3.texture.image.ColorSpace;
import com.jme3.util.BufferUtils;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.PaletteTexels;

/**
 * The GPU path's joint palette: one RGBA32F texture in core's {@link PaletteTexels} layout (the
 * Android app's too, since both read it through skinning.glsl's paletteRow/paletteRotation/
 * paletteDual/boneRow), a row per palette joint. The control fills it each frame; jME uploads it
 * when the material binds it.
 */
final class PaletteTexture {
    private final Image image;
    private final Texture2D texture;
    private final ByteBuffer bytes;
    private final FloatBuffer floats;
    private final float[] packed;

    PaletteTexture(int joints) {
        packed = new float[PaletteTexels.floats(joints)];
        bytes = BufferUtils.createByteBuffer(4 * packed.length);
        floats = bytes.asFloatBuffer();
        image = new Image(Image.Format.RGBA32F, PaletteTexels.TEXELS_PER_JOINT, joints, bytes, ColorSpace.Linear);
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
        PaletteTexels.pack(palette, withBones, packed);
        floats.clear();
        floats.put(packed);
        bytes.rewind();
        image.setData(0, bytes);
    }
}
