package org.skinlab.desktop.ar;

import java.awt.image.BufferedImage;
import java.awt.image.ComponentSampleModel;
import java.awt.image.DataBufferByte;
import java.awt.image.DataBufferInt;
import java.awt.image.Raster;
import java.awt.image.SinglePixelPackedSampleModel;

/**
 * Decoded pictures (an image file's, a webcam's) into a {@link CameraImage}: the colour as the
 * picture's sRGB values ({@code BufferedImage.getRGB}'s), and the luminance by
 * {@link GrayImages#luminance} of those, so the tracker reads exactly what {@link GrayImages#of}
 * gives it; an 8-bit gray picture keeps its own values in both. The types ImageIO and webcams
 * produce (8-bit gray, BGR and ABGR bytes, RGB and ARGB ints) are read straight from their pixel
 * arrays, whose bytes are those values; any other goes through {@code getRGB}.
 */
public final class CameraImages {
    private CameraImages() {
    }

    /** Fills {@code into} (of the picture's size) with {@code image}; {@code what} names the picture in errors. */
    public static void fill(BufferedImage image, CameraImage into, String what) {
        into.requireSize(image.getWidth(), image.getHeight(), what);
        Raster raster = image.getRaster();
        boolean plain = raster.getSampleModelTranslateX() == 0 && raster.getSampleModelTranslateY() == 0;
        switch (plain ? image.getType() : BufferedImage.TYPE_CUSTOM) {
            case BufferedImage.TYPE_BYTE_GRAY:
                if (byteRows(raster, 1)) {
                    gray(((DataBufferByte) raster.getDataBuffer()).getData(), into);
                    return;
                }
                break;
            case BufferedImage.TYPE_3BYTE_BGR:
                if (byteRows(raster, 3)) {
                    bytes(((DataBufferByte) raster.getDataBuffer()).getData(), 3, into);
                    return;
                }
                break;
            case BufferedImage.TYPE_4BYTE_ABGR:
                if (byteRows(raster, 4)) {
                    bytes(((DataBufferByte) raster.getDataBuffer()).getData(), 4, into);
                    return;
                }
                break;
            case BufferedImage.TYPE_INT_RGB:
            case BufferedImage.TYPE_INT_ARGB:
                if (raster.getSampleModel() instanceof SinglePixelPackedSampleModel
                        && ((SinglePixelPackedSampleModel) raster.getSampleModel()).getScanlineStride() == image.getWidth()
                        && raster.getDataBuffer().getOffset() == 0) {
                    ints(((DataBufferInt) raster.getDataBuffer()).getData(), into);
                    return;
                }
                break;
            default:
                break;
        }
        viaGetRgb(image, into);
    }

    /** Whether the raster's rows are {@code bytesPerPixel * width} bytes apart from the array's start. */
    private static boolean byteRows(Raster raster, int bytesPerPixel) {
        return raster.getSampleModel() instanceof ComponentSampleModel
                && ((ComponentSampleModel) raster.getSampleModel()).getPixelStride() == bytesPerPixel
                && ((ComponentSampleModel) raster.getSampleModel()).getScanlineStride() == bytesPerPixel * raster.getWidth()
                && raster.getDataBuffer().getOffset() == 0;
    }

    private static void gray(byte[] data, CameraImage into) {
        int n = into.width() * into.height();
        byte[] rgb = into.rgb();
        System.arraycopy(data, 0, into.gray().pixels(), 0, n);
        for (int i = 0, o = 0; i < n; i++, o += 3) {
            byte v = data[i];
            rgb[o] = v;
            rgb[o + 1] = v;
            rgb[o + 2] = v;
        }
    }

    /** BGR or ABGR bytes: the colour bytes are the last three of each pixel, blue first. */
    private static void bytes(byte[] data, int bytesPerPixel, CameraImage into) {
        int n = into.width() * into.height();
        byte[] rgb = into.rgb();
        byte[] gray = into.gray().pixels();
        int blue = bytesPerPixel - 3;
        for (int i = 0, s = blue, o = 0; i < n; i++, s += bytesPerPixel, o += 3) {
            int b = data[s] & 0xFF;
            int g = data[s + 1] & 0xFF;
            int r = data[s + 2] & 0xFF;
            put(r, g, b, rgb, o, gray, i);
        }
    }

    private static void ints(int[] data, CameraImage into) {
        int n = into.width() * into.height();
        byte[] rgb = into.rgb();
        byte[] gray = into.gray().pixels();
        for (int i = 0, o = 0; i < n; i++, o += 3) {
            int c = data[i];
            put(c >> 16 & 0xFF, c >> 8 & 0xFF, c & 0xFF, rgb, o, gray, i);
        }
    }

    private static void viaGetRgb(BufferedImage image, CameraImage into) {
        int w = into.width();
        int[] row = new int[w];
        byte[] rgb = into.rgb();
        byte[] gray = into.gray().pixels();
        for (int y = 0; y < into.height(); y++) {
            image.getRGB(0, y, w, 1, row, 0, w);
            for (int x = 0; x < w; x++) {
                int c = row[x];
                int i = y * w + x;
                put(c >> 16 & 0xFF, c >> 8 & 0xFF, c & 0xFF, rgb, 3 * i, gray, i);
            }
        }
    }

    private static void put(int r, int g, int b, byte[] rgb, int o, byte[] gray, int i) {
        rgb[o] = (byte) r;
        rgb[o + 1] = (byte) g;
        rgb[o + 2] = (byte) b;
        gray[i] = (byte) GrayImages.luminance(r, g, b);
    }
}
