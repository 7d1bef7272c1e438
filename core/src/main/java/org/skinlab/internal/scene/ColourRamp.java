package org.skinlab.internal.scene;

import java.util.Locale;

import org.skinlab.glsl.GlslInclude;

/**
 * The colour map of the viewer's data views (the weight and difference views): blue, cyan, green,
 * yellow and red at fractions 0, 1/4, 1/2, 3/4 and 1, mixed linearly between neighbours, so that
 * a picture reads without a legend's fine print. Its one home: the fragment shader's
 * {@code colourRamp(x)} is generated from {@link #STOPS} ({@link #expand}, for the line
 * {@code #include "colour-ramp.glsl"}), and {@link #colour(double)} gives the same colours to Java
 * code (a Java2D legend beside a picture: {@code new java.awt.Color(ColourRamp.colour(f))}).
 * Both compute in single precision by GLSL's {@code mix(a, b, t) = a (1 - t) + b t}, so the
 * shader and the legend agree to the rounding of the 8-bit framebuffer. Plain Java: no GL, no AWT.
 */
public final class ColourRamp {
    /** The colours at equal steps of the fraction, RGB in 0..1 as the framebuffer stores them. */
    private static final float[][] STOPS = {
        {0.10f, 0.20f, 0.75f}, // blue: none
        {0.10f, 0.75f, 0.85f}, // cyan
        {0.20f, 0.80f, 0.20f}, // green
        {0.95f, 0.85f, 0.15f}, // yellow
        {0.90f, 0.15f, 0.10f}, // red: the top of the scale, and beyond
    };

    private static final GlslInclude FILE = GlslInclude.generated("colour-ramp.glsl", glsl());

    /** The line of a shader that {@link #expand} replaces with {@code colourRamp}'s definition. */
    public static final String INCLUDE = FILE.line();

    private ColourRamp() {
    }

    /** Number of colour stops: fractions {@code i / (stopCount() - 1)}. */
    public static int stopCount() {
        return STOPS.length;
    }

    /**
     * The colour at {@code fraction} of the scale (clamped to 0..1; NaN counts as 0), as red, green,
     * blue in 0..1 into {@code rgb[0..2]}. Allocation-free.
     */
    public static void colour(double fraction, float[] rgb) {
        float x = (float) fraction;
        // clamp(x, 0.0, 1.0) in GLSL; NaN would pick no segment there either.
        x = x > 0f ? Math.min(x, 1f) : 0f;
        float s = x * (STOPS.length - 1);
        int i = Math.min((int) s, STOPS.length - 2);
        float t = s - i;
        float[] a = STOPS[i];
        float[] b = STOPS[i + 1];
        for (int c = 0; c < 3; c++) {
            rgb[c] = a[c] * (1f - t) + b[c] * t;
        }
    }

    /**
     * The colour at {@code fraction} of the scale (clamped to 0..1) as 8-bit sRGB packed
     * {@code 0xRRGGBB}, what {@code java.awt.Color(int)} and {@code BufferedImage.setRGB} take
     * (the alpha byte is 0: use {@code 0xFF000000 | colour(f)} for an opaque ARGB pixel).
     */
    public static int colour(double fraction) {
        float[] rgb = new float[3];
        colour(fraction, rgb);
        return level(rgb[0]) << 16 | level(rgb[1]) << 8 | level(rgb[2]);
    }

    /** A colour channel in 0..1 as the framebuffer's 8-bit level (GL's conversion rounds to nearest). */
    private static int level(float c) {
        return Math.round(Math.max(0f, Math.min(1f, c)) * 255f);
    }

    /**
     * {@code shader} with its {@link #INCLUDE} line replaced by the definition of
     * {@code vec3 colourRamp(float x)} (valid GLSL 330 and GLSL ES 3.00); a shader without the line
     * comes back unchanged.
     *
     * @throws IllegalStateException when the line occurs twice
     */
    public static String expand(String shader) {
        return FILE.expand(shader);
    }

    /** The definition of {@code colourRamp}, one segment per pair of neighbouring stops. */
    private static String glsl() {
        StringBuilder b = new StringBuilder();
        b.append("// The data views' colour map, generated from org.skinlab.internal.scene.ColourRamp's stops.\n");
        b.append("vec3 colourRamp(float x) {\n");
        for (int i = 0; i < STOPS.length; i++) {
            b.append("    const vec3 c").append(i).append(" = vec3(").append(literal(STOPS[i][0])).append(", ")
                    .append(literal(STOPS[i][1])).append(", ").append(literal(STOPS[i][2])).append(");\n");
        }
        b.append("    float s = clamp(x, 0.0, 1.0) * ").append(literal(STOPS.length - 1)).append(";\n");
        for (int i = 0; i < STOPS.length - 2; i++) {
            b.append("    if (s < ").append(literal(i + 1)).append(") return mix(c").append(i).append(", c")
                    .append(i + 1).append(", s - ").append(literal(i)).append(");\n");
        }
        int last = STOPS.length - 2;
        b.append("    return mix(c").append(last).append(", c").append(last + 1).append(", s - ")
                .append(literal(last)).append(");\n");
        b.append("}\n");
        return b.toString();
    }

    /**
     * A float as a GLSL literal that parses to the same float: Java's shortest round-trip digits,
     * with a decimal point always (GLSL ES refuses {@code 1} where it wants a float).
     */
    private static String literal(float f) {
        String s = Float.toString(f).toLowerCase(Locale.ROOT);
        return s.contains(".") || s.contains("e") ? s : s + ".0";
    }
}
