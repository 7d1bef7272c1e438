package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ar.DemoVideo;
import org.skinlab.desktop.ar.GrayImages;
import org.skinlab.desktop.ar.IntrinsicsFile;
import org.skinlab.desktop.bench.ArFrameChecks;
import org.skinlab.desktop.bench.RenderBench;
import org.skinlab.desktop.render.GlTestDisplay;

/**
 * {@code skinlab bench ar-frame}: the stages of an AR frame, timed in every frame of every run, on
 * the synthetic demo video encoded to an MP4 (so decoding is JCodec's H.264 decoder at work) and
 * on an image folder. The times are not judged (benchmarks judge speed); their bookkeeping is: five
 * runs of each variant, a run's stages adding up to its frame time within the rounding of the
 * stored values (6 x 0.0005 ms), the medians likewise, the work each stage must have done (a
 * decode, a search, a draw in every run; a CPU skin only where the CPU skins), the marker found and
 * the model drawn in every frame of the demo video, and the renderer named.
 */
class ArFrameBenchCommandTest {
    @Test
    void theDemoVideoTimedPerStageForEachMethodAndSkinning(@TempDir Path dir) throws Exception {
        GlTestDisplay.assume();
        Path json = dir.resolve("ar-frame.json");
        Cli r = Cli.run("bench", "ar-frame", "--demo-frames", "4", "--method", "lbs,dqs", "--skinning", "both",
                "--runs", "5", "--warmup-seconds", "0", "--json", json.toString());
        assertEquals(0, r.status, r::toString);
        JsonNode doc = new ObjectMapper().readTree(json.toFile());
        assertTrue(doc.get("source").asText().contains("synthetic demo video"), doc.get("source").asText());
        assertEquals(640, doc.get("width").asInt());
        assertEquals(4, doc.get("framesPerRun").asInt(), "every frame of the video once");
        assertEquals(5, doc.get("runs").asInt());
        List<String> keys = new ArrayList<>();
        doc.get("variants").forEach(v -> keys.add(v.get("key").asText()));
        assertEquals(List.of("lbs-cpu", "lbs-gpu", "dqs-cpu", "dqs-gpu"), keys);
        ArFrameChecks.bookkeeping(doc);
        for (JsonNode v : doc.get("variants")) {
            for (JsonNode shown : v.get("modelFrames")) {
                assertEquals(4, shown.asInt(), "the demo marker is found and the model drawn in every frame: " + v);
            }
        }
        String renderer = doc.get("renderer").asText();
        assertTrue(!renderer.isBlank() && r.out.contains("renderer: " + renderer), r.out);
        assertEquals(RenderBench.isSoftware(renderer), doc.get("softwareRenderer").asBoolean());
        if (RenderBench.isSoftware(renderer)) {
            assertTrue(r.out.contains("software rasteriser on the CPU") && !r.out.contains("on the GPU"), r.out);
        }
        assertTrue(r.out.contains("| decode |") && r.out.contains("of 16.7 ms (60 Hz)"), r.out);
    }

    @Test
    void anImageFolderThroughItsCamera(@TempDir Path dir) throws Exception {
        GlTestDisplay.assume();
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(320, 240, 60);
        DemoVideo video = new DemoVideo(k, 3);
        Path frames = Files.createDirectories(dir.resolve("frames"));
        for (int i = 0; i < 3; i++) {
            GrayImages.writePng(video.frame(i), frames.resolve("f" + i + ".png"));
        }
        Path intrinsics = dir.resolve("k.json");
        IntrinsicsFile.write(k, intrinsics);
        Cli r = Cli.run("bench", "ar-frame", "--images", frames.toString(), "--intrinsics", intrinsics.toString(),
                "--skinning", "cpu", "--runs", "6", "--warmup-seconds", "0", "--json", "-");
        assertEquals(0, r.status, r::toString);
        JsonNode doc = new ObjectMapper().readTree(r.out.substring(r.out.indexOf("{\n")));
        assertTrue(doc.get("source").asText().startsWith("3 images of frames (320x240"), doc.get("source").asText());
        assertEquals(6, doc.get("runs").asInt());
        assertEquals(1, doc.get("variants").size());
        ArFrameChecks.bookkeeping(doc);
        assertEquals(3, doc.at("/variants/0/modelFrames/0").asInt(), doc.toString());
    }

    @Test
    void badOptionsAndFilesAreNamed(@TempDir Path dir) throws Exception {
        Cli fewRuns = Cli.run("bench", "ar-frame", "--runs", "4");
        assertEquals(ExitCodes.USAGE, fewRuns.status, fewRuns::toString);
        assertTrue(fewRuns.err.contains("--runs must be at least 5"), fewRuns::toString);
        Cli missing = Cli.run("bench", "ar-frame", "--video", dir.resolve("none.mp4").toString());
        assertEquals(ExitCodes.USAGE, missing.status, missing::toString);
        assertTrue(missing.err.contains("none.mp4"), missing::toString);
        Cli noSource = Cli.run("bench", "ar-frame", "--intrinsics", dir.resolve("k.json").toString());
        assertEquals(ExitCodes.USAGE, noSource.status, noSource::toString);
        Cli where = Cli.run("bench", "ar-frame", "--skinning", "tpu");
        assertEquals(ExitCodes.USAGE, where.status, where::toString);
        Path junk = dir.resolve("junk.mp4");
        Files.writeString(junk, "not a video");
        Cli bad = Cli.run("bench", "ar-frame", "--video", junk.toString());
        assertEquals(ExitCodes.INVALID_FILE, bad.status, bad::toString);
        assertTrue(bad.err.contains("junk.mp4") && bad.errLines().length == 1, bad::toString);
    }
}
