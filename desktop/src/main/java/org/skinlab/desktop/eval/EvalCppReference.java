package org.skinlab.desktop.eval;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.knowm.xchart.XYChart;
import org.skinlab.bench.Rounds;
import org.skinlab.bench.Spread;
import org.skinlab.desktop.bench.CppSkinningReference;
import org.skinlab.desktop.bench.SkinningTiming;
import org.skinlab.desktop.bench.SyntheticSkinData;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * The time section's last part: our kernels against the shared scalar C++ reference
 * ({@code ../shared/perf/skin_ref.cpp}) on its own synthetic data (4 influences, 64 joints, normals
 * by the blended matrix as it computes them), compiled and run here; the checksums show both
 * skinned the same data the same way. The reference, our scalar and our fastest kernels are timed
 * in interleaved rounds: each round runs the reference's program once (one round of its own) and
 * each of our kernels once, starting one further along.
 */
final class EvalCppReference {
    /** The shared scalar C++ skinning reference, from the repository root. */
    static final String SOURCE = "../shared/perf/skin_ref.cpp";
    private static final List<SkinningMethod> METHODS = List.of(SkinningMethod.LBS, SkinningMethod.DQS);
    private static final String[] OURS = {"scalar", "fastest"};

    private EvalCppReference() {
    }

    static void measure(EvalContext context, ObjectNode results) {
        Path source = context.root().resolve(SOURCE).normalize();
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
        double seconds = quick ? 0.1 : 0.5;
        double warmup = quick ? 0.3 : 1.5;
        results.put("source", SOURCE);
        results.put("compiler", compiler + " -O3 -DNDEBUG -std=c++17");
        results.put("joints", SyntheticSkinData.JOINTS);
        results.put("influences", SyntheticSkinData.INFLUENCES);
        results.put("rounds", Rounds.MIN_RUNS);
        results.put("roundSeconds", seconds);
        results.put("oursWarmupSeconds", warmup);
        Path dir = null;
        try {
            dir = Files.createTempDirectory("skinlab-eval-cpp");
            CppSkinningReference cpp = CppSkinningReference.compile(compiler, source, dir);
            measureRounds(cpp, sizes, seconds, warmup, context, results.putArray("rows"));
        } catch (IOException e) {
            results.remove("rows");
            results.put("skipped", e.getMessage());
        } finally {
            deleteQuietly(dir);
        }
    }

    /** One row per method and size: the reference's and our kernels' ns per vertex, each run kept. */
    private static void measureRounds(CppSkinningReference cpp, List<Integer> sizes, double seconds, double warmup,
            EvalContext context, ArrayNode rows) throws IOException {
        int n = METHODS.size() * sizes.size();
        double[][][] runs = new double[1 + OURS.length][n][Rounds.MIN_RUNS];
        double[] cppChecksum = new double[n];
        Ours[] ours = new Ours[n];
        for (int i = 0; i < n; i++) {
            ours[i] = new Ours(METHODS.get(i % METHODS.size()), sizes.get(i / METHODS.size()));
        }
        List<String> variants = new ArrayList<>();
        METHODS.forEach(m -> variants.add("c-" + m.key()));
        for (int r = 0; r < Rounds.MIN_RUNS; r++) {
            for (int k = 0; k <= OURS.length; k++) {
                int who = (r + k) % (1 + OURS.length);
                if (who == 0) {
                    for (CppSkinningReference.Result c : cpp.run(variants, 1, seconds, sizes)) {
                        int i = sizes.indexOf(c.vertices()) * METHODS.size()
                                + METHODS.indexOf(SkinningMethod.fromKey(c.variant().substring(2)));
                        runs[0][i][r] = c.medianNs();
                        cppChecksum[i] = c.checksum();
                    }
                } else {
                    for (int i = 0; i < n; i++) {
                        runs[who][i][r] = ours[i].time(who == 1, r == 0 ? warmup : 0.05, seconds);
                    }
                }
            }
            context.progress(0.85 + 0.15 * (r + 1) / Rounds.MIN_RUNS);
        }
        for (int i = 0; i < n; i++) {
            ObjectNode row = rows.addObject();
            row.put("vertices", ours[i].vertices);
            row.put("method", ours[i].method.key());
            EvalReport.putSpread(row, "cppNs", Spread.of(runs[0][i]));
            for (int k = 0; k < OURS.length; k++) {
                String kernels = OURS[k];
                Spread ns = Spread.of(runs[1 + k][i]);
                row.put(kernels + "Kernel", ours[i].kernel(kernels.equals("scalar")).implementation());
                EvalReport.putSpread(row, kernels + "Ns", ns);
                row.put(kernels + "Ratio", EvalReport.round(ns.median() / Spread.of(runs[0][i]).median()));
                // Both sum the same outputs; float rounding differs only in the last digits.
                row.put(kernels + "ChecksumAgrees",
                        Math.abs(ours[i].checksum - cppChecksum[i]) <= 1e-4 * Math.abs(cppChecksum[i]));
            }
        }
    }

    /** Our scalar and fastest kernels of one method on the reference's data of one size. */
    private static final class Ours {
        final SkinningMethod method;
        final int vertices;
        final JointPalette palette;
        final float[] positions;
        final float[] normals;
        final Skinner scalar;
        final Skinner fastest;
        double checksum;

