package org.skinlab.desktop.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.LensDistortion;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.desktop.ar.DemoVideo;
import org.skinlab.desktop.ar.GrayImages;
import org.skinlab.desktop.ar.IntrinsicsFile;
import org.skinlab.desktop.render.GlTestDisplay;

/**
 * {@code skinlab ar} renders one frame of the demo video under Xvfb, once following marker 0 (the
 * model shown) and once following marker 99 (not in the frame: only the camera image), at the
 * camera's own size so that screen pixels are image pixels. The pixels that differ are the model's;
 * they must stand on the marker: some within 12 px of where the marker's centre projects (the
 * feet; the tracker's pose puts it within a pixel or two, the model's soles a few pixels around
 * it), and all inside the projection of the box the model can occupy on a 10 cm marker (1.5
 * marker widths tall, within a marker width of the centre, MarkerSceneTest), widened by 4 px.
 */
class ArWindowTest {
    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    @Test
    void theModelStandsOnTheMarker(@TempDir Path dir) throws Exception {
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(640, 480, 60);
        DemoVideo video = new DemoVideo(k, 120);
        int frame = 10;
        Path frames = Files.createDirectories(dir.resolve("frames"));
        GrayImages.writePng(video.frame(frame), frames.resolve("f.png"));
        Path intrinsics = dir.resolve("k.json");
        IntrinsicsFile.write(k, intrinsics);
        Path with = dir.resolve("with.png");
        Path without = dir.resolve("without.png");
        for (Object[] run : new Object[][] {{"0", with}, {"99", without}}) {
            ViewerWindowTest.Run r = ViewerWindowTest.skinlab("ar", "--images", frames.toString(), "--intrinsics",
                    intrinsics.toString(), "--id", (String) run[0], "--hide-ui", "--size", "640x480", "--screenshot",
                    run[1].toString());
            assertEquals(0, r.status(), r.toString());
        }
        BufferedImage a = ImageIO.read(with.toFile());
        BufferedImage b = ImageIO.read(without.toFile());
        assertEquals(640, a.getWidth());
        PlacedMarker m = video.marker(frame);
        assertModelOverMarker(a, b, k, m);
    }

