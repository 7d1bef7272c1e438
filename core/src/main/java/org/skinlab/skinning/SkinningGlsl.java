package org.skinlab.skinning;

import org.skinlab.glsl.GlslInclude;

/**
 * The GPU's twin of this package's kernels: the GLSL text of LBS, DQS and CoR
 * ({@code skinning.glsl}, a resource beside this class; its opening comment says what a shader
 * must declare before it and why it lives here), which the desktop's and the Android app's vertex
 * shaders both include. Plain text to core: no GL here.
 */
public final class SkinningGlsl {
    private static final GlslInclude FILE = new GlslInclude("/org/skinlab/skinning/skinning.glsl", "the skinning shader's formulas");

    /** The line of a shader that {@link #expand} replaces with the formulas. */
    public static final String INCLUDE = FILE.line();

    private SkinningGlsl() {
    }

    /**
     * {@code shader} with its {@link #INCLUDE} line replaced by the formulas; a shader without
     * that line comes back unchanged.
     *
     * @throws IllegalStateException when the line occurs more than once (GLSL refuses functions
     *                               defined twice; better said here), or the resource cannot be read
     */
    public static String expand(String shader) {
        return FILE.expand(shader);
    }

    /** The code of a method in the formulas' {@code skin(method, ...)}: 1 LBS, 2 DQS, 3 CoR (0 skins nothing). */
    public static int methodCode(SkinningMethod method) {
        switch (method) {
            case LBS:
                return 1;
            case DQS:
                return 2;
            case COR:
                return 3;
            case STBS_LBS:
                return 5;
            case STBS_DQS:
                return 6;
            default:
                throw new IllegalArgumentException("no shader code for " + method);
        }
    }

    /** The formulas' text, read from the resource on each call (once per program a renderer builds). */
    public static String formulas() {
        return FILE.text();
    }
}
