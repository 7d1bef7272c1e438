package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;

import com.fasterxml.jackson.databind.JsonNode;

import org.skinlab.internal.bench.Rounds;

/**
 * What every timing of {@code skinlab eval}'s results.json must be ({@link EvalReport#putSpread}):
 * at least {@link Rounds#MIN_RUNS} runs, each kept, and the median, extremes and quartiles those
 * runs' own. The runs are stored rounded to 0.001, so the median of an even count (the mean of the
 * two middle runs) may differ from the mean of the rounded ones by half of that.
 */
final class SpreadCheck {
    private static final double ROUNDING = 0.0005 + 1e-9;

    private SpreadCheck() {
    }

    /** {@code spread} (at {@code where}) holds at least MIN_RUNS runs, and its median is theirs. */
    static void check(JsonNode spread, String where) {
        assertTrue(spread != null && spread.has("runs"), where + ": no runs in " + spread);
        double[] runs = new double[spread.get("runs").size()];
        for (int i = 0; i < runs.length; i++) {
            runs[i] = spread.get("runs").get(i).asDouble();
        }
        assertTrue(runs.length >= Rounds.MIN_RUNS, where + ": " + runs.length + " runs");
        double[] sorted = runs.clone();
        Arrays.sort(sorted);
        int n = sorted.length;
        double median = n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
        assertEquals(median, spread.get("median").asDouble(), ROUNDING, where + ": the median of its runs");
        assertEquals(sorted[0], spread.get("min").asDouble(), 0, where + ": the fastest run");
        assertEquals(sorted[n - 1], spread.get("max").asDouble(), 0, where + ": the slowest run");
        assertTrue(sorted[0] <= spread.get("q1").asDouble() && spread.get("q1").asDouble() <= median + ROUNDING
                && median - ROUNDING <= spread.get("q3").asDouble() && spread.get("q3").asDouble() <= sorted[n - 1],
                where + ": quartiles between the extremes and around the median: " + spread);
    }

    /**
     * {@code ratio} is {@code scale * numerator / denominator} (positive), the three stored rounded
     * to 0.001: the unrounded values lie within 0.0005 of the stored ones, so the unrounded ratio
     * lies between scale (n - 0.0005) / (d + 0.0005) and scale (n + 0.0005) / (d - 0.0005), and the
     * stored ratio within 0.0005 of that.
     */
    static void ratio(double ratio, double scale, double numerator, double denominator, String where) {
        assertTrue(numerator > 0 && denominator > 0, where + ": " + numerator + " / " + denominator);
        double low = scale * (numerator - ROUNDING) / (denominator + ROUNDING) - ROUNDING;
        double high = denominator > ROUNDING ? scale * (numerator + ROUNDING) / (denominator - ROUNDING) + ROUNDING
                : Double.POSITIVE_INFINITY;
        assertTrue(low <= ratio && ratio <= high, where + ": " + ratio + " is not " + scale + " x the ratio of "
                + numerator + " / " + denominator);
    }
}
