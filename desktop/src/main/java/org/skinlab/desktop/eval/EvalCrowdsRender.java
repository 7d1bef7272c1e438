package org.skinlab.desktop.eval;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.Styler;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.bench.CrowdBench;
import org.skinlab.desktop.bench.RenderBench;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinningMethod;

/**
 * The drawn part of {@link EvalCrowdsSection}: {@code bench-render}'s frames per second against
 * copies ({@link RenderBench}, in this process), CPU and GPU skinning, each method, with the
 * renderer's name; skipped, with the reason, without a display. A software rasteriser (Mesa's
 * llvmpipe under Xvfb) runs the "GPU" series on the CPU too, and the report and figure say so.
 */
final class EvalCrowdsRender {
    static final List<Integer> QUICK_STEPS = List.of(1, 12);
    static final int MAX_INSTANCES = 64;
    static final int WIDTH = 640;
    static final int HEIGHT = 480;

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
        double seconds = quick ? 0.2 : 1.0;
        double warmup = quick ? 0.5 : 2.0;
        double minFps = quick ? 0 : 10;
        List<Integer> steps = quick ? QUICK_STEPS : RenderBench.steps(MAX_INSTANCES);
        results.put("file", file.getFileName().toString());
        if (display() == null) {
            skip(context, results, "no display (neither DISPLAY nor WAYLAND_DISPLAY is set): run eval under"
                    + " xvfb-run or on a desktop to draw");
            return;
        }
        results.put("display", display());
        results.put("width", WIDTH);
        results.put("height", HEIGHT);
        results.put("seconds", seconds);
        results.put("warmupSeconds", warmup);
        results.put("minFps", minFps);
        results.put("maxInstances", steps.get(steps.size() - 1));
        ArrayNode stepsNode = results.putArray("steps");
        steps.forEach(stepsNode::add);
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
            ArrayNode points = results.putArray("points");
            int series = 2 * CrowdBench.METHODS.size();
            int done = 0;
            for (boolean gpu : new boolean[] {false, true}) {
                for (SkinningMethod method : CrowdBench.METHODS) {
                    for (int i = 0; i < steps.size(); i++) {
                        RenderBench.Point p = bench.measure(model, gpu, method, steps.get(i), seconds);
                        points.addObject().put("skinning", p.skinning()).put("method", p.method())
                                .put("instances", p.instances()).put("fps", EvalReport.round(p.fps()))
                                .put("msPerFrame", EvalReport.round(p.msPerFrame()))
                                .put("bytesPerFrame", EvalReport.round(p.bytesPerFrame()));
                        context.progress(start + (1 - start) * (done + (i + 1.0) / steps.size()) / series);
                        if (p.fps() < minFps) {
                            break;
                        }
                    }
                    done++;
                }
            }
        }
    }

    private static void skip(EvalContext context, ObjectNode results, String why) {
        results.put("skipped", why);
        context.say("crowds: drawing skipped: " + why);
    }

    /** Which copies were drawn: the steps, and where a series stops. */
    private static String stepsText(JsonNode render, String at, JsonNode results) {
        List<String> steps = new ArrayList<>();
        for (int i = 0; i < render.get("steps").size(); i++) {
            steps.add(EvalReport.num(results, at + "/steps/" + i));
        }
        String text = "copies " + String.join(", ", steps);
        return render.get("minFps").asDouble() > 0 ? text + "; a series stops below " + EvalReport.num(results,
                at + "/minFps") + " fps" : text;
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
                + "`, each its own simulation stepped every frame (CPU skinning skins every copy, as the thesis'"
                + " meshes were skinned; GPU skinning uploads each copy's palette), drawn " + EvalReport.num(results,
                at + "/width") + "x" + EvalReport.num(results, at + "/height") + " off-screen without vsync, "
                + EvalReport.num(results, at + "/seconds") + " s per point after a warm-up of "
                + EvalReport.num(results, at + "/warmupSeconds") + " s per method; " + stepsText(render, at, results)
                + ". Renderer: `" + render.get("renderer").asText() + "`, OpenGL `"
                + render.get("version").asText() + "`." + (software ? " **This is a software rasteriser**: the"
                + " GPU series run the vertex shader on the same CPU cores, so they compare costs on this machine,"
                + " not a GPU's." : ""));
        report.header("skinning", "method", "copies", "fps", "ms per frame", "bytes per frame");
        JsonNode points = render.get("points");
        for (int i = 0; i < points.size(); i++) {
            String p = at + "/points/" + i;
            JsonNode pt = points.get(i);
            report.row(pt.get("skinning").asText().toUpperCase(Locale.ROOT), EvalCrowdsSection.upper(pt.get("method")),
                    EvalReport.num(results, p + "/instances"), EvalReport.num(results, p + "/fps"),
                    EvalReport.num(results, p + "/msPerFrame"), EvalReport.num(results, p + "/bytesPerFrame"));
        }
        report.line("");
        XYChart chart = new XYChartBuilder().width(1100).height(550)
                .title("Drawn fps against copies, " + render.get("file").asText() + ", " + render.get("renderer").asText()
                        + (software ? " (a software rasteriser: \"GPU\" runs on the CPU)" : ""))
                .xAxisTitle("copies").yAxisTitle("frames per second").build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNE);
        chart.getStyler().setYAxisLogarithmic(true);
        for (String skinning : new String[] {"cpu", "gpu"}) {
            for (SkinningMethod method : CrowdBench.METHODS) {
                ArrayNode of = JsonNodeFactory.instance.arrayNode();
                for (JsonNode pt : points) {
                    if (pt.get("skinning").asText().equals(skinning)) {
                        of.add(pt);
                    }
                }
                EvalCrowdsSection.series(chart, skinning.toUpperCase(Locale.ROOT) + " skinning "
                        + method.key().toUpperCase(Locale.ROOT), of, method, "instances", "fps");
            }
        }
        EvalCrowdsSection.thesisSeries(chart, results);
        report.figure("crowds-render.png", "Drawn frames per second against copies, " + render.get("renderer").asText()
                + (software ? " (a software rasteriser)" : ""), chart);
    }
}
