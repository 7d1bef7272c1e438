package org.skinlab.desktop.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.LensDistortion;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.MarkerPattern;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.SceneOptions;
import org.skinlab.internal.synthetic.SyntheticCamera;
import org.skinlab.desktop.ar.GrayImages;
import org.skinlab.desktop.ar.IntrinsicsFile;
import org.skinlab.desktop.render.GlTestDisplay;

/**
 * {@code skinlab ar} through a strong webcam lens (DistortedTrackingTest's): one frame with the
 * marker in the image's upper-left part, where the lens bends its edges, shown at the camera's own
 * size under Xvfb (Mesa's llvmpipe). The background must be the ideal pinhole image (the shader's
 * lens.glsl): the marker's edges lie on the straight lines between the pinhole projections of its
 * corners (in the frame itself they bow, and lie pixels away from those lines). The model, drawn
 * with the pinhole projection from the pose tracked through the lens, stands on the marker as
 * ArWindowTest asks of an ideal camera: near the pinhole projection of the marker's centre and
 * inside the box over it.
 */
class ArLensWindowTest {
    static final CameraIntrinsics K = new CameraIntrinsics(640, 480, 520, 521, 322.3, 236.9,
            new LensDistortion(-0.32, 0.12, -0.02, 0.0012, -0.0008));
    /** The ideal camera the background and the model are drawn with. */
    static final CameraIntrinsics PINHOLE = K.withDistortion(LensDistortion.NONE);
    /**
     * Largest distance (px) of the shown marker's edges from the pinhole's straight lines: the edge
     * is found to a few tenths of a pixel (blur 0.8 px, noise, bilinear sampling of the frame); a
     * lens left in the background moves them by several pixels.
     */
    static final double STRAIGHT = 0.75;

    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    @Test
    void theBackgroundIsThePinholeImageAndTheModelStandsOnTheMarker(@TempDir Path dir) throws Exception {
        double[] ray = new double[2];
        K.toNormalized(175, 150, ray);
        double d = 0.42;
        PlacedMarker m = PlacedMarker.of(MarkerPattern.of(MarkerDictionary.DEFAULT, 0), 0.10,
                PlacedMarker.facingCamera(-20, 10, 5), new double[] {ray[0] * d, ray[1] * d, d});
        SyntheticCamera camera = new SyntheticCamera(K);
        GrayImage frame = camera.render(List.of(m), SceneOptions.camera(3));
        Path frames = Files.createDirectories(dir.resolve("frames"));
        GrayImages.writePng(frame, frames.resolve("f.png"));
        Path intrinsics = dir.resolve("k.json");
        IntrinsicsFile.write(K, intrinsics);
        Path with = dir.resolve("with.png");
        Path without = dir.resolve("without.png");
        for (Object[] run : new Object[][] {{"0", with}, {"99", without}}) {
            ViewerWindowTest.Run r = ViewerWindowTest.skinlab("ar", "--images", frames.toString(), "--intrinsics",
                    intrinsics.toString(), "--id", (String) run[0], "--hide-ui", "--size", "640x480", "--screenshot",
                    run[1].toString());
            assertEquals(0, r.status(), r.toString());
        }
        BufferedImage shown = ImageIO.read(without.toFile());
        BufferedImage raw = GrayImages.toBufferedImage(frame);

        double[] pinholeCorners = new SyntheticCamera(PINHOLE).projectCorners(m);
        double[] shownOffsets = edgeOffsets(shown, pinholeCorners);
        double[] rawOffsets = edgeOffsets(raw, pinholeCorners);
        double[] rawBow = edgeOffsets(raw, camera.projectCorners(m));
        System.out.printf(Locale.ROOT, "marker edges from the pinhole's lines: shown %.2f px max (mean |.| %.2f);"
                + " in the frame %.1f px max; the frame's edges bow %.2f px from their chords%n", shownOffsets[0],
                shownOffsets[1], rawOffsets[0], rawBow[0]);
        assertTrue(shownOffsets[0] <= STRAIGHT, "shown edges off the pinhole's lines by " + shownOffsets[0] + " px");
        assertTrue(rawOffsets[0] >= 4, "the frame's edges are where the lens puts them: " + rawOffsets[0] + " px");
        assertTrue(rawBow[0] >= 1, "the frame's edges bow: " + rawBow[0] + " px");

        BufferedImage a = ImageIO.read(with.toFile());
        ArWindowTest.assertModelOverMarker(a, shown, K, m);
    }

    /**
     * Where the marker's black-to-white edge crosses the normals of the four sides from
     * {@code corners} (TL, TR, BR, BL), at 15%..85% along each side: {max |offset|, mean |offset|}
     * in pixels; an edge not found within 8 px counts as 8.
     */
    static double[] edgeOffsets(BufferedImage image, double[] corners) {
        double cx = (corners[0] + corners[2] + corners[4] + corners[6]) / 4;
        double cy = (corners[1] + corners[3] + corners[5] + corners[7]) / 4;
        double max = 0;
        double sum = 0;
        int n = 0;
        for (int side = 0; side < 4; side++) {
            double x0 = corners[2 * side], y0 = corners[2 * side + 1];
            double x1 = corners[2 * ((side + 1) % 4)], y1 = corners[2 * ((side + 1) % 4) + 1];
            double length = Math.hypot(x1 - x0, y1 - y0);
            double nx = (y1 - y0) / length, ny = -(x1 - x0) / length;
            // Outward: away from the square's centre.
            if (nx * ((x0 + x1) / 2 - cx) + ny * ((y0 + y1) / 2 - cy) < 0) {
                nx = -nx;
                ny = -ny;
            }
            for (double t = 0.15; t <= 0.851; t += 0.05) {
                double px = x0 + t * (x1 - x0), py = y0 + t * (y1 - y0);
                double offset = 8;
                double previous = gray(image, px - 8 * nx, py - 8 * ny);
                for (double s = -8 + 0.05; s <= 8; s += 0.05) {
                    double v = gray(image, px + s * nx, py + s * ny);
                    // Ink inside (25), paper outside (230): the first rise through their middle.
                    if (previous < 127.5 && v >= 127.5) {
                        offset = s - 0.05 * (v - 127.5) / (v - previous);
                        break;
                    }
                    previous = v;
                }
                max = Math.max(max, Math.abs(offset));
                sum += Math.abs(offset);
                n++;
            }
        }
        return new double[] {max, sum / n};
    }

    /** Bilinear gray level (the red channel) at pixel coordinates (x, y), pixel centres at integers. */
    private static double gray(BufferedImage image, double x, double y) {
        int ix = (int) Math.floor(x);
        int iy = (int) Math.floor(y);
        double fx = x - ix, fy = y - iy;
        double top = (1 - fx) * red(image, ix, iy) + fx * red(image, ix + 1, iy);
        double bottom = (1 - fx) * red(image, ix, iy + 1) + fx * red(image, ix + 1, iy + 1);
        return (1 - fy) * top + fy * bottom;
    }

    private static int red(BufferedImage image, int x, int y) {
        x = Math.max(0, Math.min(image.getWidth() - 1, x));
        y = Math.max(0, Math.min(image.getHeight() - 1, y));
        return image.getRGB(x, y) >> 16 & 0xFF;
    }
}
