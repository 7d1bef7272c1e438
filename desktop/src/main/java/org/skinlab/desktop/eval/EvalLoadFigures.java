package org.skinlab.desktop.eval;

import java.awt.Color;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;

import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.Styler;

/**
 * The load section's figures, drawn from results.json by {@link EvalCharts}' rules: each file's
 * median run with a bar from its fastest to its slowest run, ours and assimp's side by side, on a
 * logarithmic time axis (the files' times span three orders of magnitude).
 */
final class EvalLoadFigures {
    static final Color OURS = new Color(0x1f77b4);
    static final Color ASSIMP = new Color(0xff7f0e);

    /**
     * One file of a table: its name and its spreads (results.json nodes of {@link EvalReport#putSpread};
     * {@code assimp} null or missing when assimp did not import it).
     */
    record Row(String file, JsonNode ours, JsonNode assimp) {
    }

    private EvalLoadFigures() {
    }

    /**
     * Every file of our assets and the corpus, ours and assimp's runs side by side: file i's at
     * slots 2i and 2i + 1 ({@link EvalCharts#categories}), labelled with the file's name at 2i.
     */
    static void files(List<Row> rows, boolean assimp, EvalReport report) {
        // EvalCharts.xy's chart, taller: the files' names stand below the plot.
        XYChart chart = new XYChartBuilder().width(1000).height(800).title("Import time per file, skinlab and assimp")
                .xAxisTitle("file").yAxisTitle("ms, " + EvalCharts.SPREAD).build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.OutsideE);
        chart.getStyler().setMarkerSize(7);
        EvalCharts.logY(chart);
        int per = assimp ? 2 : 1;
        List<String> labels = new ArrayList<>();
        for (Row r : rows) {
            labels.add(r.file());
            if (assimp) {
                labels.add(" ");
            }
        }
        EvalCharts.categories(chart, labels, 90);
        series(chart, "skinlab", rows, 0, per, OURS, false);
        if (assimp) {
            series(chart, "assimp", rows, 1, per, ASSIMP, true);
        }
        report.figure("load-files.png", "Import time per file, skinlab and assimp (median run, bars from the"
                + " fastest to the slowest run)", chart);
    }

    private static void series(XYChart chart, String name, List<Row> rows, int slot, int per, Color colour,
            boolean theirs) {
        List<Double> x = new ArrayList<>();
        List<JsonNode> spreads = new ArrayList<>();
        for (int i = 0; i < rows.size(); i++) {
            JsonNode spread = theirs ? rows.get(i).assimp() : rows.get(i).ours();
            if (drawable(spread)) {
                x.add((double) (per * i + slot));
                spreads.add(spread);
            }
        }
        if (!x.isEmpty()) {
            EvalCharts.medians(chart, name, x, spreads, colour, false);
        }
    }

    /**
     * The conformance suite's files, each tool's sorted by its median run: the distribution, each
     * file's runs as a bar.
     */
    static void suite(JsonNode group, EvalReport report) {
        List<JsonNode> ours = sorted(group, "oursMs");
        if (ours.isEmpty()) {
            return;
        }
        XYChart chart = EvalCharts.xy("Conformance suite: import time per file, each tool's files sorted by their"
                + " median run", "files, fastest first", "ms, " + EvalCharts.SPREAD);
        EvalCharts.logY(chart);
        EvalCharts.medians(chart, "skinlab (" + ours.size() + " files imported)", ranks(ours.size()), ours, OURS,
                false);
        List<JsonNode> theirs = sorted(group, "assimpMs");
        if (!theirs.isEmpty()) {
            EvalCharts.medians(chart, "assimp (" + theirs.size() + " files imported)", ranks(theirs.size()), theirs,
                    ASSIMP, false);
        }
        report.figure("load-cts.png", "Conformance suite: import time per file, sorted (median run, bars from the"
                + " fastest to the slowest run)", chart);
    }

    /**
     * The files' spreads of {@code field}, sorted by median; a log axis has no zero, so runs under
     * the rounding are left out.
     */
    private static List<JsonNode> sorted(JsonNode group, String field) {
        List<JsonNode> spreads = new ArrayList<>();
        for (JsonNode f : group.get("files")) {
            if (drawable(f.get(field))) {
                spreads.add(f.get(field));
            }
        }
        spreads.sort(Comparator.comparingDouble(s -> s.get("median").asDouble()));
        return spreads;
    }

    private static boolean drawable(JsonNode spread) {
        return spread != null && spread.has("min") && spread.get("min").asDouble() > 0;
    }

    private static List<Double> ranks(int n) {
        List<Double> rank = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            rank.add((double) (i + 1));
        }
        return rank;
    }
}
