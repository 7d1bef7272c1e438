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
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.MarkerPattern;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.SceneOptions;
import org.skinlab.internal.synthetic.SyntheticCamera;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ar.DemoVideo;
import org.skinlab.desktop.ar.GrayImages;
import org.skinlab.desktop.ar.IntrinsicsFile;

/**
 * {@code skinlab track} on synthetic frames of known pose written as PNG: the JSON has one entry per
 * image in name order, the markers' ids, corners (within 0.3 px of their projections: the
 * tracker's corner accuracy, FiducialTrackerTest, plus PNG's rounding to whole gray levels), R and
 * t (within 2 mm at 0.4-0.7 m), and empty detections where there is no marker.
 */
class TrackCommandTest {
    private static final CameraIntrinsics K = new CameraIntrinsics(640, 480, 560, 560, 319.5, 239.5);

    @Test
    void writesTheStableJsonFormat(@TempDir Path dir) throws Exception {
        Path frames = Files.createDirectories(dir.resolve("frames"));
        SyntheticCamera camera = new SyntheticCamera(K);
        PlacedMarker a = PlacedMarker.of(MarkerPattern.of(MarkerDictionary.DEFAULT, 5), 0.1,
                PlacedMarker.facingCamera(30, -10, 20), new double[] {0.02, -0.03, 0.5});
        PlacedMarker b = PlacedMarker.of(MarkerPattern.of(MarkerDictionary.DEFAULT, 77), 0.1,
                PlacedMarker.facingCamera(-20, 35, -60), new double[] {-0.05, 0.04, 0.7});
        GrayImages.writePng(camera.render(List.of(a), SceneOptions.camera(1)), frames.resolve("f001.png"));
        GrayImages.writePng(camera.render(List.of(), SceneOptions.camera(2).withClutter(6)), frames.resolve("f002.png"));
        GrayImages.writePng(camera.render(List.of(b), SceneOptions.camera(3)), frames.resolve("f003.png"));
        Files.writeString(frames.resolve("notes.txt"), "not an image");
        Path intrinsics = dir.resolve("k.json");
        IntrinsicsFile.write(K, intrinsics);
        Path out = dir.resolve("out/track.json");
        Cli cli = Cli.run("track", "--images", frames.toString(), "--intrinsics", intrinsics.toString(),
                "--marker-size", "100", "--json", out.toString());
        assertEquals(0, cli.status, cli.toString());
        JsonNode root = new ObjectMapper().readTree(Files.readString(out));
        assertEquals(List.of("frames"), Cli.keys(root));
        JsonNode list = root.get("frames");
        assertEquals(3, list.size());
        assertEquals("f001.png", list.get(0).get("frame").asText());
        assertEquals("f002.png", list.get(1).get("frame").asText());
        assertEquals(0, list.get(1).get("detections").size(), "no marker, empty detections");
        assertEquals(List.of("frame", "millis", "detections"), Cli.keys(list.get(0)));
        check(camera, a, list.get(0).get("detections"));
        check(camera, b, list.get(2).get("detections"));
    }

