package org.skinlab.android.logic;

import java.nio.ByteBuffer;

import org.skinlab.ar.GrayImage;

/**
 * The luminance plane of a YUV_420_888 camera image (Android's ImageReader) as a {@link GrayImage}:
 * rows are {@code rowStride} bytes apart and pixels {@code pixelStride} bytes apart (1 on most
 * devices, 2 on some); copied into a reused array, so the camera's buffer can go back at once.
 */
public final class YPlane {
    private byte[] pixels = new byte[0];

    /** Copies the plane into this object's array; returns a gray image over it (valid until the next copy). */
    public GrayImage copy(ByteBuffer plane, int rowStride, int pixelStride, int width, int height) {
        if (pixelStride < 1 || rowStride < width * pixelStride - (pixelStride - 1)) {
            throw new IllegalArgumentException("bad Y plane layout: width " + width + ", row stride " + rowStride
                    + ", pixel stride " + pixelStride);
        }
        if (pixels.length < width * height) {
            pixels = new byte[width * height];
        }
        ByteBuffer b = plane.duplicate();
        int base = b.position();
        for (int y = 0; y < height; y++) {
            int row = base + y * rowStride;
            if (pixelStride == 1) {
                b.position(row);
                b.get(pixels, y * width, width);
            } else {
                for (int x = 0; x < width; x++) {
                    pixels[y * width + x] = b.get(row + x * pixelStride);
                }
            }
        }
        return new GrayImage(width, height, width, pixels);
    }
}
