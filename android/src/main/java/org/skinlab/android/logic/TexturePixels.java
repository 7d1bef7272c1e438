package org.skinlab.android.logic;

import java.nio.ByteBuffer;

/**
 * One decoded picture ready for {@code glTexImage2D}: RGBA, 8 bits per channel, straight (not
 * premultiplied) alpha, the image's bottom row first, because the model's texture coordinate
 * (0, 0) is the image's bottom left (COLLADA's convention; the glTF importer flips v to match) and
 * OpenGL's first row is t = 0.
 *
 * @param width  pixels per row
 * @param height rows
 * @param rgba   {@code 4 * width * height} bytes in a direct buffer, read-only for users
 */
public record TexturePixels(int width, int height, ByteBuffer rgba) {
    public TexturePixels {
        if (width < 1 || height < 1 || rgba == null || !rgba.isDirect() || rgba.remaining() != 4 * width * height) {
            throw new IllegalArgumentException("a " + width + "x" + height + " picture needs " + 4L * width * height
                    + " bytes of RGBA in a direct buffer");
        }
    }

    /**
     * From packed ARGB pixels ({@code 0xAARRGGBB}), the image's top row first, as Android's
     * {@code Bitmap.getPixels} and Java's {@code BufferedImage.getRGB} give them.
     */
    public static TexturePixels fromArgbTopRowFirst(int width, int height, int[] argb) {
        if (argb.length != width * height) {
            throw new IllegalArgumentException(argb.length + " pixels for a " + width + "x" + height + " picture");
        }
        ByteBuffer out = ByteBuffer.allocateDirect(4 * width * height);
        for (int row = height - 1; row >= 0; row--) {
            for (int x = 0; x < width; x++) {
                int p = argb[row * width + x];
                out.put((byte) (p >>> 16)).put((byte) (p >>> 8)).put((byte) p).put((byte) (p >>> 24));
            }
        }
        out.flip();
        return new TexturePixels(width, height, out);
    }
}
