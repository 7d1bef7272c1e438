package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;

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
