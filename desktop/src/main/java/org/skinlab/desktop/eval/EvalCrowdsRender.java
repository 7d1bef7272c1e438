package org.skinlab.desktop.eval;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.bench.CrowdBench;
import org.skinlab.desktop.bench.RenderBench;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinningMethod;

/**
 * The drawn part of {@link EvalCrowdsSection}: {@code bench-render}'s frames per second against
 * copies ({@link RenderBench}, in this process), each copy skinned by our CPU kernels or in the
 * vertex shader, each method, with the renderer's name; skipped, with the reason, without a
 * display. Each count's series run in interleaved rounds. A software rasteriser (Mesa's
 * llvmpipe under Xvfb) runs the vertex shader on the CPU too: then no text, title or label calls
 * it a GPU ({@link #skinningLabel}).
 */
final class EvalCrowdsRender {
    static final List<Integer> QUICK_STEPS = List.of(1, 12);
    /**
     * {@code --quick}'s methods: the thesis' pair. A drawn run takes at least 7 frames, which a busy
     * machine stretches (12 copies took 250 ms a frame under a load of 24 on 2 cores), so CoR's
     * series, a third of the drawing, are the full run's only.
     */
    static final List<SkinningMethod> QUICK_METHODS = List.of(SkinningMethod.LBS, SkinningMethod.DQS);
    static final int MAX_INSTANCES = 64;
    static final int WIDTH = 640;
    static final int HEIGHT = 480;
    /** The skinnings' keys in results.json: our CPU kernels, the vertex shader (wherever it runs). */
    static final String CPU = "cpu";
    static final String SHADER = "shader";

    private EvalCrowdsRender() {
    }

    /** The display a window would open on (DISPLAY or WAYLAND_DISPLAY), or null without one. */
    static String display() {
        for (String name : new String[] {"DISPLAY", "WAYLAND_DISPLAY"}) {
            String v = System.getenv(name);
            if (v != null && !v.isBlank()) {
                return name + "=" + v;
            }
        }
        return null;
    }

    /** Measures into {@code results}; the progress runs from {@code start} to 1 of the section. */
    static void measure(EvalContext context, ObjectNode results, Path file, double start) {
        boolean quick = context.quick();
        double seconds = quick ? 0.05 : 0.3;
        double runWarmup = quick ? 0.02 : 0.1;
        double warmup = quick ? 0.5 : 2.0;
        double minFps = quick ? 0 : 10;
        List<Integer> steps = quick ? QUICK_STEPS : RenderBench.steps(MAX_INSTANCES);
        List<SkinningMethod> methods = quick ? QUICK_METHODS : CrowdBench.METHODS;
        results.put("file", file.getFileName().toString());
        if (display() == null) {
            skip(context, results, "no display (neither DISPLAY nor WAYLAND_DISPLAY is set): run eval under"
                    + " xvfb-run or on a desktop to draw");
            return;
        }
        results.put("display", display());
        results.put("width", WIDTH);
        results.put("height", HEIGHT);
        results.put("runs", EvalCrowdsSection.RUNS);
        results.put("seconds", seconds);
        results.put("runWarmupSeconds", runWarmup);
        results.put("runWarmupFrames", RenderBench.MIN_WARMUP_FRAMES);
        results.put("minFrames", RenderBench.MIN_FRAMES);
        results.put("warmupSeconds", warmup);
        results.put("minFps", minFps);
        results.put("maxInstances", steps.get(steps.size() - 1));
        ArrayNode stepsNode = results.putArray("steps");
        steps.forEach(stepsNode::add);
        ArrayNode methodsNode = results.putArray("methods");
        methods.forEach(m -> methodsNode.add(m.key()));
        Model model = ModelFiles.load(file).model;
        RenderBench bench;
        try {
            bench = RenderBench.open(WIDTH, HEIGHT);
        } catch (GlWindow.WindowUnavailableException | LinkageError e) {
            skip(context, results, "no OpenGL window: " + e.getMessage());
            return;
        }
        try (bench) {
            results.put("renderer", bench.renderer());
            results.put("version", bench.version());
            results.put("software", RenderBench.isSoftware(bench.renderer()));
            bench.warmUp(model, warmup);
            List<RenderBench.Series> series = new ArrayList<>();
            for (boolean shader : new boolean[] {false, true}) {
                for (SkinningMethod method : methods) {
                    series.add(new RenderBench.Series(shader, method));
                }
            }
            FrameTimes.Protocol protocol = new FrameTimes.Protocol(EvalCrowdsSection.RUNS, runWarmup, runWarmup,
                    seconds);
            int total = steps.size() * series.size() * protocol.rounds();
            int[] done = {0};
            // Each count's series interleaved; from the thesis' 12 meshes on (they are compared whatever the
            // rate), the sweep ends after the first count at which a series' median is below the lowest rate.
            List<RenderBench.Timing> timings = new ArrayList<>();
            for (int n : steps) {
                List<RenderBench.Timing> atN = bench.measure(model, series, n, protocol,
                        () -> context.progress(start + (1 - start) * ++done[0] / total));
                timings.addAll(atN);
                if (n >= EvalCrowdsThesis.THESIS_MESHES && atN.stream().anyMatch(t -> 1000 / t.msPerFrame().median()
                        < minFps)) {
                    break;
                }
            }
            ArrayNode points = results.putArray("points");
            for (RenderBench.Series s : series) {
                for (RenderBench.Timing t : timings) {
                    if (t.series().equals(s)) {
                        ObjectNode p = points.addObject().put("skinning", s.shader() ? SHADER : CPU)
                                .put("method", s.method().key()).put("instances", t.instances())
                                .put("frames", t.frames());
                        EvalReport.putSpread(p, "msPerFrame", t.msPerFrame());
                        EvalReport.putSpread(p, "fps", EvalCrowdsSection.reciprocal(t.msPerFrame(), 1000));
                        p.put("bytesPerFrame", EvalReport.round(t.bytesPerFrame()));
                    }
                }
            }
        }
    }

