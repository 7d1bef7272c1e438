package org.skinlab.desktop.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL33C.*;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.IntBuffer;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.lwjgl.stb.STBImage;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.system.MemoryUtil;

/**
 * The framebuffer reaches a PNG with its top row first: a framebuffer cleared to one colour with
 * a red square at its top left, written, read back with stb_image and compared pixel by pixel.
 */
class ScreenshotTest {
    private static final float[] BACKGROUND = {0.2f, 0.4f, 0.6f};
    /** Side of the red square in the framebuffer's top left corner. */
    private static final int SQUARE = 16;

    private static GlWindow window;
    private static int width;
    private static int height;

    @TempDir
    Path dir;

    /** Opens the window on first use, so the counting test runs without a display. */
    private static void context() {
        GlTestDisplay.assume();
        if (window == null) {
            window = GlTestDisplay.window("ScreenshotTest", 64, 48, false);
            int[] size = new int[2];
            window.framebufferSize(size);
            width = size[0];
            height = size[1];
        }
    }

    @AfterAll
    static void close() {
        if (window != null) {
            window.close();
        }
    }

    private static void drawScene() {
        context();
        glDisable(GL_SCISSOR_TEST);
        glClearColor(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 0.5f);
        glClear(GL_COLOR_BUFFER_BIT);
        // GL's window coordinates start at the bottom left: this square is the top left one.
        glEnable(GL_SCISSOR_TEST);
        glScissor(0, height - SQUARE, SQUARE, SQUARE);
        glClearColor(1f, 0f, 0f, 1f);
        glClear(GL_COLOR_BUFFER_BIT);
        glDisable(GL_SCISSOR_TEST);
        assertEquals(GL_NO_ERROR, glGetError());
    }

    @Test
    void aPngRoundTripKeepsEveryPixelTopRowFirst() throws IOException {
        drawScene();
        Path file = dir.resolve("new/folders/shot.png");
        Screenshot.write(file, width, height);
        assertTrue(Files.size(file) > 0);
        try (MemoryStack stack = MemoryStack.stackPush()) {
            IntBuffer w = stack.mallocInt(1);
            IntBuffer h = stack.mallocInt(1);
            IntBuffer channels = stack.mallocInt(1);
            ByteBuffer png = STBImage.stbi_load(file.toString(), w, h, channels, 4);
            assertNotNull(png, STBImage.stbi_failure_reason());
            try {
                assertEquals(width, w.get(0));
                assertEquals(height, h.get(0));
                int wrong = 0;
                for (int y = 0; y < height; y++) {
                    for (int x = 0; x < width; x++) {
                        boolean red = x < SQUARE && y < SQUARE;
                        int o = 4 * (y * width + x);
                        // Exact up to one level: 0.2, 0.4 and 0.6 are 51, 102 and 153 of 255.
                        boolean ok = near(png.get(o), red ? 255 : 51) && near(png.get(o + 1), red ? 0 : 102)
                                && near(png.get(o + 2), red ? 0 : 153)
                                // The background was cleared with alpha 0.5: a screenshot is opaque.
                                && (png.get(o + 3) & 0xFF) == 255;
                        if (!ok) {
                            wrong++;
                        }
                    }
                }
                assertEquals(0, wrong, "pixels unlike the scene (" + width + "x" + height + ")");
            } finally {
                STBImage.stbi_image_free(png);
            }
        }
    }

    @Test
    void readGivesTheBottomRowFirstAndCountsWhatWasDrawn() {
        drawScene();
        ByteBuffer rgba = Screenshot.read(0, 0, width, height);
        try {
            assertEquals(4 * width * height, rgba.remaining());
            assertEquals(SQUARE * SQUARE,
                    Screenshot.countPixelsDifferentFrom(rgba, width, height, BACKGROUND[0], BACKGROUND[1],
                            BACKGROUND[2], 2));
            assertEquals(width * height - SQUARE * SQUARE,
                    Screenshot.countPixelsDifferentFrom(rgba, width, height, 1f, 0f, 0f, 2));
            // Row 0 is the bottom: background; the last row starts with the square.
            assertEquals(51, rgba.get(0) & 0xFF, 1);
            assertEquals(255, rgba.get(4 * (height - 1) * width) & 0xFF);
        } finally {
            MemoryUtil.memFree(rgba);
        }
        // A rectangle of the framebuffer: the square alone.
        ByteBuffer square = Screenshot.read(0, height - SQUARE, SQUARE, SQUARE);
        try {
            assertEquals(0, Screenshot.countPixelsDifferentFrom(square, SQUARE, SQUARE, 1f, 0f, 0f, 0));
        } finally {
            MemoryUtil.memFree(square);
        }
    }

    private static boolean near(byte value, int expected) {
        return Math.abs((value & 0xFF) - expected) <= 1;
    }

    @Test
    void failuresNameTheScreenshot() throws IOException {
        context();
        Path blocker = Files.writeString(dir.resolve("blocker"), "a file, not a folder");
        Path underAFile = blocker.resolve("shot.png");
        IOException e = assertThrows(IOException.class, () -> Screenshot.write(underAFile, width, height));
        assertTrue(e.getMessage().contains(underAFile.toString()), e.getMessage());
        Path aFolder = Files.createDirectory(dir.resolve("folder.png"));
        e = assertThrows(IOException.class, () -> Screenshot.write(aFolder, width, height));
        assertTrue(e.getMessage().contains(aFolder.toString()), e.getMessage());
    }

    /** The counting alone, on pixels made here: a difference of exactly the tolerance is no difference. */
    @Test
    void countingComparesEachChannelAgainstTheTolerance() {
        ByteBuffer rgba = MemoryUtil.memCalloc(4 * 4);
        try {
            // (0.5, 0.5, 0.5) is 128 per channel. Pixel 0 equal, 1 three levels off in blue,
            // 2 four levels off in green, 3 equal in colour with another alpha (alpha is not compared).
            int[][] pixels = {{128, 128, 128, 255}, {128, 128, 131, 255}, {128, 124, 128, 255}, {128, 128, 128, 0}};
            for (int i = 0; i < 4; i++) {
                for (int c = 0; c < 4; c++) {
                    rgba.put(4 * i + c, (byte) pixels[i][c]);
                }
            }
            assertEquals(1, Screenshot.countPixelsDifferentFrom(rgba, 2, 2, 0.5f, 0.5f, 0.5f, 3));
            assertEquals(2, Screenshot.countPixelsDifferentFrom(rgba, 2, 2, 0.5f, 0.5f, 0.5f, 2));
            assertEquals(0, Screenshot.countPixelsDifferentFrom(rgba, 2, 2, 0.5f, 0.5f, 0.5f, 4));
            assertEquals(4, Screenshot.countPixelsDifferentFrom(rgba, 2, 2, 0f, 0f, 0f, 100));
        } finally {
            MemoryUtil.memFree(rgba);
        }
    }
}
