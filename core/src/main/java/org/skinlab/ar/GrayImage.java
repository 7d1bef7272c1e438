package org.skinlab.ar;

/**
 * An 8-bit gray image, row-major, {@code rowStride} bytes from one row to the next (an Android
 * camera's Y plane has padding at each row's end). The tracker reads such images; the synthetic
 * camera writes them. The array is shared, not copied: whoever fills it owns it.
 *
 * @param width     pixels per row
 * @param height    rows
 * @param rowStride bytes from one row's start to the next's, at least {@code width}
 * @param pixels    the luminance bytes (unsigned), at least {@code rowStride * (height - 1) + width}
 */
public record GrayImage(int width, int height, int rowStride, byte[] pixels) {

    public GrayImage {
        if (width <= 0 || height <= 0 || rowStride < width) {
            throw new IllegalArgumentException("bad image layout: " + width + "x" + height + " stride " + rowStride);
        }
        if (pixels.length < (long) rowStride * (height - 1) + width) {
            throw new IllegalArgumentException("pixel array too short for " + width + "x" + height
                    + " stride " + rowStride + ": " + pixels.length);
        }
    }

    /** A black image without row padding. */
    public static GrayImage blank(int width, int height) {
        return new GrayImage(width, height, width, new byte[width * height]);
    }

    /** The pixel at column x, row y, as 0..255. */
    public int get(int x, int y) {
        return pixels[y * rowStride + x] & 0xFF;
    }

    /** Sets the pixel at column x, row y to {@code value} (0..255). */
    public void set(int x, int y, int value) {
        pixels[y * rowStride + x] = (byte) value;
    }
}
