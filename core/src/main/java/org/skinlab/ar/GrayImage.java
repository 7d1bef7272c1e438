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

    /**
     * Checks the layout; keeps {@code pixels} itself (no copy).
     *
     * @param width     pixels per row, positive
     * @param height    rows, positive
     * @param rowStride bytes from one row's start to the next's, at least {@code width}
     * @param pixels    the luminance bytes (unsigned), at least {@code rowStride * (height - 1) + width}; shared
     * @throws IllegalArgumentException when {@code width} or {@code height} is not positive, {@code rowStride} is
     *         less than {@code width}, or {@code pixels} is shorter than {@code rowStride * (height - 1) + width}
     * @throws NullPointerException when {@code pixels} is null
     */
    public GrayImage {
        if (width <= 0 || height <= 0 || rowStride < width) {
            throw new IllegalArgumentException("bad image layout: " + width + "x" + height + " stride " + rowStride);
        }
        if (pixels.length < (long) rowStride * (height - 1) + width) {
            throw new IllegalArgumentException("pixel array too short for " + width + "x" + height
                    + " stride " + rowStride + ": " + pixels.length);
        }
    }

    /**
     * A black image without row padding.
     *
     * @param width  pixels per row, positive
     * @param height rows, positive
     * @return a new all-zero image with {@code rowStride == width} and its own array of {@code width * height} bytes
     */
    public static GrayImage blank(int width, int height) {
        return new GrayImage(width, height, width, new byte[width * height]);
    }

    /**
     * The pixel at column x, row y, as 0..255.
     *
     * @param x column, 0 to {@code width - 1} (not checked against {@code width}: a larger x reads the row padding
     *          or the next row)
     * @param y row, 0 to {@code height - 1}
     * @return the unsigned luminance, 0 (black) to 255 (white)
     * @throws ArrayIndexOutOfBoundsException when the position lies outside the array
     */
    public int get(int x, int y) {
        return pixels[y * rowStride + x] & 0xFF;
    }

    /**
     * Sets the pixel at column x, row y to {@code value} (0..255).
     *
     * @param x     column, 0 to {@code width - 1} (not checked against {@code width})
     * @param y     row, 0 to {@code height - 1}
     * @param value the luminance, 0 (black) to 255 (white); only its low 8 bits are stored
     * @throws ArrayIndexOutOfBoundsException when the position lies outside the array
     */
    public void set(int x, int y, int value) {
        pixels[y * rowStride + x] = (byte) value;
    }
}
