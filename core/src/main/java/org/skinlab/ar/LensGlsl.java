package org.skinlab.ar;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

/**
 * The GPU's twin of {@link LensDistortion#distort}: the GLSL text of {@code lens.glsl} (a resource
 * beside this class; its opening comment says how a background shader uses it), which the
 * desktop's and the Android app's camera-background fragment shaders both include, so that the
 * background they draw is the pinhole image the model is projected into. Plain text to core: no
 * GL here. {@link #uniforms} gives the numbers its functions take.
 */
public final class LensGlsl {
    /** The line of a shader that {@link #expand} replaces with the formulas. */
    public static final String INCLUDE = "#include \"lens.glsl\"";

    private static final String RESOURCE = "/org/skinlab/ar/lens.glsl";

    private LensGlsl() {
    }

    /**
     * {@code shader} with its {@link #INCLUDE} line (alone on its line) replaced by the formulas; a
     * shader without that line comes back unchanged.
     *
     * @throws IllegalStateException when the line occurs twice, or the resource cannot be read
     */
    public static String expand(String shader) {
        int at = lineStart(shader, 0);
        if (at < 0) {
            return shader;
        }
        if (lineStart(shader, at + INCLUDE.length()) >= 0) {
            throw new IllegalStateException("a shader includes lens.glsl twice");
        }
        return shader.substring(0, at) + formulas() + shader.substring(at + INCLUDE.length());
    }

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

    /**
     * The arguments of {@code lensSourceCoord} for camera {@code k}, into {@code out[0..10]}: size
     * (w, h), pinhole (fx, fy, cx, cy), radial (k1, k2, k3), tangential (p1, p2).
     */
    public static float[] uniforms(CameraIntrinsics k, float[] out) {
        LensDistortion d = k.distortion();
        out[0] = k.width();
        out[1] = k.height();
        out[2] = (float) k.fx();
        out[3] = (float) k.fy();
        out[4] = (float) k.cx();
        out[5] = (float) k.cy();
        out[6] = (float) d.k1();
        out[7] = (float) d.k2();
        out[8] = (float) d.k3();
        out[9] = (float) d.p1();
        out[10] = (float) d.p2();
        return out;
    }

    /** The formulas' text, read from the resource on each call (once per program a renderer builds). */
    public static String formulas() {
        // Read by hand: InputStream.readAllBytes needs Android 13, and the app runs from Android 8.
        try (InputStream in = LensGlsl.class.getResourceAsStream(RESOURCE)) {
            if (in == null) {
                throw new IllegalStateException("the lens shader's formulas " + RESOURCE
                        + " are missing from the classpath (an APK must carry them at its root)");
            }
            ByteArrayOutputStream out = new ByteArrayOutputStream(4096);
            byte[] buffer = new byte[4096];
            for (int n = in.read(buffer); n >= 0; n = in.read(buffer)) {
                out.write(buffer, 0, n);
            }
            return new String(out.toByteArray(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalStateException("cannot read the lens shader's formulas " + RESOURCE, e);
        }
    }
}
