package org.skinlab.desktop.eval;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import boofcv.concurrency.BoofConcurrency;

import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.bench.ArFrameBench;
import org.skinlab.desktop.bench.ArFrameInput;
import org.skinlab.desktop.bench.ArFrameJson;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.model.Model;
import org.skinlab.internal.scene.DefaultAsset;
import org.skinlab.skinning.SkinningMethod;

/**
 * Section "ar-frame": one AR frame end to end, per stage ({@link ArFrameBench}, as {@code skinlab
 * bench ar-frame} measures it): decode, track, pose, skin, draw, against a 60 Hz frame, for the
 * default character on the real video the evaluation is given ({@code --ar-video}) or else the
 * synthetic demo video encoded to H.264; the report says which. Each timing keeps its runs beside
 * its median ({@link ArFrameJson}); the figure shows the stages' medians stacked against the
 * budget and each stage's range over the runs. Skipped, with the reason, without a display.
 */
final class EvalArFrameSection implements EvalSection {
    /** Demo video frames: a quick run renders few (rendering is the slow part), a full run two seconds' worth. */
    private static final int QUICK_DEMO_FRAMES = 8;
    private static final int FULL_DEMO_FRAMES = 60;
    private static final int RUNS = 5;
    /** A quick run plays at most this many frames of a real video per run. */
    private static final int QUICK_REAL_FRAMES = 30;
    /** The real video's markers' size, unknown: it scales the model on them, not the times. */
    private static final double REAL_MARKER_METRES = 0.10;

    private record Plan(List<ArFrameBench.Variant> variants, double warmupSeconds, int demoFrames) {
    }

    private static Plan plan(boolean quick) {
        ArFrameBench.Variant lbsCpu = new ArFrameBench.Variant(SkinningMethod.LBS, false);
        ArFrameBench.Variant lbsGpu = new ArFrameBench.Variant(SkinningMethod.LBS, true);
        return quick ? new Plan(List.of(lbsCpu, lbsGpu), 1.5, QUICK_DEMO_FRAMES)
                : new Plan(List.of(lbsCpu, lbsGpu, new ArFrameBench.Variant(SkinningMethod.DQS, false)), 3,
                        FULL_DEMO_FRAMES);
    }

    @Override
    public String key() {
        return "ar-frame";
    }

    @Override
    public String title() {
        return "An AR frame, end to end";
    }

    @Override
    public double estimatedSeconds(EvalContext context) {
        if (!ViewerProcess.displayAvailable()) {
            return 1;
        }
        return context.quick() ? (context.arVideo() != null ? 20 : 12) : context.arVideo() != null ? 150 : 60;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        Plan plan = plan(context.quick());
        boolean real = context.arVideo() != null;
        results.put("input", real ? "real" : "synthetic");
        results.put("model", DefaultAsset.fileName());
        if (!ViewerProcess.displayAvailable()) {
            skip(context, results, "no display (neither DISPLAY nor WAYLAND_DISPLAY is set): run eval under xvfb-run"
                    + " or on a desktop to draw");
            return;
        }
        Model model = ModelFiles.load(context.root().resolve("assets").resolve(DefaultAsset.PATH)).model;
        boolean concurrent = BoofConcurrency.USE_CONCURRENT;
        Path work = null;
        try {
            ArFrameInput input;
            if (real) {
                TrackerConfig tracking = TrackerConfig.of(MarkerDictionary.byName(context.arDictionary()),
                        REAL_MARKER_METRES);
                input = ArFrameInput.file(context.arVideo(), context.arIntrinsics(), 60, tracking);
                results.put("dictionary", context.arDictionary());
                results.put("intrinsics", context.arIntrinsics() == null ? "a 60 degree field of view"
                        : context.arIntrinsics().getFileName().toString());
            } else {
                work = Files.createTempDirectory("skinlab-eval-ar-frame");
                input = ArFrameInput.synthetic(plan.demoFrames(), work);
                results.put("dictionary", MarkerDictionary.DEFAULT.key());
            }
            context.progress(0.2);
            try (input) {
                measure(context, results, plan, input, model);
            }
        } catch (GlWindow.WindowUnavailableException | LinkageError e) {
            skip(context, results, "no OpenGL window: " + e.getMessage());
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } finally {
            BoofConcurrency.USE_CONCURRENT = concurrent;
            if (work != null) {
                try {
                    Files.deleteIfExists(work);
                } catch (IOException e) {
                    // A temporary folder left behind is harmless.
                }
            }
        }
    }

