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
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.XYSeries;
import org.knowm.xchart.style.Styler;
import org.knowm.xchart.style.markers.SeriesMarkers;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.bench.CrowdBench;
import org.skinlab.desktop.bench.RenderBench;
import org.skinlab.skinning.SkinningMethod;

/**
 * Section "crowds": how many characters a frame holds. On the CPU ({@link CrowdBench}: copies of
 * a character at spread clip times, sampled, posed and skinned every frame, shared among a fixed
 * pool of threads) the frame time against the threads at a fixed crowd, as characters per 16.7 ms
 * frame, and against the number of characters at all threads, as frames per second; then the
 * rendered frames per second against instances of {@code bench-render} ({@link RenderBench},
 * {@link EvalCrowdsRender}) when a display exists. Beside the thesis' figure: 1, 4, 8 and 12
 * meshes at 60/60, 60/48, 18/11 and 7/5 fps (DQS/LBS) on its desktop.
 */
final class EvalCrowdsSection implements EvalSection {
    /** A frame beyond this many budgets ends the characters sweep. */
    static final double STOP_BUDGETS = 3;
    static final int[] QUICK_CHARACTERS = {1, 4, 12, 64, 256};
    static final int[] CHARACTERS = {1, 4, 8, 12, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096};
    /** The thesis' desktop measurements: meshes, DQS fps, LBS fps. */
    static final double[][] THESIS = {{1, 60, 60}, {4, 60, 48}, {8, 18, 11}, {12, 7, 5}};
    static final int THESIS_MESHES = 12;
    static final String WALKER = "characters/humanoid-walk.dae";

    @Override
    public String key() {
        return "crowds";
    }

    @Override
    public String title() {
        return "Crowds";
    }

    @Override
    public double estimatedSeconds(EvalContext context) {
        // Measured on the project's 2-core machine while other work ran (warm-ups then take longer).
        double render = EvalCrowdsRender.display() == null ? 0 : context.quick() ? 12 : 100;
        return (context.quick() ? 18 : 130) + render;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        boolean quick = context.quick();
        int cores = Runtime.getRuntime().availableProcessors();
        int[] counts = quick ? QUICK_CHARACTERS : CHARACTERS;
        int threadCrowd = quick ? 64 : 256;
        double firstWarmup = quick ? 0.4 : 2.0;
        double maxWarmup = quick ? 3 : 10;
        double warmup = quick ? 0.05 : 0.3;
        double seconds = quick ? 0.1 : 1.0;
        double threadSeconds = quick ? 0.2 : 1.5;
        results.put("cores", cores);
        results.put("frameBudgetMillis", EvalReport.round(CrowdBench.FRAME_MILLIS));
        results.put("stopMillis", EvalReport.round(STOP_BUDGETS * CrowdBench.FRAME_MILLIS));
        results.put("firstWarmupSeconds", firstWarmup);
        results.put("maxWarmupSeconds", maxWarmup);
        results.put("warmupSeconds", warmup);
        results.put("seconds", seconds);
        results.put("threadSeconds", threadSeconds);
        results.put("threadCrowd", threadCrowd);
        results.put("compiledBytes", CrowdBench.COMPILED_BYTES);
        results.put("maxCharacters", counts[counts.length - 1]);
        putThesis(results.putArray("thesis"));
        List<Path> files = files(context, results);
        boolean render = EvalCrowdsRender.display() != null;
        double cpuShare = render ? (quick ? 0.55 : 0.6) : 1;
        int block = cores + counts.length;
        int total = files.size() * CrowdBench.METHODS.size() * block;
        int done = 0;
        ArrayNode models = results.putArray("models");
        for (Path f : files) {
            ObjectNode m = models.addObject();
            m.put("file", f.getFileName().toString());
            CrowdBench bench = new CrowdBench(ModelFiles.load(f).model, Math.max(threadCrowd, counts[counts.length - 1]));
            m.put("pointsPerCharacter", bench.pointsPerCharacter());
            ObjectNode warmed = m.putObject("warmedSeconds");
            ArrayNode threads = m.putArray("threads");
            ArrayNode crowd = m.putArray("crowd");
            for (SkinningMethod method : CrowdBench.METHODS) {
                int blockStart = done;
                warmed.put(method.key(), EvalReport.round(bench.warmUp(method, threadCrowd, cores,
                        firstWarmup, maxWarmup)));
                for (int t = 1; t <= cores; t++) {
                    CrowdBench.Timing timing = bench.measure(method, threadCrowd, t, warmup, threadSeconds);
                    point(threads.addObject(), timing).put("charactersPerFrame",
                            EvalReport.round(threadCrowd * CrowdBench.FRAME_MILLIS / timing.medianMillis()));
                    context.progress(cpuShare * ++done / total);
                }
                for (int n : counts) {
                    CrowdBench.Timing timing = bench.measure(method, n, cores, warmup, seconds);
                    point(crowd.addObject(), timing).put("fps", EvalReport.round(1000 / timing.medianMillis()));
                    context.progress(cpuShare * ++done / total);
                    if (timing.medianMillis() > STOP_BUDGETS * CrowdBench.FRAME_MILLIS) {
                        break;
                    }
                }
                done = blockStart + block;
            }
        }
        EvalCrowdsRender.measure(context, results.putObject("render"), files.get(files.size() - 1), cpuShare);
        beside(results);
    }

