package org.skinlab.internal.scene;

import org.skinlab.glsl.GlslInclude;

/**
 * The fragment shaders' surface formulas, {@code material.glsl} (a resource beside this class; its
 * opening comment lists its uniforms): base colour times texture and vertex colour, the alpha
 * modes, texture transforms and emission of a {@link PartMaterial}. The desktop's and the Android
 * app's model fragment shaders both include it. Plain text to core: no GL here.
 */
public final class MaterialGlsl {
    private static final GlslInclude FILE = new GlslInclude("/org/skinlab/internal/scene/material.glsl",
            "the material shader's formulas");

    /** The line of a shader that {@link #expand} replaces with the formulas. */
    public static final String INCLUDE = FILE.line();

    /** {@code uAlphaMode}'s values. */
    public static final int OPAQUE = 0;
    public static final int MASK = 1;
    public static final int BLEND = 2;

    private MaterialGlsl() {
    }

    /**
     * {@code shader} with its {@link #INCLUDE} line replaced by the formulas; a shader without it
     * comes back unchanged.
     *
     * @throws IllegalStateException when the line occurs twice, or the resource cannot be read
     */
    public static String expand(String shader) {
        return FILE.expand(shader);
    }

    /** The {@code uAlphaMode} value of {@code m}. */
    public static int alphaMode(PartMaterial m) {
        return switch (m.alphaMode()) {
            case OPAQUE -> OPAQUE;
            case MASK -> MASK;
            case BLEND -> BLEND;
        };
    }
}
