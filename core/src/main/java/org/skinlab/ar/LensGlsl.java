package org.skinlab.ar;

import org.skinlab.glsl.GlslInclude;

/**
 * The GPU's twin of {@link LensDistortion#distort}: the GLSL text of {@code lens.glsl} (a resource
 * beside this class; its opening comment says how a background shader uses it), which the
 * desktop's and the Android app's camera-background fragment shaders both include, so that the
 * background they draw is the pinhole image the model is projected into. Plain text to core: no
 * GL here. {@link #uniforms} gives the numbers its functions take.
 */
public final class LensGlsl {
    private static final GlslInclude FILE = new GlslInclude("/org/skinlab/ar/lens.glsl", "the lens shader's formulas");

    /** The line of a shader that {@link #expand} replaces with the formulas. */
    public static final String INCLUDE = FILE.line();

    private LensGlsl() {
    }

    /**
     * {@code shader} with its {@link #INCLUDE} line (alone on its line) replaced by the formulas; a
     * shader without that line comes back unchanged.
     *
     * @param shader a fragment shader's GLSL source, possibly with the {@link #INCLUDE} line
     * @return the expanded source, or {@code shader} itself when it has no such line
     * @throws IllegalStateException when the line occurs twice, or the resource cannot be read
     */
    public static String expand(String shader) {
        return FILE.expand(shader);
    }

    /**
     * The arguments of {@code lensSourceCoord} for camera {@code k}, into {@code out[0..10]}: size
     * (w, h), pinhole (fx, fy, cx, cy), radial (k1, k2, k3), tangential (p1, p2).
     *
     * @param k   the camera whose image the background shows (its size in pixels, pinhole and lens)
     * @param out at least 11 floats; entries 0..10 are overwritten, the rest untouched
     * @return {@code out}, for chaining
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

    /**
     * The formulas' text, read from the resource on each call (once per program a renderer builds).
     *
     * @return the GLSL text of {@code lens.glsl} that {@link #expand} puts in place of the {@link #INCLUDE} line
     * @throws IllegalStateException when the resource cannot be read
     */
    public static String formulas() {
        return FILE.text();
    }
}
