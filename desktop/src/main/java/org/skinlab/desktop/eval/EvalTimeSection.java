package org.skinlab.desktop.eval;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.knowm.xchart.XYChart;
import org.skinlab.internal.bench.FrameBench;
import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.internal.bench.Rounds;
import org.skinlab.internal.bench.Spread;
import org.skinlab.desktop.ModelFileSearch;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.bench.JitWarmup;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.PositionSharing;
import org.skinlab.skinning.SkinningMethod;

/**
 * Section "time": the time of one frame per asset and method ({@link FrameBench}, the timing of
 * {@code bench frame}: sample, skinning matrices, skin, one thread, exact normals), every method
 * with the fastest kernels (SIMD where the JVM has the Vector API) and with core's scalar ones,
 * with all influences and cut to 4 (where a geometry has more), each timing in interleaved rounds
 * ({@link FrameTimes}, the protocol the Android app runs too); DQS over LBS per round; beside the
 * thesis' table; then our kernels against the shared C++ reference ({@link EvalCppReference}).
 * The assets: every skinned file of assets/, the thesis' cowboy and the stormtrooper of the shared
 * corpus.
 */
final class EvalTimeSection implements EvalSection {
    /** The methods also timed with their influences capped (the files that have more than 4). */
    static final List<SkinningMethod> CAPPED = List.of(SkinningMethod.LBS, SkinningMethod.DQS, SkinningMethod.COR);

    static final int CAP = 4;

    /** The shared corpus' characters timed beside ours: the thesis' cowboy and the largest, the stormtrooper. */
    static final List<String> CORPUS = List.of("S01_cowboy.dae", "S03_stormtrooper.dae");

    /** One row of the thesis' table: its asset, ours, and its DQS and LBS times in ms. */
    record ThesisRow(String thesisName, String file, double dqsMillis, double lbsMillis) {
    }

    static final List<ThesisRow> THESIS = List.of(new ThesisRow("cowboy", "S01_cowboy.dae", 4.35, 4.55),
            new ThesisRow("cylinderYLow", "cylinder-twist-low.dae", 2.67, 3.00),
            new ThesisRow("cylinderXHigh", "cylinder-bend.dae", 5.43, 6.5),
            new ThesisRow("cylinderYHigh", "cylinder-twist-high.dae", 4.86, 6.37));

    private static final String[] KERNELS = {"fastest", "scalar"};

    @Override
    public String key() {
        return "time";
    }

    @Override
    public String title() {
        return "Time per deformation";
    }

    @Override
    public double estimatedSeconds(EvalContext context) {
        return context.quick() ? 45 : 420;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        boolean quick = context.quick();
        FrameTimes.Protocol first = quick ? new FrameTimes.Protocol(Rounds.MIN_RUNS, 0.5, 0.01, 0.04)
                : new FrameTimes.Protocol(Rounds.MIN_RUNS, 2.0, 0.05, 0.4);
        FrameTimes.Protocol later = new FrameTimes.Protocol(first.rounds(), quick ? 0.05 : 0.3,
                first.warmupSeconds(), first.seconds());
        ObjectNode protocol = results.putObject("protocol");
        protocol.put("rounds", first.rounds());
        protocol.put("firstWarmupSeconds", first.firstWarmupSeconds());
        protocol.put("assetWarmupSeconds", later.firstWarmupSeconds());
        protocol.put("warmupSeconds", first.warmupSeconds());
        protocol.put("seconds", first.seconds());
        results.put("cap", CAP);
        List<Path> files = files(context, results);
        List<SkinningMethod> all = List.of(SkinningMethod.values());
        List<SkinningMethod> scalarMethods = quick ? CAPPED : all;
        ArrayNode assets = results.putArray("assets");
        boolean[] warmed = new boolean[2];
        for (int a = 0; a < files.size(); a++) {
            Model model = ModelFiles.load(files.get(a)).model;
            ObjectNode asset = assets.addObject();
            asset.put("file", files.get(a).getFileName().toString());
            ArrayNode runs = asset.putArray("runs");
            for (int cap : new int[] {0, CAP}) {
                for (int k = 0; k < KERNELS.length; k++) {
                    boolean scalar = k == 1;
                    List<SkinningMethod> methods = cap != 0 ? CAPPED : scalar ? scalarMethods : all;
                    FrameBench bench = new FrameBench(model, NormalTransform.INVERSE_TRANSPOSE, PositionSharing.AUTO,
                            scalar, cap, methods, JitWarmup.WARMUP);
                    if (cap == 0 && !scalar) {
                        putShape(asset, bench.shape());
                    } else if (cap != 0 && bench.shape().influences() == asset.get("influences").asInt()) {
                        asset.put("capNoEffect", true);
                        break;
                    }
                    for (FrameTimes.Result r : FrameTimes.measure(bench, methods, warmed[k] ? later : first)) {
                        putRun(runs.addObject(), r, KERNELS[k], cap);
                    }
                    warmed[k] = true;
                }
            }
            putDqsOverLbs(asset);
            context.progress(0.85 * (a + 1) / files.size());
        }
        thesis(results);
        EvalCppReference.measure(context, results.putObject("reference"));
    }