    private void measure(EvalContext context, ObjectNode results, Plan plan, ArFrameInput input, Model model)
            throws IOException {
        try (ArFrameBench bench = ArFrameBench.open(input.name(), input.frames(), input.camera(), input.tracking(),
                model)) {
            int frames = context.quick() ? Math.min(input.frameCount(), QUICK_REAL_FRAMES) : input.frameCount();
            ArFrameBench.Result result = bench.run(plan.variants(), RUNS, frames, plan.warmupSeconds(),
                    f -> context.progress(0.2 + 0.8 * f));
            ArFrameJson.write(result, results);
        }
        putGpuAgainstCpu(results);
    }

    /**
     * Per method timed both ways, what moving skinning into the vertex shader does (medians, ms):
     * what it leaves of the skin stage, and how the draw and the stages' sum change.
     */
    private static void putGpuAgainstCpu(ObjectNode results) {
        ArrayNode pairs = results.putArray("gpuAgainstCpu");
        for (JsonNode cpu : results.get("variants")) {
            if (!cpu.get("skinning").asText().equals("cpu")) {
                continue;
            }
            for (JsonNode gpu : results.get("variants")) {
                if (gpu.get("skinning").asText().equals("gpu") && gpu.get("method").equals(cpu.get("method"))) {
                    ObjectNode p = pairs.addObject();
                    p.put("method", cpu.get("method").asText());
                    p.put("skinCpuMs", cpu.at("/stages/skin/medianMs").asDouble());
                    p.put("skinGpuMs", gpu.at("/stages/skin/medianMs").asDouble());
                    p.put("drawCpuMs", cpu.at("/stages/draw/medianMs").asDouble());
                    p.put("drawGpuMs", gpu.at("/stages/draw/medianMs").asDouble());
                    p.put("drawChangeMs", ArFrameJson.round(gpu.at("/stages/draw/medianMs").asDouble()
                            - cpu.at("/stages/draw/medianMs").asDouble()));
                    p.put("stageMediansChangeMs", ArFrameJson.round(gpu.get("stageMediansMs").asDouble()
                            - cpu.get("stageMediansMs").asDouble()));
                }
            }
        }
    }

    private static void skip(EvalContext context, ObjectNode results, String why) {
        results.put("skipped", why);
        context.say("ar-frame skipped: " + why);
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        boolean real = results.get("input").asText().equals("real");
        if (results.has("skipped")) {
            report.paragraph("Skipped: `" + results.get("skipped").asText() + "`. It times the "
                    + (real ? "real video given" : "synthetic demo video") + " when a window can be opened.");
            return;
        }
        introduction(results, report, real);
        table(results, report);
        gpuAgainstCpu(results, report);
        report.image("ar-frame-stages.png", "An AR frame per stage against a 60 Hz frame, " + results.get("renderer")
                .asText(), EvalArFrameFigure.draw(results));
    }

    private static void introduction(JsonNode results, EvalReport report, boolean real) {
        String input = real
                ? "**The real video** given to the evaluation: `" + results.get("source").asText() + "`, its markers of `"
                        + results.get("dictionary").asText() + "`, its camera from `" + results.get("intrinsics").asText()
                        + "`."
                : "**The synthetic demo video** (`" + results.get("source").asText() + "`; no real video was given:"
                        + " `skinlab eval --ar-video FILE --ar-intrinsics FILE --ar-dictionary NAME` times one, e.g. the"
                        + " hand-held video of docs/benchmarks.md, \"An AR frame\").";
        boolean software = results.get("softwareRenderer").asBoolean();
        report.paragraph("One AR frame as `skinlab ar` makes it, every stage timed in every frame on one thread"
                + " (`ArFrameBench`, the code of `skinlab bench ar-frame`): **decode** (the next camera frame from the"
                + " source, decoded, with its colour and luminance), **track** (`ArSession.onCameraFrame`: the marker"
                + " search and the pose), **pose** (the clip sampled, the skeleton posed, the joint palette), **skin**"
                + " (the CPU kernels deforming the mesh) and **draw** (the camera picture and the model uploaded and"
                + " drawn on the marker, ended by `glFinish`), for `" + results.get("model").asText() + "`. " + input
                + " A run plays " + EvalReport.num(results, "/framesPerRun") + " frames from the start; "
                + EvalReport.num(results, "/runs") + " runs of each variant, interleaved, after "
                + EvalReport.num(results, "/warmupSeconds") + " s of warm-up; a stage's value in a run is its mean per"
                + " frame, so a run's stages add up to its frame. The window is " + EvalReport.num(results, "/width")
                + " x " + EvalReport.num(results, "/height") + " pixels, one per camera pixel. Renderer: `"
                + results.get("renderer").asText() + "`, OpenGL `" + results.get("glVersion").asText() + "`."
                + (software ? " **This is a software rasteriser on the CPU, not a GPU**: the draw, and GPU skinning"
                        + " with it, run on the same cores as everything else." : ""));
    }

