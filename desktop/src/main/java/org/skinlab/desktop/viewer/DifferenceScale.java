package org.skinlab.desktop.viewer;

import java.util.Locale;

import org.skinlab.desktop.render.DrawSettings;

/**
 * The top of the difference view's colour scale (red; blue is 0): a fixed share of the model's
 * size, or "auto", the largest LBS-DQS distance over the clip being played
 * ({@link org.skinlab.internal.metrics.LargestDifference}), so that the whole scale is used and a colour
 * means the same distance at every time of the clip. Immutable.
 *
 * @param auto     the clip's largest distance is red
 * @param fraction with {@code auto} false, the share of the model's size that is red (0.05: 5 %)
 */
public record DifferenceScale(boolean auto, double fraction) {
    /** Smallest and largest fixed scales, in percent of the model's size. */
    public static final double MIN_PERCENT = 0.01;
    public static final double MAX_PERCENT = 100;
    /** Red at {@link DrawSettings#DIFFERENCE_FULL} of the model's size. */
    public static final DifferenceScale DEFAULT = new DifferenceScale(false, DrawSettings.DIFFERENCE_FULL);
    public static final DifferenceScale AUTO = new DifferenceScale(true, Double.NaN);

    public DifferenceScale {
        if (!auto && !(fraction >= MIN_PERCENT / 100 && fraction <= MAX_PERCENT / 100)) {
            throw new IllegalArgumentException("a difference scale of " + 100 * fraction + " % of the model's size"
                    + " (need " + MIN_PERCENT + " to " + MAX_PERCENT + ")");
        }
    }

    /** Red at {@code percent} % of the model's size. */
    public static DifferenceScale percent(double percent) {
        return new DifferenceScale(false, percent / 100);
    }

    /**
     * {@code auto}, or a percentage of the model's size (a plain number, an optional trailing
     * {@code %}), as {@code --difference-scale} takes it.
     *
     * @throws IllegalArgumentException with a message for the user
     */
    public static DifferenceScale parse(String text) {
        String t = text.trim().toLowerCase(Locale.ROOT);
        if (t.equals("auto")) {
            return AUTO;
        }
        if (t.endsWith("%")) {
            t = t.substring(0, t.length() - 1).trim();
        }
        double percent;
        try {
            percent = Double.parseDouble(t);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + text + "' is neither auto nor a percentage of the model's size");
        }
        if (!(percent >= MIN_PERCENT && percent <= MAX_PERCENT)) {
            throw new IllegalArgumentException("'" + text + "': the percentage must lie between " + MIN_PERCENT
                    + " and " + MAX_PERCENT);
        }
        return percent(percent);
    }

    /**
     * The share of the model's size that is red: the fixed one, or for auto the clip's largest
     * difference ({@code clipLargest}, relative to the size); the default's while that is not
     * known (NaN) or is 0 (methods that agree over the whole clip: every colour is blue anyway).
     */
    public double fractionFor(double clipLargest) {
        if (!auto) {
            return fraction;
        }
        return clipLargest > 0 ? clipLargest : DEFAULT.fraction;
    }

    @Override
    public String toString() {
        return auto ? "auto" : String.format(Locale.ROOT, "%.3g %%", 100 * fraction);
    }
}
