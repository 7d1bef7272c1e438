package org.skinlab.desktop.ar;

import java.io.IOException;
import java.nio.file.Path;

import org.jcodec.api.transcode.PixelStore;
import org.jcodec.api.transcode.SinkImpl;
import org.jcodec.api.transcode.VideoFrameWithPacket;
import org.jcodec.common.Codec;
import org.jcodec.common.Format;
import org.jcodec.common.io.NIOUtils;
import org.jcodec.common.model.ColorSpace;
import org.jcodec.common.model.Packet;
import org.jcodec.common.model.Picture;

import org.skinlab.ar.GrayImage;

/**
 * Frames into an MP4 file with H.264, encoded in pure Java by JCodec's encoder, so that a video
 * made here (the demo video, test videos) is decoded by {@link VideoFileSource} as a camera's
 * would be. The colour goes in as BT.601 in limited range ({@link YCbCr#BT601}), what an H.264
 * stream without colour information means and what {@link VideoFileSource} then assumes; the
 * Y'CbCr planes are handed to JCodec's encoder as they are (its {@code SequenceEncoder} takes only
 * RGB and converts it to full-range samples in a stream that does not say so, weighing blue 15/256
 * instead of 29/256 in its luma). Chroma is the mean of each 2x2 block's Cb and Cr (4:2:0). Width
 * and height must be even.
 */
public final class Mp4Writer implements AutoCloseable {
    private final Path file;
    private final int width;
    private final int height;
    private final int fps;
    private final SinkImpl sink;
    private final Picture picture;
    private long frames;
    private boolean finished;

    /** A new file of {@code width x height} frames played at {@code fps} frames per second. */
    public Mp4Writer(Path file, int width, int height, int fps) throws IOException {
        if (width <= 0 || height <= 0 || width % 2 != 0 || height % 2 != 0) {
            throw new IllegalArgumentException(file + ": H.264 with 4:2:0 chroma needs an even width and height, not "
                    + width + "x" + height);
        }
        if (fps <= 0) {
            throw new IllegalArgumentException(file + ": frames per second must be positive: " + fps);
        }
        this.file = file;
        this.width = width;
        this.height = height;
        this.fps = fps;
        this.sink = SinkImpl.createWithStream(NIOUtils.writableChannel(file.toFile()), Format.MOV, Codec.H264, null);
        sink.init();
        this.picture = Picture.create(width, height, ColorSpace.YUV420J);
    }

    /** Appends a colour frame: R, G, B bytes per pixel, rows top first, no padding. */
    public void write(byte[] rgb) throws IOException {
        if (rgb.length < 3 * width * height) {
            throw new IllegalArgumentException(file + ": a " + width + "x" + height + " frame needs " + 3 * width * height
                    + " RGB bytes, not " + rgb.length);
        }
        byte[] y = picture.getPlaneData(0);
        byte[] cb = picture.getPlaneData(1);
        byte[] cr = picture.getPlaneData(2);
        int lumaStride = picture.getPlaneWidth(0);
        int chromaStride = picture.getPlaneWidth(1);
        for (int by = 0; by < height; by += 2) {
            for (int bx = 0; bx < width; bx += 2) {
                int sumCb = 0;
                int sumCr = 0;
                for (int dy = 0; dy < 2; dy++) {
                    for (int dx = 0; dx < 2; dx++) {
                        int p = 3 * ((by + dy) * width + bx + dx);
                        int[] s = YCbCr.BT601.fromRgb(rgb[p] & 0xFF, rgb[p + 1] & 0xFF, rgb[p + 2] & 0xFF);
                        // JCodec keeps samples as signed bytes offset by -128.
                        y[(by + dy) * lumaStride + bx + dx] = (byte) (s[0] - 128);
                        sumCb += s[1];
                        sumCr += s[2];
                    }
                }
                int c = (by / 2) * chromaStride + bx / 2;
                cb[c] = (byte) ((sumCb + 2) / 4 - 128);
                cr[c] = (byte) ((sumCr + 2) / 4 - 128);
            }
        }
        encode();
    }

    /** Appends a gray frame (a colourless picture: Cb = Cr = 128). */
    public void write(GrayImage gray) throws IOException {
        if (gray.width() != width || gray.height() != height) {
            throw new IllegalArgumentException(file + ": a " + gray.width() + "x" + gray.height() + " frame in a "
                    + width + "x" + height + " video");
        }
        byte[] y = picture.getPlaneData(0);
        int lumaStride = picture.getPlaneWidth(0);
        for (int row = 0; row < height; row++) {
            for (int x = 0; x < width; x++) {
                int v = gray.get(x, row);
                int[] s = YCbCr.BT601.fromRgb(v, v, v);
                y[row * lumaStride + x] = (byte) (s[0] - 128);
            }
        }
        java.util.Arrays.fill(picture.getPlaneData(1), (byte) 0);
        java.util.Arrays.fill(picture.getPlaneData(2), (byte) 0);
        encode();
    }

    /** The picture as the next frame, 1/fps s long (encoded at once: the picture is free again). */
    private void encode() throws IOException {
        Packet packet = Packet.createPacket(null, frames, fps, 1, frames, Packet.FrameType.KEY, null);
        sink.outputVideoFrame(new VideoFrameWithPacket(packet, new PixelStore.LoanerPicture(picture, 0)));
        frames++;
    }

    /** Finishes the file (its index); idempotent. */
    @Override
    public void close() throws IOException {
        if (!finished) {
            finished = true;
            sink.finish();
        }
    }
}
