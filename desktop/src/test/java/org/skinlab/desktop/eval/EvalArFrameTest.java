package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.bench.ArFrameChecks;
import org.skinlab.desktop.bench.RenderBench;

/**
 * {@code skinlab eval --quick}'s ar-frame section ({@link EvalQuickRun}, whose test checks that
 * every number of the report is one of results.json and that its figure is drawn): without a real
 * video it plays the synthetic one and says so; its timings are consistent (ArFrameChecks: at
 * least 5 runs each, stages adding up to the frame per run and in their medians, every stage at
 * work); the renderer is named, a software one as such; GPU skinning leaves nothing of the skin
 * stage. Speed is not judged here. Without a display the section is skipped with the reason, in
 * results.json and in the report.
 */
class EvalArFrameTest {
    @Test
    void quickArFrameIsConsistentAndNamesItsInputAndRenderer() {
        EvalQuickRun run = EvalQuickRun.get();
        JsonNode s = run.section("ar-frame");
        assertEquals("synthetic", s.get("input").asText(), "no --ar-video: the synthetic video");
        String section = run.readme.substring(run.readme.indexOf("## An AR frame, end to end\n"));
        section = section.substring(0, section.indexOf("\n## ", 4) < 0 ? section.length() : section.indexOf("\n## ", 4));
        if (s.has("skipped")) {
            assertTrue(section.contains("Skipped: `" + s.get("skipped").asText() + "`"), section);
            return;
        }
        assertTrue(section.contains("**The synthetic demo video**"), section);
        ArFrameChecks.bookkeeping(s);
        List<String> keys = new java.util.ArrayList<>();
        s.get("variants").forEach(v -> keys.add(v.get("key").asText()));
        assertEquals(List.of("lbs-cpu", "lbs-gpu"), keys);
        for (JsonNode v : s.get("variants")) {
            for (JsonNode shown : v.get("modelFrames")) {
                assertEquals(s.get("framesPerRun").asInt(), shown.asInt(), "the model on the marker in every frame: " + v);
            }
        }
        String renderer = s.get("renderer").asText();
        assertTrue(!renderer.isBlank() && section.contains("Renderer: `" + renderer + "`"), section);
        assertEquals(RenderBench.isSoftware(renderer), s.get("softwareRenderer").asBoolean(), renderer);
        if (s.get("softwareRenderer").asBoolean()) {
            assertTrue(section.contains("software rasteriser on the CPU, not a GPU"), section);
        }
        JsonNode pair = s.at("/gpuAgainstCpu/0");
        assertEquals(0, pair.get("skinGpuMs").asDouble(), 0, pair.toString());
        assertEquals(s.at("/variants/0/stages/skin/medianMs").asDouble(), pair.get("skinCpuMs").asDouble(), 0);
        assertTrue(EvalReportCheck.linked(run.readme).contains("ar-frame-stages.png"), run.readme);
        assertTrue(section.contains("| **stage medians summed** (share of " + EvalReport.format(s.get("budgetMs"))
                + " ms, 60 Hz) |"), section);
    }

    /** Run in a JVM of its own without DISPLAY and WAYLAND_DISPLAY: skipped, saying why, in both files. */
    @Test
    void withoutADisplayItIsSkippedWithTheReason(@TempDir Path dir) throws Exception {
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        ProcessBuilder pb = new ProcessBuilder(List.of(java.toString(), "-cp", System.getProperty("java.class.path"),
                "org.skinlab.desktop.cli.SkinlabMain", "eval", "--quick", "--only", "ar-frame", "--out", dir.toString()));
        pb.environment().remove("DISPLAY");
        pb.environment().remove("WAYLAND_DISPLAY");
        pb.redirectErrorStream(true);
        pb.directory(new File(System.getProperty("skinlab.root", "..")));
        Process p = pb.start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "eval did not end within two minutes");
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(0, p.exitValue(), output);
        JsonNode s = new ObjectMapper().readTree(dir.resolve("results.json").toFile()).at("/sections/ar-frame");
        String why = s.get("skipped").asText();
        assertTrue(why.startsWith("no display"), s.toString());
        assertTrue(Files.readString(dir.resolve("README.md")).contains("Skipped: `" + why + "`"), output);
        assertTrue(output.contains("ar-frame skipped: " + why), output);
    }
}
