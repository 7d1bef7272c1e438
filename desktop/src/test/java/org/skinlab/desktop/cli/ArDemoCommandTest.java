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
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.MarkerDetection;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ar.CameraImage;
import org.skinlab.desktop.ar.GrayImages;
import org.skinlab.desktop.ar.IntrinsicsFile;
import org.skinlab.desktop.ar.VideoFileSource;

/**
 * {@code skinlab ar-demo} writes frames, intrinsics and true poses that {@code skinlab track} reads
 * back: every frame's marker found, within 3 mm of its true position (0.35-0.75 m away at 320x240:
 * the marker 25-50 px wide, depth known to about 0.5%).
 */
class ArDemoCommandTest {
    @Test
    void theDemoVideoTracksToItsTruePoses(@TempDir Path dir) throws Exception {
        Path out = dir.resolve("demo");
        Cli demo = Cli.run("ar-demo", out.toString(), "--frames", "4", "--size", "320x240");
        assertEquals(0, demo.status, demo.toString());
        for (String f : new String[] {"frame-0000.png", "frame-0003.png", "intrinsics.json", "poses.json"}) {
            assertTrue(Files.isRegularFile(out.resolve(f)), f);
        }
        Path json = dir.resolve("track.json");
        Cli track = Cli.run("track", "--images", out.toString(), "--intrinsics", out.resolve("intrinsics.json").toString(),
                "--marker-size", "100", "--json", json.toString());
        assertEquals(0, track.status, track.toString());
        JsonNode found = new ObjectMapper().readTree(Files.readString(json)).get("frames");
        JsonNode truth = new ObjectMapper().readTree(Files.readString(out.resolve("poses.json"))).get("frames");
        assertEquals(4, found.size());
        for (int i = 0; i < 4; i++) {
            JsonNode d = found.get(i).get("detections");
            assertEquals(1, d.size(), "frame " + i);
            assertEquals(0, d.get(0).get("id").asInt());
            JsonNode real = truth.get(i).get("detections").get(0);
            for (int c = 0; c < 3; c++) {
                assertEquals(real.get("t").get(c).asDouble(), d.get(0).get("t").get(c).asDouble(), 0.003,
                        "frame " + i + " t" + c);
            }
            // The same format: the true corners where the tracker finds them (a 320x240 frame, blur and noise).
            for (int c = 0; c < 4; c++) {
                for (int xy = 0; xy < 2; xy++) {
                    assertEquals(real.get("corners").get(c).get(xy).asDouble(),
                            d.get(0).get("corners").get(c).get(xy).asDouble(), 0.5, "frame " + i + " corner " + c);
                }
            }
            assertTrue(found.get(i).has("millis") && !truth.get(i).has("millis"), "the truth took no time");
        }
        Cli bad = Cli.run("ar-demo", dir.resolve("x").toString(), "--size", "640by480");
        assertEquals(ExitCodes.USAGE, bad.status);
        assertTrue(bad.err.contains("WIDTHxHEIGHT"), bad.toString());
    }

