package org.skinlab.desktop.eval;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.lines.SeriesLines;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.skinlab.desktop.ModelFileSearch;
import org.skinlab.skinning.SkinningMethod;

/**
 * Section "advice": what the numbers mean for AR on a phone. It measures how a frame's cost grows
 * ({@link EvalScaling}: vertices, influences, joints; fits by {@link EvalFits}), then draws a
 * recommendation per use from the sections measured before it in the same run
 * ({@link EvalAdviceInputs} copies every number it argues with into its own results, so that the
 * text prints only numbers of results.json; {@link EvalAdvice} writes them). A use whose inputs
 * were not measured (an {@code --only} run) says so.
 */
final class EvalAdviceSection implements EvalSection {
    /** The character the advice is about: ours, with 4 influences, as a phone AR scene would hold. */
    static final String CHARACTER = "humanoid-walk.dae";
    /** The share of a 60 Hz frame (µs) left to skinning: the camera, tracking and drawing need the rest. */
    static final double BUDGET_MICROS = 4000;
    static final int FRAME_RATE = 60;
    static final double FRAME_MICROS = 1e6 / FRAME_RATE;

    @Override
    public String key() {
        return "advice";
    }

    @Override
    public String title() {
        return "What it means for AR on a phone";
    }

    @Override
    public double estimatedSeconds(EvalContext context) {
        return context.quick() ? 16 : 110;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        boolean quick = context.quick();
        double warmup = quick ? 0.1 : 0.4;
        double seconds = quick ? 0.04 : 0.3;
        results.put("warmupSeconds", warmup);
        results.put("seconds", seconds);
        results.put("rounds", org.skinlab.internal.bench.Rounds.MIN_RUNS);
        EvalScaling.vertices(quick ? List.of(2_000, 8_000, 32_000) : List.of(1_000, 4_000, 16_000, 64_000, 256_000),
                warmup, seconds, results.putObject("vertices"), f -> context.progress(0.6 * f));
        EvalScaling.influences(quick ? 8_000 : 32_000, List.of(1, 2, 4, 8), warmup, seconds,
                results.putObject("influences"), f -> context.progress(0.6 + 0.25 * f));
        List<Path> files = new ArrayList<>();
        for (ModelFileSearch.Entry e : ModelFileSearch.expand(List.of(context.root().resolve("assets")),
                ModelFileSearch.COLLADA)) {
            files.add(e.path());
        }
        for (String name : EvalTimeSection.CORPUS) {
            Path f = context.corpus() == null ? null : context.corpus().resolve(name);
            if (f != null && Files.isRegularFile(f)) {
                files.add(f);
            }
        }
        EvalScaling.joints(files, warmup, seconds, results.putObject("joints"), f -> context.progress(0.85 + 0.15 * f));
        budgets(results);
        EvalAdviceInputs.collect(context, results.putObject("inputs"));
    }

    /** Per method and kernel, the vertices the fitted cost per vertex skins within {@link #BUDGET_MICROS}. */
    private static void budgets(ObjectNode results) {
        results.put("budgetMicros", BUDGET_MICROS);
        results.put("frameRateHz", FRAME_RATE);
        results.put("frameMicros", EvalReport.round(FRAME_MICROS));
        for (JsonNode s : results.at("/vertices/series")) {
            double ns = s.at("/fit/slope").asDouble();
            ((ObjectNode) s).put("verticesInBudget", ns <= 0 ? 0 : (long) Math.floor(BUDGET_MICROS * 1000 / ns));
        }
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        report.heading(3, "How the cost grows");
        verticesReport(results, report);
        influencesReport(results, report);
        jointsReport(results, report);
        report.heading(3, "Recommendations");
        EvalAdvice.write(results, report);
    }