    private static void check(SyntheticCamera camera, PlacedMarker m, JsonNode detections) {
        assertEquals(1, detections.size());
        JsonNode d = detections.get(0);
        assertEquals(List.of("id", "corners", "R", "t"), Cli.keys(d));
        assertEquals(m.pattern().id(), d.get("id").asInt());
        double[] truth = camera.projectCorners(m);
        for (int i = 0; i < 4; i++) {
            assertEquals(truth[2 * i], d.get("corners").get(i).get(0).asDouble(), 0.3, "corner " + i + " x");
            assertEquals(truth[2 * i + 1], d.get("corners").get(i).get(1).asDouble(), 0.3, "corner " + i + " y");
        }
        double[] t = m.translation();
        for (int i = 0; i < 3; i++) {
            assertEquals(t[i], d.get("t").get(i).asDouble(), 0.002, "t " + i);
        }
        double[] r = m.rotation();
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 3; col++) {
                assertEquals(r[3 * row + col], d.get("R").get(row).get(col).asDouble(), 0.01, "R " + row + col);
            }
        }
    }

    /**
     * {@code --sequence} on the synthetic demo video (DemoVideo: one marker circled by a hand-held
     * camera, a loop in 16 frames, so up to 60 px a frame) finds in every frame the markers the
     * whole-image search finds, corners within 0.05 px (FiducialTrackerVideoTest's tolerance: the
     * same BoofCV edge fit on a differently thresholded region); and it really is the video search:
     * a second marker coming into view far from the first is not looked for until the next
     * whole-frame pass, where the whole-image search finds it at once.
     */
    @Test
    void sequenceFindsTheWholeImageDetectionsOnAVideo(@TempDir Path dir) throws Exception {
        Path frames = Files.createDirectories(dir.resolve("video"));
        DemoVideo video = new DemoVideo(K, 16);
        for (int i = 0; i < video.frames(); i++) {
            GrayImages.writePng(video.frame(i), frames.resolve(String.format("f%03d.png", i)));
        }
        Path intrinsics = dir.resolve("k.json");
        IntrinsicsFile.write(K, intrinsics);
        JsonNode whole = track(frames, intrinsics, false);
        JsonNode sequence = track(frames, intrinsics, true);
        assertEquals(video.frames(), sequence.size());
        for (int i = 0; i < video.frames(); i++) {
            JsonNode a = whole.get(i).get("detections");
            JsonNode b = sequence.get(i).get("detections");
            assertEquals(whole.get(i).get("frame"), sequence.get(i).get("frame"));
            assertEquals(1, a.size(), "frame " + i + ": the whole-image search");
            assertEquals(a.size(), b.size(), "frame " + i);
            assertEquals(a.get(0).get("id"), b.get(0).get("id"), "frame " + i);
            for (int c = 0; c < 4; c++) {
                for (int xy = 0; xy < 2; xy++) {
                    assertEquals(a.get(0).get("corners").get(c).get(xy).asDouble(),
                            b.get(0).get("corners").get(c).get(xy).asDouble(), 0.05, "frame " + i + " corner " + c);
                }
            }
        }

        Path arrival = Files.createDirectories(dir.resolve("arrival"));
        SyntheticCamera camera = new SyntheticCamera(K);
        PlacedMarker near = PlacedMarker.of(MarkerPattern.of(MarkerDictionary.DEFAULT, 5), 0.1,
                PlacedMarker.facingCamera(20, 0, 0), new double[] {-0.15, -0.1, 0.6});
        PlacedMarker far = PlacedMarker.of(MarkerPattern.of(MarkerDictionary.DEFAULT, 9), 0.1,
                PlacedMarker.facingCamera(20, 0, 0), new double[] {0.15, 0.1, 0.6});
        for (int i = 0; i < 4; i++) {
            List<PlacedMarker> markers = i < 2 ? List.of(near) : List.of(near, far);
            GrayImages.writePng(camera.render(markers, SceneOptions.camera(10 + i)), arrival.resolve("f" + i + ".png"));
        }
        JsonNode all = track(arrival, intrinsics, false);
        JsonNode first = track(arrival, intrinsics, true);
        assertEquals(2, all.get(3).get("detections").size(), "the whole-image search sees both");
        assertEquals(1, first.get(3).get("detections").size(), "the video search looks near marker 5 only");
        assertEquals(5, first.get(3).get("detections").get(0).get("id").asInt());
    }

    private static JsonNode track(Path frames, Path intrinsics, boolean sequence) throws Exception {
        Path out = frames.resolveSibling(frames.getFileName() + (sequence ? "-sequence.json" : "-whole.json"));
        List<String> args = new java.util.ArrayList<>(List.of("track", "--images", frames.toString(), "--intrinsics",
                intrinsics.toString(), "--marker-size", "100", "--json", out.toString()));
        if (sequence) {
            args.add("--sequence");
        }
        Cli cli = Cli.run(args.toArray(new String[0]));
        assertEquals(0, cli.status, cli.toString());
        return new ObjectMapper().readTree(Files.readString(out)).get("frames");
    }

    @Test
    void badInputsAreNamed(@TempDir Path dir) throws Exception {
        Path frames = Files.createDirectories(dir.resolve("frames"));
        Path k = dir.resolve("k.json");
        Files.writeString(k, "{\"width\": 640, \"height\": 480, \"fx\": 500, \"fy\": 500, \"cx\": 320}");
        Cli empty = Cli.run("track", "--images", frames.toString(), "--intrinsics", k.toString(), "--marker-size",
                "100", "--json", "-");
        assertEquals(ExitCodes.USAGE, empty.status);
        assertTrue(empty.err.contains("no images"), empty.toString());
        GrayImages.writePng(new SyntheticCamera(new CameraIntrinsics(400, 400, 400, 400, 200, 200))
                .render(List.of(), SceneOptions.clean(1)), frames.resolve("square.png"));
        Cli missing = Cli.run("track", "--images", frames.toString(), "--intrinsics", k.toString(), "--marker-size",
                "100", "--json", "-");
        assertEquals(ExitCodes.USAGE, missing.status);
        assertTrue(missing.err.contains("k.json") && missing.err.contains("\"cy\" missing"), missing.toString());
        IntrinsicsFile.write(K, k);
        Cli aspect = Cli.run("track", "--images", frames.toString(), "--intrinsics", k.toString(), "--marker-size",
                "100", "--json", "-");
        assertEquals(ExitCodes.INVALID_FILE, aspect.status);
        assertTrue(aspect.err.contains("square.png") && aspect.err.contains("400x400"), aspect.toString());
        Files.writeString(frames.resolve("broken.png"), "no png");
        Cli broken = Cli.run("track", "--images", frames.toString(), "--marker-size", "100", "--json", "-");
        assertEquals(ExitCodes.INVALID_FILE, broken.status);
        assertTrue(broken.err.contains("broken.png"), broken.toString());
        // A PNG cut short: ImageIO's own message names no file; ours does.
        Files.delete(frames.resolve("broken.png"));
        byte[] png = Files.readAllBytes(frames.resolve("square.png"));
        Files.write(frames.resolve("cut.png"), java.util.Arrays.copyOf(png, png.length / 2));
        Cli cut = Cli.run("track", "--images", frames.toString(), "--marker-size", "100", "--json", "-");
        assertEquals(ExitCodes.INVALID_FILE, cut.status);
        assertTrue(cut.err.contains("cut.png"), cut.toString());
        Files.delete(frames.resolve("cut.png"));
        // Intrinsics files: text after the object, bytes that are not UTF-8, a side beyond any camera.
        String[][] badIntrinsics = {
            {"{\"width\": 400, \"height\": 400, \"fx\": 400, \"fy\": 400, \"cx\": 200, \"cy\": 200} x", "not JSON"},
            {"{\"width\": 1e10, \"height\": 400, \"fx\": 400, \"fy\": 400, \"cx\": 200, \"cy\": 200}", "\"width\""},
        };
        for (String[] bad : badIntrinsics) {
            Files.writeString(k, bad[0]);
            Cli r = Cli.run("track", "--images", frames.toString(), "--intrinsics", k.toString(), "--marker-size",
                    "100", "--json", "-");
            assertEquals(ExitCodes.USAGE, r.status, r::toString);
            assertTrue(r.err.contains("k.json") && r.err.contains(bad[1]), r.toString());
        }
        Files.write(k, new byte[] {'{', '"', (byte) 0xff, (byte) 0xfe, '"', ':', '1', '}'});
        Cli latin = Cli.run("track", "--images", frames.toString(), "--intrinsics", k.toString(), "--marker-size", "100",
                "--json", "-");
        assertEquals(ExitCodes.USAGE, latin.status, latin::toString);
        assertTrue(latin.err.contains("k.json: not JSON"), latin.toString());
        IntrinsicsFile.write(K, k);
        Cli dictionary = Cli.run("track", "--images", frames.toString(), "--marker-size", "100", "--dictionary", "x",
                "--json", "-");
        assertEquals(ExitCodes.USAGE, dictionary.status);
        assertTrue(dictionary.err.contains("aruco_mip_36h12"), dictionary.toString());
    }
}
