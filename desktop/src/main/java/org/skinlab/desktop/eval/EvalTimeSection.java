package org.skinlab.desktop.eval;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.knowm.xchart.CategoryChart;
import org.knowm.xchart.CategoryChartBuilder;
import org.knowm.xchart.style.Styler;
import org.skinlab.bench.FrameBench;
import org.skinlab.desktop.ModelFileSearch;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.bench.CppSkinningReference;
import org.skinlab.desktop.bench.JitWarmup;
import org.skinlab.desktop.bench.SkinningTiming;
import org.skinlab.desktop.bench.SyntheticSkinData;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.PositionSharing;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * Section "time": the time of one frame per asset and method ({@link FrameBench}, the timing of
 * {@code bench frame}: sample, skinning matrices, skin, one thread, exact normals), with the
 * fastest kernels (SIMD where the JVM has the Vector API) and core's scalar ones, with all
 * influences and cut to 4 (only where a geometry has more), beside the thesis' table. The thesis'
 * assets are ours: its cylinders are rebuilt in assets/cylinders (assets/README.md), its cowboy is
 * S01_cowboy.dae of the shared corpus.
 */
final class EvalTimeSection implements EvalSection {
    /**
     * The methods timed in every variant (scalar kernels, influences capped); the outlook methods
     * (bulge-free DQS, stretchable and twistable bones, splines) only with the fastest kernels and
     * every influence, their cost per vertex beside DQS's: in every variant they quadrupled the
     * section's run (measured: `eval --quick` from 2.5 to 7.4 minutes).
     */
    static final List<SkinningMethod> EVERY_VARIANT = List.of(SkinningMethod.LBS, SkinningMethod.DQS,
            SkinningMethod.COR);

    static final int CAP = 4;
    /** The shared scalar C++ skinning reference, from the repository root. */
    static final String CPP_REFERENCE = "../shared/perf/skin_ref.cpp";

    /** One row of the thesis' table: its asset, ours, and its DQS and LBS times in ms. */
    record ThesisRow(String thesisName, String file, double dqsMillis, double lbsMillis) {
    }

