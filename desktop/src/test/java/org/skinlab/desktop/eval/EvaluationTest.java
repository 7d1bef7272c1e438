package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.stream.Collectors;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.DoubleNode;
import com.fasterxml.jackson.databind.node.IntNode;

import org.junit.jupiter.api.Test;
import org.skinlab.desktop.Cli;

/**
 * {@code skinlab eval --quick}: the report, results.json and every figure are written, and every
 * number README.md prints is a number of results.json (printed by the same rule); the load, time
 * and quality sections measure what they should. The quick run of every section is shared with
 * the other sections' tests ({@link EvalQuickRun}).
 */
class EvaluationTest {
    @Test
    void quickRunWritesTheReportFromItsResultsWithEveryFigure() throws Exception {
        EvalQuickRun run = EvalQuickRun.get();
        Path dir = run.dir;
        JsonNode results = run.results;
        String readme = run.readme;
        assertEquals(Evaluation.SECTIONS.stream().map(EvalSection::key).collect(Collectors.toList()),
                Cli.keys(results.get("sections")));
        assertEquals("skinlab eval --quick --out " + dir, results.at("/machine/command").asText());
        assertTrue(readme.contains(results.at("/machine/cpu").asText()), "the report names the CPU");
        for (EvalSection s : Evaluation.SECTIONS) {
            assertTrue(readme.contains("## " + s.title() + "\n"), s.title());
        }

        // The load section's files: EvalLoadTest.

        List<String> linked = EvalReportCheck.figuresAndNumbers(dir, results, readme);
        assertTrue(linked.contains("load-files.png") && linked.contains("time-fastest.png")
                && linked.contains("time-scalar.png"), linked.toString());
        // At least one figure per section that draws (the claims are a table), or why not (the
        // section skipped, or only its figure).
        for (EvalSection s : Evaluation.SECTIONS) {
            if (s.summary()) {
                continue;
            }
            JsonNode section = results.at("/sections/" + s.key());
            assertTrue(linked.stream().anyMatch(f -> f.startsWith(s.key() + "-")) || section.has("skipped")
                    || section.has("figureSkipped"), "no figure of " + s.key() + ": " + linked);
        }
        Set<String> values = new HashSet<>();
        EvalReportCheck.collect(results, values);
        assertTrue(EvalReportCheck.numbers(readme) > 300, "only " + EvalReportCheck.numbers(readme) + " numbers in the report");
        // The thesis' table is there, beside ours.
        assertTrue(values.contains("4.35") && values.contains("6.37"));
        assertTrue(readme.contains("| cylinderYLow | `cylinder-twist-low.dae` | 2.67 |"), readme);
        // The C++ reference and our kernels skinned the same data alike (or it says why it did not run).
        JsonNode reference = results.at("/sections/time/reference");
        if (!reference.has("skipped")) {
            // The quick run: one size, every kernel with both methods.
            assertEquals(EvalCppReference.KERNELS.size(), reference.get("rows").size(), reference.toString());
            int compared = 0;
            for (JsonNode row : reference.get("rows")) {
                SpreadCheck.check(row.get("dqsOverLbs"), row.toString());
                if (row.has("checksumAgrees")) {
                    assertTrue(row.get("checksumAgrees").asBoolean(), row.toString());
                    compared++;
                }
            }
            // Every Java kernel without normals or with the reference's blended ones has a C++ counterpart.
            assertEquals(4, compared, reference.toString());
            assertTrue(linked.contains("time-cpp-reference.png"), linked.toString());
        } else {
            assertTrue(readme.contains("Not run: `" + reference.get("skipped").asText()), readme);
        }
    }

