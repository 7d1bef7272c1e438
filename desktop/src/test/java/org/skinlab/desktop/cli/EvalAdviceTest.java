package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code skinlab eval}'s advice: the fitted lines, and recommendations argued from the numbers
 * of the sections run before it (here quality only, whose numbers are deterministic; the time
 * section's are not, so no test asserts what they recommend). About 15 s.
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
    void theAdviceArguesFromTheQualityNumbersAndSaysWhatItLacks(@TempDir Path dir) throws Exception {
        Cli run = Cli.run("eval", "--quick", "--only", "quality,advice", "--out", dir.toString());
        assertEquals(ExitCodes.OK, run.status, run.err);
        JsonNode results = new ObjectMapper().readTree(dir.resolve("results.json").toFile());
        String readme = Files.readString(dir.resolve("README.md"));
        assertEquals(List.of("quality", "advice"), Cli.keys(results.get("sections")));
        List<String> linked = EvalReportCheck.figuresAndNumbers(dir, results, readme);
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
        // No time section in this run: the crowd advice says so instead of guessing.
        assertTrue(readme.contains("**Crowds.** Not argued here: the section `time` was not run"), readme);

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
}
