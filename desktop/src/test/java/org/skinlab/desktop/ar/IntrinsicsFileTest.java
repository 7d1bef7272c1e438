package org.skinlab.desktop.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

import boofcv.struct.calib.CameraPinholeBrown;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.ar.BoofCameras;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.LensDistortion;

/**
 * {@link IntrinsicsFile#read} on each format it accepts, in each format's real layout: ours (JSON),
 * files OpenCV 5.0.0's {@code cv2.FileStorage} wrote (test resources, see their README), OpenCV
 * 4's {@code %YAML:1.0} layout and BoofCV's {@code CalibrationIO} layout written here, and bad
 * input of each.
 */
class IntrinsicsFileTest {
    private static final LensDistortion WEBCAM = new LensDistortion(-0.32, 0.12, -0.02, 0.0012, -0.0008);

    @TempDir
    Path dir;

    @Test
    void jsonRoundTripKeepsTheLensAndOmitsAnIdealOne() throws IOException {
        CameraIntrinsics k = new CameraIntrinsics(640, 480, 520, 518, 319.5, 241.25, WEBCAM);
        Path file = dir.resolve("k.json");
        IntrinsicsFile.write(k, file);
        assertEquals(k, IntrinsicsFile.read(file));
        CameraIntrinsics pinhole = new CameraIntrinsics(640, 480, 520, 518, 319.5, 241.25);
        IntrinsicsFile.write(pinhole, file);
        assertFalse(Files.readString(file).contains("k1"), "an ideal lens writes no terms");
        assertEquals(pinhole, IntrinsicsFile.read(file));
    }

    @Test
    void jsonLensTermsAreOptionalAndChecked() throws IOException {
        Path file = write("k.json", "{\"width\":640,\"height\":480,\"fx\":500,\"fy\":500,\"cx\":320,\"cy\":240,"
                + "\"k1\":-0.1,\"p2\":0.001}");
        assertEquals(new LensDistortion(-0.1, 0, 0, 0, 0.001), IntrinsicsFile.read(file).distortion());
        Path bad = write("bad.json", "{\"width\":640,\"height\":480,\"fx\":500,\"fy\":500,\"cx\":320,\"cy\":240,"
                + "\"k2\":\"0.1\"}");
        assertMessage(bad, "field \"k2\" must be a finite number");
    }

    /** The pixels OpenCV's cv2.projectPoints gave for three points through the fixtures' camera (README). */
    @Test
    void openCvYamlAndXmlAsOpenCvWroteThemProjectAsOpenCvDoes() throws IOException {
        for (String name : new String[] {"opencv_calibration.yml", "opencv_calibration.xml"}) {
            CameraIntrinsics k = IntrinsicsFile.read(resource(name));
            assertEquals(new CameraIntrinsics(640, 480, 520, 518, 319.5, 241.25, WEBCAM), k, name);
            double[][] points = {{0.3, -0.2, 1.0}, {-0.5, 0.35, 1.2}, {0.01, 0.02, 0.8}};
            double[][] opencv = {{469.11607336, 141.93447538}, {118.69999893, 381.35514314},
                {325.99831048, 254.19776707}};
            double[] pixel = new double[2];
            for (int i = 0; i < points.length; i++) {
                k.toPixel(points[i][0], points[i][1], points[i][2], pixel);
                // OpenCV printed 8 decimals; its convention (pixel centres at integers) is ours.
                assertEquals(opencv[i][0], pixel[0], 1e-7, name + " point " + i + " u");
                assertEquals(opencv[i][1], pixel[1], 1e-7, name + " point " + i + " v");
            }
        }
    }

    @Test
    void openCv4YamlLayoutWithFourTermsReads() throws IOException {
        // OpenCV 4's FileStorage starts with its own "%YAML:1.0" directive.
        Path file = write("calib.yaml", "%YAML:1.0\n---\nimage_width: 1280\nimage_height: 720\n"
                + "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
                + "   data: [ 9.1e+02, 0., 6.395e+02, 0., 9.1e+02, 3.595e+02, 0., 0., 1. ]\n"
                + "distortion_coefficients: !!opencv-matrix\n   rows: 4\n   cols: 1\n   dt: d\n"
                + "   data: [ -1.5e-01, 4.0e-02, 1.0e-04, -2.0e-04 ]\n");
        assertEquals(new CameraIntrinsics(1280, 720, 910, 910, 639.5, 359.5,
                new LensDistortion(-0.15, 0.04, 0, 1e-4, -2e-4)), IntrinsicsFile.read(file));
    }