    /** The thesis' frame rates per number of meshes, DQS and LBS. */
    private static void putThesis(ArrayNode thesis) {
        for (double[] t : THESIS) {
            thesis.addObject().put("meshes", (int) t[0]).put("dqsFps", t[1]).put("lbsFps", t[2]);
        }
    }

    /** The walker, and the thesis' cowboy when the shared corpus has it (else why not, in results and said). */
    private static List<Path> files(EvalContext context, ObjectNode results) {
        List<Path> files = new ArrayList<>();
        files.add(context.root().resolve("assets").resolve(WALKER));
        String cowboyName = EvalTimeSection.THESIS.get(0).file();
        Path cowboy = context.corpus() == null ? null : context.corpus().resolve(cowboyName);
        if (cowboy != null && Files.isRegularFile(cowboy)) {
            files.add(cowboy);
        } else {
            results.put("cowboySkipped", "no " + cowboyName + " in the shared corpus at " + context.corpusPlace());
            context.say("crowds: " + results.get("cowboySkipped").asText());
        }
        return files;
    }

    /** One timing's numbers: microseconds, as a frame of one character is some of them. */
    private static ObjectNode point(ObjectNode p, CrowdBench.Timing t) {
        p.put("method", t.method().key());
        p.put("threads", t.threads());
        p.put("characters", t.characters());
        p.put("frames", t.frames());
        p.put("medianMicros", EvalReport.round(t.medianMillis() * 1000));
        p.put("minMicros", EvalReport.round(t.minMillis() * 1000));
        p.put("bytesPerFrame", EvalReport.round(t.bytesPerFrame()));
        p.put("callerShare", EvalReport.round(t.callerShare()));
        return p;
    }

    /** Ours at the thesis' 12 meshes beside its fps: skinning alone per model, then rendered. */
    private static void beside(ObjectNode results) {
        ArrayNode rows = results.putArray("atTwelve");
        for (SkinningMethod method : new SkinningMethod[] {SkinningMethod.DQS, SkinningMethod.LBS}) {
            double thesisFps = THESIS[THESIS.length - 1][method == SkinningMethod.DQS ? 1 : 2];
            for (JsonNode m : results.get("models")) {
                for (JsonNode p : m.get("crowd")) {
                    if (p.get("characters").asInt() == THESIS_MESHES && p.get("method").asText().equals(method.key())) {
                        row(rows, "cpu", m.get("file").asText(), method, thesisFps, p.get("fps").asDouble());
                    }
                }
            }
            JsonNode render = results.get("render");
            for (String skinning : new String[] {"cpu", "gpu"}) {
                for (JsonNode p : render.path("points")) {
                    if (p.get("instances").asInt() == THESIS_MESHES && p.get("method").asText().equals(method.key())
                            && p.get("skinning").asText().equals(skinning)) {
                        row(rows, "render-" + skinning, render.get("file").asText(), method, thesisFps,
                                p.get("fps").asDouble());
                    }
                }
            }
        }
    }

    private static void row(ArrayNode rows, String what, String file, SkinningMethod method, double thesisFps,
            double fps) {
        rows.addObject().put("what", what).put("file", file).put("method", method.key()).put("thesisFps", thesisFps)
                .put("fps", fps).put("ratio", EvalReport.round(fps / thesisFps));
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        introduce(results, report);
        if (results.has("cowboySkipped")) {
            report.paragraph("The cowboy is skipped: `" + results.get("cowboySkipped").asText() + "`.");
        }
        threadsTable(results, report);
        threadsFigure(results, report);
        crowdTable(results, report);
        charactersFigure(results, report);
        EvalCrowdsRender.report(results.get("render"), "/render", results, report);
        besideTable(results, report);
    }

