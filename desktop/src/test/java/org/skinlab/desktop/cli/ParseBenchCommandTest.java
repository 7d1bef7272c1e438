package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.skinlab.desktop.Cli;
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

    /** A .glb is measured like a .dae: the same report, with the glTF file's name, size and triangles. */
    @Test
    void measuresAGlbFile() throws Exception {
        Path file = Cli.defaultAsset().resolveSibling("humanoid-walk.glb");
        Cli r = Cli.run("bench", "parse", file.toString(), "--warmup-seconds", "0", "--runs", "2", "--json");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        JsonNode f = new ObjectMapper().readTree(r.out).get("files").get(0);
        assertEquals("humanoid-walk.glb", f.get("file").asText());
        assertEquals(Files.size(file), f.get("bytes").longValue());
        assertEquals(1896, f.get("triangles").longValue(), "the same triangles as the .dae");
        assertTrue(f.get("minMillis").doubleValue() > 0, r::toString);
    }

    /**
     * Without FILEs: the character generated as .glb and as .dae has the same triangles in both,
     * and the report compares our two imports of it (COLLADA median / glTF median).
     */
    @Test
    void comparesTheSameCharacterAsGlbAndDae(@org.junit.jupiter.api.io.TempDir Path empty) throws Exception {
        Cli r = Cli.run("bench", "parse", "--assets", empty.toString(), "--corpus", empty.resolve("none").toString(),
                "--generated-triangles", "0", "--twin-triangles", "2000", "--warmup-seconds", "0", "--runs", "2",
                "--json");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        JsonNode root = new ObjectMapper().readTree(r.out);
        assertEquals(List.of("benchmark", "java", "cores", "files", "sameCharacter"), Cli.keys(root));
        JsonNode files = root.get("files");
        assertEquals(2, files.size(), r::toString);
        assertEquals("twin-2000-triangles.glb", files.get(0).get("file").asText());
        assertEquals("twin-2000-triangles.dae", files.get(1).get("file").asText());
        long triangles = files.get(0).get("triangles").longValue();
        assertTrue(triangles >= 2000, r::toString);
        assertEquals(triangles, files.get(1).get("triangles").longValue(), "the same character");
        JsonNode same = root.get("sameCharacter");
        assertEquals("twin-2000-triangles.glb", same.get("gltf").asText());
        assertEquals("twin-2000-triangles.dae", same.get("collada").asText());
        double expected = files.get(1).get("medianMillis").doubleValue() / files.get(0).get("medianMillis").doubleValue();
        assertEquals(expected, same.get("colladaOverGltf").doubleValue(), expected * 0.01 + 0.001);

        Cli text = Cli.run("bench", "parse", "--assets", empty.toString(), "--corpus", empty.resolve("none").toString(),
                "--generated-triangles", "0", "--twin-triangles", "2000", "--warmup-seconds", "0", "--runs", "2");
        assertEquals(ExitCodes.OK, text.status, text::toString);
        assertTrue(text.out.contains("same character: .glb "), text::toString);
        assertTrue(text.out.contains("x our COLLADA import"), text::toString);
    }
}
