package org.skinlab.internal.bench;

import java.util.Arrays;

/**
 * A timing taken several times: each run's value, in the order the runs were taken, and their
 * median, extremes and quartiles. The quartiles interpolate linearly between the sorted values
 * (the "type 7" rule of R and NumPy's default), so five runs have quartiles at the second and
 * fourth values.
 *
 * @param runs   each run's value, in run order (a copy is kept)
 * @param median the middle value (the mean of the two middle ones for an even count)
 */
public record Spread(double[] runs, double median, double min, double max, double lowerQuartile,
        double upperQuartile) {

    public Spread {
        runs = runs.clone();
    }

    /** The spread of {@code runs} (at least one value). */
    public static Spread of(double... runs) {
        if (runs.length == 0) {
            throw new IllegalArgumentException("a spread needs at least one run");
        }
        double[] sorted = runs.clone();
        Arrays.sort(sorted);
        return new Spread(runs, quantile(sorted, 0.5), sorted[0], sorted[sorted.length - 1], quantile(sorted, 0.25),
                quantile(sorted, 0.75));
    }

    /** Each run's value (a copy). */
    @Override
    public double[] runs() {
        return runs.clone();
    }

    /** How many runs. */
    public int count() {
        return runs.length;
    }

    /**
     * The interquartile range over the median: how far runs of the same thing lie apart, as a
     * fraction of what they measure (0 for one run or a zero median).
     */
    public double relativeInterquartileRange() {
        return median == 0 ? 0 : (upperQuartile - lowerQuartile) / median;
    }

    /** The linearly interpolated quantile {@code q} (0 to 1) of sorted values. */
    static double quantile(double[] sorted, double q) {
        double position = q * (sorted.length - 1);
        int below = (int) Math.floor(position);
        int above = Math.min(sorted.length - 1, below + 1);
        return sorted[below] + (position - below) * (sorted[above] - sorted[below]);
    }
}