    /**
     * Quality on the cylinders against the volumes assets/README.md states (check_assets.py, an
     * independent mesh computation: rest 0.3902, LBS 0.3238 on twist-high at 172 degrees, 0.3569
     * on the bend at 170), and the candy wrapper: LBS's joint ring near 0 at 172 degrees of twist
     * (cos 86 degrees = 0.07), DQS's near 1.
     */
    @Test
    void quickQualityMeasuresTheKnownArtefacts() {
        EvalQuickRun run = EvalQuickRun.get();
        JsonNode results = run.results;
        List<String> linked = EvalReportCheck.linked(run.readme);
        assertTrue(linked.containsAll(List.of("quality-angle-cylinder-twist-high.png", "quality-angle-cylinder-bend.png",
                "quality-volume-humanoid-walk.png")), linked.toString());
        JsonNode twist = asset(results, "cylinder-twist-high.dae");
        JsonNode angles = twist.get("angleDegrees");
        int last = angles.size() - 1;
        assertEquals(172, angles.get(last).asDouble(), 0.5, "the clip ends at 172 degrees of twist");
        assertEquals(0, angles.get(0).asDouble(), 0.5);
        assertTrue(twist.at("/methods/lbs/ringRadius/" + last).asDouble() < 0.2, twist.toString());
        assertTrue(twist.at("/methods/dqs/ringRadius/" + last).asDouble() > 0.9, twist.toString());
        // Mesh volume against check_assets.py's: 0.01 covers the quick run's samples and float sums.
        assertEquals(0.3238 / 0.3902, twist.at("/methods/lbs/minVolume").asDouble(), 0.01);
        assertTrue(twist.at("/methods/dqs/minVolume").asDouble() > 0.97, twist.toString());
        JsonNode bend = asset(results, "cylinder-bend.dae");
        assertEquals(170, bend.at("/angleDegrees/" + last).asDouble(), 0.5);
        assertEquals(0.3569 / 0.3902, bend.at("/methods/lbs/minVolume").asDouble(), 0.01);
        assertTrue(bend.at("/methods/dqs/maxBulge").asDouble() > bend.at("/methods/lbs/maxBulge").asDouble(),
                "DQS bulges more than LBS at a bent joint: " + bend);
        assertTrue(EvalQualitySection.pair(twist, "lbs", "dqs").get("maxPercent").asDouble() > 1,
                "LBS and DQS differ under twist");
        // A smooth blend turns the joint ring by half the joint's angle: 85 degrees at 170.
        JsonNode at170 = EvalAdviceInputs.atAngle(twist, 170);
        assertEquals(85, at170.at("/methods/dqs/ringTurnDegrees/0").asDouble(), 0.05);
        assertEquals(170, at170.get("angleDegrees").asDouble());
        // Two influences per point: capping at 4 or 8 changes nothing.
        for (JsonNode cap : twist.get("caps")) {
            assertEquals(0, cap.get("cappedPositions").asInt());
            assertEquals(0, cap.get("lbsPercent").asDouble());
        }
    }

    private static JsonNode asset(JsonNode results, String file) {
        for (JsonNode a : results.at("/sections/quality/assets")) {
            if (a.get("file").asText().equals(file)) {
                return a;
            }
        }
        throw new AssertionError("no " + file + " in " + results);
    }

    /**
     * Every timing of the quick run keeps at least 5 runs and its median is its runs' median;
     * every asset's frame is timed with every method; the claims table answers every claim.
     */
    @Test
    void everyTimingIsRepeatedAndEveryMethodTimed() {
        JsonNode results = EvalQuickRun.get().results;
        List<JsonNode> spreads = new java.util.ArrayList<>();
        CommittedReportTest.collectSpreads(results.get("sections"), spreads);
        assertTrue(spreads.size() > 50, "only " + spreads.size() + " timings with runs");
        for (JsonNode s : spreads) {
            assertTrue(s.get("runs").size() >= org.skinlab.internal.bench.Rounds.MIN_RUNS, s.toString());
            double[] runs = new double[s.get("runs").size()];
            for (int i = 0; i < runs.length; i++) {
                runs[i] = s.get("runs").get(i).asDouble();
            }
            assertEquals(org.skinlab.internal.bench.Spread.of(runs).median(), s.get("median").asDouble(), 0.0015, s.toString());
        }
        for (JsonNode asset : results.at("/sections/time/assets")) {
            for (org.skinlab.skinning.SkinningMethod m : org.skinlab.skinning.SkinningMethod.values()) {
                assertTrue(EvalTimeSection.run(asset, m, "fastest", "all") != null, asset.get("file") + " " + m);
            }
        }
        assertTrue(results.at("/noise/timings").asInt() == spreads.size(), results.get("noise").toString());
        for (JsonNode claim : results.at("/sections/claims/claims")) {
            assertTrue(List.of(EvalClaimsSection.HOLDS, EvalClaimsSection.FAILS, EvalClaimsSection.MIXED,
                    EvalClaimsSection.UNMEASURED).contains(claim.get("verdict").asText()), claim.toString());
            if (claim.has("missing")) {
                assertEquals(EvalClaimsSection.UNMEASURED, claim.get("verdict").asText(), claim.toString());
            }
        }
        String readme = EvalQuickRun.get().readme;
        assertTrue(readme.indexOf("## The thesis' claims, answered") < readme.indexOf("## Load: import time"),
                "the claims come first");
    }

    @Test
    void theNumberRulePrintsStoredValuesPlainly() {
        assertEquals("1.5", EvalReport.format(new DoubleNode(1.50)));
        assertEquals("3", EvalReport.format(new DoubleNode(3.0)));
        assertEquals("0.0001", EvalReport.format(new DoubleNode(1e-4)));
        assertEquals("12000", EvalReport.format(new DoubleNode(1.2e4)));
        assertEquals("42", EvalReport.format(new IntNode(42)));
        assertEquals(0.123, EvalReport.round(0.12345));
    }

}
