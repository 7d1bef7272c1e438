package org.skinlab.desktop.eval;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.lines.SeriesLines;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.skinlab.desktop.ModelFileSearch;
import org.skinlab.skinning.SkinningMethod;

/**
 * Section "advice": what the numbers mean for AR on a phone. It measures how a frame's cost grows
 * ({@link EvalScaling}: vertices, influences, joints), then draws a recommendation per use from
 * the sections measured before it in the same run (time, quality, crowds, tracking), copying every
 * number it argues with into its own results so that the text prints only numbers of
 * results.json. A use whose inputs were not measured (an {@code --only} run) says so.
 */
final class EvalAdviceSection implements EvalSection {
    /** The character the advice is about: ours, with 4 influences, as a phone AR scene would hold. */
    static final String CHARACTER = "humanoid-walk.dae";
    /** The share of a 60 Hz frame (µs) left to skinning: the camera, tracking and drawing need the rest. */
    static final double BUDGET_MICROS = 4000;
    static final int FRAME_RATE = 60;
    /** One colour per method, in SkinningMethod's order (LBS, DQS, CoR, BFDQS, STBS-LBS, STBS-DQS, spline). */
    private static final java.awt.Color[] COLOURS = {new java.awt.Color(0x1f77b4), new java.awt.Color(0xd62728),
        new java.awt.Color(0x2ca02c), new java.awt.Color(0x9467bd), new java.awt.Color(0xff7f0e),
        new java.awt.Color(0x8c564b), new java.awt.Color(0x17becf)};
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
        return context.quick() ? 14 : 75;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        boolean quick = context.quick();
        double warmup = quick ? 0.1 : 0.4;
        double seconds = quick ? 0.15 : 1.0;
        results.put("warmupSeconds", warmup);
        results.put("seconds", seconds);
        EvalScaling.vertices(quick ? List.of(2_000, 8_000, 32_000) : List.of(1_000, 4_000, 16_000, 64_000, 256_000),
                warmup, seconds, results.putObject("vertices"), f -> context.progress(0.6 * f));
        EvalScaling.influences(quick ? 8_000 : 32_000, List.of(1, 2, 4, 8), warmup, seconds,
                results.putObject("influences"), f -> context.progress(0.6 + 0.25 * f));
        List<Path> files = new ArrayList<>();
        Path assetsFolder = context.root().resolve("assets");
        for (ModelFileSearch.Entry e : ModelFileSearch.expand(List.of(assetsFolder), ModelFileSearch.COLLADA)) {
            files.add(e.path());
        }
        Path cowboy = context.corpus() == null ? null : context.corpus().resolve(EvalTimeSection.THESIS.get(0).file());
        if (cowboy != null && Files.isRegularFile(cowboy)) {
            files.add(cowboy);
        }
        EvalScaling.joints(files, warmup, seconds, results.putObject("joints"), f -> context.progress(0.85 + 0.15 * f));
        budgets(results);
        inputs(context, results.putObject("inputs"));
    }

    /** Per method and kernel, the vertices the fitted line skins within {@link #BUDGET_MICROS}. */
    private static void budgets(ObjectNode results) {
        results.put("budgetMicros", BUDGET_MICROS);
        results.put("frameRateHz", FRAME_RATE);
        for (JsonNode s : results.at("/vertices/series")) {
            double slope = s.get("nsPerVertex").asDouble();
            ((ObjectNode) s).put("verticesInBudget", slope <= 0 ? 0
                    : Math.round((BUDGET_MICROS - Math.max(0, s.get("interceptMicros").asDouble())) * 1000 / slope));
        }
    }

    /** The numbers of the earlier sections the advice argues with, and the ratios derived from them. */
    private static void inputs(EvalContext context, ObjectNode in) {
        in.put("frameMicros", EvalReport.round(FRAME_MICROS));
        JsonNode time = context.measured("time");
        if (time != null) {
            characterTimes(time, in);
        }
        JsonNode quality = context.measured("quality");
        if (quality != null) {
            qualityInputs(quality, in);
        }
        EvalAdvice.crowdsAndTracking(context, in);
    }

    /** The bundled character's frame per method and kernels, and the methods' cost ratios. */
    private static void characterTimes(JsonNode time, ObjectNode in) {
        for (JsonNode asset : time.get("assets")) {
            if (!asset.get("file").asText().equals(CHARACTER)) {
                continue;
            }
            ObjectNode c = in.putObject("character");
            c.put("file", CHARACTER);
            c.put("vertices", asset.get("renderVertices").asInt());
            c.put("joints", asset.get("joints").asInt());
            for (JsonNode run : asset.get("runs")) {
                if (run.get("influences").asText().equals("all")) {
                    ObjectNode k = object(c, run.get("kernels").asText());
                    double micros = run.at("/micros/median").asDouble();
                    k.put(run.get("method").asText() + "Micros", micros);
                    k.put(run.get("method").asText() + "PerFrame", (long) Math.floor(FRAME_MICROS / micros));
                }
            }
            for (String k : new String[] {"fastest", "scalar"}) {
                ObjectNode n = object(c, k);
                n.put("dqsOverLbs", EvalReport.round(n.get("dqsMicros").asDouble() / n.get("lbsMicros").asDouble()));
                n.put("corOverDqs", EvalReport.round(n.get("corMicros").asDouble() / n.get("dqsMicros").asDouble()));
            }
        }
    }

    /** The twist, bend, character and influence-cap numbers of the quality section. */
    private static void qualityInputs(JsonNode quality, ObjectNode in) {
        for (JsonNode asset : quality.get("assets")) {
            String file = asset.get("file").asText();
            if (asset.has("skipped")) {
                continue;
            }
            if (file.equals("cylinder-twist-high.dae")) {
                ObjectNode t = in.putObject("twist");
                t.put("file", file);
                JsonNode angles = asset.get("angleDegrees");
                t.put("angleDegrees", angles.get(angles.size() - 1).asDouble());
                for (SkinningMethod m : SkinningMethod.values()) {
                    t.put(m.key() + "Ring", asset.at("/methods/" + m.key() + "/minRingRadius").asDouble());
                }
                // The first sampled angle at which LBS has lost a tenth of the ring.
                JsonNode ring = asset.at("/methods/lbs/ringRadius");
                for (int i = 0; i < ring.size(); i++) {
                    if (ring.get(i).asDouble() < 0.9) {
                        t.put("lbsRingBelow90PercentAtDegrees", angles.get(i).asDouble());
                        break;
                    }
                }
            } else if (file.equals("cylinder-bend.dae")) {
                ObjectNode b = in.putObject("bend");
                b.put("file", file);
                JsonNode angles = asset.get("angleDegrees");
                b.put("angleDegrees", angles.get(angles.size() - 1).asDouble());
                for (SkinningMethod m : SkinningMethod.values()) {
                    b.put(m.key() + "Bulge", asset.at("/methods/" + m.key() + "/maxBulge").asDouble());
                    b.put(m.key() + "Volume", asset.at("/methods/" + m.key() + "/minVolume").asDouble());
                }
            } else if (file.equals(CHARACTER)) {
                ObjectNode d = in.putObject("characterQuality");
                d.put("maxLbsDqsPercent", pair(asset, "lbs", "dqs").get("maxPercent").asDouble());
                d.put("maxDqsCorPercent", pair(asset, "dqs", "cor").get("maxPercent").asDouble());
            } else if (asset.get("influences").asInt() > InfluenceCapReport.CAP_4) {
                ObjectNode cap = in.putObject("cap");
                cap.put("file", file);
                cap.put("influences", asset.get("influences").asInt());
                for (JsonNode c : asset.get("caps")) {
                    if (c.get("cap").asInt() == InfluenceCapReport.CAP_4) {
                        cap.put("cap", InfluenceCapReport.CAP_4);
                        cap.put("cappedPositions", c.get("cappedPositions").asInt());
                        cap.put("lbsPercent", c.get("lbsPercent").asDouble());
                        cap.put("dqsPercent", c.get("dqsPercent").asDouble());
                    }
                }
            }
        }
    }

    /** The quality section's comparison of methods {@code a} and {@code b} on an asset. */
    static JsonNode pair(JsonNode asset, String a, String b) {
        for (JsonNode p : asset.get("pairs")) {
            if (p.get("a").asText().equals(a) && p.get("b").asText().equals(b)) {
                return p;
            }
        }
        throw new IllegalStateException("no pair " + a + " - " + b + " in " + asset.get("file"));
    }

    private static ObjectNode object(ObjectNode parent, String name) {
        return parent.has(name) ? (ObjectNode) parent.get(name) : parent.putObject(name);
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        scalingReport(results, report);
        report.heading(3, "Recommendations");
        EvalAdvice.write(results, report);
    }

    private static void scalingReport(JsonNode results, EvalReport report) {
        report.heading(3, "How the cost grows");
        verticesReport(results, report);
        influencesReport(results, report);
        jointsReport(results, report);
    }

    /** Time per frame against vertices: the fitted lines and the vertices each fits into the budget. */
    private static void verticesReport(JsonNode results, EvalReport report) {
        report.paragraph("Skinning alone (no pose), one thread, positions and exact normals, on the shared C++"
                + " reference's synthetic data (" + EvalReport.num(results, "/vertices/joints") + " joints, "
                + EvalReport.num(results, "/vertices/influences") + " influences per vertex), the median of "
                + EvalReport.num(results, "/seconds") + " s after " + EvalReport.num(results, "/warmupSeconds")
                + " s of warm-up per point, and a least-squares line through the points: its slope is the cost of one"
                + " more vertex, its intercept the cost of a frame without vertices. The scalar kernels are the ones a"
                + " phone runs (Android's runtime has no Vector API). The vertices in budget are what the line fits into "
                + EvalReport.num(results, "/budgetMicros") + " µs, the share of a " + EvalReport.num(results, "/frameRateHz") + " Hz frame this advice leaves to"
                + " skinning (the camera image, the tracker and the drawing need the rest) on one core of this machine.");
        report.header("method", "kernels", "kernel name", "ns per vertex (slope)", "intercept µs", "r²",
                "vertices in budget");
        JsonNode series = results.at("/vertices/series");
        for (int i = 0; i < series.size(); i++) {
            String p = "/vertices/series/" + i;
            JsonNode s = series.get(i);
            report.row(s.get("method").asText().toUpperCase(Locale.ROOT), s.get("kernels").asText(),
                    "`" + s.get("kernel").asText() + "`", EvalReport.num(results, p + "/nsPerVertex"),
                    EvalReport.num(results, p + "/interceptMicros"), EvalReport.num(results, p + "/r2"),
                    EvalReport.num(results, p + "/verticesInBudget"));
        }
        report.line("");
        report.figure("advice-vertices.png", "Time per frame against vertices, with the fitted lines",
                verticesChart(results));
    }

    /** Time per vertex against influences per vertex. */
    private static void influencesReport(JsonNode results, EvalReport report) {
        report.paragraph("Against the influences per vertex (" + EvalReport.num(results, "/influences/vertices")
                + " vertices, the fastest kernels): the slope is the cost of one more influence per vertex.");
        report.header("method", "kernel name", "ns per vertex at each influence count", "ns per influence (slope)",
                "r²");
        JsonNode inf = results.at("/influences/series");
        for (int i = 0; i < inf.size(); i++) {
            String p = "/influences/series/" + i;
            List<String> values = new ArrayList<>();
            JsonNode counts = results.at("/influences/influences");
            for (int k = 0; k < counts.size(); k++) {
                values.add(EvalReport.num(results, "/influences/influences/" + k) + ": "
                        + EvalReport.num(results, p + "/nsPerVertex/" + k));
            }
            report.row(inf.get(i).get("method").asText().toUpperCase(Locale.ROOT),
                    "`" + inf.get(i).get("kernel").asText() + "`", String.join(", ", values),
                    EvalReport.num(results, p + "/nsPerInfluence"), EvalReport.num(results, p + "/r2"));
        }
        report.line("");
        report.figure("advice-influences.png", "ns per vertex against influences per vertex", influencesChart(results));
    }

    /** A frame's pose against the skin's joints, per file, and the fitted line when there is one. */
    private static void jointsReport(JsonNode results, EvalReport report) {
        report.paragraph("Against the joints: the pose of a frame (sample the clip, evaluate the skeleton, the skinning"
                + " matrices and dual quaternions) of each skinned file, against its skin's joints. The line through"
                + " files of different skeletons and clips is rough; its slope is about what one more joint costs.");
        report.header("file", "joints", "scene nodes", "pose µs (median)");
        JsonNode files = results.at("/joints/files");
        for (int i = 0; i < files.size(); i++) {
            String p = "/joints/files/" + i;
            report.row("`" + files.get(i).get("file").asText() + "`", EvalReport.num(results, p + "/joints"),
                    EvalReport.num(results, p + "/nodes"), EvalReport.num(results, p + "/medianMicros"));
        }
        report.line("");
        if (results.at("/joints").has("microsPerJoint")) {
            report.paragraph("Fitted: " + EvalReport.num(results, "/joints/microsPerJoint") + " µs per joint, "
                    + EvalReport.num(results, "/joints/interceptMicros") + " µs intercept, r² "
                    + EvalReport.num(results, "/joints/r2") + ".");
        }
    }

    private static XYChart verticesChart(JsonNode results) {
        XYChart chart = new XYChartBuilder().width(900).height(550)
                .title("Skinning time against vertices (synthetic data, one thread)").xAxisTitle("vertices")
                .yAxisTitle("µs per frame (median)").build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        List<Double> x = new ArrayList<>();
        results.at("/vertices/vertices").forEach(v -> x.add(v.asDouble()));
        // The line at 40 log-spaced points, so that it reads as the fitted curve on the log axes.
        List<Double> dense = new ArrayList<>();
        double lo = Math.log(x.get(0));
        double hi = Math.log(x.get(x.size() - 1));
        for (int i = 0; i < 40; i++) {
            dense.add(Math.exp(lo + (hi - lo) * i / 39));
        }
        for (JsonNode s : results.at("/vertices/series")) {
            String name = s.get("method").asText().toUpperCase(Locale.ROOT) + " " + s.get("kernels").asText();
            java.awt.Color colour = COLOURS[SkinningMethod.fromKey(s.get("method").asText()).ordinal()];
            List<Double> y = new ArrayList<>();
            s.get("medianMicros").forEach(v -> y.add(v.asDouble()));
            XYSeries points = chart.addSeries(name, x, y);
            points.setLineStyle(SeriesLines.NONE);
            points.setMarkerColor(colour);
            points.setMarker(s.get("kernels").asText().equals("scalar") ? SeriesMarkers.SQUARE : SeriesMarkers.CIRCLE);
            List<Double> fit = new ArrayList<>();
            for (double v : dense) {
                fit.add(Math.max(1e-3, s.get("interceptMicros").asDouble() + s.get("nsPerVertex").asDouble() * v / 1000));
            }
            XYSeries line = chart.addSeries(name + ": " + EvalReport.format(s.get("nsPerVertex")) + " ns/vertex", dense,
                    fit);
            line.setMarker(SeriesMarkers.NONE);
            line.setLineColor(colour);
            line.setLineStyle(s.get("kernels").asText().equals("scalar") ? SeriesLines.DASH_DASH : SeriesLines.SOLID);
        }
        return chart;
    }

    private static XYChart influencesChart(JsonNode results) {
        XYChart chart = new XYChartBuilder().width(900).height(500)
                .title("Skinning cost against influences per vertex (fastest kernels)").xAxisTitle("influences per vertex")
                .yAxisTitle("ns per vertex (median)").build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        List<Double> x = new ArrayList<>();
        results.at("/influences/influences").forEach(v -> x.add(v.asDouble()));
        for (JsonNode s : results.at("/influences/series")) {
            List<Double> y = new ArrayList<>();
            s.get("nsPerVertex").forEach(v -> y.add(v.asDouble()));
            chart.addSeries(s.get("method").asText().toUpperCase(Locale.ROOT) + ": "
                    + EvalReport.format(s.get("nsPerInfluence")) + " ns per influence", x, y);
        }
        return chart;
    }
}