    /**
     * The camera image in colour: a 320x240 frame of 8x8-pixel blocks of random colours over a
     * gradient, played through {@code skinlab ar --images} with the model off (following marker 99)
     * at the frame's own size, so that each screen pixel samples its image pixel's centre. Every
     * pixel of the picture, block edges included, is the frame's colour within 2 levels per
     * channel (the lens shader's float arithmetic may move a sample by a hair, never by a pixel:
     * a half-pixel shift would blend neighbouring blocks and miss by tens of levels). Its luminance
     * alone, the old gray background, misses the saturated colours by over 100 levels.
     */
    @Test
    void theBackgroundShowsTheFramesColours(@TempDir Path dir) throws Exception {
        int w = 320;
        int h = 240;
        BufferedImage frame = new BufferedImage(w, h, BufferedImage.TYPE_3BYTE_BGR);
        java.util.Random random = new java.util.Random(42);
        int[] blocks = new int[(w / 8) * (h / 8)];
        for (int i = 0; i < blocks.length; i++) {
            blocks[i] = random.nextInt(0x1000000);
        }
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int b = blocks[(y / 8) * (w / 8) + x / 8];
                // Every other block a smooth gradient, the rest flat random colours.
                int c = ((x / 8 + y / 8) % 2 == 0) ? (x * 255 / w) << 16 | (y * 255 / h) << 8 | 128 : b;
                frame.setRGB(x, y, c);
            }
        }
        Path frames = Files.createDirectories(dir.resolve("frames"));
        ImageIO.write(frame, "png", frames.resolve("colour.png").toFile());
        Path shot = dir.resolve("shot.png");
        ViewerWindowTest.Run r = ViewerWindowTest.skinlab("ar", "--images", frames.toString(), "--id", "99", "--hide-ui",
                "--size", w + "x" + h, "--screenshot", shot.toString());
        assertEquals(0, r.status(), r.toString());
        BufferedImage seen = ImageIO.read(shot.toFile());
        assertEquals(w, seen.getWidth());
        int worst = 0;
        int grayWorst = 0;
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int want = frame.getRGB(x, y);
                int got = seen.getRGB(x, y);
                int gray = (299 * (want >> 16 & 0xFF) + 587 * (want >> 8 & 0xFF) + 114 * (want & 0xFF) + 500) / 1000;
                for (int shift = 0; shift <= 16; shift += 8) {
                    worst = Math.max(worst, Math.abs((want >> shift & 0xFF) - (got >> shift & 0xFF)));
                    grayWorst = Math.max(grayWorst, Math.abs((want >> shift & 0xFF) - gray));
                }
            }
        }
        assertTrue(worst <= 2, "the background's colours are the frame's: worst channel " + worst + " levels off");
        assertTrue(grayWorst > 100, "the frame is colourful enough to tell: " + grayWorst);
    }

    /**
     * The model drawn in {@code with} (against {@code without}, the same frame with the model off)
     * stands on the marker: over 200 pixels change, none outside the screen box of |x|, |y| <= 0.1 m,
     * 0 <= z <= 0.155 m over the marker, and one within 12 px of its centre (the feet), projected by
     * {@code k} without its lens (the views draw the undistorted pinhole image).
     */
    static void assertModelOverMarker(BufferedImage with, BufferedImage without, CameraIntrinsics k, PlacedMarker m) {
        CameraIntrinsics pinhole = k.withDistortion(LensDistortion.NONE);
        double[] centre = project(pinhole, m, 0, 0, 0);
        double[] box = boxBounds(pinhole, m);
        int changed = 0;
        int outside = 0;
        double nearest = Double.POSITIVE_INFINITY;
        for (int y = 0; y < with.getHeight(); y++) {
            for (int x = 0; x < with.getWidth(); x++) {
                if (differs(with.getRGB(x, y), without.getRGB(x, y))) {
                    changed++;
                    if (x < box[0] - 4 || x > box[2] + 4 || y < box[1] - 4 || y > box[3] + 4) {
                        outside++;
                    }
                    nearest = Math.min(nearest, Math.hypot(x - centre[0], y - centre[1]));
                }
            }
        }
        assertTrue(changed > 200, "the model is drawn: " + changed + " pixels");
        assertEquals(0, outside, "model pixels outside the box over the marker " + java.util.Arrays.toString(box));
        assertTrue(nearest < 12, "the feet at the marker's centre " + java.util.Arrays.toString(centre) + ": " + nearest);
    }

    private static boolean differs(int p, int q) {
        int d = Math.abs((p >> 16 & 0xFF) - (q >> 16 & 0xFF)) + Math.abs((p >> 8 & 0xFF) - (q >> 8 & 0xFF))
                + Math.abs((p & 0xFF) - (q & 0xFF));
        return d > 24;
    }

    private static double[] project(CameraIntrinsics k, PlacedMarker m, double x, double y, double z) {
        double[] r = m.rotation();
        double[] t = m.translation();
        double cx = r[0] * x + r[1] * y + r[2] * z + t[0];
        double cy = r[3] * x + r[4] * y + r[5] * z + t[1];
        double cz = r[6] * x + r[7] * y + r[8] * z + t[2];
        double[] out = new double[2];
        k.toPixel(cx, cy, cz, out);
        return out;
    }

    /** The screen bounds (x0, y0, x1, y1) of the box |x|, |y| <= 0.1 m, 0 <= z <= 0.155 m over the marker. */
    private static double[] boxBounds(CameraIntrinsics k, PlacedMarker m) {
        double[] b = {Double.MAX_VALUE, Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (double x : new double[] {-0.1, 0.1}) {
            for (double y : new double[] {-0.1, 0.1}) {
                for (double z : new double[] {0, 0.155}) {
                    double[] p = project(k, m, x, y, z);
                    b[0] = Math.min(b[0], p[0]);
                    b[1] = Math.min(b[1], p[1]);
                    b[2] = Math.max(b[2], p[0]);
                    b[3] = Math.max(b[3], p[1]);
                }
            }
        }
        return b;
    }
}
