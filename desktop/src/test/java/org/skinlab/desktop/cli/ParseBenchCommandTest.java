package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.skinlab.desktop.ExitCodes;

/** {@code skinlab bench parse FILE --json}: the keys ParseBenchCommand writes, with sane values. */
class ParseBenchCommandTest {
    @Test
    void jsonReportsOneFileWithItsSizeTrianglesAndTimes() throws Exception {
        Path file = Cli.defaultAsset();
        Cli r = Cli.run("bench", "parse", file.toString(), "--generated-triangles", "0", "--warmup-seconds", "0",
                "--runs", "2", "--json");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        assertTrue(r.out.indexOf('\n') == r.out.length() - 1, r::toString);

        JsonNode root = new ObjectMapper().readTree(r.out);
        assertEquals(List.of("benchmark", "java", "cores", "files"), Cli.keys(root));
        assertEquals("parse", root.get("benchmark").asText());
        assertEquals(System.getProperty("java.version"), root.get("java").asText());
        assertEquals(Runtime.getRuntime().availableProcessors(), root.get("cores").intValue());
        assertEquals(1, root.get("files").size());
        JsonNode f = root.get("files").get(0);
        assertEquals(List.of("file", "bytes", "triangles", "runs", "minMillis", "medianMillis", "mbPerSecond"), Cli.keys(f));
        assertEquals("humanoid-walk.dae", f.get("file").asText());
        assertEquals(Files.size(file), f.get("bytes").longValue());
        assertEquals(1896, f.get("triangles").longValue());
        assertEquals(2, f.get("runs").intValue());
        double min = f.get("minMillis").doubleValue();
        double median = f.get("medianMillis").doubleValue();
        assertTrue(min > 0 && min <= median, r::toString);
        // Throughput at the median: bytes / 10^6 / (median / 1000), rounded to 3 decimals.
        double expected = Files.size(file) / 1e6 / (median / 1000.0);
        assertEquals(expected, f.get("mbPerSecond").doubleValue(), expected * 0.01 + 0.001);
        // Progress goes to stderr, one line per file, so stdout stays one JSON document.
        assertTrue(r.err.startsWith("bench parse: humanoid-walk.dae "), r::toString);
    }
}
