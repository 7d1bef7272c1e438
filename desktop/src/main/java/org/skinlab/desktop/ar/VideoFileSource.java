package org.skinlab.desktop.ar;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;

import org.jcodec.api.FrameGrab;
import org.jcodec.api.JCodecException;
import org.jcodec.common.io.NIOUtils;
import org.jcodec.common.io.SeekableByteChannel;
import org.jcodec.codecs.h264.H264Utils;
import org.jcodec.codecs.h264.io.model.NALUnit;
import org.jcodec.codecs.h264.io.model.NALUnitType;
import org.jcodec.codecs.h264.io.model.SeqParameterSet;
import org.jcodec.codecs.h264.io.model.VUIParameters;
import org.jcodec.common.model.Picture;

/**
 * The frames of a video file (MP4 with H.264, decoded in pure Java by JCodec), looping at the end:
 * the luminance plane as it is decoded (the tracker's input), and the colour converted from the
 * Y'CbCr planes by the video's own colour matrix and range (its H.264 VUI; BT.601 in limited range
 * where the stream says nothing, as the standard has it: {@link YCbCr#h264}), the chroma planes'
 * samples each covering the pixels they were subsampled from.
 */
public final class VideoFileSource implements FrameSource {
    private final Path file;
    private final double fps;
    private final int width;
    private final int height;
    private final YCbCr colour;
    private final int frameCount;
    private SeekableByteChannel channel;
    private FrameGrab grab;

    public VideoFileSource(Path file, double fps) throws IOException {
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException(file + ": no such video file");
        }
        this.file = file;
        this.fps = fps;
        open();
        Picture first;
        try {
            first = decode();
        } catch (IOException | RuntimeException e) {
            close();
            throw e;
        }
        if (first == null) {
            close();
            throw new IllegalArgumentException(file + ": no frames");
        }
        width = first.getCroppedWidth();
        height = first.getCroppedHeight();
        frameCount = grab.getVideoTrack().getMeta().getTotalFrames();
        try {
            colour = colourOf(grab.getVideoTrack().getMeta().getCodecPrivate());
        } catch (RuntimeException e) {
            close();
            throw new IllegalArgumentException(file + ": " + e.getMessage(), e);
        }
        // From the first frame again: next() plays the video from its start.
        open();
    }

    /**
     * The colour matrix the first sequence parameter set's VUI names (BT.601, limited range, when
     * there is no VUI or it says nothing); {@code codecPrivate} holds the parameter sets as NAL units.
     */
    static YCbCr colourOf(ByteBuffer codecPrivate) {
        if (codecPrivate == null) {
            return YCbCr.BT601;
        }
        ByteBuffer units = codecPrivate.duplicate();
        ByteBuffer unit;
        while ((unit = H264Utils.nextNALUnit(units)) != null) {
            if (NALUnit.read(unit).type == NALUnitType.SPS) {
                return colourOf(H264Utils.readSPS(unit));
            }
        }
        return YCbCr.BT601;
    }

    /** The colour matrix of one sequence parameter set (see {@link #colourOf(ByteBuffer)}). */
    static YCbCr colourOf(SeqParameterSet sps) {
        VUIParameters vui = sps.vuiParams;
        if (vui == null || !vui.videoSignalTypePresentFlag) {
            return YCbCr.BT601;
        }
        return YCbCr.h264(vui.colourDescriptionPresentFlag ? vui.matrixCoefficients : 2, vui.videoFullRangeFlag);
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

    /** The frames the container lists. */
    @Override
    public int frameCount() {
        return frameCount;
    }

    /** The video's colour matrix and range. */
    public YCbCr colour() {
        return colour;
    }

    @Override
    public void next(CameraImage into) throws IOException {
        into.requireSize(width, height, file.toString());
        Picture p = decode();
        if (p == null) {
            open();
            p = decode();
            if (p == null) {
                throw new IllegalArgumentException(file + ": no frames");
            }
        }
        if (p.getCroppedWidth() != width || p.getCroppedHeight() != height) {
            throw new IllegalArgumentException(file + ": a frame of " + p.getCroppedWidth() + "x" + p.getCroppedHeight()
                    + " after frames of " + width + "x" + height);
        }
        convert(p, into);
    }

    /**
     * The picture's planes into {@code into}: the luminance bytes as decoded, the colour through
     * {@link #colour}. JCodec keeps samples as signed bytes offset by -128.
     */
    private void convert(Picture p, CameraImage into) {
        byte[] luma = p.getPlaneData(0);
        int stride = p.getPlaneWidth(0);
        byte[] cb = p.getPlaneData(1);
        byte[] cr = p.getPlaneData(2);
        boolean chroma = cb != null && cr != null;
        int chromaStride = chroma ? p.getPlaneWidth(1) : 0;
        int shiftX = chroma && p.getPlaneWidth(1) < stride ? 1 : 0;
        int shiftY = chroma && p.getPlaneHeight(1) < p.getPlaneHeight(0) ? 1 : 0;
        byte[] gray = into.gray().pixels();
        byte[] rgb = into.rgb();
        for (int y = 0; y < height; y++) {
            int row = y * stride;
            int chromaRow = (y >> shiftY) * chromaStride;
            int out = y * width;
            for (int x = 0; x < width; x++) {
                int l = luma[row + x] + 128;
                gray[out + x] = (byte) l;
                int c = chromaRow + (x >> shiftX);
                colour.toRgb(l, chroma ? cb[c] + 128 : 128, chroma ? cr[c] + 128 : 128, rgb, 3 * (out + x));
            }
        }
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
