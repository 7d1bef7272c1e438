package org.skinlab.desktop.bench;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.desktop.ar.DemoVideo;
import org.skinlab.desktop.ar.FrameSource;
import org.skinlab.desktop.ar.ImageFolderSource;
import org.skinlab.desktop.ar.IntrinsicsFile;
import org.skinlab.desktop.ar.VideoFileSource;

/**
 * What {@link ArFrameBench} plays: a camera's frames (a video file, an image folder, or the
 * synthetic demo video encoded into a temporary MP4 so that its decode stage is a real H.264
 * decode), the camera that saw them, the tracking, and how many frames a run plays (the source's
 * own count). Closing it deletes what it wrote.
 *
 * @param name         what reports call it
 * @param frames       the frames, opened afresh per run
 * @param frameCount   frames before the source loops
 * @param camera       the camera, of the frames' size
 * @param tracking     the marker dictionary, size and target id
 * @param written      a file this input wrote (the demo MP4), or null
 */
public record ArFrameInput(String name, ArFrameBench.Frames frames, int frameCount, CameraIntrinsics camera,
        TrackerConfig tracking, Path written) implements AutoCloseable {
    /** The demo video's frame rate in its MP4. */
    public static final int DEMO_FPS = 30;

    /**
     * {@link DemoVideo}'s first {@code count} frames at 640x480 (60 degrees, the default marker of
     * 10 cm), rendered and encoded into {@code dir}/ar-frame-demo.mp4 by JCodec's H.264 encoder
     * (BT.601). Rendering is the slow part: about a fifth of a second per frame on one core.
     */
    public static ArFrameInput synthetic(int count, Path dir) throws IOException {
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(640, 480, 60);
        Path mp4 = dir.resolve("ar-frame-demo.mp4");
        new DemoVideo(k, count).writeMp4(mp4, DEMO_FPS);
        return new ArFrameInput(count + " frames of the synthetic demo video (skinlab ar-demo's, 640x480,"
                + " H.264 by JCodec's encoder)", () -> new VideoFileSource(mp4, DEMO_FPS), count, k,
                TrackerConfig.defaults(DemoVideo.MARKER_METRES), mp4);
    }

    /**
     * A video file (MP4 with H.264 that JCodec decodes) or, when {@code file} is a folder, its
     * images; seen by the camera of {@code intrinsics} (any file {@link IntrinsicsFile} reads,
     * scaled to the frames when of the same aspect) or, without one, a {@code fovDegrees}
     * horizontal field of view; tracked with {@code tracking}.
     *
     * @throws IllegalArgumentException naming the file for one that cannot be read
     */
    public static ArFrameInput file(Path file, Path intrinsics, double fovDegrees, TrackerConfig tracking)
            throws IOException {
        boolean folder = Files.isDirectory(file);
        ArFrameBench.Frames frames = folder ? () -> new ImageFolderSource(file, DEMO_FPS)
                : () -> new VideoFileSource(file, DEMO_FPS);
        CameraIntrinsics k;
        int count;
        int width;
        int height;
        try (FrameSource probe = frames.open()) {
            count = probe.frameCount();
            width = probe.width();
            height = probe.height();
        }
        k = intrinsics != null
                ? IntrinsicsFile.forImage(IntrinsicsFile.read(intrinsics), width, height, "the frames of " + file)
                : CameraIntrinsics.fromHorizontalFov(width, height, fovDegrees);
        String name = count + (folder ? " images of " : " frames of ") + file.getFileName() + " (" + width + "x" + height
                + (folder ? "" : ", H.264") + ")";
        return new ArFrameInput(name, frames, count, k, tracking, null);
    }

    @Override
    public void close() throws IOException {
        if (written != null) {
            Files.deleteIfExists(written);
        }
    }
}