    /** Stages down, variants across: median and the range of the runs. */
    private static void table(JsonNode results, EvalReport report) {
        JsonNode variants = results.get("variants");
        String[] header = new String[variants.size() + 1];
        header[0] = "ms per frame: median (lowest - highest run)";
        for (int v = 0; v < variants.size(); v++) {
            header[v + 1] = label(variants.get(v));
        }
        report.header(header);
        for (ArFrameBench.Stage stage : ArFrameBench.Stage.values()) {
            String[] row = new String[variants.size() + 1];
            row[0] = stage.key();
            for (int v = 0; v < variants.size(); v++) {
                row[v + 1] = timing(results, "/variants/" + v + "/stages/" + stage.key());
            }
            report.row(row);
        }
        String[] frame = new String[variants.size() + 1];
        String[] sum = new String[variants.size() + 1];
        String[] feed = new String[variants.size() + 1];
        String[] shown = new String[variants.size() + 1];
        frame[0] = "frame (each run's stages summed)";
        sum[0] = "**stage medians summed** (share of " + EvalReport.num(results, "/budgetMs") + " ms, "
                + EvalReport.num(results, "/displayHz") + " Hz)";
        feed[0] = "per thread of `skinlab ar`: feed (decode + track), simulation (pose + skin), window (draw)";
        shown[0] = "frames with the model drawn, per run";
        for (int v = 0; v < variants.size(); v++) {
            String at = "/variants/" + v;
            frame[v + 1] = timing(results, at + "/frame");
            sum[v + 1] = "**" + EvalReport.num(results, at + "/stageMediansMs") + "** ("
                    + EvalReport.num(results, at + "/budgetPercent") + "%)";
            feed[v + 1] = EvalReport.num(results, at + "/threads/feedMs") + ", " + EvalReport.num(results,
                    at + "/threads/simulationMs") + ", " + EvalReport.num(results, at + "/threads/windowMs");
            StringBuilder s = new StringBuilder();
            for (int r = 0; r < variants.get(v).get("modelFrames").size(); r++) {
                s.append(r == 0 ? "" : ", ").append(EvalReport.num(results, at + "/modelFrames/" + r));
            }
            shown[v + 1] = s.toString();
        }
        report.row(frame).row(sum).row(feed).row(shown).line("");
    }

    private static String timing(JsonNode results, String at) {
        return EvalReport.num(results, at + "/medianMs") + " (" + EvalReport.num(results, at + "/minMs") + " - "
                + EvalReport.num(results, at + "/maxMs") + ")";
    }

    private static String label(JsonNode variant) {
        return variant.get("method").asText().toUpperCase(Locale.ROOT) + ", "
                + variant.get("skinning").asText().toUpperCase(Locale.ROOT) + " skinning";
    }

    /** What GPU skinning leaves of the skin stage, and where its work went. */
    private static void gpuAgainstCpu(JsonNode results, EvalReport report) {
        JsonNode pairs = results.get("gpuAgainstCpu");
        for (int i = 0; i < pairs.size(); i++) {
            String at = "/gpuAgainstCpu/" + i;
            String method = pairs.get(i).get("method").asText().toUpperCase(Locale.ROOT);
            report.paragraph("**GPU skinning, " + method + "**: the skin stage goes from "
                    + EvalReport.num(results, at + "/skinCpuMs") + " ms to " + EvalReport.num(results, at + "/skinGpuMs")
                    + " ms (the vertex shader skins inside the draw; posing and the palette stay on the CPU, in the pose"
                    + " stage), the draw changes by " + EvalReport.num(results, at + "/drawChangeMs") + " ms ("
                    + EvalReport.num(results, at + "/drawCpuMs") + " to " + EvalReport.num(results, at + "/drawGpuMs")
                    + ") and the stages' sum by " + EvalReport.num(results, at + "/stageMediansChangeMs") + " ms."
                    + (results.get("softwareRenderer").asBoolean() ? " On this software rasteriser the vertex shader"
                            + " runs on the CPU cores too, so this is not what a GPU would make of it." : ""));
        }
    }
}