    @Test
    void longerOpenCvModelsReadWhenTheirExtraTermsAreZero() throws IOException {
        Path file = write("calib.xml", xml("<distortion_coefficients type_id=\"opencv-matrix\"><rows>1</rows>"
                + "<cols>8</cols><dt>d</dt><data>-0.1 0.02 0 0 0.003 0. 0. 0.</data></distortion_coefficients>"));
        assertEquals(new LensDistortion(-0.1, 0.02, 0.003, 0, 0), IntrinsicsFile.read(file).distortion());
        Path tilted = write("tilted.xml", xml("<distortion_coefficients type_id=\"opencv-matrix\"><rows>1</rows>"
                + "<cols>14</cols><dt>d</dt><data>-0.1 0.02 0 0 0.003 0 0 0 0 0 0 0 0.01 0</data>"
                + "</distortion_coefficients>"));
        assertMessage(tilted, "tilted-sensor model");
        assertMessage(resource("opencv_rational_model.yml"), "the rational model (k4, k5, k6) is not supported");
        Path seven = write("seven.xml", xml("<distortion_coefficients type_id=\"opencv-matrix\"><rows>1</rows>"
                + "<cols>7</cols><dt>d</dt><data>0 0 0 0 0 0 0</data></distortion_coefficients>"));
        assertMessage(seven, "<distortion_coefficients> has 7 terms");
    }

    @Test
    void openCvFilesWithoutAnImageSizeOrWithABadMatrixAreRefused() throws IOException {
        Path noSize = write("nosize.yml", "%YAML:1.0\n---\ncamera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n"
                + "   dt: d\n   data: [ 500., 0., 320., 0., 500., 240., 0., 0., 1. ]\n");
        assertMessage(noSize, "no image size");
        Path halfSize = write("half.xml", "<?xml version=\"1.0\"?>\n<opencv_storage>\n<image_width>640</image_width>\n"
                + "<camera_matrix type_id=\"opencv-matrix\"><rows>3</rows><cols>3</cols><dt>d</dt>"
                + "<data>500. 0. 320. 0. 500. 240. 0. 0. 1.</data></camera_matrix></opencv_storage>\n");
        assertMessage(halfSize, "image_height missing");
        Path short8 = write("short.yml", "%YAML:1.0\n---\nimage_width: 640\nimage_height: 480\n"
                + "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n   data: [ 500., 0., 320., 0. ]\n");
        assertMessage(short8, "camera_matrix is 3x3 but its data has 4 numbers");
        Path text = write("word.yml", "%YAML:1.0\n---\nimage_width: 640\nimage_height: 480\n"
                + "camera_matrix: !!opencv-matrix\n   rows: 3\n   cols: 3\n   dt: d\n"
                + "   data: [ 500., 0., 320., 0., five, 240., 0., 0., 1. ]\n");
        assertMessage(text, "camera_matrix.data[4] must be a number, is \"five\"");
        Path skew = write("skew.xml", xml("").replace("500. 0. 320.", "500. 3. 320."));
        assertMessage(skew, "skew 3.0");
    }

