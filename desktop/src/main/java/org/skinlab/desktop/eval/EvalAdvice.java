package org.skinlab.desktop.eval;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.ar.FiducialTracker;

/**
 * The recommendations of {@code skinlab eval}'s advice section, one per use, each argued from the
 * numbers the section copied from the others into its results (so every number printed is one of
 * results.json), each saying which inputs it lacks when a section was not run.
 */
final class EvalAdvice {
    /**
     * Largest LBS-DQS distance, in percent of a character's size, that a crowd shot hides: a
     * character 100 px tall on screen moves by at most a pixel.
     */
    static final double CROWD_INVISIBLE_PERCENT = 1.0;

    private EvalAdvice() {
    }

    /** Copies the crowds' and the tracker's numbers the advice uses (when those sections ran). */
    static void crowdsAndTracking(EvalContext context, ObjectNode in) {
        JsonNode crowds = context.measured("crowds");
        if (crowds != null) {
            for (JsonNode m : crowds.path("models")) {
                if (!m.get("file").asText().equals(EvalAdviceSection.CHARACTER)) {
                    continue;
                }
                ObjectNode c = in.putObject("crowds");
                c.put("cores", crowds.get("cores").asInt());
                c.put("crowd", crowds.get("threadCrowd").asInt());
                for (JsonNode p : m.get("threads")) {
                    if (p.get("threads").asInt() == crowds.get("cores").asInt()) {
                        c.put(p.get("method").asText() + "PerFrame", Math.round(p.get("charactersPerFrame").asDouble()));
                    }
                }
            }
            JsonNode render = crowds.path("render");
            if (render.has("renderer")) {
                for (JsonNode row : crowds.path("atTwelve")) {
                    if (row.get("what").asText().equals("render-gpu") && row.get("method").asText().equals("dqs")) {
                        ObjectNode d = in.putObject("drawn");
                        d.put("file", row.get("file").asText());
                        d.put("renderer", render.get("renderer").asText());
                        d.put("software", render.path("software").asBoolean(false));
                        d.put("copies", EvalCrowdsSection.THESIS_MESHES);
                        d.put("gpuDqsFps", row.get("fps").asDouble());
                        d.put("thesisDqsFps", row.get("thesisFps").asDouble());
                    }
                }
            }
        }
        JsonNode tracking = context.measured("tracking");
        if (tracking != null && tracking.has("time")) {
            ObjectNode k = in.putObject("tracking");
            k.put("detectMedianMs", tracking.at("/time/detectMs/median").asDouble());
            k.put("width", tracking.at("/camera/width").asInt());
            k.put("height", tracking.at("/camera/height").asInt());
            k.put("fullFrameEvery", FiducialTracker.FULL_FRAME_EVERY);
            k.put("framePercent", EvalReport.round(100 * k.get("detectMedianMs").asDouble() * 1000
                    / EvalAdviceSection.FRAME_MICROS));
        }
    }

    static void write(JsonNode results, EvalReport report) {
        JsonNode in = results.get("inputs");
        crowds(in, results, report);
        closeUps(in, results, report);
        twist(in, results, report);
        lowEnd(in, results, report);
    }

    private static void crowds(JsonNode in, JsonNode r, EvalReport report) {
        StringBuilder t = new StringBuilder("**Crowds.** ");
        if (!in.has("character")) {
            report.paragraph(t + missing("time"));
            return;
        }
        String c = "/inputs/character";
        t.append("One frame of the walking character (").append(EvalReport.num(r, c + "/vertices"))
                .append(" render vertices, ").append(EvalReport.num(r, c + "/joints")).append(" joints: sample, pose,"
                        + " skin) takes on one core of this machine, with the scalar kernels a phone runs, ")
                .append(EvalReport.num(r, c + "/scalar/lbsMicros")).append(" µs with LBS, ")
                .append(EvalReport.num(r, c + "/scalar/dqsMicros")).append(" with DQS and ")
                .append(EvalReport.num(r, c + "/scalar/corMicros")).append(" with CoR: ")
                .append(EvalReport.num(r, c + "/scalar/lbsPerFrame")).append(", ")
                .append(EvalReport.num(r, c + "/scalar/dqsPerFrame")).append(" and ")
                .append(EvalReport.num(r, c + "/scalar/corPerFrame")).append(" characters per ").append(EvalReport.num(r, "/frameRateHz")).append(" Hz frame of ")
                .append(EvalReport.num(r, "/inputs/frameMicros")).append(" µs (with the SIMD kernels of a desktop JVM: ")
                .append(EvalReport.num(r, c + "/fastest/lbsPerFrame")).append(", ")
                .append(EvalReport.num(r, c + "/fastest/dqsPerFrame")).append(" and ")
                .append(EvalReport.num(r, c + "/fastest/corPerFrame")).append("). In the scalar code DQS costs ")
                .append(EvalReport.num(r, c + "/scalar/dqsOverLbs")).append(" times LBS. ");
        if (in.has("characterQuality")) {
            double d = in.at("/characterQuality/maxLbsDqsPercent").asDouble();
            t.append("On this character LBS and DQS differ by at most ")
                    .append(EvalReport.num(r, "/inputs/characterQuality/maxLbsDqsPercent"))
                    .append(" % of its size over its clip; ");
            if (d < CROWD_INVISIBLE_PERCENT) {
                t.append("below a pixel on a character a hundred pixels tall, as crowd members are. For crowds, LBS:"
                        + " the cheapest method, whose artefacts do not show at that size.");
            } else {
                t.append("visible even on a character a hundred pixels tall. For crowds, DQS: LBS's artefacts show at"
                        + " crowd size on this character.");
            }
        } else {
            t.append(missing("quality"));
        }
        if (in.has("crowds")) {
            t.append(" With all ").append(EvalReport.num(r, "/inputs/crowds/cores")).append(" cores of this machine on a"
                    + " crowd of ").append(EvalReport.num(r, "/inputs/crowds/crowd")).append(" walkers (the crowds section, the fastest kernels), ")
                    .append(EvalReport.num(r, "/inputs/crowds/lbsPerFrame")).append(" (LBS), ")
                    .append(EvalReport.num(r, "/inputs/crowds/dqsPerFrame")).append(" (DQS) and ")
                    .append(EvalReport.num(r, "/inputs/crowds/corPerFrame"))
                    .append(" (CoR) characters are skinned per frame.");
        }
        report.paragraph(t.toString());
    }