    /** Time per frame against vertices: the proportional fits and the vertices each fits into the budget. */
    private static void verticesReport(JsonNode results, EvalReport report) {
        report.paragraph("Skinning alone (no pose), one thread, positions and exact normals, on the shared C++"
                + " reference's synthetic data (" + EvalReport.num(results, "/vertices/joints") + " joints, "
                + EvalReport.num(results, "/vertices/influences") + " influences per vertex). Each point is "
                + EvalReport.num(results, "/rounds") + " runs interleaved across the methods and kernels, a run the"
                + " median frame of " + EvalReport.num(results, "/seconds") + " s (after " + EvalReport.num(results,
                        "/warmupSeconds") + " s of warm-up before the first). The cost per vertex is a proportional"
                + " fit (time = ns per vertex x vertices, through the origin, so it never predicts a negative time),"
                + " each point weighted alike; where it misses a point by more than "
                + EvalReport.num(results, "/vertices/series/0/fit/tolerancePercent") + " % the smallest sizes are left"
                + " out (their fixed costs) and the table says from which size on it holds, with every point's"
                + " residual. The scalar kernels are the code Android runs (it has no Vector API), timed here on"
                + " this desktop's JVM, not on a phone (a phone's own numbers: section \"phone\"). The vertices in"
                + " budget are what the fitted cost fits into " + EvalReport.num(results, "/budgetMicros")
                + " µs, the share of a " + EvalReport.num(results, "/frameRateHz") + " Hz frame this advice leaves"
                + " to skinning (the camera image, the tracker and the drawing need the rest), on one core of this"
                + " machine.");
        JsonNode sizes = results.at("/vertices/vertices");
        List<String> header = new ArrayList<>(List.of("method", "kernels", "kernel name", "ns per vertex (fit)",
                "fitted from", "r²", "holds"));
        for (int i = 0; i < sizes.size(); i++) {
            header.add("residual % at " + EvalReport.num(results, "/vertices/vertices/" + i));
        }
        header.add("vertices in budget");
        report.header(header.toArray(new String[0]));
        JsonNode series = results.at("/vertices/series");
        for (int i = 0; i < series.size(); i++) {
            String p = "/vertices/series/" + i;
            JsonNode s = series.get(i);
            List<String> row = new ArrayList<>(List.of(upper(s.get("method")), s.get("kernels").asText(),
                    "`" + s.get("kernel").asText() + "`", EvalReport.num(results, p + "/fit/slope"),
                    EvalReport.num(results, p + "/fit/from"),
                    EvalReport.num(results, p + "/fit/r2"), s.at("/fit/holds").asBoolean() ? "yes" : "**no**"));
            for (int k = 0; k < sizes.size(); k++) {
                row.add(EvalReport.numOrDash(results, p + "/fit/residualsPercent/" + k));
            }
            row.add(EvalReport.num(results, p + "/verticesInBudget"));
            report.row(row.toArray(new String[0]));
        }
        report.line("");
        report.figure("advice-vertices.png", "Time per frame against vertices, medians with their range and the"
                + " fitted costs", verticesChart(results));
    }

    /** ns per vertex against influences per vertex. */
    private static void influencesReport(JsonNode results, EvalReport report) {
        report.paragraph("Against the influences per vertex (" + EvalReport.num(results, "/influences/vertices")
                + " vertices, the fastest kernels, runs interleaved across the methods): ns per vertex, and a line"
                + " (ns = fixed + per influence x influences) with its residuals; where a line does not hold, its"
                + " slope is no cost per influence.");
        JsonNode counts = results.at("/influences/influences");
        List<String> header = new ArrayList<>(List.of("method", "kernel name"));
        for (int k = 0; k < counts.size(); k++) {
            header.add("ns at " + EvalReport.num(results, "/influences/influences/" + k));
        }
        header.addAll(List.of("fit", "ns fixed", "ns per influence", "r²", "largest residual %", "holds"));
        report.header(header.toArray(new String[0]));
        JsonNode inf = results.at("/influences/series");
        for (int i = 0; i < inf.size(); i++) {
            String p = "/influences/series/" + i;
            List<String> row = new ArrayList<>(List.of(upper(inf.get(i).get("method")),
                    "`" + inf.get(i).get("kernel").asText() + "`"));
            for (int k = 0; k < counts.size(); k++) {
                row.add(EvalReport.num(results, p + "/points/" + k + "/nsPerVertex/median"));
            }
            row.add(inf.get(i).at("/fit/model").asText());
            row.add(EvalReport.num(results, p + "/fit/intercept"));
            row.add(EvalReport.num(results, p + "/fit/slope"));
            row.add(EvalReport.num(results, p + "/fit/r2"));
            row.add(EvalReport.num(results, p + "/fit/residualsPercent/" + largestResidual(inf.get(i).get("fit"))));
            row.add(inf.get(i).at("/fit/holds").asBoolean() ? "yes" : "**no**");
            report.row(row.toArray(new String[0]));
        }
        report.line("");
        report.figure("advice-influences.png", "ns per vertex against influences per vertex", influencesChart(results));
    }

    /** The index of a fit's largest residual (by size) among the points it used. */
    static int largestResidual(JsonNode fit) {
        JsonNode r = fit.get("residualsPercent");
        int best = -1;
        for (int i = 0; i < r.size(); i++) {
            if (r.get(i).isNumber() && (best < 0 || Math.abs(r.get(i).asDouble()) > Math.abs(r.get(best).asDouble()))) {
                best = i;
            }
        }
        return best;
    }