    @Test
    void xmlWithADoctypeIsRefusedWithoutReadingEntities() throws IOException {
        Path secret = write("secret.txt", "do not read me");
        Path file = write("xxe.xml", "<?xml version=\"1.0\"?>\n<!DOCTYPE opencv_storage [<!ENTITY x SYSTEM \""
                + secret.toUri() + "\">]>\n<opencv_storage><image_width>&x;</image_width></opencv_storage>\n");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> IntrinsicsFile.read(file));
        assertTrue(e.getMessage().startsWith(file.toString()) && e.getMessage().contains("DOCTYPE"), e.getMessage());
        assertFalse(e.getMessage().contains("do not read me"));
    }

    /** BoofCV's CalibrationIO layout (SnakeYAML block style, its comment header). */
    @Test
    void boofCvIntrinsicYamlReadsWithItsHalfPixelShift() throws IOException {
        Path file = write("intrinsic.yaml", boof("model: pinhole_radial_tangential", "skew: 0.0",
                "radial_tangential:\n  radial:\n  - -0.32\n  - 0.12\n  - -0.02\n  t1: 0.0012\n  t2: -0.0008\n"));
        CameraIntrinsics k = IntrinsicsFile.read(file);
        assertEquals(new CameraIntrinsics(640, 480, 520, 518, 319.5, 241.25, WEBCAM), k);
        CameraPinholeBrown c = new CameraPinholeBrown(520, 518, 0, 320, 241.75, 640, 480);
        c.fsetRadial(-0.32, 0.12, -0.02);
        c.fsetTangential(0.0012, -0.0008);
        assertEquals(BoofCameras.fromBoof(c), k, "what BoofCameras makes of BoofCV's own object");
        Path pinhole = write("pinhole.yaml", boof("model: pinhole", "skew: 0.0", ""));
        assertFalse(IntrinsicsFile.read(pinhole).isDistorted());
    }

    @Test
    void boofCvFilesBeyondOurModelAreRefused() throws IOException {
        assertMessage(write("skew.yaml", boof("model: pinhole", "skew: 2.5", "")), "skew 2.5");
        assertMessage(write("omni.yaml", boof("model: omnidirectional_universal", "skew: 0.0", "")),
                "model \"omnidirectional_universal\" is not supported");
        assertMessage(write("four.yaml", boof("model: pinhole_radial_tangential", "skew: 0.0",
                "radial_tangential:\n  radial: [0.1, 0.01, 0.001, 0.0001]\n  t1: 0.0\n  t2: 0.0\n")),
                "radial_tangential.radial has 4 terms");
        assertMessage(write("nofx.yaml", boof("model: pinhole", "skew: 0.0", "").replace("  fx: 520.0\n", "")),
                "pinhole.fx missing");
        assertMessage(write("broken.yaml", "model: [pinhole\n"), "not YAML");
    }

    @Test
    void theFormatIsToldByContentWhenTheNameDoesNotSay() throws IOException {
        Path json = write("camera.txt", "{\"width\":64,\"height\":48,\"fx\":50,\"fy\":50,\"cx\":32,\"cy\":24}");
        assertEquals(64, IntrinsicsFile.read(json).width());
        Path xml = write("camera.calib", xml(""));
        assertEquals(640, IntrinsicsFile.read(xml).width());
        Path boof = write("camera.cfg", boof("model: pinhole", "skew: 0.0", ""));
        assertEquals(640, IntrinsicsFile.read(boof).width());
        assertMessage(write("other.yml", "name: not a camera\n"), "not a camera calibration this program reads");
    }

    @Test
    void scalingToAStreamKeepsTheLensWhereItWas() throws IOException {
        CameraIntrinsics full = IntrinsicsFile.read(resource("opencv_calibration.yml"));
        CameraIntrinsics half = IntrinsicsFile.forImage(full, 320, 240, "frame");
        assertEquals(full.distortion(), half.distortion());
        double[] a = new double[2];
        double[] b = new double[2];
        full.toPixel(-0.4, 0.3, 1.0, a);
        half.toPixel(-0.4, 0.3, 1.0, b);
        // Pixel edges map to edges: (u + 0.5) halves.
        assertEquals((a[0] + 0.5) / 2 - 0.5, b[0], 1e-9);
        assertEquals((a[1] + 0.5) / 2 - 0.5, b[1], 1e-9);
    }

    /** An OpenCV XML file with a 640x480 camera; {@code extra} goes inside {@code <opencv_storage>}. */
    private static String xml(String extra) {
        return "<?xml version=\"1.0\"?>\n<opencv_storage>\n<image_width>640</image_width>\n"
                + "<image_height>480</image_height>\n<camera_matrix type_id=\"opencv-matrix\">\n  <rows>3</rows>\n"
                + "  <cols>3</cols>\n  <dt>d</dt>\n  <data>\n    500. 0. 320. 0. 500. 240. 0. 0. 1.</data></camera_matrix>\n"
                + extra + "\n</opencv_storage>\n";
    }

    /** BoofCV's intrinsic.yaml with the given model line, skew line and distortion block. */
    private static String boof(String model, String skew, String distortion) {
        return "# Pinhole camera model with radial and tangential distortion\n"
                + "# (fx,fy) = focal length, (cx,cy) = principle point, (width,height) = image shape\n"
                + "# radial = radial distortion, (t1,t2) = tangential distortion\n\n"
                + model + "\npinhole:\n  cx: 320.0\n  cy: 241.75\n  fx: 520.0\n  fy: 518.0\n  height: 480\n  "
                + skew + "\n  width: 640\n" + distortion + "version: 0\n";
    }

    private Path write(String name, String content) throws IOException {
        return Files.writeString(dir.resolve(name), content);
    }

    private Path resource(String name) throws IOException {
        Path file = dir.resolve(name);
        try (InputStream in = IntrinsicsFileTest.class.getResourceAsStream(name)) {
            Files.copy(in, file);
        }
        return file;
    }

    private static void assertMessage(Path file, String expected) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> IntrinsicsFile.read(file));
        assertTrue(e.getMessage().startsWith(file.toString()) && e.getMessage().contains(expected),
                "expected \"" + expected + "\" after the file name, got: " + e.getMessage());
    }
}