        Ours(SkinningMethod method, int vertices) {
            this.method = method;
            this.vertices = vertices;
            SyntheticSkinData data = new SyntheticSkinData(vertices);
            palette = data.palette();
            positions = new float[3 * vertices];
            normals = new float[3 * vertices];
            scalar = Skinners.scalar(method, data.geometry(), NormalTransform.BLENDED_MATRIX);
            fastest = Skinners.create(method, data.geometry(), NormalTransform.BLENDED_MATRIX);
        }

        Skinner kernel(boolean isScalar) {
            return isScalar ? scalar : fastest;
        }

        /** The median ns per vertex of one run (the reference's protocol, {@link SkinningTiming}). */
        double time(boolean isScalar, double warmup, double seconds) {
            Skinner k = kernel(isScalar);
            SkinningTiming t = SkinningTiming.measure(() -> k.skinAll(palette, positions, normals), positions, normals,
                    vertices, warmup, seconds);
            checksum = t.checksum;
            return t.median();
        }
    }

    static void report(JsonNode time, EvalReport report) {
        report.heading(3, "Against the scalar C++ reference");
        JsonNode ref = time.path("reference");
        if (ref.has("skipped")) {
            report.paragraph("Not run: `" + ref.get("skipped").asText() + "`.");
            return;
        }
        String r = "/reference";
        report.paragraph("The shared scalar C++ reference (`" + ref.get("source").asText() + "`, compiled here with `"
                + ref.get("compiler").asText() + "`) on its own synthetic data (" + EvalReport.num(time, r + "/joints")
                + " joints, " + EvalReport.num(time, r + "/influences") + " influences per vertex, normals by the"
                + " blended matrix as it computes them), and our kernels on the same data, which core's generator"
                + " reproduces bit for bit, in " + EvalReport.num(time, r + "/rounds") + " interleaved rounds: each"
                + " round runs the reference's program once (" + EvalReport.num(time, r + "/roundSeconds")
                + " s per variant) and each of our kernels once (as long, after " + EvalReport.num(time,
                        r + "/oursWarmupSeconds") + " s of warm-up before the first round). ns per vertex: the median"
                + " round and its range; ours / C++ (of the medians) below one means we are faster; the checksums"
                + " (the sum of the outputs) agree when both skinned the same data alike.");
        report.header("vertices", "method", "C++ ns", "C++ range", "scalar Java ns", "scalar range", "scalar / C++",
                "fastest Java", "fastest ns", "fastest range", "fastest / C++", "checksums agree");
        JsonNode rows = ref.get("rows");
        for (int i = 0; i < rows.size(); i++) {
            String p = r + "/rows/" + i;
            JsonNode row = rows.get(i);
            report.row(EvalReport.num(time, p + "/vertices"), row.get("method").asText().toUpperCase(Locale.ROOT),
                    EvalReport.num(time, p + "/cppNs/median"), range(time, p + "/cppNs"),
                    EvalReport.num(time, p + "/scalarNs/median"), range(time, p + "/scalarNs"),
                    EvalReport.num(time, p + "/scalarRatio"), "`" + row.get("fastestKernel").asText() + "`",
                    EvalReport.num(time, p + "/fastestNs/median"), range(time, p + "/fastestNs"),
                    EvalReport.num(time, p + "/fastestRatio"),
                    row.get("scalarChecksumAgrees").asBoolean() && row.get("fastestChecksumAgrees").asBoolean()
                            ? "yes" : "**no**");
        }
        report.line("");
        report.figure("time-cpp-reference.png", "ns per vertex against the scalar C++ reference", chart(rows));
    }

    private static String range(JsonNode node, String spread) {
        return EvalReport.num(node, spread + "/min") + " - " + EvalReport.num(node, spread + "/max");
    }

    private static XYChart chart(JsonNode rows) {
        List<String> labels = new ArrayList<>();
        for (JsonNode row : rows) {
            labels.add(row.get("method").asText().toUpperCase(Locale.ROOT) + ", " + row.get("vertices").asInt()
                    + " vertices");
        }
        XYChart chart = EvalCharts.xy("Against the scalar C++ reference (same data, interleaved rounds)", "method",
                "ns per vertex (" + EvalCharts.SPREAD + ")");
        EvalCharts.categories(chart, labels, rows.get(0).at("/fastestNs/median").asDouble(), 0);
        String[] keys = {"cppNs", "scalarNs", "fastestNs"};
        String[] names = {"C++ scalar reference (g++ -O3)", "Java, core's scalar kernel", "Java, fastest kernel"};
        java.awt.Color[] colours = {java.awt.Color.DARK_GRAY, EvalCharts.METHOD_COLOURS[0], EvalCharts.METHOD_COLOURS[1]};
        for (int k = 0; k < keys.length; k++) {
            List<Double> x = new ArrayList<>();
            List<JsonNode> spreads = new ArrayList<>();
            for (int i = 0; i < rows.size(); i++) {
                x.add(EvalCharts.offset(i, k, keys.length));
                spreads.add(rows.get(i).get(keys[k]));
            }
            EvalCharts.medians(chart, names[k], x, spreads, colours[k], false);
        }
        chart.getStyler().setYAxisMin(0.0);
        return chart;
    }

    private static void deleteQuietly(Path dir) {
        if (dir == null) {
            return;
        }
        try (Stream<Path> files = Files.walk(dir)) {
            files.sorted(Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
        } catch (IOException e) {
            // A temporary folder left behind is harmless.
        }
    }
}
