package org.skinlab.desktop.ar;

import java.io.IOException;
import java.nio.file.Path;
import java.util.List;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.MarkerPattern;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.SceneOptions;
import org.skinlab.internal.synthetic.SyntheticCamera;

/**
 * A synthetic camera video of the default printed marker (id 0, 10 cm) on a desk: one loop of a
 * hand-held camera circling it between 0.35 and 0.75 m, looking down at 20-50 degrees, turning
 * about it by 60 degrees, with a phone camera's blur, noise and uneven light, and some clutter on
 * one frame in four. {@code skinlab ar-demo} writes it to files so that {@code skinlab ar} runs
 * anywhere; {@code skinlab bench track} times the tracker on it.
 */
public final class DemoVideo {
    /** The printed marker's width in the video. */
    public static final double MARKER_METRES = 0.10;

    private final SyntheticCamera camera;
    private final MarkerPattern pattern = MarkerPattern.of(MarkerDictionary.DEFAULT, 0);
    private final int frames;

    public DemoVideo(CameraIntrinsics intrinsics, int frames) {
        if (frames < 2) {
            throw new IllegalArgumentException("a video needs at least 2 frames: " + frames);
        }
        this.camera = new SyntheticCamera(intrinsics);
        this.frames = frames;
    }

    public int frames() {
        return frames;
    }

    public CameraIntrinsics intrinsics() {
        return camera.intrinsics();
    }

    /** Where the marker is in frame {@code i}: the ground truth. */
    public PlacedMarker marker(int i) {
        double s = i / (double) frames;
        double a = 2 * Math.PI * s;
        // Negative turns about x tip the marker's top edge away: the camera looks down onto a desk.
        double[] r = PlacedMarker.facingCamera(-(35 + 15 * Math.sin(a)), 15 * Math.cos(a), 60 * s);
        double[] t = {0.09 * Math.sin(a), 0.04 * Math.cos(2 * a), 0.55 + 0.2 * Math.sin(a + 1)};
        return PlacedMarker.of(pattern, MARKER_METRES, r, t);
    }

    /** Where the marker's corners (TL, TR, BR, BL) project in frame {@code i}: x0, y0, ..., x3, y3. */
    public double[] corners(int i) {
        return camera.projectCorners(marker(i));
    }

    /** Frame {@code i}'s image. */
    public GrayImage frame(int i) {
        SceneOptions options = SceneOptions.camera(i).withClutter(i % 4 == 0 ? 6 : 0);
        return camera.render(List.of(marker(i)), options);
    }

    /**
     * The whole video as an MP4 file (H.264, JCodec's encoder: {@link Mp4Writer}) played at
     * {@code fps}, so that a decoder has real work: a camera's video as {@code skinlab ar --video}
     * and {@code skinlab bench ar-frame} read it.
     */
    public void writeMp4(Path file, int fps) throws IOException {
        try (Mp4Writer mp4 = new Mp4Writer(file, intrinsics().width(), intrinsics().height(), fps)) {
            for (int i = 0; i < frames; i++) {
                mp4.write(frame(i));
            }
        }
    }
}
