package org.skinlab.desktop.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.Locale;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.app.Pictures.Picture;
import org.skinlab.desktop.render.GlTestDisplay;
import org.skinlab.internal.scene.ColourRamp;

/**
 * The difference view's scale ({@code --difference-scale}) changes the colours as the colour map
 * says. The view colours each fragment {@code ColourRamp(d / top)}, lit: times a scalar per pixel
 * that does not depend on the scale. So a pixel's chromaticity (its colour over the sum of its
 * channels) says where on the map it lies, and with the top 4 times higher (5 % to 20 % of the
 * model's size) each pixel must move to a quarter of its fraction, where the first picture did not
 * clip it at red. Read from the twist cylinder at 172 degrees, where the distances run from 0 to
 * 11 % of its size; with {@code auto} its largest distance is red.
 */
class DifferenceScaleTest {
    private static final Path TWIST = Pictures.asset("cylinders/cylinder-twist-high.dae");
    /** Samples of the colour map the chromaticities are matched against. */
    private static final int SAMPLES = 2001;
    private static final double[][] CHROMA = chromaticities();
    /** Farthest a pixel's chromaticity may lie from the map's to count as one of its colours. */
    private static final double OFF_MAP = 0.03;
    /**
     * How far a pixel's fraction may land from the one predicted: 8-bit channels of colours lit
     * down to a third of their level move the matched fraction by about 0.005 (the worst seen on
     * llvmpipe); at most 2 % of the pixels may be further off.
     */
    private static final double FRACTION_TOLERANCE = 0.02;

    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    private static double[][] chromaticities() {
        double[][] c = new double[SAMPLES][];
        for (int i = 0; i < SAMPLES; i++) {
            int rgb = ColourRamp.colour(i / (double) (SAMPLES - 1));
            c[i] = chromaticity(Pictures.red(rgb), Pictures.green(rgb), Pictures.blue(rgb));
        }
        return c;
    }

    private static double[] chromaticity(double r, double g, double b) {
        double sum = r + g + b;
        return new double[] {r / sum, g / sum, b / sum};
    }

    /** The fraction of the map whose chromaticity is nearest the pixel's; NaN when none is within {@link #OFF_MAP}. */
    private static double fractionOf(int rgb) {
        double[] c = chromaticity(Pictures.red(rgb), Pictures.green(rgb), Pictures.blue(rgb));
        int best = -1;
        double bestDistance = Double.MAX_VALUE;
        for (int i = 0; i < SAMPLES; i++) {
            double d = Math.hypot(Math.hypot(c[0] - CHROMA[i][0], c[1] - CHROMA[i][1]), c[2] - CHROMA[i][2]);
            if (d < bestDistance) {
                bestDistance = d;
                best = i;
            }
        }
        return bestDistance <= OFF_MAP ? best / (double) (SAMPLES - 1) : Double.NaN;
    }

    /**
     * Per pixel the fraction of the map it shows, NaN where it is not the model's, touches the
     * outline (multisampling blends the background in), is too dark to read or clipped at full
     * brightness.
     */
    private static double[] fractions(Picture p) {
        boolean[] model = Pictures.model(p);
        double[] f = new double[model.length];
        for (int y = 0; y < p.height(); y++) {
            for (int x = 0; x < p.width(); x++) {
                int i = y * p.width() + x;
                f[i] = Double.NaN;
                if (x == 0 || y == 0 || x == p.width() - 1 || y == p.height() - 1 || !model[i] || !model[i - 1]
                        || !model[i + 1] || !model[i - p.width()] || !model[i + p.width()]) {
                    continue;
                }
                int c = p.at(x, y);
                int max = Math.max(Pictures.red(c), Math.max(Pictures.green(c), Pictures.blue(c)));
                if (max >= 80 && max <= 250) {
                    f[i] = fractionOf(c);
                }
            }
        }
        return f;
    }

    private static Picture difference(Path dir, String scale) {
        return Pictures.view(dir, "difference-" + scale, TWIST, 320, 480, "--time", "4", "--view", "difference",
                "--method", "lbs", "--difference-scale", scale);
    }

    @Test
    void aFourTimesHigherTopMovesEveryColourToAQuarterOfItsFraction(@TempDir Path dir) {
        double[] at5 = fractions(difference(dir, "5"));
        double[] at20 = fractions(difference(dir, "20"));
        int compared = 0;
        int off = 0;
        int red = 0;
        int redKept = 0;
        double worst = 0;
        for (int i = 0; i < at5.length; i++) {
            if (Double.isNaN(at5[i]) || Double.isNaN(at20[i])) {
                continue;
            }
            if (at5[i] < 0.95) {
                compared++;
                double miss = Math.abs(at20[i] - at5[i] / 4);
                worst = Math.max(worst, miss);
                off += miss > FRACTION_TOLERANCE ? 1 : 0;
            } else if (at5[i] > 0.999) {
                // Clipped at red: 5 % or more, so a quarter of the map or more at 20 %.
                red++;
                redKept += at20[i] >= 0.25 - FRACTION_TOLERANCE ? 1 : 0;
            }
        }
        String numbers = String.format(Locale.ROOT, "%d pixels compared, %d off by more than %.2f (worst %.3f); "
                + "%d red at 5 %%, %d of them a quarter up the map or more at 20 %%", compared, off,
                FRACTION_TOLERANCE, worst, red, redKept);
        assertTrue(compared > 2000, numbers);
        assertTrue(off <= 0.02 * compared, numbers);
        assertTrue(red > 100, numbers);
        assertEquals(red, redKept, numbers);
    }

    @Test
    void autoPutsTheLargestDistanceAtRedAndAHighTopLeavesItBlue(@TempDir Path dir) {
        double highest = 0;
        for (double f : fractions(difference(dir, "auto"))) {
            highest = Double.isNaN(f) ? highest : Math.max(highest, f);
        }
        // The largest distance is at the joint's ring, a line of pixels: its neighbours are nearly as far.
        assertTrue(highest > 0.9, "auto: the reddest pixel is at " + highest + " of the map");
        double highestAt100 = 0;
        for (double f : fractions(difference(dir, "100"))) {
            highestAt100 = Double.isNaN(f) ? highestAt100 : Math.max(highestAt100, f);
        }
        // 11 % of the size at most, with red at 100 %: no pixel beyond 0.11 of the map (blue to cyan).
        assertTrue(highestAt100 < 0.11 + FRACTION_TOLERANCE, "top at 100 %: " + highestAt100);
    }
}
