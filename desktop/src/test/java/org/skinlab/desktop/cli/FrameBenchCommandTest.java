package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinnedGeometry;

/** {@code skinlab bench frame}: JSON keys and values on the default asset, with tiny timings. */
class FrameBenchCommandTest {
    @Test
    void jsonReportsTheCharacterAndFrameTimes() throws Exception {
        Model model = ColladaImporter.read(Cli.defaultAsset());
        // Expected sizes computed here from the model, independently of the command.
        int points = model.instances().stream().mapToInt(i -> SkinnedGeometry.of(i).pointCount()).sum();
        int joints = model.instances().stream().mapToInt(i -> SkinnedGeometry.of(i).jointCount()).sum();
        for (String method : new String[] {"lbs", "dqs"}) {
            Cli r = Cli.run("bench", "frame", Cli.defaultAsset().toString(), "--method", method, "--warmup-seconds",
                    "0", "--seconds", "0", "--json");
            assertEquals(ExitCodes.OK, r.status, r::toString);
            JsonNode root = new ObjectMapper().readTree(r.out);
            assertEquals(List.of("benchmark", "file", "method", "normals", "points", "joints", "frames",
                    "minMicrosPerFrame", "medianMicrosPerFrame", "implementation"), Cli.keys(root));
            assertEquals("frame", root.get("benchmark").asText());
            assertEquals("humanoid-walk.dae", root.get("file").asText());
            assertEquals(method, root.get("method").asText());
            assertEquals("exact", root.get("normals").asText());
            assertEquals(points, root.get("points").intValue());
            assertEquals(joints, root.get("joints").intValue());
            assertTrue(root.get("frames").intValue() >= 5, r::toString);
            double min = root.get("minMicrosPerFrame").doubleValue();
            assertTrue(min > 0 && min <= root.get("medianMicrosPerFrame").doubleValue(), r::toString);
            assertEquals("vector-256", root.get("implementation").asText());
        }
    }

    @Test
    void missingFileAndBadMethodAreUsageErrors() {
        Cli r = Cli.run("bench", "frame", "no-such-file.dae", "--seconds", "0");
        assertEquals(ExitCodes.USAGE, r.status, r::toString);
        assertEquals("skinlab: file not found: no-such-file.dae", r.errLines()[0]);
        r = Cli.run("bench", "frame", Cli.defaultAsset().toString(), "--method", "xyz");
        assertEquals(ExitCodes.USAGE, r.status, r::toString);
        assertEquals(1, r.errLines().length, r::toString);
    }
}
