package org.skinlab.desktop.render;

import static org.lwjgl.opengl.GL33C.*;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;

import org.lwjgl.stb.STBImageWrite;
import org.lwjgl.system.MemoryUtil;

/** Reads the framebuffer back and writes it as PNG (stb_image_write; no AWT). */
public final class Screenshot {
    private Screenshot() {
    }

    /**
     * The RGBA pixels of a rectangle of the current read buffer, bottom row first (OpenGL's
     * order). The caller frees the buffer with {@link MemoryUtil#memFree}.
     */
    public static ByteBuffer read(int x, int y, int width, int height) {
        ByteBuffer rgba = MemoryUtil.memAlloc(4 * width * height);
        glPixelStorei(GL_PACK_ALIGNMENT, 1);
        glReadPixels(x, y, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
        return rgba;
    }

    /** Writes the framebuffer's {@code width x height} pixels to {@code file} as an opaque PNG. */
    public static void write(Path file, int width, int height) throws IOException {
        ByteBuffer rgba = read(0, 0, width, height);
        try {
            // Opaque: a translucent material must not punch holes into the picture.
            for (int i = 3; i < rgba.capacity(); i += 4) {
                rgba.put(i, (byte) 0xFF);
            }
            Path parent = file.toAbsolutePath().getParent();
            if (parent != null) {
                try {
                    Files.createDirectories(parent);
                } catch (IOException e) {
                    // Java's message is the bare folder name (e.g. a file stands in its way).
                    throw new IOException("cannot write the screenshot " + file + ": cannot create the folder "
                            + parent + " (" + e.getClass().getSimpleName() + ")", e);
                }
            }
            // OpenGL's rows run bottom up. stb's flag is global state: set for this call only.
            STBImageWrite.stbi_flip_vertically_on_write(true);
            boolean written = STBImageWrite.stbi_write_png(file.toString(), width, height, 4, rgba, 4 * width);
            STBImageWrite.stbi_flip_vertically_on_write(false);
            if (!written) {
                throw new IOException("cannot write the screenshot " + file);
            }
        } finally {
            MemoryUtil.memFree(rgba);
        }
    }

    /** Pixels whose colour differs from {@code (r, g, b)} (0-1) by more than {@code tolerance} levels. */
    public static int countPixelsDifferentFrom(ByteBuffer rgba, int width, int height, float r, float g, float b,
            int tolerance) {
        int rr = Math.round(r * 255);
        int gg = Math.round(g * 255);
        int bb = Math.round(b * 255);
        int n = 0;
        for (int i = 0; i < width * height; i++) {
            int o = 4 * i;
            if (Math.abs((rgba.get(o) & 0xFF) - rr) > tolerance || Math.abs((rgba.get(o + 1) & 0xFF) - gg) > tolerance
                    || Math.abs((rgba.get(o + 2) & 0xFF) - bb) > tolerance) {
                n++;
            }
        }
        return n;
    }
}