    /** A frame's pose against the skin's joints, per file, and the fit when there is one. */
    private static void jointsReport(JsonNode results, EvalReport report) {
        report.paragraph("Against the joints: the pose of a frame (sample the clip, evaluate the skeleton, the skinning"
                + " matrices and dual quaternions) of each skinned file, runs interleaved across the files, against its"
                + " skin's joints. Files differ in clips and scene nodes as well, so a fit through them is rough:"
                + " its residuals say how rough.");
        report.header("file", "joints", "scene nodes", "pose µs (median)", "fastest", "slowest", "residual %");
        JsonNode files = results.at("/joints/files");
        for (int i = 0; i < files.size(); i++) {
            String p = "/joints/files/" + i;
            report.row("`" + files.get(i).get("file").asText() + "`", EvalReport.num(results, p + "/joints"),
                    EvalReport.num(results, p + "/nodes"), EvalReport.num(results, p + "/micros/median"),
                    EvalReport.num(results, p + "/micros/min"), EvalReport.num(results, p + "/micros/max"),
                    EvalReport.numOrDash(results, "/joints/fit/residualsPercent/" + i));
        }
        report.line("");
        if (results.at("/joints").has("fit")) {
            String f = "/joints/fit";
            report.paragraph("Fitted (" + results.at(f + "/model").asText() + "): " + EvalReport.num(results, f
                    + "/slope") + " µs per joint" + (results.at(f + "/model").asText().equals("line") ? ", "
                    + EvalReport.num(results, f + "/intercept") + " µs fixed" : "") + ", r² " + EvalReport.num(results,
                    f + "/r2") + (results.at(f + "/holds").asBoolean() ? "; every file within "
                    + EvalReport.num(results, f + "/tolerancePercent") + " %." : "; not every file lies within "
                    + EvalReport.num(results, f + "/tolerancePercent") + " % of it, so the slope is only what one more"
                    + " joint costs on average over these files."));
        }
    }

    private static XYChart verticesChart(JsonNode results) {
        XYChart chart = EvalCharts.xy("Skinning time against vertices (synthetic data, one thread)", "vertices",
                "µs per frame (" + EvalCharts.SPREAD + ")");
        EvalCharts.logX(chart);
        EvalCharts.logY(chart);
        List<Double> x = new ArrayList<>();
        results.at("/vertices/vertices").forEach(v -> x.add(v.asDouble()));
        for (JsonNode s : results.at("/vertices/series")) {
            String name = upper(s.get("method")) + " " + s.get("kernels").asText();
            int m = SkinningMethod.fromKey(s.get("method").asText()).ordinal();
            List<JsonNode> spreads = new ArrayList<>();
            s.get("points").forEach(p -> spreads.add(p.get("micros")));
            XYSeries points = EvalCharts.medians(chart, name, x, spreads, EvalCharts.METHOD_COLOURS[m], false);
            points.setMarker(s.get("kernels").asText().equals("scalar") ? SeriesMarkers.SQUARE : SeriesMarkers.CIRCLE);
            // The fit, drawn only over the sizes it was fitted to.
            double ns = s.at("/fit/slope").asDouble();
            List<Double> fx = List.of(s.at("/fit/from").asDouble(), x.get(x.size() - 1));
            List<Double> fy = List.of(ns * fx.get(0) / 1000, ns * fx.get(1) / 1000);
            XYSeries line = chart.addSeries(name + " fit: " + EvalReport.format(s.at("/fit/slope")) + " ns/vertex", fx,
                    fy);
            line.setMarker(SeriesMarkers.NONE);
            line.setLineColor(EvalCharts.METHOD_COLOURS[m]);
            line.setLineStyle(s.get("kernels").asText().equals("scalar") ? SeriesLines.DASH_DASH : SeriesLines.SOLID);
        }
        return chart;
    }

    private static XYChart influencesChart(JsonNode results) {
        XYChart chart = EvalCharts.xy("Skinning cost against influences per vertex (fastest kernels)",
                "influences per vertex", "ns per vertex (" + EvalCharts.SPREAD + ")");
        List<Double> x = new ArrayList<>();
        results.at("/influences/influences").forEach(v -> x.add(v.asDouble()));
        for (JsonNode s : results.at("/influences/series")) {
            int m = SkinningMethod.fromKey(s.get("method").asText()).ordinal();
            List<JsonNode> spreads = new ArrayList<>();
            s.get("points").forEach(p -> spreads.add(p.get("nsPerVertex")));
            EvalCharts.medians(chart, upper(s.get("method")) + (s.at("/fit/holds").asBoolean() ? ": "
                    + EvalReport.format(s.at("/fit/slope")) + " ns per influence" : ": not a line"), x, spreads,
                    EvalCharts.METHOD_COLOURS[m], true);
        }
        chart.getStyler().setYAxisMin(0.0);
        return chart;
    }

    private static String upper(JsonNode key) {
        return key.asText().toUpperCase(Locale.ROOT);
    }
}
