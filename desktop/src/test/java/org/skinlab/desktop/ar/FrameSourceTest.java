package org.skinlab.desktop.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;

import org.jcodec.api.SequenceEncoder;
import org.jcodec.codecs.h264.io.model.SeqParameterSet;
import org.jcodec.common.io.NIOUtils;
import org.jcodec.common.model.ColorSpace;
import org.jcodec.common.model.Picture;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;
import org.skinlab.desktop.cli.SkinlabCommand;

/** The frame sources of {@code skinlab ar}: order, looping, sizes, and clear errors. */
class FrameSourceTest {
    private static GrayImage flat(int w, int h, int value) {
        GrayImage g = GrayImage.blank(w, h);
        java.util.Arrays.fill(g.pixels(), (byte) value);
        return g;
    }

    @Test
    void anImageFolderPlaysInNameOrderAndLoops(@TempDir Path dir) throws Exception {
        GrayImages.writePng(flat(32, 24, 30), dir.resolve("b.png"));
        GrayImages.writePng(flat(32, 24, 10), dir.resolve("a.png"));
        GrayImages.writePng(flat(32, 24, 20), dir.resolve("a2.png"));
        Files.writeString(dir.resolve("readme.txt"), "x");
        try (ImageFolderSource s = new ImageFolderSource(dir, 30)) {
            assertEquals(32, s.width());
            assertEquals(24, s.height());
            CameraImage frame = new CameraImage(32, 24);
            int[] expected = {10, 20, 30, 10};
            for (int v : expected) {
                s.next(frame);
                assertEquals(v, frame.gray().get(0, 0));
                assertEquals(v, frame.rgb()[0] & 0xFF, "a gray file's colour is its gray");
            }
        }
    }

    @Test
    void aFolderWithoutImagesOrWithAnotherSizeOrABrokenFileIsNamed(@TempDir Path dir) throws Exception {
        IllegalArgumentException empty = assertThrows(IllegalArgumentException.class, () -> new ImageFolderSource(dir, 30));
        assertTrue(empty.getMessage().contains("no images"), empty.getMessage());
        GrayImages.writePng(flat(32, 24, 0), dir.resolve("a.png"));
        GrayImages.writePng(flat(16, 24, 0), dir.resolve("b.png"));
        Files.writeString(dir.resolve("c.png"), "not a png");
        try (ImageFolderSource s = new ImageFolderSource(dir, 30)) {
            CameraImage frame = new CameraImage(32, 24);
            s.next(frame);
            IllegalArgumentException size = assertThrows(IllegalArgumentException.class, () -> s.next(frame));
            assertTrue(size.getMessage().contains("b.png") && size.getMessage().contains("16x24"), size.getMessage());
            IllegalArgumentException broken = assertThrows(IllegalArgumentException.class, () -> s.next(frame));
            assertTrue(broken.getMessage().contains("c.png"), broken.getMessage());
        }
    }

