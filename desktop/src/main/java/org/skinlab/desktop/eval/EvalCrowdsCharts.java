package org.skinlab.desktop.eval;

import java.awt.BasicStroke;
import java.awt.Color;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.TreeSet;

import com.fasterxml.jackson.databind.JsonNode;

import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.lines.SeriesLines;
import org.knowm.xchart.style.markers.Marker;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.skinlab.desktop.bench.CrowdBench;
import org.skinlab.skinning.SkinningMethod;

/**
 * The crowds section's figures, by {@link EvalCharts}' rules (medians with a bar from the fastest
 * to the slowest run, log axes said in their titles, the legend outside the plot, a colour per
 * method): the skinning-only rates in figures of their own (characters per frame against threads,
 * frame time against characters, with the 60 Hz budget), and the drawn frames per second beside
 * the thesis' drawn points, the one figure the thesis' points appear in. Package-private so that
 * the section's test can read what each figure holds.
 */
final class EvalCrowdsCharts {
    /** A character's marker: the walker's, the cowboy's. */
    private static final Marker[] MODEL_MARKERS = {SeriesMarkers.CIRCLE, SeriesMarkers.SQUARE};
    /** A character's line: the walker's solid, the cowboy's dashed (in the drawn figure, the vertex shader's). */
    private static final BasicStroke[] LINES = {new BasicStroke(1.5f), new BasicStroke(1.5f, BasicStroke.CAP_BUTT,
        BasicStroke.JOIN_MITER, 10f, new float[] {6f, 4f}, 0f)};

    private EvalCrowdsCharts() {
    }

    /** Characters per 60 Hz frame against threads, per character and method (skinning only). */
    static XYChart threads(JsonNode results) {
        XYChart chart = EvalCharts.xy("Characters per " + EvalReport.num(results, "/frameBudgetMillis")
                + " ms frame against threads, skinning only (" + EvalReport.num(results, "/threadCrowd")
                + " copies, our CPU kernels)", "threads",
                "characters per frame (" + EvalCharts.SPREAD + ")");
        int cores = results.get("cores").asInt();
        List<String> labels = new ArrayList<>();
        for (int t = 1; t <= cores; t++) {
            labels.add(Integer.toString(t));
        }
        JsonNode models = results.get("models");
        EvalCharts.categories(chart, labels, 0);
        int count = models.size() * CrowdBench.METHODS.size();
        int s = 0;
        for (int i = 0; i < models.size(); i++) {
            for (SkinningMethod method : CrowdBench.METHODS) {
                List<Double> x = new ArrayList<>();
                List<JsonNode> spreads = new ArrayList<>();
                for (JsonNode p : of(models.get(i).get("threads"), method)) {
                    x.add(EvalCharts.offset(p.get("threads").asInt() - 1, s, count));
                    spreads.add(p.get("charactersPerFrame"));
                }
                XYSeries series = EvalCharts.medians(chart, label(models.get(i), method), x, spreads, colour(method),
                        true);
                series.setMarker(MODEL_MARKERS[i % MODEL_MARKERS.length]);
                series.setLineStyle(LINES[i % LINES.length]);
                s++;
            }
        }
        return chart;
    }

    /** Frame time against characters at all threads, per character and method (skinning only), and the 60 Hz budget. */
    static XYChart characters(JsonNode results) {
        XYChart chart = EvalCharts.xy("Frame time against characters, skinning only (our CPU kernels, "
                + EvalReport.num(results, "/cores") + " threads)", "characters",
                "frame time, µs (" + EvalCharts.SPREAD + ")");
        EvalCharts.logX(chart);
        EvalCharts.logY(chart);
        chart.getStyler().setXAxisDecimalPattern("#,##0");
        chart.getStyler().setYAxisDecimalPattern("#,##0");
        JsonNode models = results.get("models");
        for (int i = 0; i < models.size(); i++) {
            for (SkinningMethod method : CrowdBench.METHODS) {
                List<Double> x = new ArrayList<>();
                List<JsonNode> spreads = new ArrayList<>();
                for (JsonNode p : of(models.get(i).get("crowd"), method)) {
                    x.add(p.get("characters").asDouble());
                    spreads.add(p.get("frameMicros"));
                }
                if (!x.isEmpty()) {
                    XYSeries series = EvalCharts.medians(chart, label(models.get(i), method), x, spreads,
                            colour(method), true);
                    series.setMarker(MODEL_MARKERS[i % MODEL_MARKERS.length]);
                    series.setLineStyle(LINES[i % LINES.length]);
                }
            }
        }
        double budget = results.get("frameBudgetMicros").asDouble();
        XYSeries line = chart.addSeries("a 60 Hz frame (" + EvalReport.num(results, "/frameBudgetMillis") + " ms)",
                new double[] {1, results.get("maxCharacters").asDouble()}, new double[] {budget, budget});
        line.setMarker(SeriesMarkers.NONE);
        line.setLineColor(Color.GRAY);
        line.setLineStyle(SeriesLines.DOT_DOT);
        return chart;
    }

