package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ar.CalibrationPhotos;
import org.skinlab.desktop.ar.GrayImages;

/**
 * {@code skinlab calibrate} end to end on a folder of PNG photos of the target
 * ({@link CalibrationPhotos}): the report names every file (found, not found and why, not an
 * image), and the written intrinsics file has the camera within 1% (fx, fy, k1) and the lens
 * terms; bad inputs fail with one line and their status.
 */
class CalibrateCommandTest {
    private static Path photos(Path dir, int... views) throws Exception {
        Path d = Files.createDirectories(dir);
        List<GrayImage> images = CalibrationPhotos.images();
        for (int v : views) {
            GrayImages.writePng(images.get(v), d.resolve(String.format("photo%02d.png", v)));
        }
        return d;
    }

    private static int[] all() {
        int[] v = new int[CalibrationPhotos.images().size()];
        for (int i = 0; i < v.length; i++) {
            v[i] = i;
        }
        return v;
    }

    @Test
    void calibratesAFolderAndWritesTheIntrinsicsFile(@TempDir Path dir) throws Exception {
        Path images = photos(dir.resolve("photos"), all());
        GrayImages.writePng(CalibrationPhotos.withoutTarget(), images.resolve("photo99-empty.png"));
        Files.writeString(images.resolve("photo98-broken.png"), "not a PNG");
        Files.writeString(images.resolve("notes.txt"), "not an image");
        Path out = dir.resolve("out/camera.json");
        Files.createDirectories(out.getParent());
        Cli cli = Cli.run("calibrate", "--images", images.toString(), "--out", out.toString());
        assertEquals(0, cli.status, cli.toString());
        assertTrue(cli.out.contains("photo00.png: found"), cli.out);
        assertTrue(cli.out.contains("photo98-broken.png: not used: "), cli.out);
        assertTrue(cli.out.contains("photo99-empty.png: not found: no board: "), cli.out);
        assertTrue(cli.out.contains("views: 14 of 16 images (640 x 480)"), cli.out);
        assertTrue(cli.out.contains("reprojection error (RMS per view): mean 0.0"), cli.out);
        assertFalse(cli.out.contains("warning"), cli.out);
        JsonNode k = new ObjectMapper().readTree(Files.readString(out));
        assertEquals(List.of("width", "height", "fx", "fy", "cx", "cy", "k1", "k2", "k3", "p1", "p2"), Cli.keys(k));
        CameraIntrinsics truth = CalibrationPhotos.CAMERA;
        assertEquals(640, k.get("width").asInt());
        assertEquals(480, k.get("height").asInt());
        assertEquals(truth.fx(), k.get("fx").asDouble(), 0.01 * truth.fx());
        assertEquals(truth.fy(), k.get("fy").asDouble(), 0.01 * truth.fy());
        assertEquals(truth.cx(), k.get("cx").asDouble(), 1.0);
        assertEquals(truth.cy(), k.get("cy").asDouble(), 1.0);
        assertEquals(truth.distortion().k1(), k.get("k1").asDouble(), 0.01 * Math.abs(truth.distortion().k1()));
        assertEquals(truth.distortion().k2(), k.get("k2").asDouble(), 0.05 * truth.distortion().k2());
        assertEquals(0, k.get("k3").asDouble());
        assertEquals(truth.distortion().p1(), k.get("p1").asDouble(), 2e-4);
        assertEquals(truth.distortion().p2(), k.get("p2").asDouble(), 2e-4);
    }

    @Test
    void fewViewsCalibrateWithAWarning(@TempDir Path dir) throws Exception {
        Path images = photos(dir, 2, 3, 4, 5, 10);
        Path out = dir.resolve("k.json");
        Cli cli = Cli.run("calibrate", "--images", images.toString(), "--out", out.toString());
        assertEquals(0, cli.status, cli.toString());
        assertTrue(cli.out.contains("warning: only 5 views of the target"), cli.out);
        assertTrue(Files.exists(out));
    }

    @Test
    void tooFewViewsAreRefused(@TempDir Path dir) throws Exception {
        Path images = photos(dir, 0, 1);
        GrayImages.writePng(CalibrationPhotos.withoutTarget(), images.resolve("x.png"));
        Path out = dir.resolve("k.json");
        Cli cli = Cli.run("calibrate", "--images", images.toString(), "--out", out.toString());
        assertEquals(ExitCodes.INVALID_FILE, cli.status, cli.toString());
        assertEquals(1, cli.errLines().length, cli.err);
        assertTrue(cli.err.contains(images.toString()) && cli.err.contains("is in 2 of 3 images")
                && cli.err.contains("at least 3"), cli.err);
        assertFalse(Files.exists(out));
    }

