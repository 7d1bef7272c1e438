package org.skinlab.desktop.ar;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferByte;
import java.nio.file.Path;
import java.util.Random;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * An image folder's frames in colour: each file's colour exactly as ImageIO decodes it
 * ({@code getRGB}), and a luminance byte for byte what the tracker read before colour came
 * ({@link GrayImages#read}, whose rule and code path this test does not share for the common
 * types: those are read from the pixel arrays), for every kind of file a camera folder may hold.
 */
class CameraImagesTest {
    private static final int W = 37;
    private static final int H = 23;

    /** Random colours, and a few pure ones, in a picture of {@code type}. */
    private static BufferedImage picture(int type, long seed) {
        BufferedImage image = new BufferedImage(W, H, type);
        Random random = new Random(seed);
        int[] pure = {0xFF0000, 0x00FF00, 0x0000FF, 0xFFFFFF, 0x000000, 0xFFFF00};
        for (int y = 0; y < H; y++) {
            for (int x = 0; x < W; x++) {
                int c = x < pure.length && y == 0 ? pure[x] : random.nextInt(0x1000000);
                image.setRGB(x, y, 0xFF000000 | c);
            }
        }
        return image;
    }

    @Test
    void everyKindOfFileGivesItsColoursAndTheTrackersLuminance(@TempDir Path dir) throws Exception {
        Object[][] kinds = {
            {BufferedImage.TYPE_3BYTE_BGR, "png"}, {BufferedImage.TYPE_4BYTE_ABGR, "png"},
            {BufferedImage.TYPE_INT_RGB, "png"}, {BufferedImage.TYPE_INT_ARGB, "png"},
            {BufferedImage.TYPE_BYTE_GRAY, "png"}, {BufferedImage.TYPE_USHORT_GRAY, "png"},
            {BufferedImage.TYPE_BYTE_INDEXED, "png"}, {BufferedImage.TYPE_3BYTE_BGR, "jpg"},
            {BufferedImage.TYPE_INT_RGB, "bmp"},
        };
        int n = 0;
        for (Object[] kind : kinds) {
            int type = (Integer) kind[0];
            Path file = dir.resolve("kind" + n + "." + kind[1]);
            BufferedImage written = picture(type, n++);
            assertEquals(true, ImageIO.write(written, (String) kind[1], file.toFile()), file.toString());
            BufferedImage decoded = ImageIO.read(file.toFile());
            CameraImage frame = new CameraImage(W, H);
            CameraImages.fill(GrayImages.decode(file), frame, file.toString());
            String what = file.getFileName() + " (decoded as type " + decoded.getType() + ")";

            assertArrayEquals(GrayImages.read(file).pixels(), frame.gray().pixels(), "the tracker's input: " + what);
            byte[] expected = new byte[3 * W * H];
            for (int y = 0; y < H; y++) {
                for (int x = 0; x < W; x++) {
                    int c = decoded.getRGB(x, y);
                    int i = 3 * (y * W + x);
                    if (decoded.getType() == BufferedImage.TYPE_BYTE_GRAY) {
                        // An 8-bit gray file shows its own values (getRGB would brighten them as linear gray).
                        int v = ((DataBufferByte) decoded.getRaster().getDataBuffer()).getData()[y * W + x] & 0xFF;
                        c = v << 16 | v << 8 | v;
                    }
                    expected[i] = (byte) (c >> 16);
                    expected[i + 1] = (byte) (c >> 8);
                    expected[i + 2] = (byte) c;
                }
            }
            assertArrayEquals(expected, frame.rgb(), "the colour: " + what);
            if (type != BufferedImage.TYPE_BYTE_GRAY && type != BufferedImage.TYPE_USHORT_GRAY
                    && type != BufferedImage.TYPE_BYTE_INDEXED && !"jpg".equals(kind[1])) {
                // Lossless files of colour pictures: the colours written, exactly.
                assertEquals(written.getRGB(5, 0) & 0xFFFFFF, (frame.rgb()[15] & 0xFF) << 16
                        | (frame.rgb()[16] & 0xFF) << 8 | frame.rgb()[17] & 0xFF, what);
                assertEquals(written.getRGB(W - 1, H - 1) & 0xFFFFFF, rgbAt(frame, W - 1, H - 1), what);
            }
        }
    }

    private static int rgbAt(CameraImage frame, int x, int y) {
        int i = 3 * (y * frame.width() + x);
        return (frame.rgb()[i] & 0xFF) << 16 | (frame.rgb()[i + 1] & 0xFF) << 8 | frame.rgb()[i + 2] & 0xFF;
    }

    @Test
    void aPictureOfAnotherSizeIsNamed() {
        CameraImage frame = new CameraImage(W, H);
        IllegalArgumentException e = org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class,
                () -> CameraImages.fill(new BufferedImage(W + 1, H, BufferedImage.TYPE_INT_RGB), frame, "pic.png"));
        assertEquals("pic.png delivers 38x23 frames, not 37x23", e.getMessage());
    }
}