    private static void skip(EvalContext context, ObjectNode results, String why) {
        results.put("skipped", why);
        context.say("crowds: drawing skipped: " + why);
    }

    /** The renderer's name up to its details in brackets ("llvmpipe" of "llvmpipe (LLVM 15.0.6, 256 bits)"). */
    static String rendererName(JsonNode render) {
        String r = render.get("renderer").asText();
        int bracket = r.indexOf(" (");
        return bracket > 0 ? r.substring(0, bracket) : r;
    }

    /**
     * What skinned the copies, said as it is: our CPU kernels, or the vertex shader, on the CPU
     * where the renderer is a software rasteriser and on the GPU otherwise; in the report's text
     * ({@code markdown}: the renderer's name as code, whose digits are no measured numbers) or a
     * figure's legend.
     */
    static String skinningLabel(JsonNode render, String skinning, boolean markdown) {
        if (skinning.equals(CPU)) {
            return "skinned by our CPU kernels";
        }
        String name = markdown ? "`" + rendererName(render) + "`" : rendererName(render);
        return render.get("software").asBoolean() ? "skinned in the vertex shader (" + name + ", on the CPU)"
                : "skinned in the vertex shader (on the GPU)";
    }

    /** The drawn methods, e.g. "LBS, DQS and COR". */
    private static String methodsText(JsonNode render) {
        List<String> names = new ArrayList<>();
        render.get("methods").forEach(m -> names.add(EvalCrowdsSection.upper(m)));
        return names.size() == 1 ? names.get(0) : String.join(", ", names.subList(0, names.size() - 1)) + " and "
                + names.get(names.size() - 1);
    }

    /** Which copies were drawn: the steps, and where the sweep stops. */
    private static String stepsText(JsonNode render, String at, JsonNode results) {
        List<String> steps = new ArrayList<>();
        for (int i = 0; i < render.get("steps").size(); i++) {
            steps.add(EvalReport.num(results, at + "/steps/" + i));
        }
        String text = "copies " + String.join(", ", steps);
        return render.get("minFps").asDouble() > 0 ? text + "; from " + EvalReport.num(results, "/atTwelve/copies")
                + " copies on, the sweep stops after the first count at which a series' median is below "
                + EvalReport.num(results, at + "/minFps") + " fps" : text;
    }

    /** Its part of the report; {@code at} is the pointer of {@code render} below {@code results}. */
    static void report(JsonNode render, String at, JsonNode results, EvalReport report) {
        report.heading(3, "Drawn: frames per second against copies");
        if (render.has("skipped")) {
            report.paragraph("Drawing (`bench-render`) is skipped: `" + render.get("skipped").asText() + "`.");
            return;
        }
        boolean software = render.get("software").asBoolean();
        report.paragraph("`bench-render`'s loop in this process: a grid of copies of `" + render.get("file").asText()
                + "`, each its own simulation stepped every frame and either " + skinningLabel(render, CPU, true)
                + " on the render thread, as the thesis' meshes were skinned, or " + skinningLabel(render, SHADER, true)
                + " from its uploaded palette; drawn "
                + EvalReport.num(results, at + "/width") + "x" + EvalReport.num(results, at + "/height")
                + " off-screen without vsync. After a warm-up of " + EvalReport.num(results, at + "/warmupSeconds")
                + " s per method, each count's series (each skinning with " + methodsText(render) + ") are timed in "
                + EvalReport.num(results, at + "/runs") + " interleaved runs of "
                + EvalReport.num(results, at + "/runWarmupSeconds") + " s of frames (at least "
                + EvalReport.num(results, at + "/runWarmupFrames") + ") and a window of "
                + EvalReport.num(results, at + "/seconds") + " s (at least "
                + EvalReport.num(results, at + "/minFrames") + " frames); a run's value is the window's mean frame,"
                + " timed between two `glFinish`; " + stepsText(render, at, results)
                + ". Renderer: `" + render.get("renderer").asText() + "`, OpenGL `" + render.get("version").asText()
                + "`." + (software ? " **This is a software rasteriser**: the drawing and the vertex shader run on"
                + " this machine's CPU cores, beside our kernels, so both series measure this machine's CPU, not a"
                + " graphics processor." : ""));
        report.header("skinning", "method", "copies", "frames", "fps, median (min–max)",
                "ms per frame, median (fastest–slowest run)", "bytes per frame");
        JsonNode points = render.get("points");
        for (int i = 0; i < points.size(); i++) {
            String p = at + "/points/" + i;
            JsonNode pt = points.get(i);
            report.row(skinningLabel(render, pt.get("skinning").asText(), true),
                    EvalCrowdsSection.upper(pt.get("method")),
                    EvalReport.num(results, p + "/instances"), EvalReport.num(results, p + "/frames"),
                    EvalCrowdsSection.spread(results, p + "/fps"), EvalCrowdsSection.spread(results, p + "/msPerFrame"),
                    EvalReport.num(results, p + "/bytesPerFrame"));
        }
        report.line("");
        report.figure("crowds-render.png", "Drawn frames per second against copies, ours and the thesis', "
                + render.get("renderer").asText() + (software ? " (a software rasteriser)" : ""),
                EvalCrowdsCharts.render(render, results));
    }
}
