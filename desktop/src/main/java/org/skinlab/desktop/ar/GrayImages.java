package org.skinlab.desktop.ar;

import java.awt.image.BufferedImage;
import java.awt.image.DataBufferByte;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import org.skinlab.ar.GrayImage;

/** Camera frames from files on the desktop (ImageIO: PNG, JPEG, BMP, GIF) as gray images, and back. */
public final class GrayImages {
    private GrayImages() {
    }

    /** The image files of a folder (png, jpg, jpeg, bmp), in name order; an error when there are none. */
    public static List<Path> list(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) {
            throw new IllegalArgumentException(dir + ": not a folder");
        }
        List<Path> files;
        try (Stream<Path> s = Files.list(dir)) {
            files = s.filter(p -> {
                String n = p.getFileName().toString().toLowerCase(Locale.ROOT);
                return Files.isRegularFile(p) && (n.endsWith(".png") || n.endsWith(".jpg") || n.endsWith(".jpeg")
                        || n.endsWith(".bmp"));
            }).sorted().collect(Collectors.toList());
        }
        if (files.isEmpty()) {
            throw new IllegalArgumentException(dir + ": no images (.png, .jpg, .jpeg, .bmp)");
        }
        return files;
    }

    /**
     * An image file's luminance (Rec. 601 weights); IllegalArgumentException naming the file when
     * it is not an image, is damaged or cannot be read.
     */
    public static GrayImage read(Path file) {
        return of(decode(file));
    }

    /**
     * An image file decoded by ImageIO; IllegalArgumentException naming the file when it is not an
     * image, is damaged or cannot be read.
     */
    public static BufferedImage decode(Path file) {
        BufferedImage image;
        try {
            image = ImageIO.read(file.toFile());
        } catch (IOException | RuntimeException e) {
            // ImageIO's messages ("Error reading PNG image data") say what, not which file.
            throw new IllegalArgumentException(file + ": cannot be read as an image: " + e.getMessage(), e);
        }
        if (image == null) {
            throw new IllegalArgumentException(file + ": not an image ImageIO can read");
        }
        return image;
    }

    /**
     * The luminance the tracker reads of a colour (0-255 each): Rec. 601's weights, rounded. The
     * one rule for every colour camera frame on the desktop ({@link CameraImages} too).
     */
    static int luminance(int r, int g, int b) {
        return (299 * r + 587 * g + 114 * b + 500) / 1000;
    }

    /** The luminance of a decoded image (an 8-bit gray image's own values). */
    public static GrayImage of(BufferedImage image) {
        int w = image.getWidth();
        int h = image.getHeight();
        byte[] pixels = new byte[w * h];
        if (image.getType() == BufferedImage.TYPE_BYTE_GRAY) {
            byte[] data = ((DataBufferByte) image.getRaster().getDataBuffer()).getData();
            System.arraycopy(data, 0, pixels, 0, pixels.length);
        } else {
            int[] row = new int[w];
            for (int y = 0; y < h; y++) {
                image.getRGB(0, y, w, 1, row, 0, w);
                for (int x = 0; x < w; x++) {
                    int c = row[x];
                    pixels[y * w + x] = (byte) luminance(c >> 16 & 0xFF, c >> 8 & 0xFF, c & 0xFF);
                }
            }
        }
        return new GrayImage(w, h, w, pixels);
    }

    /** A gray image as an 8-bit gray BufferedImage (for PNG files). */
    public static BufferedImage toBufferedImage(GrayImage g) {
        BufferedImage image = new BufferedImage(g.width(), g.height(), BufferedImage.TYPE_BYTE_GRAY);
        byte[] data = ((DataBufferByte) image.getRaster().getDataBuffer()).getData();
        for (int y = 0; y < g.height(); y++) {
            System.arraycopy(g.pixels(), y * g.rowStride(), data, y * g.width(), g.width());
        }
        return image;
    }

    /** Writes a gray image as PNG. */
    public static void writePng(GrayImage g, Path file) throws IOException {
        if (!ImageIO.write(toBufferedImage(g), "png", file.toFile())) {
            throw new IOException(file + ": no PNG writer");
        }
    }

    /**
     * {@code g} resampled to {@code width x height} (bilinear; pixel edges map to pixel edges, as
     * {@link org.skinlab.ar.CameraIntrinsics#scaledTo} maps the camera).
     */
    public static GrayImage scaled(GrayImage g, int width, int height) {
        byte[] out = new byte[width * height];
        double sx = (double) g.width() / width;
        double sy = (double) g.height() / height;
        for (int y = 0; y < height; y++) {
            double fy = Math.min(Math.max((y + 0.5) * sy - 0.5, 0), g.height() - 1);
            int y0 = Math.min((int) fy, g.height() - 2 < 0 ? 0 : g.height() - 2);
            int y1 = Math.min(y0 + 1, g.height() - 1);
            double wy = fy - y0;
            for (int x = 0; x < width; x++) {
                double fx = Math.min(Math.max((x + 0.5) * sx - 0.5, 0), g.width() - 1);
                int x0 = Math.min((int) fx, g.width() - 2 < 0 ? 0 : g.width() - 2);
                int x1 = Math.min(x0 + 1, g.width() - 1);
                double wx = fx - x0;
                double top = g.get(x0, y0) * (1 - wx) + g.get(x1, y0) * wx;
                double bottom = g.get(x0, y1) * (1 - wx) + g.get(x1, y1) * wx;
                out[y * width + x] = (byte) Math.round(top * (1 - wy) + bottom * wy);
            }
        }
        return new GrayImage(width, height, width, out);
    }
}
