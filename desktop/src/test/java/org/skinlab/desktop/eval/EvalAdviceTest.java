package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code skinlab eval}'s advice: the fitted lines, and recommendations argued from the numbers
 * of the sections run before it (from the shared quick run, {@link EvalQuickRun}; only the quality
 * numbers are deterministic, so no test asserts what the timings recommend), and what it says
 * when a section it argues from was not run.
 */
class EvalAdviceTest {
    @Test
    void aLineThroughExactPointsIsThatLine() {
        EvalScaling.Line l = EvalScaling.Line.fit(new double[] {1, 2, 4, 8}, new double[] {5, 7, 11, 19});
        assertEquals(2, l.slope(), 1e-12);
        assertEquals(3, l.intercept(), 1e-12);
        assertEquals(1, l.r2(), 1e-12);
    }

    @Test
    void aLineThroughScatteredPointsIsTheLeastSquaresOne() {
        // x 0 1 2 3, y 1 3 2 4: mean x 1.5, mean y 2.5, deviations x (-1.5 -0.5 0.5 1.5), y (-1.5 0.5
        // -0.5 1.5): Sxy = 2.25 - 0.25 - 0.25 + 2.25 = 4, Sxx = Syy = 5, so the slope is 0.8, the
        // intercept 2.5 - 0.8 * 1.5 = 1.3, r² = 4² / (5 * 5) = 0.64.
        EvalScaling.Line l = EvalScaling.Line.fit(new double[] {0, 1, 2, 3}, new double[] {1, 3, 2, 4});
        assertEquals(0.8, l.slope(), 1e-12);
        assertEquals(1.3, l.intercept(), 1e-12);
        assertEquals(0.64, l.r2(), 1e-12);
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
        assertEquals(twistQuality.at("/methods/lbs/minRingRadius").asDouble(), advice.at("/inputs/twist/lbsRing").asDouble());
        // The candy wrapper (LBS's ring near 0 at 172 degrees) makes the twist advice DQS or CoR.
        assertTrue(readme.contains("need DQS or CoR"), readme);
        // DQS bulges more than CoR on the bend and CoR keeps more volume than LBS: CoR for close-ups.
        assertTrue(readme.contains("Close to the camera, where a joint fills the screen, CoR"), readme);
        // The crowd advice is argued from the time section's character.
        assertEquals(results.at("/sections/advice/inputs/character/scalar/lbsMicros").asDouble(),
                lbsMicros(results.at("/sections/time/assets")), 0);

        // The budget is the fitted line's, as stored.
        for (JsonNode s : advice.at("/vertices/series")) {
            assertEquals(advice.at("/vertices/vertices").size(), s.get("medianMicros").size());
            double slope = s.get("nsPerVertex").asDouble();
            if (slope > 0) {
                double expected = (advice.get("budgetMicros").asDouble()
                        - Math.max(0, s.get("interceptMicros").asDouble())) * 1000 / slope;
                assertEquals(expected, s.get("verticesInBudget").asDouble(), 1, s.toString());
            }
        }
        // Joints: every skinned asset's pose, joints as the files have them.
        JsonNode humanoid = advice.at("/joints/files/0");
        assertEquals("humanoid-walk.dae", humanoid.get("file").asText());
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
                        return r.get("medianMicros").asDouble();
                    }
                }
            }
        }
        throw new AssertionError("no scalar LBS run of " + EvalAdviceSection.CHARACTER);
    }
}
