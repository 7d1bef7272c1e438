package org.skinlab.android.logic;

import org.skinlab.simulation.Frame;
import org.skinlab.skinning.PaletteTexels;

/**
 * One geometry's joint palette of a {@link Frame} laid out for an OpenGL ES 3.0 float texture
 * (ES 3.0 has no texture buffers), in core's {@link PaletteTexels} layout: one row of
 * {@value #TEXELS_PER_JOINT} RGBA32F texels per joint. The shader's header takes the texels from
 * {@link PaletteTexels}' constants ({@link GlesShaders}).
 *
 * <p>The bone rows are packed with every frame, whatever its method: the palette goes up as one
 * texture per geometry in one call, and leaving 6 of 14 texels out would take a second call and
 * an unpack row length to save 96 bytes per joint.
 */
public final class PaletteTexture {
    /** {@link PaletteTexels#TEXELS_PER_JOINT}: the texture's width. */
    public static final int TEXELS_PER_JOINT = PaletteTexels.TEXELS_PER_JOINT;

    private PaletteTexture() {
    }

    /** Floats needed for {@code joints} joints. */
    public static int floats(int joints) {
        return PaletteTexels.floats(joints);
    }

    /** Packs geometry {@code g}'s palette of {@code frame} into {@code dest} (at least {@link #floats}). */
    public static void pack(Frame frame, int g, float[] dest) {
        PaletteTexels.pack(frame.palette(g), true, dest);
    }
}
