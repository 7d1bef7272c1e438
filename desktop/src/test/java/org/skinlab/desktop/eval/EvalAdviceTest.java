package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code skinlab eval}'s advice: the fits (hand-computed cases), and recommendations argued from the numbers
 * of the sections run before it (from the shared quick run, {@link EvalQuickRun}; only the quality
 * numbers are deterministic, so no test asserts what the timings recommend), and what it says
 * when a section it argues from was not run.
 */
class EvalAdviceTest {
    @Test
    void aLineThroughExactPointsIsThatLine() {
        EvalFits.Fit l = EvalFits.line(new double[] {1, 2, 4, 8}, new double[] {5, 7, 11, 19});
        assertEquals("line", l.model());
        assertEquals(2, l.slope(), 1e-12);
        assertEquals(3, l.intercept(), 1e-12);
        assertEquals(1, l.r2(), 1e-12);
        assertTrue(l.holds());
    }

    @Test
    void aLineThroughScatteredPointsIsTheLeastSquaresOneWithItsResiduals() {
        // x 0 1 2 3, y 1 3 2 4: mean x 1.5, mean y 2.5, Sxy = 4, Sxx = Syy = 5: slope 0.8, intercept
        // 2.5 - 0.8 * 1.5 = 1.3, r² = 1 - SSres / SStot = 16 / 25 = 0.64; the fitted values 1.3 2.1 2.9
        // 3.7 miss the points by -30 %, +30 %, -45 %, +7.5 % of each point.
        EvalFits.Fit l = EvalFits.line(new double[] {0, 1, 2, 3}, new double[] {1, 3, 2, 4});
        assertEquals(0.8, l.slope(), 1e-12);
        assertEquals(1.3, l.intercept(), 1e-12);
        assertEquals(0.64, l.r2(), 1e-12);
        assertArrayEquals(new double[] {-30, 30, -45, 7.5}, l.residualsPercent(), 1e-9);
        assertFalse(l.holds(), "points 45 % off the line are not described by it");
    }

    @Test
    void aLineThatWouldGoNegativeBecomesProportional() {
        // y = 2x - 1 exactly: the line would give -1 at x = 0, a negative time.
        EvalFits.Fit f = EvalFits.line(new double[] {1, 2, 3, 4}, new double[] {1, 3, 5, 7});
        assertEquals("proportional", f.model());
        assertEquals(0, f.intercept());
        assertTrue(f.slope() > 0);
    }

    @Test
    void aProportionalFitLeavesOutTheSmallSizesItDoesNotDescribe() {
        // 10 ns per item plus 500 ns fixed: at 10 and 100 items the fixed part is 83 % and 33 %; from
        // 1000 on, under 5 %: the fit leaves the two smallest out and holds from 1000 on.
        double[] x = {10, 100, 1000, 10_000, 100_000};
        double[] y = new double[x.length];
        for (int i = 0; i < x.length; i++) {
            y[i] = 500 + 10 * x[i];
        }
        EvalFits.Fit f = EvalFits.proportional(x, y);
        assertEquals(1000, f.from());
        assertTrue(f.holds());
        assertTrue(Double.isNaN(f.residualsPercent()[0]) && Double.isNaN(f.residualsPercent()[1]));
        assertEquals(10, f.slope(), 0.5);
        // Never more than MIN_POINTS are left: through two exact points, nothing is dropped.
        EvalFits.Fit two = EvalFits.proportional(new double[] {1, 2}, new double[] {2, 4});
        assertEquals(1, two.from());
        assertEquals(2, two.slope(), 1e-12);
    }

    @Test
    void theAdviceArguesFromTheQualityNumbers() {
        EvalQuickRun run = EvalQuickRun.get();
        JsonNode results = run.results;
        String readme = run.readme;
        List<String> linked = EvalReportCheck.linked(readme);
        assertTrue(linked.containsAll(List.of("advice-vertices.png", "advice-influences.png")), linked.toString());

        JsonNode advice = results.at("/sections/advice");
        JsonNode twistQuality = null;
        for (JsonNode a : results.at("/sections/quality/assets")) {
            if (a.get("file").asText().equals("cylinder-twist-high.dae")) {
                twistQuality = a;
            }
        }
        // The twist advice quotes the ring at 170 degrees, where the quality section measured it.
        assertEquals(EvalAdviceInputs.atAngle(twistQuality, 170).at("/methods/lbs/ringRadius/0").asDouble(),
                advice.at("/inputs/twist/lbsRing").asDouble());
        // The candy wrapper (LBS's ring near 0 at 172 degrees) makes the twist advice DQS or CoR.
        assertTrue(readme.contains("need DQS or CoR"), readme);
        // DQS bulges more than CoR on the bend and CoR keeps more volume than LBS: CoR for close-ups.
        assertTrue(readme.contains("Close to the camera, where a joint fills the screen, CoR"), readme);
        // The crowd advice is argued from the time section's character.
        assertEquals(results.at("/sections/advice/inputs/character/scalar/lbsMicros").asDouble(),
                lbsMicros(results.at("/sections/time/assets")), 0);

        // The budget is the fitted cost's, as stored; every point is its runs' median.
        for (JsonNode s : advice.at("/vertices/series")) {
            assertEquals(advice.at("/vertices/vertices").size(), s.get("points").size());
            double ns = s.at("/fit/slope").asDouble();
            assertTrue(ns > 0, s.toString());
            assertEquals(Math.floor(advice.get("budgetMicros").asDouble() * 1000 / ns),
                    s.get("verticesInBudget").asDouble(), 0, s.toString());
            assertEquals("proportional", s.at("/fit/model").asText(), "a cost per vertex never goes negative");
        }
        // Joints: every skinned asset's pose, joints as the files have them.
        JsonNode humanoid = null;
        for (JsonNode f : advice.at("/joints/files")) {
            if (f.get("file").asText().equals("humanoid-walk.dae")) {
                humanoid = f;
            }
        }
        assertTrue(humanoid != null, "the walking character's joints are measured: " + advice.at("/joints/files"));
        assertEquals(19, humanoid.get("joints").asInt());
    }

    @Test
    void aUseWhoseSectionWasNotRunSaysSo(@org.junit.jupiter.api.io.TempDir Path dir) {
        com.fasterxml.jackson.databind.node.ObjectNode results = new ObjectMapper().createObjectNode();
        results.putObject("inputs");
        results.putObject("vertices").putArray("series");
        EvalReport report = new EvalReport(dir, new ObjectMapper().createObjectNode());
        EvalAdvice.write(results, report);
        String text = report.markdown();
        assertTrue(text.contains("**Crowds.** Not argued here: the section `time` was not run"), text);
        assertTrue(text.contains("**Twisting limbs.** Not argued here: the section `quality` was not run"), text);
    }

    private static double lbsMicros(JsonNode timeAssets) {
        for (JsonNode a : timeAssets) {
            if (a.get("file").asText().equals(EvalAdviceSection.CHARACTER)) {
                for (JsonNode r : a.get("runs")) {
                    if (r.get("method").asText().equals("lbs") && r.get("kernels").asText().equals("scalar")
                            && r.get("influences").asText().equals("all")) {
                        return r.at("/micros/median").asDouble();
                    }
                }
            }
        }
        throw new AssertionError("no scalar LBS run of " + EvalAdviceSection.CHARACTER);
    }
}
