package org.skinlab.desktop.eval;

import java.util.function.Function;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;


/**
 * Section "claims": the thesis' claims (its chapters 4.2 and 6, /work/shared/seed/DIGEST.md)
 * answered one by one with this run's numbers, each with a verdict: holds, does not hold, or
 * cannot be measured here (and why). It measures nothing itself: it reads the other sections'
 * results ({@link EvalClaims} finds each number), copies what it quotes into its own, and is
 * written at the top of the report though it is derived last.
 */
final class EvalClaimsSection implements EvalSection {
    static final String HOLDS = "holds";
    static final String FAILS = "does not hold";
    static final String MIXED = "holds in part";
    static final String UNMEASURED = "cannot be measured here";

    @Override
    public String key() {
        return "claims";
    }

    @Override
    public String title() {
        return "The thesis' claims, answered";
    }

    @Override
    public boolean summary() {
        return true;
    }

    @Override
    public double estimatedSeconds(EvalContext context) {
        return 0.1;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        derive(context::measured, results);
    }

    @Override
    public void derive(Function<String, JsonNode> sections, ObjectNode results) {
        results.put("requirementsChapter", 4.2).put("resultsChapter", 6).put("deformationChapter", 5.8);
        ArrayNode claims = results.putArray("claims");
        EvalClaims.load(sections.apply("load"), claims.addObject());
        EvalClaims.playback(sections.apply("crowds"), claims.addObject());
        for (String kernels : new String[] {"scalar", "fastest"}) {
            EvalClaims.dqsFasterOnAssets(sections.apply("time"), kernels, claims.addObject());
        }
        EvalClaims.dqsFasterInCpp(sections.apply("time"), claims.addObject());
        EvalClaims.dqsFasterWithoutNormals(sections.apply("time"), claims.addObject());
        EvalClaims.meshes(sections.apply("crowds"), 1, claims.addObject());
        EvalClaims.meshes(sections.apply("crowds"), EvalCrowdsThesis.THESIS_MESHES, claims.addObject());
        EvalClaims.lbsLosesVolume(sections.apply("quality"), claims.addObject());
        EvalClaims.dqsKeepsVolume(sections.apply("quality"), claims.addObject());
        EvalClaims.dqsBulges(sections.apply("quality"), claims.addObject());
        EvalClaims.phone(sections.apply("phone"), claims.addObject());
        EvalClaims.whyItFlips(sections.apply("advice"), results.putObject("flip"));
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        report.paragraph("Each claim of the thesis (its requirements, chapter " + EvalReport.num(results,
                "/requirementsChapter") + ", and its results, chapter " + EvalReport.num(results, "/resultsChapter")
                + ") beside"
                + " this run's number for it, from the sections below, and a verdict: holds, does not hold, holds in"
                + " part, or cannot be measured here (with the reason). The thesis measured its own desktop and a"
                + " Galaxy S7; where the claim is a comparison (DQS against LBS), the verdict is about the"
                + " comparison on this machine, not about the thesis' hardware.");
        report.header("the thesis claims", "this run", "verdict");
        JsonNode claims = results.get("claims");
        for (int i = 0; i < claims.size(); i++) {
            String[] cells = EvalClaims.cells(results, i);
            report.row(cells[0], cells[1], "**" + claims.get(i).get("verdict").asText() + "**");
        }
        report.line("");
        EvalClaims.flipParagraph(results, report);
    }

    /** The verdict of a comparison "a is smaller than b" from the values' ranges: clear either way, or within the spread. */
    static String smaller(double aMin, double aMax, double bMin, double bMax) {
        if (aMax < bMin) {
            return HOLDS;
        }
        if (bMax < aMin) {
            return FAILS;
        }
        return "within the spread";
    }
}
