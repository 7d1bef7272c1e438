package org.skinlab.desktop.eval;

import java.util.List;
import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.skinning.SkinningMethod;

/**
 * The crowds beside the thesis' desktop figure: 1, 4, 8 and 12 meshes at 60/60, 60/48, 18/11 and
 * 7/5 fps (DQS/LBS), skinned on the CPU, one thread per mesh, and drawn. Only our drawn frames
 * (the {@code render} node of {@link EvalCrowdsRender}) compare with them; skinning-only rates
 * never stand beside them. At the thesis' 12 meshes, {@code atTwelve} keeps per skinning and
 * method our fps with their spread, ours / thesis, and whether DQS and LBS differ beyond the spread.
 */
final class EvalCrowdsThesis {
    /** The thesis' desktop measurements: meshes, DQS fps, LBS fps. */
    static final double[][] THESIS = {{1, 60, 60}, {4, 60, 48}, {8, 18, 11}, {12, 7, 5}};
    static final int THESIS_MESHES = 12;
    /** The thesis' pair, in its order. */
    static final List<SkinningMethod> METHODS = List.of(SkinningMethod.DQS, SkinningMethod.LBS);
    static final List<String> SKINNINGS = List.of(EvalCrowdsRender.CPU, EvalCrowdsRender.SHADER);

    private EvalCrowdsThesis() {
    }

    /** The thesis' frame rates per number of meshes, DQS and LBS. */
    static void putThesis(ArrayNode thesis) {
        for (double[] t : THESIS) {
            thesis.addObject().put("meshes", (int) t[0]).put("dqsFps", t[1]).put("lbsFps", t[2]);
        }
    }

    /**
     * {@code atTwelve}: our drawn frames at the thesis' 12 meshes, per skinning ({@code cpu},
     * {@code shader}) and method ({@code dqs}, {@code lbs}): the fps spread, the thesis' fps and
     * ours / thesis (of the median); per skinning {@code fasterBeyondSpread}: "dqs" when DQS's
     * slowest run is faster than LBS's fastest, "lbs" the other way round, "neither" when their
     * runs overlap. The drawn part's skip, when it was skipped.
     */
    static void putAtTwelve(ObjectNode results) {
        ObjectNode at = results.putObject("atTwelve");
        at.put("copies", THESIS_MESHES);
        JsonNode render = results.get("render");
        at.put("file", render.get("file").asText());
        if (render.has("skipped")) {
            at.put("skipped", render.get("skipped").asText());
            return;
        }
        at.put("renderer", render.get("renderer").asText());
        at.put("software", render.get("software").asBoolean());
        ObjectNode drawn = at.putObject("drawn");
        for (String skinning : SKINNINGS) {
            JsonNode dqs = drawnPoint(render, skinning, SkinningMethod.DQS, THESIS_MESHES);
            JsonNode lbs = drawnPoint(render, skinning, SkinningMethod.LBS, THESIS_MESHES);
            if (dqs == null || lbs == null) {
                continue;
            }
            ObjectNode s = drawn.putObject(skinning);
            for (SkinningMethod method : METHODS) {
                JsonNode p = method == SkinningMethod.DQS ? dqs : lbs;
                double thesisFps = thesisFps(method, THESIS_MESHES);
                ObjectNode m = s.putObject(method.key());
                m.put("thesisFps", thesisFps);
                m.set("fps", p.get("fps").deepCopy());
                m.put("ratio", EvalReport.round(p.at("/fps/median").asDouble() / thesisFps));
            }
            s.put("fasterBeyondSpread", dqs.at("/fps/min").asDouble() > lbs.at("/fps/max").asDouble() ? "dqs"
                    : lbs.at("/fps/min").asDouble() > dqs.at("/fps/max").asDouble() ? "lbs" : "neither");
        }
    }

    /** The thesis' fps for {@code method} at {@code meshes}, or NaN where it has none. */
    static double thesisFps(SkinningMethod method, int meshes) {
        for (double[] t : THESIS) {
            if (t[0] == meshes) {
                return method == SkinningMethod.DQS ? t[1] : t[2];
            }
        }
        return Double.NaN;
    }

    /** The drawn point of a skinning and method at {@code copies}, or null when none was measured. */
    static JsonNode drawnPoint(JsonNode render, String skinning, SkinningMethod method, int copies) {
        int i = pointIndex(render, skinning, method, copies);
        return i < 0 ? null : render.get("points").get(i);
    }

    /** The index of that point in {@code render.points}, or -1. */
    static int pointIndex(JsonNode render, String skinning, SkinningMethod method, int copies) {
        JsonNode points = render.path("points");
        for (int i = 0; i < points.size(); i++) {
            JsonNode p = points.get(i);
            if (p.get("skinning").asText().equals(skinning) && p.get("method").asText().equals(method.key())
                    && p.get("instances").asInt() == copies) {
                return i;
            }
        }
        return -1;
    }

