package org.skinlab.desktop.eval;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * The recommendations of {@code skinlab eval}'s advice section, one per use, each argued from the
 * numbers {@link EvalAdviceInputs} copied from the other sections into the advice's results (so
 * every number printed is one of results.json), values quoted at their stated angle and extremes
 * as extremes, each saying which inputs it lacks when a section was not run.
 */
final class EvalAdvice {
    private EvalAdvice() {
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
                        + " skin) takes on one core of this machine, with the scalar kernels (the code Android runs,"
                        + " here on a desktop JVM), ")
                .append(EvalReport.num(r, c + "/scalar/lbsMicros")).append(" µs with LBS, ")
                .append(EvalReport.num(r, c + "/scalar/dqsMicros")).append(" with DQS and ")
                .append(EvalReport.num(r, c + "/scalar/corMicros")).append(" with CoR (medians of the time section's"
                        + " runs): ")
                .append(EvalReport.num(r, c + "/scalar/lbsPerFrame")).append(", ")
                .append(EvalReport.num(r, c + "/scalar/dqsPerFrame")).append(" and ")
                .append(EvalReport.num(r, c + "/scalar/corPerFrame")).append(" characters per ")
                .append(EvalReport.num(r, "/frameRateHz")).append(" Hz frame of ")
                .append(EvalReport.num(r, "/frameMicros")).append(" µs (with the SIMD kernels of a desktop JVM: ")
                .append(EvalReport.num(r, c + "/fastest/lbsPerFrame")).append(", ")
                .append(EvalReport.num(r, c + "/fastest/dqsPerFrame")).append(" and ")
                .append(EvalReport.num(r, c + "/fastest/corPerFrame")).append("). In the scalar code DQS takes ")
                .append(EvalReport.num(r, c + "/scalar/dqsOverLbs")).append(" times LBS's time (the median round). ");
        if (in.has("characterQuality")) {
            String q = "/inputs/characterQuality";
            t.append("On this character LBS and DQS place points at most ")
                    .append(EvalReport.num(r, q + "/maxLbsDqsPercent")).append(" % of its size apart over its clip: ")
                    .append(EvalReport.num(r, q + "/maxLbsDqsPixels")).append(" pixels on a phone's screen where it"
                            + " stands ").append(EvalReport.num(r, q + "/characterPixels")).append(" pixels tall (the"
                            + " quality section's camera), ")
                    .append(EvalReport.num(r, q + "/crowdLbsDqsPixels")).append(" pixels for a crowd member ")
                    .append(EvalReport.num(r, q + "/crowdPixels")).append(" pixels tall. ");
            if (in.at("/characterQuality/crowdLbsDqsPixels").asDouble() < 1) {
                t.append("Below a pixel: for crowds, LBS, the cheapest method, whose artefacts do not show at that"
                        + " size.");
            } else {
                t.append("A pixel or more even at that size: for crowds, DQS.");
            }
        } else {
            t.append(missing("quality"));
        }
        if (in.has("crowds")) {
            t.append(" With all ").append(EvalReport.num(r, "/inputs/crowds/cores")).append(" cores of this machine on a"
                    + " crowd of ").append(EvalReport.num(r, "/inputs/crowds/crowd")).append(" walkers (the crowds"
                            + " section, the fastest kernels), ")
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
        t.append("At ").append(EvalReport.num(r, b + "/angleDegrees")).append(" degrees of bend the bend cylinder keeps ")
                .append(EvalReport.num(r, b + "/lbsVolume")).append(" of its volume with LBS (the elbow collapses), ")
                .append(EvalReport.num(r, b + "/dqsVolume")).append(" with DQS and ")
                .append(EvalReport.num(r, b + "/corVolume")).append(" with CoR; there the joint bulges by ")
                .append(EvalReport.num(r, b + "/dqsBulge")).append(" % of the model's size with DQS, ")
                .append(EvalReport.num(r, b + "/corBulge")).append(" with CoR and ")
                .append(EvalReport.num(r, b + "/lbsBulge")).append(" with LBS. Over the whole bend the largest bulges are ")
                .append(EvalReport.num(r, b + "/dqsMaxBulge")).append(" (DQS, at ")
                .append(EvalReport.num(r, b + "/dqsMaxBulgeDegrees")).append(" degrees), ")
                .append(EvalReport.num(r, b + "/corMaxBulge")).append(" (CoR, at ")
                .append(EvalReport.num(r, b + "/corMaxBulgeDegrees")).append(") and ")
                .append(EvalReport.num(r, b + "/lbsMaxBulge")).append(" (LBS, at ")
                .append(EvalReport.num(r, b + "/lbsMaxBulgeDegrees")).append("). On a phone's screen DQS and CoR differ"
                        + " by up to ").append(EvalReport.num(r, b + "/dqsCorPixels")).append(" pixels on this bend. ");
        boolean corBulgesLess = in.at("/bend/corBulge").asDouble() < in.at("/bend/dqsBulge").asDouble()
                && in.at("/bend/corMaxBulge").asDouble() < in.at("/bend/dqsMaxBulge").asDouble();
        boolean corKeeps = in.at("/bend/corVolume").asDouble() > in.at("/bend/lbsVolume").asDouble();
        if (corBulgesLess && corKeeps) {
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
        t.append("At ").append(EvalReport.num(r, w + "/angleDegrees"))
                .append(" degrees of twist the twist cylinder's joint ring keeps ").append(EvalReport.num(r, w + "/lbsRing"))
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
        if (in.has("fullTwist")) {
            String f = "/inputs/fullTwist";
            t.append(" Past a half turn every method reads the joint's rotation the short way round: on `")
                    .append(in.at("/fullTwist/file").asText()).append("` the joint ring has turned ")
                    .append(EvalReport.num(r, f + "/dqsTurnBefore")).append(" degrees with DQS at ")
                    .append(EvalReport.num(r, f + "/beforeDegrees")).append(" degrees of twist and ")
                    .append(EvalReport.num(r, f + "/dqsTurnAfter")).append(" at ")
                    .append(EvalReport.num(r, f + "/afterDegrees")).append(" (CoR ")
                    .append(EvalReport.num(r, f + "/corTurnBefore")).append(" and ")
                    .append(EvalReport.num(r, f + "/corTurnAfter")).append(", LBS ")
                    .append(EvalReport.num(r, f + "/lbsTurnBefore")).append(" and ")
                    .append(EvalReport.num(r, f + "/lbsTurnAfter")).append("), and at ")
                    .append(EvalReport.num(r, f + "/fullDegrees")).append(" degrees it is back at ")
                    .append(EvalReport.num(r, f + "/dqsTurnFull")).append(" with DQS: the skin snaps back as the"
                            + " twist passes a half turn and shows no twist at a full one. A rig that twists a limb"
                            + " that far needs the twist split over several joints (twist bones), each under a half"
                            + " turn.");
        }
        report.paragraph(t.toString());
    }

    private static void lowEnd(JsonNode in, JsonNode r, EvalReport report) {
        StringBuilder t = new StringBuilder("**Low-end phones.** ");
        JsonNode series = r.at("/vertices/series");
        int lbs = scalarSeries(series, "lbs");
        int dqs = scalarSeries(series, "dqs");
        if (lbs < 0 || dqs < 0) {
            report.paragraph(t + "Not argued here: no scalar kernels' costs were measured.");
            return;
        }
        t.append("With the scalar kernels, the fitted cost per vertex puts ")
                .append(EvalReport.num(r, "/vertices/series/" + lbs + "/verticesInBudget")).append(" vertices (LBS) or ")
                .append(EvalReport.num(r, "/vertices/series/" + dqs + "/verticesInBudget"))
                .append(" (DQS) into ").append(EvalReport.num(r, "/budgetMicros"))
                .append(" µs on one core of this desktop; what a phone fits is the phone section's to say (its own"
                        + " measurement, never an estimate from this machine). Beyond that, skin in the vertex shader"
                        + " (the apps' default): the GPU does the per-vertex work, and the CPU keeps only the pose");
        JsonNode files = r.at("/joints/files");
        for (int i = 0; i < files.size(); i++) {
            if (files.get(i).get("file").asText().equals(EvalAdviceSection.CHARACTER)) {
                t.append(" (").append(EvalReport.num(r, "/joints/files/" + i + "/micros/median"))
                        .append(" µs for the walking character here)");
            }
        }
        t.append(". ");
        lowEndCap(in, r, t);
        lowEndTracking(in, r, t);
        report.paragraph(t.toString());
    }

    /** The index in {@code series} of the scalar kernels' series of {@code method}, or -1. */
    private static int scalarSeries(JsonNode series, String method) {
        for (int i = 0; i < series.size(); i++) {
            if (series.get(i).get("kernels").asText().equals("scalar")
                    && series.get(i).get("method").asText().equals(method)) {
                return i;
            }
        }
        return -1;
    }

    /** What capping the influences to the GPU's costs, or that no file needed it. */
    private static void lowEndCap(JsonNode in, JsonNode r, StringBuilder t) {
        if (in.has("cap")) {
            t.append("A GPU's skinning reads ").append(EvalReport.num(r, "/inputs/cap/cap"))
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
                    .append("th frame and when it loses a marker, and otherwise only near the last markers: ")
                    .append(EvalReport.num(r, "/inputs/tracking/trackMedianMs")).append(" ms a frame, ")
                    .append(EvalReport.num(r, "/inputs/tracking/detectOverTrack"))
                    .append(" times faster (the tracking section's video).");
        } else {
            t.append(" The tracker's time per frame: the section `tracking` was not run (`--only`).");
        }
    }

    private static String missing(String section) {
        return "Not argued here: the section `" + section + "` was not run (`--only`).";
    }
}