    /**
     * With --mp4 the same frames are one H.264 video (BT.601, limited range; JCodec's encoder at its
     * default quality): decoded, its colour is the PNG frames' gray within a mean of 5 levels and
     * 16 levels at the 99th percentile (JCodec's rate control spends few bits on the predicted
     * frames: measured 2.3 and 7 on the first, 3.1 and 11 on the second) (the codec smooths the frames' noise, sigma 2-5 levels), and
     * the tracker finds the marker in its luminance at the true position within 3 mm, as in the PNGs.
     */
    @Test
    void theDemoVideoAsAnMp4(@TempDir Path dir) throws Exception {
        Path out = dir.resolve("demo");
        Cli demo = Cli.run("ar-demo", out.toString(), "--frames", "3", "--size", "320x240", "--mp4");
        assertEquals(0, demo.status, demo.toString());
        assertTrue(demo.out.contains("demo.mp4"), demo.out);
        CameraIntrinsics k = IntrinsicsFile.read(out.resolve("intrinsics.json"));
        JsonNode truth = new ObjectMapper().readTree(Files.readString(out.resolve("poses.json"))).get("frames");
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(0.1), k);
        try (VideoFileSource video = new VideoFileSource(out.resolve("demo.mp4"), 30)) {
            assertEquals(3, video.frameCount());
            CameraImage frame = new CameraImage(320, 240);
            for (int i = 0; i < 3; i++) {
                video.next(frame);
                GrayImage png = GrayImages.read(out.resolve(String.format("frame-%04d.png", i)));
                int[] errors = new int[320 * 240];
                double sum = 0;
                for (int p = 0; p < errors.length; p++) {
                    errors[p] = Math.abs((frame.rgb()[3 * p + 1] & 0xFF) - (png.pixels()[p] & 0xFF));
                    sum += errors[p];
                }
                java.util.Arrays.sort(errors);
                System.out.println("demo.mp4 frame " + i + ": mean " + sum / errors.length + " levels, 99th percentile "
                        + errors[(int) (0.99 * errors.length)]);
                assertTrue(sum / errors.length < 5, "frame " + i + " mean " + sum / errors.length);
                assertTrue(errors[(int) (0.99 * errors.length)] <= 16, "frame " + i);
                List<MarkerDetection> found = tracker.detect(frame.gray());
                assertEquals(1, found.size(), "frame " + i);
                JsonNode real = truth.get(i).get("detections").get(0);
                for (int c = 0; c < 3; c++) {
                    assertEquals(real.get("t").get(c).asDouble(), found.get(0).translation()[c], 0.003, "frame " + i);
                }
            }
        }
    }

    /** With --distortion the frames are filmed through the lens, intrinsics.json carries it, and the tracker, given it, finds the true poses. */
    @Test
    void aDistortedDemoVideoTracksToItsTruePosesWithItsIntrinsics(@TempDir Path dir) throws Exception {
        Path out = dir.resolve("demo");
        Cli demo = Cli.run("ar-demo", out.toString(), "--frames", "3", "--size", "320x240", "--distortion",
                "-0.32,0.12,-0.02,0.0012,-0.0008");
        assertEquals(0, demo.status, demo.toString());
        JsonNode k = new ObjectMapper().readTree(Files.readString(out.resolve("intrinsics.json")));
        assertEquals(-0.32, k.get("k1").asDouble(), 0);
        assertEquals(-0.0008, k.get("p2").asDouble(), 0);
        Path json = dir.resolve("track.json");
        Cli track = Cli.run("track", "--images", out.toString(), "--intrinsics", out.resolve("intrinsics.json").toString(),
                "--marker-size", "100", "--json", json.toString());
        assertEquals(0, track.status, track.toString());
        JsonNode found = new ObjectMapper().readTree(Files.readString(json)).get("frames");
        JsonNode truth = new ObjectMapper().readTree(Files.readString(out.resolve("poses.json"))).get("frames");
        for (int i = 0; i < 3; i++) {
            JsonNode d = found.get(i).get("detections");
            assertEquals(1, d.size(), "frame " + i);
            JsonNode real = truth.get(i).get("detections").get(0);
            for (int c = 0; c < 3; c++) {
                assertEquals(real.get("t").get(c).asDouble(), d.get(0).get("t").get(c).asDouble(), 0.003,
                        "frame " + i + " t" + c);
            }
            for (int c = 0; c < 4; c++) {
                for (int xy = 0; xy < 2; xy++) {
                    assertEquals(real.get("corners").get(c).get(xy).asDouble(),
                            d.get(0).get("corners").get(c).get(xy).asDouble(), 0.5, "frame " + i + " corner " + c);
                }
            }
        }
        Cli bad = Cli.run("ar-demo", dir.resolve("x").toString(), "--distortion", "-0.3,0.1");
        assertEquals(ExitCodes.USAGE, bad.status);
        assertTrue(bad.err.contains("--distortion must be five numbers"), bad.toString());
    }
}
