package org.skinlab.desktop.bench;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.desktop.bench.ArFrameBench.Stage;
import org.skinlab.desktop.bench.ArFrameBench.Timing;
import org.skinlab.desktop.bench.ArFrameBench.VariantResult;

/**
 * {@link ArFrameBench}'s results as JSON, the one layout of {@code skinlab bench ar-frame --json}
 * and of {@code skinlab eval}'s "ar-frame" section: every time in milliseconds rounded to 3
 * decimals (a microsecond), each timing with its runs beside its median:
 * <pre>
 * {"source", "width", "height", "framesPerRun", "runs", "warmupSeconds", "renderer", "glVersion",
 *  "softwareRenderer", "displayHz": 60, "budgetMs": 16.667,
 *  "variants": [{"key": "lbs-cpu", "method": "lbs", "skinning": "cpu",
 *    "stages": {"decode": {"runs": [...], "medianMs", "minMs", "maxMs"}, "track", "pose", "skin", "draw"},
 *    "frame": {the same: each run's stages summed},
 *    "stageMediansMs": the stages' medians summed, "budgetPercent": that against budgetMs,
 *    "threads": {"feedMs": decode + track, "simulationMs": pose + skin, "windowMs": draw},
 *    "modelFrames": [per run, the frames with the model drawn]}]}
 * </pre>
 * A run's stages add up to its frame time within the rounding (5 x 0.0005 ms), and the medians to
 * {@code stageMediansMs} likewise.
 */
public final class ArFrameJson {
    private ArFrameJson() {
    }

    /** A time rounded to a microsecond, as stored. */
    public static double round(double ms) {
        return Math.round(ms * 1000.0) / 1000.0;
    }

    /** Writes {@code result} into {@code node}. */
    public static void write(ArFrameBench.Result result, ObjectNode node) {
        node.put("source", result.source());
        node.put("width", result.width());
        node.put("height", result.height());
        node.put("framesPerRun", result.framesPerRun());
        node.put("runs", result.runs());
        node.put("warmupSeconds", result.warmupSeconds());
        node.put("renderer", result.renderer());
        node.put("glVersion", result.glVersion());
        node.put("softwareRenderer", result.softwareRenderer());
        node.put("displayHz", 60);
        node.put("budgetMs", round(ArFrameBench.FRAME_BUDGET_MS));
        ArrayNode variants = node.putArray("variants");
        for (VariantResult v : result.variants()) {
            ObjectNode out = variants.addObject();
            out.put("key", v.variant().key());
            out.put("method", v.variant().method().key());
            out.put("skinning", v.variant().gpuSkinning() ? "gpu" : "cpu");
            ObjectNode stages = out.putObject("stages");
            for (Stage s : Stage.values()) {
                timing(v.stage(s), stages.putObject(s.key()));
            }
            timing(v.frame(), out.putObject("frame"));
            out.put("stageMediansMs", round(v.stageMediansMs()));
            out.put("budgetPercent", round(100 * v.stageMediansMs() / ArFrameBench.FRAME_BUDGET_MS));
            ObjectNode threads = out.putObject("threads");
            threads.put("feedMs", round(v.stage(Stage.DECODE).median() + v.stage(Stage.TRACK).median()));
            threads.put("simulationMs", round(v.stage(Stage.POSE).median() + v.stage(Stage.SKIN).median()));
            threads.put("windowMs", round(v.stage(Stage.DRAW).median()));
            ArrayNode shown = out.putArray("modelFrames");
            for (int f : v.modelFrames()) {
                shown.add(f);
            }
        }
    }

    private static void timing(Timing t, ObjectNode node) {
        ArrayNode runs = node.putArray("runs");
        for (double r : t.runs()) {
            runs.add(round(r));
        }
        node.put("medianMs", round(t.median()));
        node.put("minMs", round(t.min()));
        node.put("maxMs", round(t.max()));
    }
}
