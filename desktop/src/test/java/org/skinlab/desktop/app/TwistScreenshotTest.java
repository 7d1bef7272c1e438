package org.skinlab.desktop.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.ByteBuffer;
import java.nio.IntBuffer;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.lwjgl.stb.STBImage;
import org.lwjgl.system.MemoryStack;
import org.skinlab.desktop.render.GlTestDisplay;

/**
 * The thesis' comparison as pictures: the twist cylinder at 172 degrees (assets/README.md),
 * rendered by {@code skinlab view --screenshot} with LBS and with DQS. LBS collapses the joint
 * (the candy wrapper: a ring half on each joint lands at r cos(86 deg) = 0.07 r from the axis),
 * DQS keeps its radius. Measured as the silhouette's width in pixels at the joint's row against
 * the width at the cylinder's upper quarter.
 */
class TwistScreenshotTest {
    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    /** Silhouette widths (pixels not the background) at the middle row and at a quarter from the top. */
    private static int[] widths(Path png) {
        try (MemoryStack stack = MemoryStack.stackPush()) {
            IntBuffer w = stack.mallocInt(1);
            IntBuffer h = stack.mallocInt(1);
            IntBuffer c = stack.mallocInt(1);
            ByteBuffer pixels = STBImage.stbi_load(png.toString(), w, h, c, 3);
            try {
                int width = w.get(0);
                int height = h.get(0);
                int background = rgb(pixels, width, 0, 0);
                // The cylinder spans the picture's height: its joint (z = 1 of 0..2) at the middle.
                int middle = narrowestNear(pixels, width, height / 2, 6, background);
                int quarter = narrowestNear(pixels, width, height / 4, 0, background);
                return new int[] {middle, quarter};
            } finally {
                STBImage.stbi_image_free(pixels);
            }
        }
    }

    /** The narrowest silhouette width over the rows within {@code spread} of {@code row}. */
    private static int narrowestNear(ByteBuffer p, int width, int row, int spread, int background) {
        int narrowest = Integer.MAX_VALUE;
        for (int y = row - spread; y <= row + spread; y++) {
            int n = 0;
            for (int x = 0; x < width; x++) {
                if (rgb(p, width, x, y) != background) {
                    n++;
                }
            }
            narrowest = Math.min(narrowest, n);
        }
        return narrowest;
    }

    private static int rgb(ByteBuffer p, int width, int x, int y) {
        int o = 3 * (y * width + x);
        return (p.get(o) & 0xFF) << 16 | (p.get(o + 1) & 0xFF) << 8 | (p.get(o + 2) & 0xFF);
    }

    @Test
    void lbsIsNarrowerAtTheJointThanDqs(@TempDir Path dir) {
        Path cylinder = Path.of(System.getProperty("skinlab.root", ".."), "assets/cylinders/cylinder-twist-high.dae");
        int[][] w = new int[2][];
        String[] methods = {"lbs", "dqs"};
        for (int i = 0; i < 2; i++) {
            Path png = dir.resolve(methods[i] + ".png");
            ViewerWindowTest.Run r = ViewerWindowTest.skinlab("view", cylinder.toString(), "--method", methods[i],
                    "--time", "4", "--hide-ui", "--size", "400x600", "--screenshot", png.toString());
            assertEquals(0, r.status(), r::toString);
            assertTrue(Files.isRegularFile(png));
            w[i] = widths(png);
        }
        int[] lbs = w[0];
        int[] dqs = w[1];
        // Both render the same cylinder away from the joint.
        assertEquals(lbs[1], dqs[1], 2, "upper quarter widths");
        assertTrue(lbs[1] > 40, "the cylinder fills a good part of the picture: " + lbs[1] + " px");
        // LBS: the joint nearly collapses (0.07 r by hand; the shading edge adds a few pixels).
        assertTrue(lbs[0] < 0.25 * lbs[1], "LBS joint " + lbs[0] + " px vs body " + lbs[1] + " px");
        // DQS: the joint keeps the radius (a little narrower through the smoothing of the twist).
        assertTrue(dqs[0] > 0.8 * dqs[1], "DQS joint " + dqs[0] + " px vs body " + dqs[1] + " px");
    }
}
