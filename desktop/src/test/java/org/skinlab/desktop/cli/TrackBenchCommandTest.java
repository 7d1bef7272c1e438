package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ar.DemoVideo;
import org.skinlab.desktop.ar.GrayImages;

/** {@code skinlab bench track} runs every contender on the same frames and reports them (no timing asserted). */
class TrackBenchCommandTest {
    @Test
    void reportsTheThreeContendersAndWhatTheyFound() throws Exception {
        Cli cli = Cli.run("bench", "track", "--frames", "6", "--seconds", "0.1", "--warmup-seconds", "0", "--json");
        assertEquals(0, cli.status, cli.toString());
        JsonNode o = new ObjectMapper().readTree(cli.out);
        assertEquals(6, o.get("frames").asInt());
        assertTrue(o.get("rounds").asInt() >= 5, "at least Rounds.MIN_RUNS");
        for (String f : new String[] {"boofcvDefaultMs", "detectMs", "trackMs"}) {
            assertTrue(o.get(f).asDouble() > 0, f);
        }
        // One marker in every frame: our tracker finds exactly it, in both modes.
        assertEquals(1.0, o.get("markersPerFrameDetect").asDouble(), 0);
        assertEquals(1.0, o.get("markersPerFrameTrack").asDouble(), 0);
        Cli bad = Cli.run("bench", "track", "--frames", "1");
        assertEquals(ExitCodes.USAGE, bad.status);
    }

    /**
     * On a folder of frames with BoofCV's intrinsic.yaml, resampled: every contender reports; our
     * two searches find the demo video's one marker in every frame; OpenCV, when python3 has cv2,
     * reads the same id (the codes handed to it are in its bit order), else the report says why.
     */
    @Test
    void framesFromAFolderWithBoofCvIntrinsicsAndOpenCvBeside(@TempDir Path dir) throws Exception {
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(640, 480, 60);
        DemoVideo video = new DemoVideo(k, 6);
        Path frames = Files.createDirectories(dir.resolve("frames"));
        for (int i = 0; i < video.frames(); i++) {
            GrayImages.writePng(video.frame(i), frames.resolve("f" + i + ".png"));
        }
        Path yaml = dir.resolve("intrinsic.yaml");
        Files.writeString(yaml, String.format(Locale.ROOT, "pinhole:\n  fx: %s\n  fy: %s\n  cx: %s\n  cy: %s\n"
                + "  width: 640\n  height: 480\n  skew: 0.0\nmodel: pinhole_radial_tangential\n"
                + "radial_tangential:\n  radial:\n  - 0.0\n  - 0.0\n  t1: 0.0\n  t2: 0.0\nversion: 0\n",
                k.fx(), k.fy(), k.cx() + 0.5, k.cy() + 0.5));
        Path script = Cli.root().resolve("bench/aruco_opencv.py");
        Cli cli = Cli.run("bench", "track", "--images", frames.toString(), "--intrinsics", yaml.toString(), "--size",
                "480x360", "--opencv-script", script.toString(), "--seconds", "0.1", "--warmup-seconds", "0", "--json");
        assertEquals(0, cli.status, cli.toString());
        JsonNode o = new ObjectMapper().readTree(cli.out);
        assertEquals(6, o.get("frames").asInt());
        assertEquals(480, o.get("width").asInt());
        assertEquals(360, o.get("height").asInt());
        assertEquals(1.0, o.get("detectMarkersPerFrame").asDouble(), 0);
        assertEquals(6, o.get("trackFramesWithDetectIds").asInt());
        if (o.has("opencvMs")) {
            assertTrue(o.get("opencvMs").asDouble() > 0);
            assertTrue(o.get("opencvFramesWithDetectIds").asInt() >= 4, o.toString());
        } else {
            assertTrue(o.get("opencv").asText().startsWith("not"), o.toString());
        }
        Cli badSize = Cli.run("bench", "track", "--images", frames.toString(), "--size", "480by360");
        assertEquals(ExitCodes.USAGE, badSize.status);
        assertTrue(badSize.err.contains("--size"), badSize.toString());
    }
}
