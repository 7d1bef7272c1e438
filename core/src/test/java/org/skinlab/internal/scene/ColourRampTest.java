package org.skinlab.internal.scene;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.regex.Matcher;
import java.util.regex.Pattern;

import org.junit.jupiter.api.Test;

/**
 * The data views' colour map: blue, cyan, green, yellow and red at quarters of the scale, linear
 * between them, clamped outside; the shader text generated from the same stops. (That the GPU
 * draws these colours is ColourRampShaderTest's, in desktop: it reads back a rendered strip.)
 */
class ColourRampTest {
    /** The stops as docs/desktop.md lists them. */
    private static final float[][] STOPS = {{0.10f, 0.20f, 0.75f}, {0.10f, 0.75f, 0.85f}, {0.20f, 0.80f, 0.20f},
        {0.95f, 0.85f, 0.15f}, {0.90f, 0.15f, 0.10f}};

    private static float[] rgb(double fraction) {
        float[] c = new float[3];
        ColourRamp.colour(fraction, c);
        return c;
    }

    @Test
    void theStopsSitAtQuartersAndMidpointsAreTheirMeans() {
        assertEquals(5, ColourRamp.stopCount());
        for (int i = 0; i < 5; i++) {
            assertArrayEquals(STOPS[i], rgb(i / 4.0), 1e-6f, "stop " + i);
        }
        for (int i = 0; i < 4; i++) {
            float[] mid = new float[3];
            for (int c = 0; c < 3; c++) {
                mid[c] = (STOPS[i][c] + STOPS[i + 1][c]) / 2;
            }
            assertArrayEquals(mid, rgb((i + 0.5) / 4), 1e-6f, "between stops " + i + " and " + (i + 1));
        }
        // A quarter of the way from green to yellow: fraction 0.5 + 0.25 / 4.
        assertArrayEquals(new float[] {0.2f + 0.25f * 0.75f, 0.8f + 0.25f * 0.05f, 0.2f - 0.25f * 0.05f},
                rgb(0.5625), 1e-6f);
    }

    @Test
    void outsideTheScaleItClamps() {
        assertArrayEquals(STOPS[0], rgb(-3), 0f);
        assertArrayEquals(STOPS[0], rgb(Double.NaN), 0f);
        assertArrayEquals(STOPS[4], rgb(7.5), 0f);
        assertArrayEquals(STOPS[4], rgb(Double.POSITIVE_INFINITY), 0f);
    }

    @Test
    void packedColoursAreEightBitLevelsRoundedToNearest() {
        // Blue (0.10, 0.20, 0.75): 25.5 -> 26, 51, 191.25 -> 191.
        assertEquals(0x1A33BF, ColourRamp.colour(0.0));
        // Red (0.90, 0.15, 0.10): 229.5 -> 230, 38.25 -> 38, 25.5 -> 26.
        assertEquals(0xE6261A, ColourRamp.colour(1.0));
        assertEquals(0, ColourRamp.colour(0.3) & 0xFF000000, "no alpha byte");
    }

    @Test
    void theShaderTextDefinesTheRampFromTheSameStops() {
        String shader = ColourRamp.expand("#version 330 core\n" + ColourRamp.INCLUDE + "\nvoid main() {}\n");
        assertTrue(shader.contains("vec3 colourRamp(float x)"), shader);
        Matcher m = Pattern.compile("const vec3 c(\\d) = vec3\\(([^,]+), ([^,]+), ([^)]+)\\);").matcher(shader);
        int found = 0;
        while (m.find()) {
            int i = Integer.parseInt(m.group(1));
            float[] written = {Float.parseFloat(m.group(2)), Float.parseFloat(m.group(3)),
                Float.parseFloat(m.group(4))};
            // Written exactly: the literal parses to the very float the Java side mixes.
            assertArrayEquals(rgb(i / 4.0), written, 0f, "c" + i);
            found++;
        }
        assertEquals(5, found, shader);
        assertEquals("#version 330 core\n", ColourRamp.expand("#version 330 core\n"), "no include, no change");
    }
}
