package org.skinlab.skinning;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

/**
 * The GPU's twin of this package's kernels: the GLSL text of LBS, DQS and CoR
 * ({@code skinning.glsl}, a resource beside this class; its opening comment says what a shader
 * must declare before it and why it lives here), which the desktop's and the Android app's vertex
 * shaders both include. Plain text to core: no GL here.
 */
public final class SkinningGlsl {
    /** The line of a shader that {@link #expand} replaces with the formulas. */
    public static final String INCLUDE = "#include \"skinning.glsl\"";

    private static final String RESOURCE = "/org/skinlab/skinning/skinning.glsl";

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
        int at = lineStart(shader, 0);
        if (at < 0) {
            return shader;
        }
        if (lineStart(shader, at + INCLUDE.length()) >= 0) {
            throw new IllegalStateException("a shader includes skinning.glsl twice");
        }
        return shader.substring(0, at) + formulas() + shader.substring(at + INCLUDE.length());
    }

    /** Where the include line starts at or after {@code from} (alone on its line), or -1. */
    private static int lineStart(String shader, int from) {
        for (int at = shader.indexOf(INCLUDE, from); at >= 0; at = shader.indexOf(INCLUDE, at + 1)) {
            int end = at + INCLUDE.length();
            boolean startsLine = at == 0 || shader.charAt(at - 1) == '\n';
            boolean endsLine = end == shader.length() || shader.charAt(end) == '\n' || shader.charAt(end) == '\r';
            if (startsLine && endsLine) {
                return at;
            }
        }
        return -1;
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
            default:
                throw new IllegalArgumentException("no shader code for " + method);
        }
    }

    /** The formulas' text, read from the resource on each call (once per program a renderer builds). */
    public static String formulas() {
        // Read by hand: InputStream.readAllBytes needs Android 13, and the app runs from Android 8.
        try (InputStream in = SkinningGlsl.class.getResourceAsStream(RESOURCE)) {
            if (in == null) {
                throw new IllegalStateException("the skinning shader's formulas " + RESOURCE
                        + " are missing from the classpath (an APK must carry them at its root)");
            }
            ByteArrayOutputStream out = new ByteArrayOutputStream(8192);
            byte[] buffer = new byte[8192];
            for (int n = in.read(buffer); n >= 0; n = in.read(buffer)) {
                out.write(buffer, 0, n);
            }
            return new String(out.toByteArray(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalStateException("cannot read the skinning shader's formulas " + RESOURCE, e);
        }
    }
}
