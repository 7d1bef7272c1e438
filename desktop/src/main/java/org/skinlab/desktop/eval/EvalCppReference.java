package org.skinlab.desktop.eval;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.knowm.xchart.AnnotationLine;
import org.knowm.xchart.XYChart;
import org.skinlab.internal.bench.Rounds;
import org.skinlab.internal.bench.Spread;
import org.skinlab.desktop.bench.CppSkinningReference;
import org.skinlab.desktop.bench.SkinningTiming;
import org.skinlab.desktop.bench.SyntheticSkinData;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * The time section's last part: DQS against LBS per kernel, with and without normals, on the
 * shared C++ reference's synthetic data (4 influences, 64 joints): the shared scalar C++
 * reference ({@code ../shared/perf/skin_ref.cpp}, normals by the blended matrix), our own
 * positions-only C++ beside it ({@code bench/cpp/skin_positions.cpp}), and our scalar and fastest
 * Java kernels with no normals, the reference's blended normals and exact normals. All are timed
 * in interleaved rounds (each round runs both C++ programs once, one round of their own, and every
 * Java kernel once, starting one further along); DQS over LBS is taken per round, where the two
 * ran side by side. The checksums show our kernels skinned the reference's data as it does.
 */
final class EvalCppReference {
    /** The shared scalar C++ skinning reference, from the repository root. */
    static final String SOURCE = "../shared/perf/skin_ref.cpp";
    /** A kernel and the normals it computes: one row of the comparison. */
    record Kernel(String kernel, String normals) {
    }

    static final List<Kernel> KERNELS = List.of(new Kernel("C++ reference", "blended"),
            new Kernel("C++ ours", "none"), new Kernel("scalar", "none"), new Kernel("scalar", "blended"),
            new Kernel("scalar", "exact"), new Kernel("fastest", "none"), new Kernel("fastest", "blended"),
            new Kernel("fastest", "exact"));
    private static final List<SkinningMethod> METHODS = List.of(SkinningMethod.LBS, SkinningMethod.DQS);

    private EvalCppReference() {
    }

    static void measure(EvalContext context, ObjectNode results) {
        Path source = context.root().resolve(SOURCE).normalize();
        Path ours = context.root().resolve(CppSkinningReference.POSITIONS_SOURCE);
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
        double seconds = quick ? 0.08 : 0.4;
        double warmup = quick ? 0.3 : 1.5;
        results.put("source", SOURCE);
        results.put("positionsSource", CppSkinningReference.POSITIONS_SOURCE);
        results.put("compiler", compiler + " -O3 -DNDEBUG -std=c++17");
        results.put("joints", SyntheticSkinData.JOINTS);
        results.put("influences", SyntheticSkinData.INFLUENCES);
        results.put("rounds", Rounds.MIN_RUNS);
        results.put("roundSeconds", seconds);
        results.put("oursWarmupSeconds", warmup);
        Path dir = null;
        try {
            dir = Files.createTempDirectory("skinlab-eval-cpp");
            CppSkinningReference reference = CppSkinningReference.compile(compiler, source, dir);
            CppSkinningReference positions = CppSkinningReference.compile(compiler, ours, dir);
            new Comparison(reference, positions, sizes, seconds, warmup).measure(context, results.putArray("rows"));
        } catch (IOException e) {
            results.remove("rows");
            results.put("skipped", e.getMessage());
        } finally {
            deleteQuietly(dir);
        }
    }

    /** The interleaved rounds of one comparison: per size, kernel and method, each round's ns per vertex. */
    private static final class Comparison {
        private final CppSkinningReference reference;
        private final CppSkinningReference positions;
        private final List<Integer> sizes;
        private final double seconds;
        private final double warmup;
        /** [size][kernel][method][round] ns per vertex; the checksums of the last round. */
        private final double[][][][] ns;
        private final double[][][] checksums;
        private final String[][] implementations;

        Comparison(CppSkinningReference reference, CppSkinningReference positions, List<Integer> sizes, double seconds,
                double warmup) {
            this.reference = reference;
            this.positions = positions;
            this.sizes = sizes;
            this.seconds = seconds;
            this.warmup = warmup;
            int runs = Rounds.MIN_RUNS;
            ns = new double[sizes.size()][KERNELS.size()][METHODS.size()][runs];
            checksums = new double[sizes.size()][KERNELS.size()][METHODS.size()];
            implementations = new String[sizes.size()][KERNELS.size()];
        }

