package org.skinlab.skinning;

import org.skinlab.glsl.GlslInclude;

/**
 * The GPU's twin of this package's kernels: the GLSL text of the methods that fit a vertex shader
 * ({@code skinning.glsl}, a resource beside this class; its opening comment says what a shader
 * must declare before it, among it the palette's bone rows {@code boneRow(joint, row)} for the
 * methods that read bones, and why it lives here), which the desktop's and the Android app's
 * vertex shaders both include. Plain text to core: no GL here.
 *
 * <p>A method without shader code ({@link #hasCode} false) is skinned on the CPU even when the
 * configuration asks for GPU skinning: the simulation then publishes skinned frames, which both
 * renderers draw as they are (see {@code SkeletalAnimatedMesh}).
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
     * @param shader the GLSL source text, with {@link #INCLUDE} alone on its line where the formulas go
     * @return the expanded source, or {@code shader} itself when it has no include line
     * @throws IllegalStateException when the line occurs more than once (GLSL refuses functions
     *                               defined twice; better said here), or the resource cannot be read
     */
    public static String expand(String shader) {
        return FILE.expand(shader);
    }

    /**
     * Whether the formulas' {@code skin(method, ...)} has code for {@code method}, so that a
     * renderer may skin it in the vertex shader; a method without is skinned on the CPU.
     *
     * @param method the method
     * @return true for every method but {@link SkinningMethod#SPLINE}
     */
    public static boolean hasCode(SkinningMethod method) {
        return code(method) != 0;
    }

    /**
     * The code of a method in the formulas' {@code skin(method, ...)}: 1 LBS, 2 DQS, 3 CoR (0 skins
     * nothing).
     *
     * @param method a method with shader code ({@link #hasCode})
     * @return the value of the shader's {@code method} argument: 1 LBS, 2 DQS, 3 CoR, 4 BFDQS,
     *         5 STBS_LBS, 6 STBS_DQS
     * @throws IllegalArgumentException for a method without shader code ({@link #hasCode})
     */
    public static int methodCode(SkinningMethod method) {
        int code = code(method);
        if (code == 0) {
            throw new IllegalArgumentException("no shader code for " + method);
        }
        return code;
    }

    /** The one list of codes: each method helper adds its case here; 0 for a method without shader code. */
    private static int code(SkinningMethod method) {
        switch (method) {
            case LBS:
                return 1;
            case DQS:
                return 2;
            case COR:
                return 3;
            case BFDQS:
                return 4;
            case STBS_LBS:
                return 5;
            case STBS_DQS:
                return 6;
            default:
                return 0;
        }
    }

    /**
     * The formulas' text, read from the resource on each call (once per program a renderer builds).
     *
     * @return the GLSL text of {@code skinning.glsl}, decoded as UTF-8
     * @throws IllegalStateException when the resource is missing from the class path or cannot be read
     */
    public static String formulas() {
        return FILE.text();
    }
}