    /** How a crowd is run and timed, and this machine's cores. */
    private static void introduce(JsonNode results, EvalReport report) {
        report.paragraph("A crowd on the CPU: copies of a character, each playing its first clip from its own point"
                + " (phases spread over the clip), every frame each copy sampled, posed and skinned, positions and"
                + " exact normals (`bench frame`'s frame, the fastest kernels), the copies handed out to a fixed pool"
                + " of threads (the caller's included) one at a time; the copies share the mesh and the kernels and"
                + " own their poses and outputs; nothing is drawn. Crowds run LBS, DQS and CoR; the outlook methods"
                + " (bulge-free DQS, stretchable and twistable bones, splines) are timed per frame in the time section."
                + " This machine has "
                + EvalReport.num(results, "/cores") + " cores. First the threads: a crowd of "
                + EvalReport.num(results, "/threadCrowd") + " copies, the median frame over "
                + EvalReport.num(results, "/threadSeconds") + " s, as characters per "
                + EvalReport.num(results, "/frameBudgetMillis") + " ms frame (copies times the budget over the"
                + " median frame); then the crowd's size at all threads, the median over "
                + EvalReport.num(results, "/seconds") + " s per point after " + EvalReport.num(results, "/warmupSeconds")
                + " s of warm-up. Before a method's first point, the crowd runs at least "
                + EvalReport.num(results, "/firstWarmupSeconds") + " s and on until its threads allocate under "
                + EvalReport.num(results, "/compiledBytes") + " bytes a frame (the JIT has compiled the kernels; the"
                + " Vector API allocates until it has), at most " + EvalReport.num(results, "/maxWarmupSeconds")
                + " s: " + warmups(results) + ";"
                + " up to " + EvalReport.num(results, "/maxCharacters") + " copies or until a frame takes more than "
                + EvalReport.num(results, "/stopMillis") + " ms. Bytes per frame: what the crowd's threads allocated"
                + " per timed frame; caller's share: the part of the copies the calling thread ran itself (1 / threads"
                + " when every thread gets a core; near 1 when the machine gives the pool's threads none).");
    }

    /** A row per character, method and number of threads. */
    private static void threadsTable(JsonNode results, EvalReport report) {
        report.header("character", "points per copy", "method", "threads", "copies", "frames", "median µs",
                "min µs", "characters per frame", "caller's share", "bytes per frame");
        JsonNode models = results.get("models");
        for (int i = 0; i < models.size(); i++) {
            JsonNode m = models.get(i);
            for (int j = 0; j < m.get("threads").size(); j++) {
                String p = "/models/" + i + "/threads/" + j;
                report.row("`" + m.get("file").asText() + "`", EvalReport.num(results, "/models/" + i
                        + "/pointsPerCharacter"), upper(m.at("/threads/" + j + "/method")),
                        EvalReport.num(results, p + "/threads"), EvalReport.num(results, p + "/characters"),
                        EvalReport.num(results, p + "/frames"), EvalReport.num(results, p + "/medianMicros"),
                        EvalReport.num(results, p + "/minMicros"), EvalReport.num(results, p + "/charactersPerFrame"),
                        EvalReport.num(results, p + "/callerShare"), EvalReport.num(results, p + "/bytesPerFrame"));
            }
        }
        report.line("");
    }

    /** A row per character, method and crowd size at all threads. */
    private static void crowdTable(JsonNode results, EvalReport report) {
        JsonNode models = results.get("models");
        report.header("character", "method", "copies", "threads", "frames", "median µs", "fps", "caller's share",
                "bytes per frame");
        for (int i = 0; i < models.size(); i++) {
            JsonNode m = models.get(i);
            for (int j = 0; j < m.get("crowd").size(); j++) {
                String p = "/models/" + i + "/crowd/" + j;
                report.row("`" + m.get("file").asText() + "`", upper(m.at("/crowd/" + j + "/method")),
                        EvalReport.num(results, p + "/characters"), EvalReport.num(results, p + "/threads"),
                        EvalReport.num(results, p + "/frames"), EvalReport.num(results, p + "/medianMicros"),
                        EvalReport.num(results, p + "/fps"), EvalReport.num(results, p + "/callerShare"),
                        EvalReport.num(results, p + "/bytesPerFrame"));
            }
        }
        report.line("");
    }

    /** The warm-ups' lengths, per character and method. */
    private static String warmups(JsonNode results) {
        List<String> parts = new ArrayList<>();
        JsonNode models = results.get("models");
        for (int i = 0; i < models.size(); i++) {
            List<String> each = new ArrayList<>();
            for (SkinningMethod method : CrowdBench.METHODS) {
                each.add(method.key().toUpperCase(Locale.ROOT) + " "
                        + EvalReport.num(results, "/models/" + i + "/warmedSeconds/" + method.key()) + " s");
            }
            parts.add("`" + models.get(i).get("file").asText() + "` " + String.join(", ", each));
        }
        return String.join("; ", parts);
    }