    private static void closeUps(JsonNode in, JsonNode r, EvalReport report) {
        StringBuilder t = new StringBuilder("**Close-ups.** ");
        if (!in.has("bend")) {
            report.paragraph(t + missing("quality"));
            return;
        }
        String b = "/inputs/bend";
        t.append("Bent to ").append(EvalReport.num(r, b + "/angleDegrees")).append(" degrees, the bend cylinder keeps ")
                .append(EvalReport.num(r, b + "/lbsVolume")).append(" of its volume with LBS (the elbow collapses), ")
                .append(EvalReport.num(r, b + "/dqsVolume")).append(" with DQS and ")
                .append(EvalReport.num(r, b + "/corVolume")).append(" with CoR, while the joint bulges by ")
                .append(EvalReport.num(r, b + "/dqsBulge")).append(" % of the model's size with DQS, ")
                .append(EvalReport.num(r, b + "/corBulge")).append(" with CoR and ")
                .append(EvalReport.num(r, b + "/lbsBulge")).append(" with LBS. ");
        double cor = in.at("/bend/corBulge").asDouble();
        double dqs = in.at("/bend/dqsBulge").asDouble();
        boolean corKeeps = in.at("/bend/corVolume").asDouble() > in.at("/bend/lbsVolume").asDouble();
        if (cor < dqs && corKeeps) {
            t.append("Close to the camera, where a joint fills the screen, CoR: it keeps more volume than LBS and"
                    + " bulges less than DQS");
            if (in.has("character")) {
                t.append(", for ").append(EvalReport.num(r, "/inputs/character/fastest/corOverDqs"))
                        .append(" times DQS's time with the fastest kernels and ")
                        .append(EvalReport.num(r, "/inputs/character/scalar/corOverDqs"))
                        .append(" times in the scalar code");
            }
            t.append(".");
        } else {
            t.append("Close to the camera, DQS: CoR does not improve on it here.");
        }
        report.paragraph(t.toString());
    }

    private static void twist(JsonNode in, JsonNode r, EvalReport report) {
        StringBuilder t = new StringBuilder("**Twisting limbs.** ");
        if (!in.has("twist")) {
            report.paragraph(t + missing("quality"));
            return;
        }
        String w = "/inputs/twist";
        t.append("Twisted to ").append(EvalReport.num(r, w + "/angleDegrees"))
                .append(" degrees, the twist cylinder's joint ring keeps ").append(EvalReport.num(r, w + "/lbsRing"))
                .append(" of its radius with LBS (the candy wrapper");
        if (in.at("/twist").has("lbsRingBelow90PercentAtDegrees")) {
            t.append("; it has lost a tenth by ").append(EvalReport.num(r, w + "/lbsRingBelow90PercentAtDegrees"))
                    .append(" degrees");
        }
        t.append("), ").append(EvalReport.num(r, w + "/dqsRing")).append(" with DQS and ")
                .append(EvalReport.num(r, w + "/corRing")).append(" with CoR. ");
        if (in.at("/twist/lbsRing").asDouble() < 0.9) {
            t.append("Forearms, wrists, necks and tentacles that twist need DQS or CoR; LBS only where joints bend.");
        } else {
            t.append("LBS keeps the ring on this clip; any method will do for its twist.");
        }
        report.paragraph(t.toString());
    }

    private static void lowEnd(JsonNode in, JsonNode r, EvalReport report) {
        StringBuilder t = new StringBuilder("**Low-end phones.** ");
        JsonNode series = r.at("/vertices/series");
        int lbs = scalarSeries(series, "lbs");
        int dqs = scalarSeries(series, "dqs");
        if (lbs < 0 || dqs < 0) {
            report.paragraph(t + "Not argued here: no scalar kernels' lines were measured.");
            return;
        }
        lowEndBudget(r, lbs, dqs, t);
        lowEndDrawn(in, r, t);
        lowEndCap(in, r, t);
        lowEndTracking(in, r, t);
        report.paragraph(t.toString());
    }

