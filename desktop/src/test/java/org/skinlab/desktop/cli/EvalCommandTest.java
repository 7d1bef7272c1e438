package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashSet;
import java.util.List;
import java.util.Set;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.DoubleNode;
import com.fasterxml.jackson.databind.node.IntNode;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code skinlab eval --quick}: the report, results.json and every figure are written, and every
 * number README.md prints is a number of results.json (printed by the same rule). About 30 s on
 * the project's 2-core machine (the quick run of both sections).
 */
class EvalCommandTest {
    @Test
    void quickRunWritesTheReportFromItsResultsWithEveryFigure(@TempDir Path dir) throws Exception {
        Cli run = Cli.run("eval", "--quick", "--only", "load,time", "--out", dir.toString());
        assertEquals(ExitCodes.OK, run.status, run.err);
        JsonNode results = new ObjectMapper().readTree(dir.resolve("results.json").toFile());
        String readme = Files.readString(dir.resolve("README.md"));
        assertEquals(List.of("load", "time"), Cli.keys(results.get("sections")));
        assertEquals("skinlab eval --quick --only load,time --out " + dir, results.at("/machine/command").asText());
        assertTrue(readme.contains(results.at("/machine/cpu").asText()), "the report names the CPU");

        List<String> linked = EvalReportCheck.figuresAndNumbers(dir, results, readme);
        assertTrue(linked.contains("load-files.png") && linked.contains("time-cylinder-bend.png"), linked.toString());
        Set<String> values = new HashSet<>();
        EvalReportCheck.collect(results, values);
        assertTrue(EvalReportCheck.numbers(readme) > 60, "only " + EvalReportCheck.numbers(readme) + " numbers in the report");
        // The thesis' table is there, beside ours.
        assertTrue(values.contains("4.35") && values.contains("6.37"));
        assertTrue(readme.contains("| cylinderYLow | `cylinder-twist-low.dae` | 2.67 |"), readme);
    }

    /**
     * Quality on the cylinders against the volumes assets/README.md states (check_assets.py, an
     * independent mesh computation: rest 0.3902, LBS 0.3238 on twist-high at 172 degrees, 0.3569
     * on the bend at 170), and the candy wrapper: LBS's joint ring near 0 at 172 degrees of twist
     * (cos 86 degrees = 0.07), DQS's near 1. About 5 s.
     */
    @Test
    void quickQualityMeasuresTheKnownArtefacts(@TempDir Path dir) throws Exception {
        Cli run = Cli.run("eval", "--quick", "--only", "quality", "--out", dir.toString());
        assertEquals(ExitCodes.OK, run.status, run.err);
        JsonNode results = new ObjectMapper().readTree(dir.resolve("results.json").toFile());
        String readme = Files.readString(dir.resolve("README.md"));
        assertEquals(List.of("quality"), Cli.keys(results.get("sections")));
        List<String> linked = EvalReportCheck.figuresAndNumbers(dir, results, readme);
        assertTrue(linked.containsAll(List.of("quality-twist-ring.png", "quality-bend-bulge.png",
                "quality-volume-cylinder-twist-high.png", "quality-volume-humanoid-walk.png")), linked.toString());
        assertTrue(EvalReportCheck.numbers(readme) > 40, "only " + EvalReportCheck.numbers(readme) + " numbers in the report");
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
        assertTrue(twist.get("maxLbsDqsPercent").asDouble() > 1, "LBS and DQS differ under twist");
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

    @Test
    void anUnknownSectionIsAUsageErrorNamingTheValidOnes(@TempDir Path dir) {
        Cli run = Cli.run("eval", "--only", "load,crowds", "--out", dir.toString());
        assertEquals(ExitCodes.USAGE, run.status);
        assertTrue(run.err.contains("unknown section \"crowds\" (valid: load, time, quality, tracking)"), run.err);
    }

    @Test
    void anOutThatIsAFileIsAUsageError(@TempDir Path dir) throws Exception {
        Path file = Files.writeString(dir.resolve("report"), "");
        Cli run = Cli.run("eval", "--only", "load", "--out", file.toString());
        assertEquals(ExitCodes.USAGE, run.status);
        assertTrue(run.err.contains("--out: not a folder: " + file), run.err);
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