    /**
     * Drawn frames per second against copies: ours per skinning and method, and the thesis' drawn
     * DQS and LBS points at 1, 4, 8 and 12 meshes. The copies are categories (the counts drawn, up
     * to where the sweep stopped, and the thesis' counts), the series side by side within each.
     */
    static XYChart render(JsonNode render, JsonNode results) {
        boolean software = render.get("software").asBoolean();
        XYChart chart = EvalCharts.xy("Drawn fps against copies, ours on " + EvalCrowdsRender.rendererName(render)
                + (software ? " (on the CPU)" : "") + " and the thesis'", "copies of "
                + render.get("file").asText(), "frames per second (" + EvalCharts.SPREAD + ")");
        TreeSet<Integer> counts = new TreeSet<>();
        for (JsonNode p : render.get("points")) {
            counts.add(p.get("instances").asInt());
        }
        for (JsonNode t : results.get("thesis")) {
            counts.add(t.get("meshes").asInt());
        }
        List<Integer> categories = new ArrayList<>(counts);
        List<String> labels = new ArrayList<>();
        categories.forEach(c -> labels.add(Integer.toString(c)));
        EvalCharts.categories(chart, labels, 0);
        List<SkinningMethod> methods = new ArrayList<>();
        render.get("methods").forEach(m -> methods.add(SkinningMethod.fromKey(m.asText())));
        int seriesCount = EvalCrowdsThesis.SKINNINGS.size() * methods.size() + EvalCrowdsThesis.METHODS.size();
        int s = 0;
        for (String skinning : EvalCrowdsThesis.SKINNINGS) {
            for (SkinningMethod method : methods) {
                List<Double> x = new ArrayList<>();
                List<JsonNode> spreads = new ArrayList<>();
                for (JsonNode p : of(render.get("points"), method)) {
                    if (p.get("skinning").asText().equals(skinning)) {
                        x.add(EvalCharts.offset(categories.indexOf(p.get("instances").asInt()), s, seriesCount));
                        spreads.add(p.get("fps"));
                    }
                }
                if (!x.isEmpty()) {
                    String name = upper(method) + ", " + EvalCrowdsRender.skinningLabel(render, skinning, false);
                    XYSeries series = EvalCharts.medians(chart, name, x, spreads, colour(method), true);
                    boolean shader = skinning.equals(EvalCrowdsRender.SHADER);
                    series.setLineStyle(LINES[shader ? 1 : 0]);
                    series.setMarker(shader ? SeriesMarkers.TRIANGLE_UP : SeriesMarkers.CIRCLE);
                }
                s++;
            }
        }
        for (SkinningMethod method : EvalCrowdsThesis.METHODS) {
            List<Double> x = new ArrayList<>();
            List<Double> y = new ArrayList<>();
            for (JsonNode t : results.get("thesis")) {
                x.add(EvalCharts.offset(categories.indexOf(t.get("meshes").asInt()), s, seriesCount));
                y.add(t.get(method.key() + "Fps").asDouble());
            }
            XYSeries thesis = chart.addSeries("thesis " + upper(method) + ", drawn (its desktop)", x, y);
            thesis.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
            thesis.setMarker(SeriesMarkers.DIAMOND);
            thesis.setMarkerColor(colour(method).darker());
            s++;
        }
        return chart;
    }

    /** The points of one method, in their order. */
    private static List<JsonNode> of(JsonNode points, SkinningMethod method) {
        List<JsonNode> list = new ArrayList<>();
        for (JsonNode p : points) {
            if (p.get("method").asText().equals(method.key())) {
                list.add(p);
            }
        }
        return list;
    }

    private static Color colour(SkinningMethod method) {
        return EvalCharts.METHOD_COLOURS[method.ordinal()];
    }

    private static String label(JsonNode model, SkinningMethod method) {
        return upper(method) + " " + model.get("file").asText().replaceAll("\\.dae$", "");
    }

    private static String upper(SkinningMethod method) {
        return method.key().toUpperCase(Locale.ROOT);
    }
}