    @Test
    void imagesWithoutTheTargetAreRefusedAndSaidWhy(@TempDir Path dir) throws Exception {
        Path images = Files.createDirectories(dir.resolve("i"));
        GrayImages.writePng(CalibrationPhotos.withoutTarget(), images.resolve("a.png"));
        // The right photos, the wrong target: a 6 x 10 board is not the printed 7 x 10.
        GrayImages.writePng(CalibrationPhotos.images().get(0), images.resolve("b.png"));
        Cli cli = Cli.run("calibrate", "--images", images.toString(), "--rows", "6", "--out", dir.resolve("k.json").toString());
        assertEquals(ExitCodes.INVALID_FILE, cli.status, cli.toString());
        assertTrue(cli.out.contains("a.png: not found: no board: "), cli.out);
        assertTrue(cli.out.contains("b.png: not found: saw a chessboard of 6 x 9 inner corners, expected 5 x 9"), cli.out);
        assertTrue(cli.err.contains("is in 0 of 2 images"), cli.err);
    }

    @Test
    void anEmptyOrMissingFolderIsAUsageError(@TempDir Path dir) throws Exception {
        Path empty = Files.createDirectories(dir.resolve("empty"));
        Cli cli = Cli.run("calibrate", "--images", empty.toString(), "--out", dir.resolve("k.json").toString());
        assertEquals(ExitCodes.USAGE, cli.status, cli.toString());
        assertTrue(cli.err.startsWith("skinlab: " + empty + ": no images"), cli.err);
        Cli missing = Cli.run("calibrate", "--images", dir.resolve("nope").toString(), "--out", "k.json");
        assertEquals(ExitCodes.USAGE, missing.status, missing.toString());
        assertTrue(missing.err.contains("not a folder"), missing.err);
        Cli noOut = Cli.run("calibrate", "--images", empty.toString());
        assertEquals(ExitCodes.USAGE, noOut.status, noOut.toString());
        Cli badTarget = Cli.run("calibrate", "--images", empty.toString(), "--target", "circles", "--out", "k.json");
        assertEquals(ExitCodes.USAGE, badTarget.status, badTarget.toString());
        assertTrue(badTarget.err.contains("unknown calibration target \"circles\""), badTarget.err);
    }

    @Test
    void withoutAWebcamSaysSoInOneLine(@TempDir Path dir) {
        Cli cli = Cli.run("calibrate", "--webcam", "--out", dir.resolve("k.json").toString());
        org.junit.jupiter.api.Assumptions.assumeTrue(cli.status != 0, "a webcam is attached here");
        assertEquals(ExitCodes.UNAVAILABLE, cli.status, cli.toString());
        assertEquals(1, cli.errLines().length, cli.err);
        assertTrue(cli.err.startsWith("skinlab: no webcam found") && !cli.err.contains("--video"), cli.err);
    }

    @Test
    void theTargetCommandWritesThePageAndNamesTheOptions(@TempDir Path dir) throws Exception {
        Path pdf = dir.resolve("t.pdf");
        Cli cli = Cli.run("calibration-target", "--target", "grid", "--pdf", pdf.toString());
        assertEquals(0, cli.status, cli.toString());
        assertTrue(Files.size(pdf) > 0);
        assertTrue(cli.out.contains("grid, 5 x 7 squares of 20 mm, 10 mm apart")
                && cli.out.contains("--target grid --rows 5 --cols 7 --square-mm 20 --space-mm 10"), cli.out);
        assertEquals(ExitCodes.USAGE, Cli.run("calibration-target").status);
        Cli small = Cli.run("calibration-target", "--rows", "2", "--pdf", pdf.toString());
        assertEquals(ExitCodes.USAGE, small.status, small.toString());
        assertTrue(small.err.contains("3 to 40 rows"), small.err);
        Cli space = Cli.run("calibration-target", "--space-mm", "5", "--pdf", pdf.toString());
        assertEquals(ExitCodes.USAGE, space.status, space.toString());
        Cli big = Cli.run("calibration-target", "--square-mm", "40", "--pdf", pdf.toString());
        assertEquals(ExitCodes.USAGE, big.status, big.toString());
        assertTrue(big.err.contains("A4 page holds at most"), big.err);
    }
}