    private static void besideTable(JsonNode results, EvalReport report) {
        report.heading(3, "Beside the thesis");
        report.paragraph("The thesis drew " + EvalReport.num(results, "/thesis/3/meshes") + " cowboys at "
                + EvalReport.num(results, "/thesis/3/dqsFps") + " fps with DQS and "
                + EvalReport.num(results, "/thesis/3/lbsFps") + " with LBS on its desktop (skinned on the CPU,"
                + " one thread per mesh, drawn). Ours at as many copies: skinning alone on the CPU (nothing drawn,"
                + " all threads), and drawn by `bench-render` with CPU and with GPU skinning when a display was"
                + " there. Ours / thesis is how many times the frames per second; other hardware, and the thesis'"
                + " numbers include its drawing.");
        report.header("ours", "character", "method", "thesis fps", "our fps", "ours / thesis");
        JsonNode rows = results.get("atTwelve");
        for (int i = 0; i < rows.size(); i++) {
            JsonNode r = rows.get(i);
            String p = "/atTwelve/" + i;
            String what = r.get("what").asText();
            report.row(what.equals("cpu") ? "skinning only, CPU" : what.equals("render-cpu") ? "drawn, CPU skinning"
                    : "drawn, GPU skinning", "`" + r.get("file").asText() + "`", upper(r.get("method")),
                    EvalReport.num(results, p + "/thesisFps"), EvalReport.num(results, p + "/fps"),
                    EvalReport.num(results, p + "/ratio"));
        }
        report.line("");
    }

    private static void threadsFigure(JsonNode results, EvalReport report) {
        XYChart chart = new XYChartBuilder().width(900).height(500)
                .title("Characters per " + EvalReport.num(results, "/frameBudgetMillis") + " ms frame against threads ("
                        + EvalReport.num(results, "/threadCrowd") + " copies, CPU skinning, nothing drawn)")
                .xAxisTitle("threads").yAxisTitle("characters per frame").build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        chart.getStyler().setXAxisDecimalPattern("0");
        for (JsonNode m : results.get("models")) {
            for (SkinningMethod method : CrowdBench.METHODS) {
                series(chart, label(m, method), m.get("threads"), method, "threads", "charactersPerFrame");
            }
        }
        report.figure("crowds-threads.png", "Characters per frame against threads", chart);
    }

    private static void charactersFigure(JsonNode results, EvalReport report) {
        XYChart chart = new XYChartBuilder().width(900).height(550)
                .title("fps against characters (CPU skinning, " + EvalReport.num(results, "/cores")
                        + " threads, nothing drawn; thesis: drawn)")
                .xAxisTitle("characters").yAxisTitle("frames per second").build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNE);
        chart.getStyler().setXAxisLogarithmic(true);
        chart.getStyler().setYAxisLogarithmic(true);
        for (JsonNode m : results.get("models")) {
            for (SkinningMethod method : CrowdBench.METHODS) {
                series(chart, label(m, method), m.get("crowd"), method, "characters", "fps");
            }
        }
        thesisSeries(chart, results);
        report.figure("crowds-characters.png", "Frames per second against characters, CPU skinning", chart);
    }

    /** The thesis' points as two marked series without lines. */
    static void thesisSeries(XYChart chart, JsonNode results) {
        for (String method : new String[] {"dqs", "lbs"}) {
            List<Double> x = new ArrayList<>();
            List<Double> y = new ArrayList<>();
            for (JsonNode t : results.get("thesis")) {
                x.add(t.get("meshes").asDouble());
                y.add(t.get(method + "Fps").asDouble());
            }
            XYSeries s = chart.addSeries("thesis " + method.toUpperCase(Locale.ROOT) + " (drawn)", x, y);
            s.setXYSeriesRenderStyle(XYSeries.XYSeriesRenderStyle.Scatter);
            s.setMarker(method.equals("dqs") ? SeriesMarkers.DIAMOND : SeriesMarkers.SQUARE);
        }
    }

    /** The points of one method: x and y from the named fields. */
    static void series(XYChart chart, String name, JsonNode points, SkinningMethod method, String x, String y) {
        List<Double> xs = new ArrayList<>();
        List<Double> ys = new ArrayList<>();
        for (JsonNode p : points) {
            if (p.get("method").asText().equals(method.key())) {
                xs.add(p.get(x).asDouble());
                ys.add(p.get(y).asDouble());
            }
        }
        if (!xs.isEmpty()) {
            chart.addSeries(name, xs, ys);
        }
    }

    private static String label(JsonNode model, SkinningMethod method) {
        return method.key().toUpperCase(Locale.ROOT) + " " + model.get("file").asText().replaceAll("\\.dae$", "");
    }

    static String upper(JsonNode method) {
        return method.asText().toUpperCase(Locale.ROOT);
    }
}
