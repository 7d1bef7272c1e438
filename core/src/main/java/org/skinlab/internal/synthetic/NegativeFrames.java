package org.skinlab.internal.synthetic;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.MarkerDictionary;

/**
 * Frames without a marker of the default dictionary, where any marker a detector reports is false,
 * deterministic for the caller's {@link Random}. Two kinds:
 * <ul>
 * <li>{@link #clutter}: 12 of the {@link Background}'s items (dark boxes, squares of random bits,
 * other dictionaries' codes, checkerboards, text, binary textures, our codes with 3-6 bits
 * flipped, framed pictures), blur 0.3-1.2 px, noise 2-5 levels, up to 50% light falloff, 2x2 rays
 * per pixel;</li>
 * <li>{@link #mixed}: every third frame 14 clutter items; the others two printed 10 cm codes of
 * other dictionaries (AprilTag 36h11, ArUco 6x6 and MIP_25h7, which the default 36h12 must not read)
 * 0.3-1 m away and tilted up to 50 degrees, side by side among 6 clutter items; a phone's
 * degradation ({@link SceneOptions#camera}).</li>
 * </ul>
 */
public final class NegativeFrames {
    private static final MarkerDictionary[] OTHER_CODES = {MarkerDictionary.APRILTAG_36H11,
        MarkerDictionary.ARUCO_6X6_1000, MarkerDictionary.ARUCO_MIP_25H7};
    private static final double OTHER_SIZE = 0.10;

    private final SyntheticCamera camera;
    private final MarkerShots[] others = new MarkerShots[OTHER_CODES.length];

    public NegativeFrames(CameraIntrinsics k) {
        camera = new SyntheticCamera(k);
        for (int i = 0; i < others.length; i++) {
            others[i] = MarkerShots.central(k, OTHER_CODES[i], OTHER_SIZE);
        }
    }

    /** A frame of clutter only. */
    public GrayImage clutter(Random random) {
        SceneOptions options = new SceneOptions(0.3 + 0.9 * random.nextDouble(), 2 + 3 * random.nextDouble(),
                0.5 * random.nextDouble(), 12, 2, random.nextLong());
        return camera.render(List.of(), options);
    }

    /** The {@code frame}th frame of the mixed set: clutter, or other dictionaries' codes among clutter. */
    public GrayImage mixed(Random random, int frame) {
        if (frame % 3 == 0) {
            return camera.render(List.of(), SceneOptions.camera(random.nextLong()).withClutter(14));
        }
        List<PlacedMarker> markers = new ArrayList<>();
        for (int k = 0; k < 2; k++) {
            MarkerShots codes = others[random.nextInt(others.length)];
            double distance = 0.3 + 0.7 * random.nextDouble();
            PlacedMarker m = codes.marker(random, distance, 50 * random.nextDouble());
            // The set's random numbers include each marker's own degradation, unused here.
            codes.degradation(random);
            double[] t = m.translation();
            t[0] += k == 0 ? -0.12 * t[2] : 0.12 * t[2];
            markers.add(PlacedMarker.of(m.pattern(), OTHER_SIZE, m.rotation(), t));
        }
        return camera.render(markers, SceneOptions.camera(random.nextLong()).withClutter(6));
    }
}
