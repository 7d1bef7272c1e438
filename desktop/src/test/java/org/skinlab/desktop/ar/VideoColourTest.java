package org.skinlab.desktop.ar;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.ByteBuffer;
import java.nio.file.Path;
import java.util.Arrays;

import org.jcodec.api.FrameGrab;
import org.jcodec.api.transcode.PixelStore;
import org.jcodec.api.transcode.SinkImpl;
import org.jcodec.api.transcode.VideoFrameWithPacket;
import org.jcodec.codecs.h264.H264Utils;
import org.jcodec.codecs.h264.io.model.SeqParameterSet;
import org.jcodec.codecs.h264.io.model.VUIParameters;
import org.jcodec.common.Codec;
import org.jcodec.common.Format;
import org.jcodec.common.io.NIOUtils;
import org.jcodec.common.model.ColorSpace;
import org.jcodec.common.model.Packet;
import org.jcodec.common.model.Picture;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code skinlab ar --video} in colour: the Y'CbCr planes JCodec decodes, converted by the video's
 * colour matrix (YCbCrTest has the formulas' cases), with the luminance as decoded.
 */
class VideoColourTest {
    /**
     * A flat frame of (Y, Cb, Cr) = (144, 96, 177), encoded as it is by JCodec's encoder (no colour
     * conversion of JCodec's) and decoded back exactly (samples the codec's quantiser keeps: checked
     * on the raw planes first; (100, 150, 60) comes back as (102, 151, 60)). The stream says nothing
     * of colour, so BT.601 in limited range applies, worked by hand: E'Y = 128/219 = 0.58447,
     * E'Pb = -32/224 = -0.14286, E'Pr = 49/224 = 0.21875;
     * R = 0.58447 + 1.402 (0.21875) = 0.89116 -> 227.25 -> 227;
     * G = 0.58447 + 0.34414 (0.14286) - 0.71414 (0.21875) = 0.47742 -> 121.74 -> 122;
     * B = 0.58447 - 1.772 (0.14286) = 0.33132 -> 84.49 -> 84;
     * at every pixel, and the luminance is the decoded Y, 144.
     */
    @Test
    void aFlatFrameConvertsAsWorkedByHand(@TempDir Path dir) throws Exception {
        Path mp4 = dir.resolve("flat.mp4");
        // JCodec's encoder behind its SequenceEncoder (which takes only RGB), fed Y'CbCr planes.
        SinkImpl sink = SinkImpl.createWithStream(NIOUtils.writableChannel(mp4.toFile()), Format.MOV, Codec.H264, null);
        sink.init();
        for (int i = 0; i < 2; i++) {
            Picture p = Picture.create(48, 32, ColorSpace.YUV420J);
            Arrays.fill(p.getPlaneData(0), (byte) (144 - 128));
            Arrays.fill(p.getPlaneData(1), (byte) (96 - 128));
            Arrays.fill(p.getPlaneData(2), (byte) (177 - 128));
            sink.outputVideoFrame(new VideoFrameWithPacket(Packet.createPacket(null, i, 10, 1, i, Packet.FrameType.KEY,
                    null), new PixelStore.LoanerPicture(p, 0)));
        }
        sink.finish();
        Picture raw = FrameGrab.getFrameFromFile(new File(mp4.toString()), 1);
        assertEquals(144, raw.getPlaneData(0)[17] + 128, "JCodec gives the flat frame back");
        assertEquals(96, raw.getPlaneData(1)[5] + 128);
        assertEquals(177, raw.getPlaneData(2)[5] + 128);

        try (VideoFileSource s = new VideoFileSource(mp4, 30)) {
            assertSame(YCbCr.BT601, s.colour(), "a stream without colour information is BT.601, limited range");
            CameraImage frame = new CameraImage(48, 32);
            for (int i = 0; i < 3; i++) {
                s.next(frame);
                for (int p = 0; p < 48 * 32; p++) {
                    assertEquals(144, frame.gray().pixels()[p] & 0xFF, "luminance at " + p);
                    assertArrayEquals(new int[] {227, 122, 84}, new int[] {frame.rgb()[3 * p] & 0xFF,
                            frame.rgb()[3 * p + 1] & 0xFF, frame.rgb()[3 * p + 2] & 0xFF}, "colour at pixel " + p);
                }
            }
        }
    }

    /**
     * A video written by {@link Mp4Writer} (BT.601, limited range) of 16x16 blocks in twelve
     * colours (saturated primaries, secondaries, grays, skin and sky tones) plays back in those
     * colours: inside each block (2 px in from its edges, where H.264's 4:2:0 chroma and block
     * filters do not reach) within 6 levels per channel, the codec's loss at JCodec's default
     * quality; the luminance is the Y plane the decoder gave (checked against JCodec's own decode).
     */
    @Test
    void anMp4PlaysInTheColoursItWasWritten(@TempDir Path dir) throws Exception {
        int[] colours = {0xFF0000, 0x00FF00, 0x0000FF, 0xFFFF00, 0x00FFFF, 0xFF00FF, 0xFFFFFF, 0x000000, 0x808080,
            0xE0A080, 0x4080C0, 0x206020};
        int w = 64;
        int h = 48;
        byte[] rgb = new byte[3 * w * h];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                int c = colours[(y / 16) * 4 + x / 16];
                int i = 3 * (y * w + x);
                rgb[i] = (byte) (c >> 16);
                rgb[i + 1] = (byte) (c >> 8);
                rgb[i + 2] = (byte) c;
            }
        }
        Path mp4 = dir.resolve("blocks.mp4");
        try (Mp4Writer writer = new Mp4Writer(mp4, w, h, 10)) {
            writer.write(rgb);
            writer.write(rgb);
        }
        Picture raw = FrameGrab.getFrameFromFile(new File(mp4.toString()), 0);
        int worst = 0;
        try (VideoFileSource s = new VideoFileSource(mp4, 30)) {
            CameraImage frame = new CameraImage(w, h);
            s.next(frame);
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int p = y * w + x;
                    assertEquals(raw.getPlaneData(0)[y * raw.getPlaneWidth(0) + x] + 128, frame.gray().pixels()[p] & 0xFF,
                            "the luminance as decoded");
                    if (x % 16 < 2 || x % 16 > 13 || y % 16 < 2 || y % 16 > 13) {
                        continue;
                    }
                    for (int c = 0; c < 3; c++) {
                        int d = Math.abs((frame.rgb()[3 * p + c] & 0xFF) - (rgb[3 * p + c] & 0xFF));
                        worst = Math.max(worst, d);
                        assertTrue(d <= 6, "pixel " + x + "," + y + " channel " + c + ": " + d + " levels off");
                    }
                }
            }
        }
        System.out.println("Mp4Writer and back: worst channel " + worst + " levels inside the blocks");
    }

    /** The VUI's colour description chooses the matrix; without one, or without a VUI, BT.601 limited. */
    @Test
    void theSequenceParameterSetsVuiNamesTheMatrix() {
        SeqParameterSet sps = org.jcodec.codecs.h264.H264Encoder.createH264Encoder()
                .initSPS(new org.jcodec.common.model.Size(64, 48));
        assertSame(YCbCr.BT601, VideoFileSource.colourOf(sps));
        assertSame(YCbCr.BT601, VideoFileSource.colourOf((ByteBuffer) null), "no parameter sets at all");
        VUIParameters vui = new VUIParameters();
        sps.vuiParams = vui;
        assertSame(YCbCr.BT601, VideoFileSource.colourOf(sps), "a VUI without the signal type");
        vui.videoSignalTypePresentFlag = true;
        vui.videoFormat = 5;
        vui.videoFullRangeFlag = true;
        YCbCr full = VideoFileSource.colourOf(sps);
        assertTrue(full.fullRange() && full.kr() == 0.299, full.toString());
        vui.colourDescriptionPresentFlag = true;
        vui.colourPrimaries = 1;
        vui.transferCharacteristics = 1;
        vui.matrixCoefficients = 1;
        // Through the bytes of a parameter set NAL unit, as an MP4's codec private data holds it.
        ByteBuffer written = ByteBuffer.allocate(256);
        sps.write(written);
        written.flip();
        ByteBuffer unit = ByteBuffer.allocate(300);
        unit.put(new byte[] {0, 0, 0, 1, 0x67});
        H264Utils.escapeNAL(written, unit);
        unit.flip();
        YCbCr bt709 = VideoFileSource.colourOf(unit);
        assertEquals(0.2126, bt709.kr(), bt709.toString());
        assertTrue(bt709.fullRange(), bt709.toString());
    }
}