    @Test
    void anMp4VideoGivesItsLuminanceFramesAndLoops(@TempDir Path dir) throws Exception {
        // Written with JCodec's own H.264 encoder: three frames of known brightness.
        Path mp4 = dir.resolve("v.mp4");
        SequenceEncoder enc = SequenceEncoder.createSequenceEncoder(mp4.toFile(), 10);
        int[] levels = {40, 128, 200};
        for (int level : levels) {
            Picture p = Picture.create(64, 48, ColorSpace.RGB);
            java.util.Arrays.fill(p.getPlaneData(0), (byte) (level - 128)); // a gray frame
            enc.encodeNativeFrame(p);
        }
        enc.finish();
        try (VideoFileSource s = new VideoFileSource(mp4, 30)) {
            assertEquals(64, s.width());
            assertEquals(48, s.height());
            int[] seen = new int[4];
            CameraImage frame = new CameraImage(64, 48);
            for (int i = 0; i < 4; i++) {
                s.next(frame);
                seen[i] = frame.gray().get(32, 24);
                // RGB to YUV (video range) and H.264 move a gray level by up to ~10%.
                assertEquals(levels[i % 3], seen[i], 0.12 * levels[i % 3] + 8, "frame " + i);
            }
            assertTrue(seen[0] < seen[1] && seen[1] < seen[2], java.util.Arrays.toString(seen));
            assertEquals(seen[0], seen[3], 2, "looped to the first frame");
        }
        IllegalArgumentException missing = assertThrows(IllegalArgumentException.class,
                () -> new VideoFileSource(dir.resolve("none.mp4"), 30));
        assertTrue(missing.getMessage().contains("none.mp4"), missing.getMessage());
        Path junk = dir.resolve("junk.mp4");
        Files.writeString(junk, "not a video");
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class, () -> new VideoFileSource(junk, 30));
        assertTrue(bad.getMessage().contains("junk.mp4"), bad.getMessage());
    }

    @Test
    void anInterlacedMp4IsNamedWithWhatJCodecSaid(@TempDir Path dir) throws Exception {
        // A real MP4 from JCodec's encoder whose sequence parameter set (in the avcC box) is then
        // made to say "fields, not frames" (frame_mbs_only_flag 0): the boxes still parse, and
        // JCodec's H.264 decoder refuses the first frame, as it does camcorders' interlaced video.
        Path mp4 = dir.resolve("interlaced.mp4");
        SequenceEncoder enc = SequenceEncoder.createSequenceEncoder(mp4.toFile(), 10);
        for (int i = 0; i < 3; i++) {
            Picture p = Picture.create(64, 48, ColorSpace.RGB);
            java.util.Arrays.fill(p.getPlaneData(0), (byte) (40 * i));
            enc.encodeNativeFrame(p);
        }
        enc.finish();
        byte[] bytes = Files.readAllBytes(mp4);
        int avcC = indexOf(bytes, "avcC".getBytes(java.nio.charset.StandardCharsets.US_ASCII));
        // avcC: 4 type, 1 version, 1 profile, 1 compatibility, 1 level, 1 length size, 1 SPS count,
        // 2 SPS length, then the SPS NAL unit (a 1-byte header, then the parameters).
        assertEquals(1, bytes[avcC + 9] & 0x1f, "one SPS");
        int length = ((bytes[avcC + 10] & 0xff) << 8) | (bytes[avcC + 11] & 0xff);
        int at = avcC + 12 + 1;
        SeqParameterSet sps = SeqParameterSet.read(java.nio.ByteBuffer.wrap(bytes, at, length - 1).slice());
        assertTrue(sps.frameMbsOnlyFlag, "JCodec writes progressive frames");
        sps.frameMbsOnlyFlag = false;
        java.nio.ByteBuffer rewritten = java.nio.ByteBuffer.allocate(2 * length);
        sps.write(rewritten);
        rewritten.flip();
        // One more bit (mb_adaptive_frame_field_flag, 0) fits in the last byte's padding.
        assertEquals(length - 1, rewritten.remaining(), "the SPS keeps its length");
        rewritten.get(bytes, at, length - 1);
        Files.write(mp4, bytes);
        IllegalArgumentException bad = assertThrows(IllegalArgumentException.class, () -> new VideoFileSource(mp4, 30));
        assertTrue(bad.getMessage().startsWith(mp4 + ": ") && bad.getMessage().contains("interlace"), bad.getMessage());
        System.out.println("an interlaced video: " + bad.getMessage());
        StringWriter err = new StringWriter();
        int status = SkinlabCommand.run(new PrintWriter(new StringWriter(), true), new PrintWriter(err, true), "ar",
                "--video", mp4.toString(), "--exit-after-frames", "1");
        assertEquals(3, status, err.toString());
        assertEquals("skinlab: " + bad.getMessage(), err.toString().strip(), "one line, no stack trace");
    }

    private static int indexOf(byte[] data, byte[] part) {
        search:
        for (int i = 0; i + part.length <= data.length; i++) {
            for (int j = 0; j < part.length; j++) {
                if (data[i + j] != part[j]) {
                    continue search;
                }
            }
            return i;
        }
        throw new AssertionError("not found: " + new String(part, java.nio.charset.StandardCharsets.US_ASCII));
    }

    @Test
    void withoutAWebcamArSaysSoInOneLineAndExitsUnavailable() {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = SkinlabCommand.run(new PrintWriter(out, true), new PrintWriter(err, true), "ar", "--webcam",
                "--exit-after-frames", "1");
        // This machine has no camera; on one that has, the window would open instead.
        org.junit.jupiter.api.Assumptions.assumeTrue(status != 0, "a webcam is attached here");
        assertEquals(ExitCodes.UNAVAILABLE, status, err.toString());
        String[] lines = err.toString().strip().split("\n");
        assertEquals(1, lines.length, err.toString());
        assertTrue(lines[0].startsWith("skinlab: ") && lines[0].contains("webcam"), lines[0]);
    }

    /**
     * The feed at 240 fps while the test thread takes shots as a window would: every shot's picture,
     * colour and luminance, is whole and is the frame its number says (frame n is file (n - 1) mod 6),
     * and its pose is that frame's, for a few hundred shots taken while the feed refills the other
     * two images.
     */
    @Test
    void theFeedPublishesEachImageWithItsOwnPose(@TempDir Path dir) throws Exception {
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(320, 240, 60);
        DemoVideo video = new DemoVideo(k, 6);
        GrayImage[] frames = new GrayImage[6];
        for (int i = 0; i < 6; i++) {
            frames[i] = video.frame(i);
            GrayImages.writePng(frames[i], dir.resolve(String.format("f%02d.png", i)));
        }
        org.skinlab.ar.ArSession session = org.skinlab.ar.ArSession.of(new org.skinlab.ar.FiducialTracker(
                org.skinlab.ar.TrackerConfig.defaults(0.1), k));
        try (ArFeed feed = new ArFeed(new ImageFolderSource(dir, 240), session)) {
            assertTrue(feed.awaitFirst(10_000), "a first frame");
            long last = 0;
            int distinct = 0;
            long end = System.nanoTime() + 3_000_000_000L;
            while (distinct < 200 && System.nanoTime() < end) {
                ArFeed.Shot shot = feed.newest();
                if (shot.number() == last) {
                    Thread.onSpinWait();
                    continue;
                }
                assertTrue(shot.number() > last, "shots only move forward");
                last = shot.number();
                distinct++;
                assertTrue(shot.pose().visible(), "the demo marker is tracked");
                assertEquals(shot.number(), shot.pose().frameNumber(), "the shot's image and pose are one frame's");
                GrayImage expected = frames[(int) ((shot.number() - 1) % 6)];
                byte[] rgb = shot.image().rgb();
                for (int i = 0; i < expected.pixels().length; i++) {
                    if (shot.image().gray().pixels()[i] != expected.pixels()[i] || rgb[3 * i] != expected.pixels()[i]
                            || rgb[3 * i + 2] != expected.pixels()[i]) {
                        throw new AssertionError("shot " + shot.number() + " differs from its frame at pixel " + i);
                    }
                }
            }
            assertTrue(distinct >= 20, "shots taken: " + distinct);
        }
    }

    @Test
    void aSecondThreadTakingShotsIsRefused(@TempDir Path dir) throws Exception {
        GrayImages.writePng(flat(32, 24, 50), dir.resolve("a.png"));
        org.skinlab.ar.ArSession session = org.skinlab.ar.ArSession.of(new org.skinlab.ar.FiducialTracker(
                org.skinlab.ar.TrackerConfig.defaults(0.1), CameraIntrinsics.fromHorizontalFov(32, 24, 60)));
        try (ArFeed feed = new ArFeed(new ImageFolderSource(dir, 60), session)) {
            assertTrue(feed.awaitFirst(10_000));
            assertEquals(50, feed.newest().image().gray().get(0, 0));
            Throwable[] thrown = new Throwable[1];
            Thread other = new Thread(() -> {
                try {
                    feed.newest();
                } catch (IllegalStateException e) {
                    thrown[0] = e;
                }
            }, "second-window");
            other.start();
            other.join();
            assertTrue(thrown[0] != null && thrown[0].getMessage().contains("second-window"), String.valueOf(thrown[0]));
        }
    }
}
