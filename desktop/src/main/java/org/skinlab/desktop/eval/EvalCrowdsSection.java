package org.skinlab.desktop.eval;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.internal.bench.Rounds;
import org.skinlab.internal.bench.Spread;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.bench.CrowdBench;
import org.skinlab.desktop.bench.RenderBench;
import org.skinlab.skinning.SkinningMethod;

/**
 * Section "crowds": how many characters a frame holds. On the CPU ({@link CrowdBench}: copies of
 * a character at spread clip times, sampled, posed and skinned every frame, shared among a fixed
 * pool of threads, nothing drawn) the frame time against the threads at a fixed crowd, as
 * characters per 16.7 ms frame, and against the number of characters at all threads; then the
 * drawn frames per second against copies of {@code bench-render} ({@link RenderBench},
 * {@link EvalCrowdsRender}) when a display exists, beside the thesis' drawn figure
 * ({@link EvalCrowdsThesis}). Every timing is taken in {@link Rounds#MIN_RUNS} runs interleaved
 * across the methods (and the threads, and the drawn series), kept in results.json with their
 * spread; the figures are {@link EvalCrowdsCharts}'.
 */
final class EvalCrowdsSection implements EvalSection {
    /** A frame beyond this many budgets ends the characters sweep. */
    static final double STOP_BUDGETS = 3;
    static final int[] QUICK_CHARACTERS = {1, 4, 12, 64, 256};
    static final int[] CHARACTERS = {1, 4, 8, 12, 16, 32, 64, 128, 256, 512, 1024, 2048, 4096};
    /** Runs of every timing (odd, so the median is one of the runs). */
    static final int RUNS = Rounds.MIN_RUNS;
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
        double render = EvalCrowdsRender.display() == null ? 0 : context.quick() ? 9 : 150;
        return (context.quick() ? 14 : 130) + render;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        boolean quick = context.quick();
        int cores = Runtime.getRuntime().availableProcessors();
        int[] counts = quick ? QUICK_CHARACTERS : CHARACTERS;
        int threadCrowd = quick ? 64 : 256;
        double firstWarmup = quick ? 0.3 : 2.0;
        double maxWarmup = quick ? 3 : 10;
        double runWarmup = quick ? 0.005 : 0.05;
        double seconds = quick ? 0.02 : 0.15;
        double threadSeconds = quick ? 0.03 : 0.3;
        results.put("cores", cores);
        results.put("runs", RUNS);
        results.put("frameBudgetMillis", EvalReport.round(CrowdBench.FRAME_MILLIS));
        results.put("frameBudgetMicros", EvalReport.round(CrowdBench.FRAME_MILLIS * 1000));
        results.put("stopMillis", EvalReport.round(STOP_BUDGETS * CrowdBench.FRAME_MILLIS));
        results.put("firstWarmupSeconds", firstWarmup);
        results.put("maxWarmupSeconds", maxWarmup);
        results.put("runWarmupSeconds", runWarmup);
        results.put("runWarmupFrames", CrowdBench.MIN_WARMUP_FRAMES);
        results.put("minFrames", CrowdBench.MIN_FRAMES);
        results.put("seconds", seconds);
        results.put("threadSeconds", threadSeconds);
        results.put("threadCrowd", threadCrowd);
        results.put("compiledBytes", CrowdBench.COMPILED_BYTES);
        results.put("maxCharacters", counts[counts.length - 1]);
        EvalCrowdsThesis.putThesis(results.putArray("thesis"));
        List<Path> files = files(context, results);
        boolean render = EvalCrowdsRender.display() != null;
        double cpuShare = render ? (quick ? 0.55 : 0.5) : 1;
        int total = files.size() * RUNS * CrowdBench.METHODS.size() * (cores + counts.length);
        int[] done = {0};
        Runnable progress = () -> context.progress(cpuShare * ++done[0] / total);
        FrameTimes.Protocol threadRuns = new FrameTimes.Protocol(RUNS, runWarmup, runWarmup, threadSeconds);
        FrameTimes.Protocol crowdRuns = new FrameTimes.Protocol(RUNS, runWarmup, runWarmup, seconds);
        ArrayNode models = results.putArray("models");
        for (Path f : files) {
            ObjectNode m = models.addObject();
            m.put("file", f.getFileName().toString());
            CrowdBench bench = new CrowdBench(ModelFiles.load(f).model,
                    Math.max(threadCrowd, counts[counts.length - 1]));
            m.put("pointsPerCharacter", bench.pointsPerCharacter());
            ObjectNode warmed = m.putObject("warmedSeconds");
            for (SkinningMethod method : CrowdBench.METHODS) {
                warmed.put(method.key(), EvalReport.round(bench.warmUp(method, threadCrowd, cores, firstWarmup,
                        maxWarmup)));
            }
            // Threads: every method at every thread count, all interleaved.
            List<CrowdBench.Crowd> crowds = new ArrayList<>();
            for (SkinningMethod method : CrowdBench.METHODS) {
                for (int t = 1; t <= cores; t++) {
                    crowds.add(new CrowdBench.Crowd(method, threadCrowd, t));
                }
            }
            ArrayNode threads = m.putArray("threads");
            for (CrowdBench.Timing timing : bench.measure(crowds, threadRuns, progress)) {
                ObjectNode p = point(threads.addObject(), timing);
                double copiesTimesBudget = threadCrowd * CrowdBench.FRAME_MILLIS * 1000;
                EvalReport.putSpread(p, "charactersPerFrame", reciprocal(timing.frameMicros(), copiesTimesBudget));
            }
            // Characters: the methods interleaved at each crowd size; from the thesis' 12 meshes on, the
            // sweep ends after the first size at which a method's median frame is over the stop.
            List<CrowdBench.Timing> sweep = new ArrayList<>();
            for (int n : counts) {
                List<CrowdBench.Crowd> atN = new ArrayList<>();
                for (SkinningMethod method : CrowdBench.METHODS) {
                    atN.add(new CrowdBench.Crowd(method, n, cores));
                }
                List<CrowdBench.Timing> timings = bench.measure(atN, crowdRuns, progress);
                sweep.addAll(timings);
                if (n >= EvalCrowdsThesis.THESIS_MESHES && timings.stream().anyMatch(t -> t.frameMicros().median()
                        > STOP_BUDGETS * CrowdBench.FRAME_MILLIS * 1000)) {
                    break;
                }
            }
            ArrayNode crowd = m.putArray("crowd");
            for (SkinningMethod method : CrowdBench.METHODS) {
                for (CrowdBench.Timing timing : sweep) {
                    if (timing.crowd().method() == method) {
                        ObjectNode p = point(crowd.addObject(), timing);
                        EvalReport.putSpread(p, "fps", reciprocal(timing.frameMicros(), 1e6));
                    }
                }
            }
        }
        EvalCrowdsRender.measure(context, results.putObject("render"), files.get(files.size() - 1), cpuShare);
        EvalCrowdsThesis.putAtTwelve(results);
    }

    /** Each run's {@code numerator / value} (frames per second from frame times, and the like), in run order. */
    static Spread reciprocal(Spread spread, double numerator) {
        double[] runs = spread.runs();
        for (int i = 0; i < runs.length; i++) {
            runs[i] = numerator / runs[i];
        }
        return Spread.of(runs);
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

    /** One timing's numbers: its runs' median frames in µs, and what the runs' frames allocated and ran where. */
    private static ObjectNode point(ObjectNode p, CrowdBench.Timing t) {
        p.put("method", t.crowd().method().key());
        p.put("threads", t.crowd().threads());
        p.put("characters", t.crowd().characters());
        p.put("frames", t.frames());
        EvalReport.putSpread(p, "frameMicros", t.frameMicros());
        p.put("bytesPerFrame", EvalReport.round(t.bytesPerFrame()));
        p.put("callerShare", EvalReport.round(t.callerShare()));
        return p;
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        introduce(results, report);
        if (results.has("cowboySkipped")) {
            report.paragraph("The cowboy is skipped: `" + results.get("cowboySkipped").asText() + "`.");
        }
        threadsTable(results, report);
        report.figure("crowds-threads.png", "Characters per frame against threads, skinning only",
                EvalCrowdsCharts.threads(results));
        crowdTable(results, report);
        report.figure("crowds-characters.png", "Frame time against characters, skinning only",
                EvalCrowdsCharts.characters(results));
        EvalCrowdsRender.report(results.get("render"), "/render", results, report);
        EvalCrowdsThesis.report(results, report);
    }

    /** How a crowd is run and timed, and this machine's cores. */
    private static void introduce(JsonNode results, EvalReport report) {
        report.paragraph("A crowd on the CPU: copies of a character, each playing its first clip from its own point"
                + " (phases spread over the clip), every frame each copy sampled, posed and skinned, positions and"
                + " exact normals (`bench frame`'s frame, the fastest kernels), the copies handed out to a fixed pool"
                + " of threads (the caller's included) one at a time; the copies share the mesh and the kernels and"
                + " own their poses and outputs; nothing is drawn, so these are skinning-only rates, not comparable"
                + " with frames that are drawn (the drawn ones follow). Crowds run LBS, DQS and CoR; the outlook"
                + " methods (bulge-free DQS, stretchable and twistable bones, splines) are timed per frame in the time"
                + " section."
                + " This machine has " + EvalReport.num(results, "/cores") + " cores.");
        report.paragraph("**Every timing is " + EvalReport.num(results, "/runs") + " runs**, interleaved: each"
                + " round runs every method (in the threads sweep every method at every thread count) once, each"
                + " round starting one further along, so that the machine's drift falls on all of them alike. A run"
                + " is " + EvalReport.num(results, "/runWarmupSeconds") + " s of frames (at least "
                + EvalReport.num(results, "/runWarmupFrames") + "; the caches after another method's run), then"
                + " frames for a window (at least " + EvalReport.num(results, "/minFrames") + "); its value is the"
                + " window's median frame."
                + " The tables give the runs' median and, in brackets, their fastest and slowest; the figures draw"
                + " the median with a bar from the fastest to the slowest run. First the threads: a crowd of "
                + EvalReport.num(results, "/threadCrowd") + " copies, windows of "
                + EvalReport.num(results, "/threadSeconds") + " s, as characters per "
                + EvalReport.num(results, "/frameBudgetMillis") + " ms frame (copies times the budget over each run's"
                + " median frame); then the crowd's size at all threads, windows of "
                + EvalReport.num(results, "/seconds") + " s, up to " + EvalReport.num(results, "/maxCharacters")
                + " copies or, from " + EvalReport.num(results, "/atTwelve/copies") + " copies on, until a method's"
                + " median frame takes more than " + EvalReport.num(results, "/stopMillis") + " ms. Before a"
                + " character's first run, each method runs its crowd at least "
                + EvalReport.num(results, "/firstWarmupSeconds") + " s and on until its threads allocate under "
                + EvalReport.num(results, "/compiledBytes") + " bytes a frame (the JIT has compiled the kernels; the"
                + " Vector API allocates until it has), at most " + EvalReport.num(results, "/maxWarmupSeconds")
                + " s: " + warmups(results) + ". Bytes per frame: what the crowd's threads allocated per timed"
                + " frame over every run; caller's share: the part of the copies the calling thread ran itself"
                + " (1 / threads when every thread gets a core; near 1 when the machine gives the pool's threads"
                + " none).");
    }

    /** A row per character, method and number of threads. */
    private static void threadsTable(JsonNode results, EvalReport report) {
        report.header("character", "points per copy", "method", "threads", "copies", "frames",
                "frame µs, median (fastest–slowest run)", "characters per frame", "caller's share",
                "bytes per frame");
        JsonNode models = results.get("models");
        for (int i = 0; i < models.size(); i++) {
            JsonNode m = models.get(i);
            for (int j = 0; j < m.get("threads").size(); j++) {
                String p = "/models/" + i + "/threads/" + j;
                report.row("`" + m.get("file").asText() + "`", EvalReport.num(results, "/models/" + i
                        + "/pointsPerCharacter"), upper(m.at("/threads/" + j + "/method")),
                        EvalReport.num(results, p + "/threads"), EvalReport.num(results, p + "/characters"),
                        EvalReport.num(results, p + "/frames"), spread(results, p + "/frameMicros"),
                        spread(results, p + "/charactersPerFrame"), EvalReport.num(results, p + "/callerShare"),
                        EvalReport.num(results, p + "/bytesPerFrame"));
            }
        }
        report.line("");
    }

    /** A row per character, method and crowd size at all threads. */
    private static void crowdTable(JsonNode results, EvalReport report) {
        JsonNode models = results.get("models");
        report.header("character", "method", "copies", "threads", "frames", "frame µs, median (fastest–slowest run)",
                "frames per second, skinning only", "caller's share", "bytes per frame");
        for (int i = 0; i < models.size(); i++) {
            JsonNode m = models.get(i);
            for (int j = 0; j < m.get("crowd").size(); j++) {
                String p = "/models/" + i + "/crowd/" + j;
                report.row("`" + m.get("file").asText() + "`", upper(m.at("/crowd/" + j + "/method")),
                        EvalReport.num(results, p + "/characters"), EvalReport.num(results, p + "/threads"),
                        EvalReport.num(results, p + "/frames"), spread(results, p + "/frameMicros"),
                        spread(results, p + "/fps"), EvalReport.num(results, p + "/callerShare"),
                        EvalReport.num(results, p + "/bytesPerFrame"));
            }
        }
        report.line("");
    }

    /** A spread node's median and, in brackets, its fastest and slowest run: "12.3 (11.9–13.1)". */
    static String spread(JsonNode results, String pointer) {
        return EvalReport.num(results, pointer + "/median") + " (" + EvalReport.num(results, pointer + "/min") + "–"
                + EvalReport.num(results, pointer + "/max") + ")";
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

    static String upper(JsonNode method) {
        return method.asText().toUpperCase(Locale.ROOT);
    }
}