    /** Beside the thesis: its drawn figure and ours at the same counts, then at 12 meshes with ours / thesis. */
    static void report(JsonNode results, EvalReport report) {
        report.heading(3, "Beside the thesis");
        JsonNode render = results.get("render");
        StringBuilder t = new StringBuilder("The thesis drew its cowboy ");
        for (int i = 0; i < THESIS.length; i++) {
            t.append(i == 0 ? "" : i == THESIS.length - 1 ? " and " : ", ")
                    .append(EvalReport.num(results, "/thesis/" + i + "/meshes"));
        }
        t.append(" times at ");
        for (int i = 0; i < THESIS.length; i++) {
            t.append(i == 0 ? "" : i == THESIS.length - 1 ? " and " : ", ")
                    .append(EvalReport.num(results, "/thesis/" + i + "/dqsFps")).append("/")
                    .append(EvalReport.num(results, "/thesis/" + i + "/lbsFps"));
        }
        t.append(" fps (DQS/LBS) on its desktop: skinned on the CPU, one thread per mesh, and drawn. Its numbers are"
                + " drawn frames, so only our drawn frames stand beside them (the figure above marks its points);"
                + " the skinning-only rates earlier in this section leave the drawing out and are not comparable.");
        if (render.has("skipped")) {
            report.paragraph(t + " Drawing was skipped here (`" + render.get("skipped").asText() + "`), so this"
                    + " run has nothing to set beside the thesis.");
            return;
        }
        boolean software = render.get("software").asBoolean();
        t.append(" Ours are `").append(render.get("file").asText()).append("` drawn by `")
                .append(render.get("renderer").asText()).append("`");
        t.append(software ? ", **a software rasteriser: our drawing ran on this machine's CPU cores**, the thesis'"
                + " on its desktop's OpenGL (the thesis does not name its hardware), so ours say what this machine"
                + " draws without graphics hardware, not what a graphics processor would." : ".");
        t.append(" Each cell: the median of our runs and, in brackets, the slowest and fastest run (fps).");
        report.paragraph(t.toString());
        report.header("copies", "thesis DQS fps", "thesis LBS fps", "ours DQS, CPU kernels", "ours LBS, CPU kernels",
                "ours DQS, vertex shader", "ours LBS, vertex shader");
        for (int i = 0; i < THESIS.length; i++) {
            int copies = (int) THESIS[i][0];
            report.row(EvalReport.num(results, "/thesis/" + i + "/meshes"),
                    EvalReport.num(results, "/thesis/" + i + "/dqsFps"),
                    EvalReport.num(results, "/thesis/" + i + "/lbsFps"),
                    fpsCell(results, render, EvalCrowdsRender.CPU, SkinningMethod.DQS, copies),
                    fpsCell(results, render, EvalCrowdsRender.CPU, SkinningMethod.LBS, copies),
                    fpsCell(results, render, EvalCrowdsRender.SHADER, SkinningMethod.DQS, copies),
                    fpsCell(results, render, EvalCrowdsRender.SHADER, SkinningMethod.LBS, copies));
        }
        report.line("");
        atTwelve(results, render, report);
    }

    /** Our fps at a count, or a dash where this run drew no such point (e.g. {@code --quick}'s counts). */
    private static String fpsCell(JsonNode results, JsonNode render, String skinning, SkinningMethod method,
            int copies) {
        int i = pointIndex(render, skinning, method, copies);
        return i < 0 ? "-" : EvalCrowdsSection.spread(results, "/render/points/" + i + "/fps");
    }

    /** The thesis' 12 meshes: ours / thesis per skinning and method, and DQS against LBS beyond the spread. */
    private static void atTwelve(JsonNode results, JsonNode render, EvalReport report) {
        JsonNode drawn = results.at("/atTwelve/drawn");
        if (drawn.size() == 0) {
            report.paragraph("No drawn point at " + EvalReport.num(results, "/atTwelve/copies")
                    + " copies in this run.");
            return;
        }
        report.paragraph("At " + EvalReport.num(results, "/atTwelve/copies") + " copies, ours / thesis (of the"
                + " median)" + (render.get("software").asBoolean() ? ", ours drawn by a software rasteriser on this"
                + " machine's CPU, the thesis' by its desktop's OpenGL:" : ":"));
        report.header("skinning", "method", "thesis fps", "our fps, median (min–max)", "ours / thesis");
        StringBuilder verdicts = new StringBuilder();
        for (String skinning : SKINNINGS) {
            if (!drawn.has(skinning)) {
                continue;
            }
            for (SkinningMethod method : METHODS) {
                String p = "/atTwelve/drawn/" + skinning + "/" + method.key();
                report.row(EvalCrowdsRender.skinningLabel(render, skinning, true),
                        method.key().toUpperCase(Locale.ROOT), EvalReport.num(results, p + "/thesisFps"),
                        EvalCrowdsSection.spread(results, p + "/fps"), EvalReport.num(results, p + "/ratio"));
            }
            String s = "/atTwelve/drawn/" + skinning;
            String faster = drawn.get(skinning).get("fasterBeyondSpread").asText();
            verdicts.append(" ").append(capitalised(EvalCrowdsRender.skinningLabel(render, skinning, true)))
                    .append(": ").append(faster.equals("neither") ? "DQS and LBS within each other's spread (DQS "
                    + range(results, s + "/dqs/fps") + ", LBS " + range(results, s + "/lbs/fps") + " fps)."
                    : faster.toUpperCase(Locale.ROOT) + " faster beyond the spread (DQS "
                    + range(results, s + "/dqs/fps") + ", LBS " + range(results, s + "/lbs/fps") + " fps).");
        }
        report.line("");
        report.paragraph("DQS against LBS at " + EvalReport.num(results, "/atTwelve/copies") + " copies, by the"
                + " runs' extremes (faster beyond the spread: its slowest run faster than the other's fastest)."
                + verdicts);
    }

    private static String range(JsonNode results, String pointer) {
        return EvalReport.num(results, pointer + "/min") + "–" + EvalReport.num(results, pointer + "/max");
    }

    private static String capitalised(String s) {
        return Character.toUpperCase(s.charAt(0)) + s.substring(1);
    }
}
