package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.bench.RenderBench;
import org.skinlab.desktop.render.GlTestDisplay;

/** The thesis' figure's shape: six series (CPU and GPU; LBS, DQS, CoR) over the instance steps, each point measured. */
class RenderBenchCommandTest {
    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    @Test
    void instanceSteps() {
        assertEquals(List.of(1, 4, 8, 12, 16, 24, 32, 40, 48, 56, 64, 80, 96), RenderBench.steps(100));
        assertEquals(List.of(1), RenderBench.steps(3));
    }

    @Test
    void sixSeriesOfMeasuredPoints(@TempDir Path dir) throws Exception {
        Path json = dir.resolve("render.json");
        Cli r = Cli.run("bench-render", "--size", "160x120", "--seconds", "0.1", "--max-instances", "4", "--min-fps", "0",
                "--json", json.toString());
        assertEquals(0, r.status, r::toString);
        JsonNode points = new ObjectMapper().readTree(json.toFile()).get("points");
        assertEquals(12, points.size(), r::toString);
        for (JsonNode p : points) {
            assertTrue(p.get("fps").asDouble() > 0, p::toString);
            assertTrue(List.of("cpu", "gpu").contains(p.get("skinning").asText()), p::toString);
        }
        // CPU then GPU; LBS, DQS, CoR; 1 and 4 copies each.
        assertEquals("gpu", points.get(11).get("skinning").asText());
        assertEquals("cor", points.get(11).get("method").asText());
        assertEquals(4, points.get(11).get("instances").asInt());
        assertTrue(r.out.contains("instances") && r.out.contains("bytes/frame"), r::toString);
    }
}
