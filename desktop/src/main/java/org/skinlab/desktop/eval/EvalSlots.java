package org.skinlab.desktop.eval;

import java.util.List;

import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.lines.SeriesLines;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * A categorical x axis that XChart 3.8 labels dependably: slot k at x = k, labelled
 * {@code labels.get(k)}, every slot a point of a hidden series added before the others.
 *
 * <p>Why so: XChart labels an axis through a formatter by one of two searches. When the x values
 * of all series, in the order they were added, are equally spaced, it labels every value, or
 * every second, third ... one until the labels are unique and fit: dependable, so the hidden series
 * puts every slot there first. Otherwise it searches numeric tick steps, and a formatter that
 * names only whole positions there either gets no labels at all (when the axis' two ends format
 * alike, it takes the format for one that cannot tell them apart) or, when they differ, can loop
 * without end looking for labels that are all different. A slot that should carry no label gets
 * {@code " "}: the same blank for each, so a subset holding two of them is never taken, and the
 * named slots are the ones labelled.
 */
final class EvalSlots {
    private EvalSlots() {
    }

    /**
     * Slots 0 to {@code labels.size() - 1} on {@code chart}'s x axis; the hidden series sits at
     * {@code level} (a value inside the plotted range, positive on a log axis), turned by
     * {@code rotation} degrees.
     */
    static void axis(XYChart chart, List<String> labels, double level, int rotation) {
        double[] x = new double[labels.size()];
        double[] y = new double[labels.size()];
        for (int k = 0; k < x.length; k++) {
            x[k] = k;
            y[k] = level;
        }
        XYSeries slots = chart.addSeries(" ", x, y);
        slots.setShowInLegend(false);
        slots.setMarker(SeriesMarkers.NONE);
        slots.setLineStyle(SeriesLines.NONE);
        chart.setCustomXAxisTickLabelsFormatter(value -> {
            long k = Math.round(value);
            return k >= 0 && k < labels.size() && Math.abs(value - k) < 1e-6 ? labels.get((int) k) : " ";
        });
        chart.getStyler().setXAxisLabelRotation(rotation);
        chart.getStyler().setXAxisTickMarkSpacingHint(12);
    }
}