        void measure(EvalContext context, ArrayNode rows) throws IOException {
            List<Java> java = new ArrayList<>();
            for (int s = 0; s < sizes.size(); s++) {
                SyntheticSkinData data = new SyntheticSkinData(sizes.get(s));
                for (int k = 2; k < KERNELS.size(); k++) {
                    java.add(new Java(s, k, data));
                }
            }
            int runs = Rounds.MIN_RUNS;
            // Who runs in a round: the two C++ programs, then each Java kernel; each round starts one further along.
            int things = 2 + java.size();
            for (int r = 0; r < runs; r++) {
                for (int t = 0; t < things; t++) {
                    int who = (r + t) % things;
                    if (who == 0) {
                        cpp(reference, CppSkinningReference.REFERENCE_VARIANTS, 0, r);
                    } else if (who == 1) {
                        cpp(positions, List.of("c-lbs-pos", "c-dqs-pos"), 1, r);
                    } else {
                        java.get(who - 2).time(r == 0 ? warmup : 0.05, r);
                    }
                }
                context.progress(0.85 + 0.15 * (r + 1) / runs);
            }
            for (int s = 0; s < sizes.size(); s++) {
                for (int k = 0; k < KERNELS.size(); k++) {
                    rows.add(row(s, k));
                }
            }
        }

        private void cpp(CppSkinningReference program, List<String> variants, int kernel, int round)
                throws IOException {
            for (CppSkinningReference.Result c : program.run(variants, 1, seconds, sizes)) {
                int s = sizes.indexOf(c.vertices());
                int m = METHODS.indexOf(c.method());
                ns[s][kernel][m][round] = c.medianNs();
                checksums[s][kernel][m] = c.checksum();
                implementations[s][kernel] = kernel == 0 ? "skin_ref" : "skin_positions";
            }
        }

        private ObjectNode row(int s, int k) {
            ObjectNode row = JsonNodeFactory.instance.objectNode();
            row.put("vertices", sizes.get(s));
            row.put("kernel", KERNELS.get(k).kernel());
            row.put("normals", KERNELS.get(k).normals());
            row.put("implementation", implementations[s][k]);
            EvalReport.putSpread(row, "lbsNs", Spread.of(ns[s][k][0]));
            EvalReport.putSpread(row, "dqsNs", Spread.of(ns[s][k][1]));
            double[] ratio = new double[ns[s][k][0].length];
            for (int r = 0; r < ratio.length; r++) {
                ratio[r] = ns[s][k][1][r] / ns[s][k][0][r];
            }
            EvalReport.putSpread(row, "dqsOverLbs", Spread.of(ratio));
            // Java against the C++ program that computes the same: the reference (blended), ours (none).
            int counterpart = KERNELS.get(k).normals().equals("blended") ? 0 : KERNELS.get(k).normals().equals("none")
                    ? 1 : -1;
            if (k >= 2 && counterpart >= 0) {
                boolean agree = true;
                for (int m = 0; m < METHODS.size(); m++) {
                    double c = checksums[s][counterpart][m];
                    // Both sum the same outputs; float rounding differs only in the last digits.
                    agree &= Math.abs(checksums[s][k][m] - c) <= 1e-4 * Math.abs(c);
                }
                row.put("checksumAgrees", agree);
            }
            return row;
        }

        /** One Java kernel (both methods) on one size's data. */
        private final class Java {
            final int size;
            final int kernel;
            final JointPalette palette;
            final int vertices;
            final Skinner[] skinners = new Skinner[METHODS.size()];
            final float[] outPositions;
            final float[] outNormals;

            Java(int size, int kernel, SyntheticSkinData data) {
                this.size = size;
                this.kernel = kernel;
                vertices = data.pointCount();
                palette = data.palette();
                NormalTransform rule = switch (KERNELS.get(kernel).normals()) {
                    case "none" -> NormalTransform.NONE;
                    case "blended" -> NormalTransform.BLENDED_MATRIX;
                    default -> NormalTransform.INVERSE_TRANSPOSE;
                };
                boolean scalar = KERNELS.get(kernel).kernel().equals("scalar");
                for (int m = 0; m < METHODS.size(); m++) {
                    skinners[m] = scalar ? Skinners.scalar(METHODS.get(m), data.geometry(), rule)
                            : Skinners.create(METHODS.get(m), data.geometry(), rule);
                }
                implementations[size][kernel] = skinners[0].implementation();
                outPositions = new float[3 * vertices];
                outNormals = rule == NormalTransform.NONE ? null : new float[3 * vertices];
            }

            /** Both methods, one after the other, one run each (the reference's protocol, {@link SkinningTiming}). */
            void time(double warmupSeconds, int round) {
                for (int m = 0; m < METHODS.size(); m++) {
                    Skinner k = skinners[m];
                    SkinningTiming t = SkinningTiming.measure(() -> k.skinAll(palette, outPositions, outNormals),
                            outPositions, outNormals, vertices, warmupSeconds, seconds);
                    ns[size][kernel][m][round] = t.median();
                    checksums[size][kernel][m] = t.checksum;
                }
            }
        }
    }

