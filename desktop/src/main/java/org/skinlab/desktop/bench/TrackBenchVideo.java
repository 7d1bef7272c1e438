package org.skinlab.desktop.bench;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;
import org.skinlab.desktop.ar.DemoVideo;
import org.skinlab.desktop.ar.GrayImages;
import org.skinlab.desktop.ar.IntrinsicsFile;

/**
 * The frames {@code skinlab bench track} times, with their camera: the synthetic demo video, or a
 * folder of a real video's frames (optionally resampled, the camera with them).
 *
 * @param name   what the report calls them
 * @param frames the frames, all of the camera's size
 * @param camera their camera
 */
public record TrackBenchVideo(String name, List<GrayImage> frames, CameraIntrinsics camera) {

    /** {@code count} frames of {@link DemoVideo} at 640x480 with a 60 degree field of view: one loop. */
    public static TrackBenchVideo synthetic(int count) {
        return synthetic(count, count);
    }

    /**
     * The first {@code count} frames of a {@link DemoVideo} loop of {@code loop} frames (at least
     * {@code count}): a shorter run with the camera moving as fast as in the whole loop.
     */
    public static TrackBenchVideo synthetic(int count, int loop) {
        if (count > loop) {
            throw new IllegalArgumentException(count + " frames of a loop of " + loop);
        }
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(640, 480, 60);
        DemoVideo demo = new DemoVideo(k, loop);
        List<GrayImage> frames = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            frames.add(demo.frame(i));
        }
        return new TrackBenchVideo((count == loop ? count + "" : "the first " + count + " of " + loop)
                + " synthetic 640x480 frames (skinlab ar-demo's video)", frames, k);
    }

    /**
     * The images of {@code dir} in name order; the camera from {@code intrinsics} (any format
     * {@link IntrinsicsFile} reads, with its lens) or a 60 degree field of view; resampled to
     * {@code width x height} when those are positive.
     */
    public static TrackBenchVideo images(Path dir, Path intrinsics, int width, int height) throws IOException {
        List<GrayImage> frames = new ArrayList<>();
        for (Path file : GrayImages.list(dir)) {
            frames.add(GrayImages.read(file));
        }
        GrayImage first = frames.get(0);
        for (int i = 1; i < frames.size(); i++) {
            if (frames.get(i).width() != first.width() || frames.get(i).height() != first.height()) {
                throw new IllegalArgumentException(dir + ": frame " + i + " is " + frames.get(i).width() + "x"
                        + frames.get(i).height() + ", the first " + first.width() + "x" + first.height());
            }
        }
        CameraIntrinsics k;
        if (intrinsics == null) {
            k = CameraIntrinsics.fromHorizontalFov(first.width(), first.height(), 60);
        } else {
            k = IntrinsicsFile.forImage(IntrinsicsFile.read(intrinsics), first.width(), first.height(), dir.toString());
        }
        String name = frames.size() + " frames of " + dir.getFileName() + " (" + first.width() + "x" + first.height();
        if (width > 0 && height > 0 && (width != first.width() || height != first.height())) {
            frames.replaceAll(g -> GrayImages.scaled(g, width, height));
            k = k.scaledTo(width, height);
            name += ", resampled to " + width + "x" + height;
        }
        return new TrackBenchVideo(name + ")", frames, k);
    }
}