    /** Our skinned assets (assets/**.dae; each .glb twin holds the same scene: the load section checks it), and the corpus' characters. */
    private static List<Path> files(EvalContext context, ObjectNode results) {
        List<Path> files = new ArrayList<>();
        for (ModelFileSearch.Entry e : ModelFileSearch.expand(List.of(context.root().resolve("assets")),
                ModelFileSearch.COLLADA)) {
            Model model = ModelFiles.load(e.path()).model;
            if (model.instances().stream().anyMatch(MeshInstance::isSkinned) && !model.clips().isEmpty()) {
                files.add(e.path());
            }
        }
        ArrayNode skipped = results.putArray("corpusSkipped");
        for (String name : CORPUS) {
            Path f = context.corpus() == null ? null : context.corpus().resolve(name);
            if (f != null && Files.isRegularFile(f)) {
                files.add(f);
            } else {
                skipped.add(name + ": not in the shared corpus at " + context.corpusPlace());
                context.say("time: " + name + " skipped: no shared corpus at " + context.corpusPlace());
            }
        }
        return files;
    }

    /** What one frame of the asset skins: positions, vertices drawn, joints, influences per position. */
    private static void putShape(ObjectNode asset, FrameBench.Shape shape) {
        asset.put("positionsSkinned", shape.positionsSkinned());
        asset.put("renderVertices", shape.renderVertices());
        asset.put("joints", shape.joints());
        asset.put("influences", shape.influences());
    }

    /** One method's timing with the scalar or the fastest kernels, all influences or at most the cap. */
    private static void putRun(ObjectNode r, FrameTimes.Result result, String kernels, int cap) {
        r.put("method", result.method().key());
        r.put("kernels", kernels);
        r.put("implementation", result.kernel());
        r.put("influences", cap == 0 ? "all" : "at most " + CAP);
        r.put("frames", result.frames());
        EvalReport.putSpread(r, "micros", result.micros());
    }

    /**
     * DQS's time over LBS's, per kernel and influence variant, round by round: the two were timed
     * one right after the other in each round, so the ratio of a round cancels the machine's drift.
     */
    private static void putDqsOverLbs(ObjectNode asset) {
        ArrayNode ratios = asset.putArray("dqsOverLbs");
        for (String kernels : KERNELS) {
            for (String influences : new String[] {"all", "at most " + CAP}) {
                JsonNode lbs = run(asset, SkinningMethod.LBS, kernels, influences);
                JsonNode dqs = run(asset, SkinningMethod.DQS, kernels, influences);
                if (lbs == null || dqs == null) {
                    continue;
                }
                double[] per = new double[lbs.at("/micros/runs").size()];
                for (int i = 0; i < per.length; i++) {
                    per[i] = dqs.at("/micros/runs/" + i).asDouble() / lbs.at("/micros/runs/" + i).asDouble();
                }
                ObjectNode ratio = ratios.addObject().put("kernels", kernels).put("influences", influences);
                EvalReport.putSpread(ratio, "ratio", Spread.of(per));
            }
        }
    }

    /** The run of {@code method} with {@code kernels} and {@code influences} in an asset's results, or null. */
    static JsonNode run(JsonNode asset, SkinningMethod method, String kernels, String influences) {
        for (JsonNode r : asset.get("runs")) {
            if (r.get("method").asText().equals(method.key()) && r.get("kernels").asText().equals(kernels)
                    && r.get("influences").asText().equals(influences)) {
                return r;
            }
        }
        return null;
    }

    /** The asset named {@code file} in the section's results, or null. */
    static JsonNode asset(JsonNode results, String file) {
        for (JsonNode a : results.path("assets")) {
            if (a.get("file").asText().equals(file)) {
                return a;
            }
        }
        return null;
    }