    static final List<ThesisRow> THESIS = List.of(new ThesisRow("cowboy", "S01_cowboy.dae", 4.35, 4.55),
            new ThesisRow("cylinderYLow", "cylinder-twist-low.dae", 2.67, 3.00),
            new ThesisRow("cylinderXHigh", "cylinder-bend.dae", 5.43, 6.5),
            new ThesisRow("cylinderYHigh", "cylinder-twist-high.dae", 4.86, 6.37));

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
        return context.quick() ? 28 : 130;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        boolean quick = context.quick();
        double firstWarmup = quick ? 1.0 : 2.0;
        double warmup = quick ? 0.15 : 0.5;
        double seconds = quick ? 0.25 : 2.0;
        results.put("warmupSeconds", warmup);
        results.put("firstWarmupSeconds", firstWarmup);
        results.put("seconds", seconds);
        results.put("cap", CAP);
        List<Skinned> models = skinned(files(context, results));
        int perAsset = 3 * EVERY_VARIANT.size() + SkinningMethod.values().length;
        int total = models.size() * perAsset;
        int done = 0;
        boolean[][] warmed = new boolean[2][SkinningMethod.values().length];
        ArrayNode assets = results.putArray("assets");
        for (int a = 0; a < models.size(); a++) {
            ObjectNode asset = assets.addObject();
            asset.put("file", models.get(a).file.getFileName().toString());
            ArrayNode runs = asset.putArray("runs");
            for (int cap : new int[] {0, CAP}) {
                if (cap != 0 && asset.get("influences").asInt() <= CAP) {
                    asset.put("capNoEffect", true);
                    done += 2 * EVERY_VARIANT.size();
                    continue;
                }
                for (int k = 0; k < 2; k++) {
                    boolean scalar = k == 1;
                    List<SkinningMethod> methods = cap == 0 && !scalar ? List.of(SkinningMethod.values()) : EVERY_VARIANT;
                    FrameBench bench = new FrameBench(models.get(a).model, NormalTransform.INVERSE_TRANSPOSE,
                            PositionSharing.AUTO, scalar, cap, methods, JitWarmup.WARMUP);
                    if (cap == 0 && !scalar) {
                        putShape(asset, bench.shape());
                    }
                    for (SkinningMethod m : methods) {
                        double w = warmed[k][m.ordinal()] ? warmup : firstWarmup;
                        warmed[k][m.ordinal()] = true;
                        putRun(runs.addObject(), m, scalar, cap, bench.measure(m, w, seconds));
                        context.progress((double) ++done / total);
                    }
                }
            }
        }
        thesis(results);
        reference(context, results.putObject("reference"));
    }

    /** A file with a skinned instance, and its model. */
    private record Skinned(Path file, Model model) {
    }

    /** The files that have a skinned instance, loaded, in order. */
    private static List<Skinned> skinned(List<Path> files) {
        List<Skinned> skinned = new ArrayList<>();
        for (Path f : files) {
            Model m = ModelFiles.load(f).model;
            if (m.instances().stream().anyMatch(MeshInstance::isSkinned)) {
                skinned.add(new Skinned(f, m));
            }
        }
        return skinned;
    }

    /** What one frame of the asset skins: positions, vertices drawn, joints, influences per position. */
    private static void putShape(ObjectNode asset, FrameBench.Shape shape) {
        asset.put("positionsSkinned", shape.positionsSkinned());
        asset.put("renderVertices", shape.renderVertices());
        asset.put("joints", shape.joints());
        asset.put("influences", shape.influences());
    }

    /** One method's timing with the scalar or the fastest kernels, all influences or {@code cap}. */
    private static void putRun(ObjectNode r, SkinningMethod m, boolean scalar, int cap, FrameBench.Timing t) {
        r.put("method", m.key());
        r.put("kernels", scalar ? "scalar" : "fastest");
        r.put("implementation", t.kernel());
        r.put("influences", cap == 0 ? "all" : "at most " + CAP);
        r.put("frames", t.frames());
        r.put("medianMicros", EvalReport.round(t.medianMicros()));
        r.put("minMicros", EvalReport.round(t.minMicros()));
    }

    /** Our COLLADA assets, and the thesis' cowboy when the shared corpus has it (else why not, in results). */
    private static List<Path> files(EvalContext context, ObjectNode results) {
        List<Path> files = new ArrayList<>();
        Path assetsFolder = context.root().resolve("assets");
        for (ModelFileSearch.Entry e : ModelFileSearch.expand(List.of(assetsFolder), ModelFileSearch.COLLADA)) {
            files.add(e.path());
        }
        Path cowboy = context.corpus() == null ? null : context.corpus().resolve(THESIS.get(0).file());
        if (cowboy != null && Files.isRegularFile(cowboy)) {
            files.add(cowboy);
        } else {
            results.put("cowboySkipped", "no " + THESIS.get(0).file() + " in the shared corpus at "
                    + context.corpusPlace());
        }
        return files;
    }

    /**
     * Our kernels against the shared scalar C++ reference on its own synthetic data (4 influences,
     * 64 joints, normals by the blended matrix as it computes them), compiled and run here right
     * before ours; the checksums show both skinned the same data the same way.
     */
    private static void reference(EvalContext context, ObjectNode results) {
        Path source = context.root().resolve(CPP_REFERENCE).normalize();
        String compiler = CppSkinningReference.compiler();
        if (!Files.isRegularFile(source)) {
            results.put("skipped", "no " + source);
            return;
        }
        if (compiler == null) {
            results.put("skipped", "no C++ compiler (g++ or c++) on the PATH");
            return;
        }
        boolean quick = context.quick();
        List<Integer> sizes = quick ? List.of(10_000) : List.of(10_000, 100_000);
        int rounds = quick ? 1 : 3;
        double seconds = quick ? 0.3 : 0.7;
        results.put("source", CPP_REFERENCE);
        results.put("compiler", compiler + " -O3 -DNDEBUG -std=c++17");
        results.put("joints", SyntheticSkinData.JOINTS);
        results.put("influences", SyntheticSkinData.INFLUENCES);
        results.put("rounds", rounds);
        results.put("roundSeconds", seconds);
        List<CppSkinningReference.Result> cpp;
        Path dir = null;
        try {
            dir = Files.createTempDirectory("skinlab-eval-cpp");
            cpp = CppSkinningReference.compile(compiler, source, dir).run(List.of("c-lbs", "c-dqs"), rounds, seconds,
                    sizes);
        } catch (IOException e) {
            results.put("skipped", e.getMessage());
            return;
        } finally {
            deleteQuietly(dir);
        }
        double warmup = quick ? 0.3 : 1.5;
        double oursSeconds = rounds * seconds;
        results.put("oursWarmupSeconds", warmup);
        results.put("oursSeconds", oursSeconds);
        ArrayNode rows = results.putArray("rows");
        for (CppSkinningReference.Result c : cpp) {
            oursBeside(c, rows.addObject(), warmup, oursSeconds);
        }
    }

    /** Our scalar and fastest kernels on the C++ run {@code c}'s data, into {@code row}. */
    private static void oursBeside(CppSkinningReference.Result c, ObjectNode row, double warmup, double oursSeconds) {
        SkinningMethod method = SkinningMethod.fromKey(c.variant().substring(2));
        SyntheticSkinData data = new SyntheticSkinData(c.vertices());
        SkinnedGeometry geometry = data.geometry();
        JointPalette palette = data.palette();
        float[] positions = new float[3 * c.vertices()];
        float[] normals = new float[3 * c.vertices()];
        row.put("vertices", c.vertices());
        row.put("method", method.key());
        row.put("cppMedianNs", c.medianNs());
        row.put("cppMinNs", c.minNs());
        for (boolean scalar : new boolean[] {true, false}) {
            Skinner kernel = scalar ? Skinners.scalar(method, geometry, NormalTransform.BLENDED_MATRIX)
                    : Skinners.create(method, geometry, NormalTransform.BLENDED_MATRIX);
            SkinningTiming t = SkinningTiming.measure(() -> kernel.skinAll(palette, positions, normals), positions,
                    normals, c.vertices(), warmup, oursSeconds);
            String k = scalar ? "scalar" : "fastest";
            row.put(k + "Kernel", kernel.implementation());
            row.put(k + "MedianNs", EvalReport.round(t.median()));
            row.put(k + "Ratio", EvalReport.round(t.median() / c.medianNs()));
            // Both sum the same outputs; float rounding differs only in the last digits.
            row.put(k + "ChecksumAgrees", Math.abs(t.checksum - c.checksum()) <= 1e-4 * Math.abs(c.checksum()));
        }
    }

    private static void deleteQuietly(Path dir) {
        if (dir == null) {
            return;
        }
        try (java.util.stream.Stream<Path> files = Files.walk(dir)) {
            files.sorted(java.util.Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
        } catch (IOException e) {
            // A temporary folder left behind is harmless.
        }
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
            JsonNode dqs = ours(results, t.file(), "dqs");
            JsonNode lbs = ours(results, t.file(), "lbs");
            if (dqs == null || lbs == null) {
                row.put("missing", "not measured here");
                continue;
            }
            row.put("oursDqsMicros", dqs.get("medianMicros").asDouble());
            row.put("oursLbsMicros", lbs.get("medianMicros").asDouble());
            row.put("dqsRatio", EvalReport.round(t.dqsMillis() * 1000 / dqs.get("medianMicros").asDouble()));
            row.put("lbsRatio", EvalReport.round(t.lbsMillis() * 1000 / lbs.get("medianMicros").asDouble()));
        }
    }

    private static JsonNode ours(ObjectNode results, String file, String method) {
        for (JsonNode a : results.get("assets")) {
            if (a.get("file").asText().equals(file)) {
                for (JsonNode r : a.get("runs")) {
                    if (r.get("method").asText().equals(method) && r.get("kernels").asText().equals("fastest")
                            && r.get("influences").asText().equals("all")) {
                        return r;
                    }
                }
            }
        }
        return null;
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        report.paragraph("The time of one frame of the asset's first clip, one thread: sample the clip, the skinning"
                + " matrices (and dual quaternions for DQS and CoR), skin every mesh, positions and exact normals"
                + " (`bench frame`'s protocol). Per asset and method the median over "
                + EvalReport.num(results, "/seconds") + " s of frames after " + EvalReport.num(results, "/warmupSeconds")
                + " s of warm-up (" + EvalReport.num(results, "/firstWarmupSeconds") + " s for a kernel's first asset),"
                + " in µs; with the fastest kernels here (SIMD where the Vector API is on; the kernel's name says"
                + " which ran) and with core's scalar ones; with every influence, and cut to the "
                + EvalReport.num(results, "/cap") + " heaviest (renormalised, what a GPU's fixed slots see) where an"
                + " asset has more (the cut geometry skins every render vertex, without sharing positions, so part of"
                + " that difference is the sharing).");
        report.header("asset", "influences", "method", "kernels", "kernel name", "influences used", "median µs",
                "min µs");
        JsonNode assets = results.get("assets");
        for (int a = 0; a < assets.size(); a++) {
            JsonNode asset = assets.get(a);
            JsonNode runs = asset.get("runs");
            for (int r = 0; r < runs.size(); r++) {
                String p = "/assets/" + a + "/runs/" + r;
                JsonNode run = runs.get(r);
                report.row("`" + asset.get("file").asText() + "`", EvalReport.num(results, "/assets/" + a
                        + "/influences"), run.get("method").asText().toUpperCase(java.util.Locale.ROOT),
                        run.get("kernels").asText(), "`" + run.get("implementation").asText() + "`",
                        run.get("influences").asText().equals("all") ? "all" : "heaviest " + EvalReport.num(results,
                                "/cap"), EvalReport.num(results, p + "/medianMicros"),
                        EvalReport.num(results, p + "/minMicros"));
            }
        }
        report.line("");
        if (results.has("cowboySkipped")) {
            report.paragraph("The cowboy is skipped: `" + results.get("cowboySkipped").asText() + "`.");
        }
        report.heading(3, "Beside the thesis");
        report.paragraph("The thesis' times per deformation (its table, ms) against ours (the fastest kernels, every"
                + " influence; µs); thesis / ours is how many times faster this frame is. The thesis measured"
                + " its own desktop computer, so the ratio mixes the code's and the machine's progress.");
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
        for (int a = 0; a < assets.size(); a++) {
            assetFigure(assets.get(a), report);
        }
        referenceReport(results, report);
    }

    private static void referenceReport(JsonNode results, EvalReport report) {
        report.heading(3, "Against the scalar C++ reference");
        JsonNode ref = results.path("reference");
        if (ref.has("skipped")) {
            report.paragraph("Not run: `" + ref.get("skipped").asText() + "`.");
            return;
        }
        report.paragraph("The shared scalar C++ reference (`" + ref.get("source").asText() + "`, compiled here with `"
                + ref.get("compiler").asText() + "`) on its own synthetic data (" + EvalReport.num(results, "/reference/joints")
                + " joints, " + EvalReport.num(results, "/reference/influences") + " influences per vertex,"
                + " normals by the blended matrix as it computes them), then our kernels on the same data, which"
                + " core's generator reproduces bit for bit, in the same run: its " + EvalReport.num(results,
                "/reference/rounds") + " round(s) of " + EvalReport.num(results, "/reference/roundSeconds")
                + " s against ours, " + EvalReport.num(results, "/reference/oursSeconds") + " s after "
                + EvalReport.num(results, "/reference/oursWarmupSeconds") + " s of warm-up. ns per vertex, medians;"
                + " ours / C++ below one means we are faster; the checksums (the sum of the outputs) agree when both"
                + " skinned the same data alike.");
        report.header("vertices", "method", "C++ ns", "scalar Java ns", "scalar / C++", "fastest Java", "fastest ns",
                "fastest / C++", "checksums agree");
        JsonNode rows = ref.get("rows");
        for (int i = 0; i < rows.size(); i++) {
            String p = "/reference/rows/" + i;
            JsonNode row = rows.get(i);
            report.row(EvalReport.num(results, p + "/vertices"), row.get("method").asText().toUpperCase(java.util.Locale.ROOT),
                    EvalReport.num(results, p + "/cppMedianNs"), EvalReport.num(results, p + "/scalarMedianNs"),
                    EvalReport.num(results, p + "/scalarRatio"), "`" + row.get("fastestKernel").asText() + "`",
                    EvalReport.num(results, p + "/fastestMedianNs"), EvalReport.num(results, p + "/fastestRatio"),
                    row.get("scalarChecksumAgrees").asBoolean() && row.get("fastestChecksumAgrees").asBoolean()
                            ? "yes" : "**no**");
        }
        report.line("");
        CategoryChart chart = new CategoryChartBuilder().width(900).height(500)
                .title("Against the scalar C++ reference (same data, same run)").xAxisTitle("method, vertices")
                .yAxisTitle("ns per vertex (median)").build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        List<String> labels = new ArrayList<>();
        List<Double> cpp = new ArrayList<>();
        List<Double> scalar = new ArrayList<>();
        List<Double> fastest = new ArrayList<>();
        for (JsonNode row : rows) {
            labels.add(row.get("method").asText().toUpperCase(java.util.Locale.ROOT) + ", " + row.get("vertices").asInt());
            cpp.add(row.get("cppMedianNs").asDouble());
            scalar.add(row.get("scalarMedianNs").asDouble());
            fastest.add(row.get("fastestMedianNs").asDouble());
        }
        chart.addSeries("C++ scalar reference (g++ -O3)", labels, cpp);
        chart.addSeries("Java, core's scalar kernel", labels, scalar);
        chart.addSeries("Java, fastest kernel", labels, fastest);
        report.figure("time-cpp-reference.png", "ns per vertex against the scalar C++ reference", chart);
    }

    /** One bar chart per asset: method on the axis, a bar per kernel and influence variant. */
    private static void assetFigure(JsonNode asset, EvalReport report) {
        String file = asset.get("file").asText();
        CategoryChart chart = new CategoryChartBuilder().width(900).height(500)
                .title("Time per frame: " + file).xAxisTitle("method").yAxisTitle("µs per frame (median)").build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        List<String> variants = new ArrayList<>();
        for (JsonNode r : asset.get("runs")) {
            String v = variant(r);
            if (!variants.contains(v)) {
                variants.add(v);
            }
        }
        List<String> methods = new ArrayList<>();
        for (SkinningMethod m : SkinningMethod.values()) {
            methods.add(m.key().toUpperCase(java.util.Locale.ROOT));
        }
        for (String v : variants) {
            List<Double> values = new ArrayList<>();
            for (SkinningMethod m : SkinningMethod.values()) {
                double value = 0;
                for (JsonNode r : asset.get("runs")) {
                    if (variant(r).equals(v) && r.get("method").asText().equals(m.key())) {
                        value = r.get("medianMicros").asDouble();
                    }
                }
                values.add(value);
            }
            chart.addSeries(v, methods, values);
        }
        String png = "time-" + file.replaceAll("\\.dae$", "").replaceAll("[^A-Za-z0-9_-]", "_") + ".png";
        report.figure(png, "Time per frame, " + file, chart);
    }

    private static String variant(JsonNode run) {
        return run.get("kernels").asText() + " kernels, " + run.get("influences").asText() + " influences";
    }
}