    static void report(JsonNode time, EvalReport report) {
        report.heading(3, "DQS against LBS, per kernel, with and without normals");
        JsonNode ref = time.path("reference");
        if (ref.has("skipped")) {
            report.paragraph("Not run: `" + ref.get("skipped").asText() + "`.");
            return;
        }
        String r = "/reference";
        report.paragraph("On the shared scalar C++ reference's synthetic data (" + EvalReport.num(time, r + "/joints")
                + " joints, " + EvalReport.num(time, r + "/influences") + " influences per vertex): the reference itself"
                + " (`" + ref.get("source").asText() + "`, normals by the blended matrix, as it computes them), our"
                + " positions-only C++ beside it (`" + ref.get("positionsSource").asText() + "`, both compiled here"
                + " with `" + ref.get("compiler").asText() + "`), and our Java kernels, scalar and fastest, with no"
                + " normals, the reference's blended ones and exact ones (the inverse-transpose, renormalised, what"
                + " the apps use). " + EvalReport.num(time, r + "/rounds") + " interleaved rounds: each runs both C++"
                + " programs once (" + EvalReport.num(time, r + "/roundSeconds") + " s per variant) and every Java"
                + " kernel once (as long, after " + EvalReport.num(time, r + "/oursWarmupSeconds") + " s of warm-up"
                + " before the first). ns per vertex, the median round and the range; DQS / LBS is taken per round,"
                + " the two timed side by side, below 1 when DQS is the faster. The checksums (the sum of the outputs)"
                + " agree where a Java kernel computes what a C++ program does.");
        report.header("vertices", "kernel", "kernel name", "normals", "LBS ns", "LBS range", "DQS ns", "DQS range",
                "DQS / LBS", "range", "checksum");
        JsonNode rows = ref.get("rows");
        for (int i = 0; i < rows.size(); i++) {
            String p = r + "/rows/" + i;
            JsonNode row = rows.get(i);
            report.row(EvalReport.num(time, p + "/vertices"), row.get("kernel").asText(),
                    "`" + row.get("implementation").asText() + "`", row.get("normals").asText(),
                    EvalReport.num(time, p + "/lbsNs/median"), range(time, p + "/lbsNs"),
                    EvalReport.num(time, p + "/dqsNs/median"), range(time, p + "/dqsNs"),
                    EvalReport.num(time, p + "/dqsOverLbs/median"), range(time, p + "/dqsOverLbs"),
                    !row.has("checksumAgrees") ? "-" : row.get("checksumAgrees").asBoolean() ? "agrees" : "**differs**");
        }
        report.line("");
        report.figure("time-cpp-reference.png", "DQS over LBS per kernel and normals, against the scalar C++ reference",
                chart(rows));
    }

    private static String range(JsonNode node, String spread) {
        return EvalReport.num(node, spread + "/min") + " - " + EvalReport.num(node, spread + "/max");
    }

    /** DQS / LBS per kernel and normals (the first size), a series per normals, with the line at 1. */
    private static XYChart chart(JsonNode rows) {
        int vertices = rows.get(0).get("vertices").asInt();
        List<String> labels = new ArrayList<>();
        for (Kernel k : KERNELS) {
            if (!labels.contains(k.kernel())) {
                labels.add(k.kernel());
            }
        }
        XYChart chart = EvalCharts.xy("DQS time over LBS time per kernel, " + vertices + " vertices (below 1: DQS"
                + " faster)", "kernel", "DQS / LBS per round (" + EvalCharts.SPREAD + ")");
        EvalCharts.categories(chart, labels, 0);
        String[] normals = {"none", "blended", "exact"};
        for (int n = 0; n < normals.length; n++) {
            List<Double> x = new ArrayList<>();
            List<JsonNode> spreads = new ArrayList<>();
            for (JsonNode row : rows) {
                if (row.get("vertices").asInt() == vertices && row.get("normals").asText().equals(normals[n])) {
                    x.add(EvalCharts.offset(labels.indexOf(row.get("kernel").asText()), n, normals.length));
                    spreads.add(row.get("dqsOverLbs"));
                }
            }
            EvalCharts.medians(chart, "normals: " + normals[n], x, spreads, EvalCharts.METHOD_COLOURS[n], false);
        }
        // The line at 1 as an annotation, not a series: a series between the categories would cost the axis its labels.
        AnnotationLine one = new AnnotationLine(1, false, false);
        chart.addAnnotation(one);
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