    /** The thesis' rows beside ours (fastest kernels, all influences): thesis / ours, how many times faster. */
    private static void thesis(ObjectNode results) {
        ArrayNode rows = results.putArray("thesis");
        for (ThesisRow t : THESIS) {
            ObjectNode row = rows.addObject();
            row.put("thesisAsset", t.thesisName());
            row.put("file", t.file());
            row.put("thesisDqsMillis", t.dqsMillis());
            row.put("thesisLbsMillis", t.lbsMillis());
            JsonNode asset = asset(results, t.file());
            JsonNode dqs = asset == null ? null : run(asset, SkinningMethod.DQS, "fastest", "all");
            JsonNode lbs = asset == null ? null : run(asset, SkinningMethod.LBS, "fastest", "all");
            if (dqs == null || lbs == null) {
                row.put("missing", "not measured here");
                continue;
            }
            row.put("oursDqsMicros", dqs.at("/micros/median").asDouble());
            row.put("oursLbsMicros", lbs.at("/micros/median").asDouble());
            row.put("dqsRatio", EvalReport.round(t.dqsMillis() * 1000 / dqs.at("/micros/median").asDouble()));
            row.put("lbsRatio", EvalReport.round(t.lbsMillis() * 1000 / lbs.at("/micros/median").asDouble()));
        }
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        report.paragraph("The time of one frame of the asset's first clip, one thread: sample the clip, the skinning"
                + " matrices (and whatever else the method reads: dual quaternions, bones), skin every mesh,"
                + " positions and exact normals (`bench frame`'s frame, `FrameBench`). Every method with the"
                + " fastest kernels here (SIMD where the Vector API is on; the kernel's name says which ran) and with"
                + " core's scalar ones, the code the Android app runs (there on ART, not on this JVM: section"
                + " \"phone\" holds a phone's own times); with every influence, and cut to the "
                + EvalReport.num(results, "/cap") + " heaviest (renormalised, what a GPU's fixed slots see) where an"
                + " asset has more (the cut geometry skins every render vertex, without sharing positions, so part of"
                + " that difference is the sharing). Each timing is " + EvalReport.num(results, "/protocol/rounds")
                + " runs, interleaved across the methods (each round times every method once, starting one further"
                + " along): a run is the median frame of " + EvalReport.num(results, "/protocol/seconds")
                + " s after a warm-up of " + EvalReport.num(results, "/protocol/warmupSeconds") + " s ("
                + EvalReport.num(results, "/protocol/firstWarmupSeconds") + " s for a kernel's first asset, "
                + EvalReport.num(results, "/protocol/assetWarmupSeconds") + " s for a later asset's first round,"
                + " each also until the JIT has compiled the kernels). The table gives the median run, the fastest"
                + " and the slowest, in µs; the Android app's measurement (section \"phone\") runs the same"
                + " protocol.");
        for (JsonNode s : results.get("corpusSkipped")) {
            report.paragraph("Skipped: `" + s.asText() + "`.");
        }
        timeTable(results, report);
        ratioTable(results, report);
        thesisTable(results, report);
        figure(results, "fastest", report);
        figure(results, "scalar", report);
        EvalCppReference.report(results, report);
    }

    private static void timeTable(JsonNode results, EvalReport report) {
        report.header("asset", "positions skinned", "joints", "influences", "method", "kernels", "kernel name",
                "influences used", "median µs", "fastest µs", "slowest µs");
        JsonNode assets = results.get("assets");
        for (int a = 0; a < assets.size(); a++) {
            JsonNode asset = assets.get(a);
            JsonNode runs = asset.get("runs");
            String p0 = "/assets/" + a;
            for (int r = 0; r < runs.size(); r++) {
                String p = p0 + "/runs/" + r;
                JsonNode run = runs.get(r);
                report.row("`" + asset.get("file").asText() + "`", EvalReport.num(results, p0 + "/positionsSkinned"),
                        EvalReport.num(results, p0 + "/joints"), EvalReport.num(results, p0 + "/influences"),
                        upper(run.get("method")), run.get("kernels").asText(),
                        "`" + run.get("implementation").asText() + "`",
                        run.get("influences").asText().equals("all") ? "all"
                                : "heaviest " + EvalReport.num(results, "/cap"),
                        EvalReport.num(results, p + "/micros/median"), EvalReport.num(results, p + "/micros/min"),
                        EvalReport.num(results, p + "/micros/max"));
            }
        }
        report.line("");
    }