    /** The index in {@code series} of the scalar kernels' line of {@code method}, or -1. */
    private static int scalarSeries(JsonNode series, String method) {
        int found = -1;
        for (int i = 0; i < series.size(); i++) {
            if (series.get(i).get("kernels").asText().equals("scalar")
                    && series.get(i).get("method").asText().equals(method)) {
                found = i;
            }
        }
        return found;
    }

    /** The vertices the scalar lines {@code lbs} and {@code dqs} fit into the budget, and the GPU beyond. */
    private static void lowEndBudget(JsonNode r, int lbs, int dqs, StringBuilder t) {
        t.append("In the scalar code a phone runs, the fitted lines put ")
                .append(EvalReport.num(r, "/vertices/series/" + lbs + "/verticesInBudget")).append(" vertices (LBS) or ")
                .append(EvalReport.num(r, "/vertices/series/" + dqs + "/verticesInBudget"))
                .append(" (DQS) into ").append(EvalReport.num(r, "/budgetMicros"))
                .append(" µs on one core of this machine; a phone's core, several times slower, fits that many times"
                        + " fewer. Beyond that, skin on the GPU (the apps' default): the vertex shader does the"
                        + " per-vertex work, and the CPU keeps only the pose");
        JsonNode files = r.at("/joints/files");
        for (int i = 0; i < files.size(); i++) {
            if (files.get(i).get("file").asText().equals(EvalAdviceSection.CHARACTER)) {
                t.append(" (").append(EvalReport.num(r, "/joints/files/" + i + "/medianMicros"))
                        .append(" µs for the walking character here)");
            }
        }
        t.append(". ");
    }

    /** The drawn copies' frame rate with GPU skinning, when the crowds section drew them. */
    private static void lowEndDrawn(JsonNode in, JsonNode r, StringBuilder t) {
        if (!in.has("drawn")) {
            return;
        }
        t.append("Drawn with GPU skinning, ").append(EvalReport.num(r, "/inputs/drawn/copies")).append(" copies of `")
                .append(in.at("/drawn/file").asText()).append("` run at ")
                .append(EvalReport.num(r, "/inputs/drawn/gpuDqsFps")).append(" fps with DQS on `")
                .append(in.at("/drawn/renderer").asText()).append("`")
                .append(in.at("/drawn/software").asBoolean() ? ", a software rasteriser on the CPU, not a GPU" : "")
                .append(" (the thesis' desktop, with CPU skinning: ").append(EvalReport.num(r, "/inputs/drawn/thesisDqsFps"))
                .append(" fps). ");
    }

    /** What capping the influences to the GPU's costs, or that no file needed it. */
    private static void lowEndCap(JsonNode in, JsonNode r, StringBuilder t) {
        if (in.has("cap")) {
            t.append("A GPU reads ").append(EvalReport.num(r, "/inputs/cap/cap"))
                    .append(" influences per vertex; capping `").append(in.at("/cap/file").asText())
                    .append("` (up to ").append(EvalReport.num(r, "/inputs/cap/influences")).append(" influences) there moves ")
                    .append(EvalReport.num(r, "/inputs/cap/cappedPositions")).append(" positions, by at most ")
                    .append(EvalReport.num(r, "/inputs/cap/lbsPercent")).append(" % of its size with LBS and ")
                    .append(EvalReport.num(r, "/inputs/cap/dqsPercent")).append(" % with DQS.");
        } else {
            t.append("(No file with more influences per vertex than a GPU reads was measured, so the cost of its cap is"
                    + " not shown here.)");
        }
    }

    /** The tracker's share of a frame, or that its section was not run. */
    private static void lowEndTracking(JsonNode in, JsonNode r, StringBuilder t) {
        if (in.has("tracking")) {
            t.append(" The tracker's search of a whole ").append(EvalReport.num(r, "/inputs/tracking/width")).append("x")
                    .append(EvalReport.num(r, "/inputs/tracking/height")).append(" frame takes ")
                    .append(EvalReport.num(r, "/inputs/tracking/detectMedianMs")).append(" ms on one core here, ")
                    .append(EvalReport.num(r, "/inputs/tracking/framePercent"))
                    .append(" % of a frame at ").append(EvalReport.num(r, "/frameRateHz"))
                    .append(" Hz; in video it searches the whole frame only every ")
                    .append(EvalReport.num(r, "/inputs/tracking/fullFrameEvery"))
                    .append("th frame and when it loses a marker, and otherwise only near the last markers, several"
                            + " times faster (`skinlab bench track`).");
        } else {
            t.append(" The tracker's time per frame: the section `tracking` was not run (`--only`).");
        }
    }

    private static String missing(String section) {
        return "Not argued here: the section `" + section + "` was not run (`--only`).";
    }
}
