package org.skinlab.desktop.ar;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.jcodec.api.FrameGrab;
import org.jcodec.api.JCodecException;
import org.jcodec.common.io.NIOUtils;
import org.jcodec.common.io.SeekableByteChannel;
import org.jcodec.common.model.Picture;

import org.skinlab.ar.GrayImage;

/**
 * The frames of a video file (MP4 with H.264, decoded in pure Java by JCodec), their luminance
 * plane as gray images, looping at the end.
 */
public final class VideoFileSource implements FrameSource {
    private final Path file;
    private final double fps;
    private SeekableByteChannel channel;
    private FrameGrab grab;
    private int width;
    private int height;
    private GrayImage first;

    public VideoFileSource(Path file, double fps) throws IOException {
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException(file + ": no such video file");
        }
        this.file = file;
        this.fps = fps;
        open();
        first = next();
        width = first.width();
        height = first.height();
    }

    private void open() throws IOException {
        close();
        try {
            channel = NIOUtils.readableChannel(file.toFile());
            grab = FrameGrab.createFrameGrab(channel);
        } catch (JCodecException | RuntimeException e) {
            close();
            throw new IllegalArgumentException(file + ": not a video JCodec can read (MP4 with H.264): " + said(e), e);
        }
    }

    @Override
    public String name() {
        return file.getFileName().toString();
    }

    @Override
    public int width() {
        return width;
    }

    @Override
    public int height() {
        return height;
    }

    @Override
    public double framesPerSecond() {
        return fps;
    }

    @Override
    public GrayImage next() throws IOException {
        if (first != null) {
            GrayImage f = first;
            first = null;
            return f;
        }
        Picture p = decode();
        if (p == null) {
            open();
            p = decode();
            if (p == null) {
                throw new IllegalArgumentException(file + ": no frames");
            }
        }
        int w = p.getCroppedWidth();
        int h = p.getCroppedHeight();
        byte[] luma = p.getPlaneData(0);
        int stride = p.getPlaneWidth(0);
        byte[] pixels = new byte[w * h];
        // JCodec keeps samples as signed bytes offset by -128.
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                pixels[y * w + x] = (byte) (luma[y * stride + x] + 128);
            }
        }
        return new GrayImage(w, h, w, pixels);
    }

    /**
     * The next frame, or null at the end. JCodec reports what it cannot decode (interlaced or
     * MBAFF H.264, high bit depth, a broken stream) with bare runtime exceptions; they become
     * this file's error, saying what JCodec said.
     */
    private Picture decode() throws IOException {
        try {
            return grab.getNativeFrame();
        } catch (RuntimeException e) {
            throw new IllegalArgumentException(file + ": JCodec cannot decode this video's frames: " + said(e), e);
        }
    }

    /** What JCodec said: its message, with the exception's kind unless it is a bare RuntimeException. */
    private static String said(Exception e) {
        String kind = e.getClass() == RuntimeException.class ? "" : e.getClass().getSimpleName();
        String message = e.getMessage() == null ? "" : e.getMessage();
        return kind.isEmpty() || message.isEmpty() ? kind + message : kind + ": " + message;
    }

    @Override
    public void close() {
        if (channel != null) {
            NIOUtils.closeQuietly(channel);
            channel = null;
        }
    }
}