    private static void ratioTable(JsonNode results, EvalReport report) {
        report.heading(3, "DQS against LBS on each asset");
        report.paragraph("The thesis found DQS faster than LBS. DQS's frame time over LBS's, per round (the two were"
                + " timed one right after the other, so a round's ratio cancels the machine's drift): the median"
                + " round and the range. Below 1, DQS is the faster. Why the ratio differs between kernels:"
                + " \"DQS against LBS, per kernel\" below.");
        report.header("asset", "influences", "kernels", "influences used", "DQS / LBS (median)", "lowest",
                "highest");
        JsonNode assets = results.get("assets");
        for (int a = 0; a < assets.size(); a++) {
            JsonNode ratios = assets.get(a).get("dqsOverLbs");
            for (int i = 0; i < ratios.size(); i++) {
                String p = "/assets/" + a + "/dqsOverLbs/" + i;
                report.row("`" + assets.get(a).get("file").asText() + "`",
                        EvalReport.num(results, "/assets/" + a + "/influences"), ratios.get(i).get("kernels").asText(),
                        ratios.get(i).get("influences").asText(), EvalReport.num(results, p + "/ratio/median"),
                        EvalReport.num(results, p + "/ratio/min"), EvalReport.num(results, p + "/ratio/max"));
            }
        }
        report.line("");
    }

    private static void thesisTable(JsonNode results, EvalReport report) {
        report.heading(3, "Beside the thesis");
        report.paragraph("The thesis' times per deformation (its table, ms) against ours (the fastest kernels, every"
                + " influence, the median run; µs); thesis / ours is how many times faster this frame is. The thesis"
                + " measured its own desktop computer, so the ratio mixes the code's and the machine's progress.");
        report.header("thesis asset", "ours", "thesis DQS ms", "ours DQS µs", "DQS thesis / ours", "thesis LBS ms",
                "ours LBS µs", "LBS thesis / ours");
        JsonNode rows = results.get("thesis");
        for (int i = 0; i < rows.size(); i++) {
            String p = "/thesis/" + i;
            JsonNode row = rows.get(i);
            report.row(row.get("thesisAsset").asText(), "`" + row.get("file").asText() + "`",
                    EvalReport.num(results, p + "/thesisDqsMillis"), EvalReport.numOrDash(results, p + "/oursDqsMicros"),
                    EvalReport.numOrDash(results, p + "/dqsRatio"), EvalReport.num(results, p + "/thesisLbsMillis"),
                    EvalReport.numOrDash(results, p + "/oursLbsMicros"), EvalReport.numOrDash(results, p + "/lbsRatio"));
        }
        report.line("");
    }

    /** Every asset's frame per method with one kind of kernels, every influence: medians and their range. */
    private static void figure(JsonNode results, String kernels, EvalReport report) {
        JsonNode assets = results.get("assets");
        List<String> labels = new ArrayList<>();
        for (JsonNode a : assets) {
            labels.add(EvalCharts.shortName(a.get("file").asText()));
        }
        XYChart chart = EvalCharts.xy("Time per frame, " + kernels + " kernels, every influence", "asset",
                "µs per frame (" + EvalCharts.SPREAD + ")");
        EvalCharts.categories(chart, labels, 90);
        EvalCharts.logY(chart);
        SkinningMethod[] methods = SkinningMethod.values();
        for (int m = 0; m < methods.length; m++) {
            List<Double> x = new ArrayList<>();
            List<JsonNode> spreads = new ArrayList<>();
            for (int a = 0; a < assets.size(); a++) {
                JsonNode run = run(assets.get(a), methods[m], kernels, "all");
                if (run != null) {
                    x.add(EvalCharts.offset(a, m, methods.length));
                    spreads.add(run.get("micros"));
                }
            }
            if (!x.isEmpty()) {
                EvalCharts.medians(chart, methods[m].key().toUpperCase(Locale.ROOT), x, spreads,
                        EvalCharts.METHOD_COLOURS[m], false);
            }
        }
        report.figure("time-" + kernels + ".png", "Time per frame per asset and method, " + kernels + " kernels",
                chart);
    }

    private static String upper(JsonNode text) {
        return text.asText().toUpperCase(Locale.ROOT);
    }
}
