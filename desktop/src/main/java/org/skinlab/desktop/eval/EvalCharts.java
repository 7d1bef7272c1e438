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
     * A categorical x axis: category k at x = k, labelled {@code labels.get(k)} (unique names),
     * the axis from -0.5 to {@code labels.size() - 0.5}. Points of several series at one category
     * sit side by side ({@link #offset}).
     *
     * <p>How XChart labels it: with a formatter it draws no ticks at all when the axis' two ends
     * format alike; otherwise it tries numeric tick steps, finest first, and takes the first whose
     * labels, from one step below the axis to two above, are all different and fit their spacing.
     * The formatter names the whole positions of the categories and gives every other position
     * between them one blank, so a step finer than 1 (several blanks alike) is passed over; the
     * positions beyond the categories, the axis' ends among them, get blanks of a length of their
     * own, so a step of 1 is taken when the labels fit (else 2, labelling every second category).
     * A rotation of 90 degrees fits any number of categories.
     */
    static void categories(XYChart chart, List<String> labels, int rotation) {
        int last = labels.size() - 1;
        chart.setCustomXAxisTickLabelsFormatter(value -> {
            long k = Math.round(value);
            if (value < 0 || value > last) {
                // Beyond the categories (the axis' ends among them): blanks of a length per position,
                // even below and odd above, so that the two ends differ and a step of 1 has no two alike.
                double beyond = value < 0 ? -value : value - last;
                return " ".repeat((int) (2 * Math.ceil(2 * beyond) + (value < 0 ? 0 : 1)));
            }
            return Math.abs(value - k) > 1e-6 ? " " : labels.get((int) k);
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
