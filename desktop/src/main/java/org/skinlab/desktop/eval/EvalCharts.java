package org.skinlab.desktop.eval;

import java.awt.BasicStroke;
import java.awt.Color;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;

import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.lines.SeriesLines;
import org.knowm.xchart.style.markers.SeriesMarkers;

/**
 * The figure rules every section of {@code skinlab eval} follows, in one place: a timing is
 * drawn at its median with a bar from its fastest to its slowest run (never a lone median); a
 * logarithmic axis says so in its title; the legend sits outside the plot, so it hides no point;
 * methods keep one colour in every figure.
 */
final class EvalCharts {
    /** One colour per skinning method, in {@code SkinningMethod} order (LBS, DQS, CoR, BFDQS, STBS-LBS, STBS-DQS, spline). */
    static final Color[] METHOD_COLOURS = {new Color(0x1f77b4), new Color(0xd62728), new Color(0x2ca02c),
        new Color(0x9467bd), new Color(0xff7f0e), new Color(0x8c564b), new Color(0x17becf)};

    /** One line style per skinning method, so that lines lying on each other stay told apart. */
    static final BasicStroke[] METHOD_STROKES = {new BasicStroke(2.5f), dashes(9, 5), dashes(3, 4), dashes(12, 4, 3, 4),
        dashes(6, 3), dashes(2, 2), dashes(14, 6)};

    /** What a figure with spread bars says about them (in its y axis' title). */
    static final String SPREAD = "median; bars: fastest to slowest run";

    private EvalCharts() {
    }

    private static BasicStroke dashes(float... pattern) {
        return new BasicStroke(2f, BasicStroke.CAP_BUTT, BasicStroke.JOIN_ROUND, 10f, pattern, 0f);
    }

    /** Method {@code m}'s line (its colour and style), without markers. */
    static void methodLine(XYSeries series, int m) {
        series.setMarker(SeriesMarkers.NONE);
        series.setLineColor(METHOD_COLOURS[m]);
        series.setLineStyle(METHOD_STROKES[m]);
    }

    /** A line or point chart of the report's size, its legend outside the plot on the right. */
    static XYChart xy(String title, String xTitle, String yTitle) {
        return xy(title, xTitle, yTitle, 550);
    }

    /** As {@link #xy(String, String, String)}, {@code height} pixels tall (a panel of a stacked figure). */
    static XYChart xy(String title, String xTitle, String yTitle, int height) {
        XYChart chart = new XYChartBuilder().width(1000).height(height).title(title).xAxisTitle(xTitle)
                .yAxisTitle(yTitle).build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE);
        chart.getStyler().setMarkerSize(7);
        return chart;
    }

    /** A logarithmic x axis, said in its title. */
    static void logX(XYChart chart) {
        chart.getStyler().setXAxisLogarithmic(true);
        chart.setXAxisTitle(chart.getXAxisTitle() + " (log scale)");
    }

    /** A logarithmic y axis, said in its title. */
    static void logY(XYChart chart) {
        chart.getStyler().setYAxisLogarithmic(true);
        chart.setYAxisTitle(chart.getYAxisTitle() + " (log scale)");
    }

    /**
     * A categorical x axis XChart labels dependably: category k at x = k, labelled
     * {@code labels.get(k)}, every category a point of a hidden series added before the others,
     * at {@code level} (a value inside the plotted range, positive on a log axis). Points of several
     * series at one category sit side by side ({@link #offset}).
     *
     * <p>Why so: XChart labels an axis through a formatter by one of two searches. When the x
     * values of all series, in the order they were added, are equally spaced, it labels every
     * value, or every second, third ... one until the labels are unique and fit: dependable, so
     * the hidden series puts every category there first. Otherwise it searches numeric tick steps,
     * and a formatter that names only whole positions there either gets no labels at all (when
     * the axis' two ends format alike) or, when they differ, can loop without end looking for
     * labels that are all different. A position between categories gets {@code " "}: the same
     * blank for each, so a subset holding two of them is never taken.
     */
    static void categories(XYChart chart, List<String> labels, double level, int rotation) {
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
        chart.getStyler().setXAxisMin(-0.5);
        chart.getStyler().setXAxisMax(labels.size() - 0.5);
    }

    /** An asset's name short enough for a category axis: no extension, no "cylinder-", no corpus prefix ("S01_"). */
    static String shortName(String file) {
        return file.replaceAll("\\.(dae|glb|gltf)$", "").replaceFirst("^cylinder-", "").replaceFirst("^[A-Z]\\d\\d_", "");
    }

    /** Where series {@code s} of {@code count} sits at category {@code category}: spread over 0.6 of a category. */
    static double offset(int category, int s, int count) {
        return count <= 1 ? category : category - 0.3 + 0.6 * s / (count - 1);
    }

    /**
     * A series of medians at {@code x} with a bar from each timing's min to its max: {@code spreads}
     * are results.json nodes written by {@link EvalReport#putSpread}. The bars are series of their
     * own, hidden from the legend.
     */
    static XYSeries medians(XYChart chart, String name, List<Double> x, List<JsonNode> spreads, Color colour,
            boolean line) {
        double[] xs = new double[x.size()];
        double[] ys = new double[x.size()];
        for (int i = 0; i < xs.length; i++) {
            xs[i] = x.get(i);
            ys[i] = spreads.get(i).get("median").asDouble();
        }
        XYSeries series = chart.addSeries(name, xs, ys);
        series.setMarkerColor(colour);
        series.setLineColor(colour);
        series.setMarker(SeriesMarkers.CIRCLE);
        if (!line) {
            series.setLineStyle(SeriesLines.NONE);
        }
        for (int i = 0; i < xs.length; i++) {
            JsonNode s = spreads.get(i);
            XYSeries bar = chart.addSeries(name + " spread " + i, new double[] {xs[i], xs[i]},
                    new double[] {s.get("min").asDouble(), s.get("max").asDouble()});
            bar.setShowInLegend(false);
            bar.setMarker(SeriesMarkers.NONE);
            bar.setLineColor(colour);
            bar.setLineStyle(new BasicStroke(2f));
        }
        return series;
    }
}
