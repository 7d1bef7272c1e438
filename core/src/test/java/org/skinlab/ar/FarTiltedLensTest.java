package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.synthetic.MarkerShot;
import org.skinlab.internal.synthetic.MarkerShots;

/** FarTiltedDetectionTest's positive frames (150 mm, 1.5-2 m, tilt 0-70) through a lens. */
class FarTiltedLensTest {
    @Test
    void throughABarrelLensTheRuleFindsAsManyAsWithout() {
        // The square BoofCV hands to the rule is undistorted through the lens, so the same markers
        // seen through a strong webcam lens (k1 = -0.32) are read as well as through a pinhole.
        CameraIntrinsics pinhole = FarTiltedDetectionTest.K;
        CameraIntrinsics lens = pinhole.withDistortion(LensDistortionTest.WEBCAM);
        int withLens = count(lens);
        int without = count(pinhole);
        System.out.println("150 mm, 1.5-2 m, tilt 0-70: through a barrel lens " + withLens + " of " + FRAMES
                + ", through a pinhole " + without);
        assertTrue(Math.abs(withLens - without) <= 2, withLens + " vs " + without);
        assertTrue(withLens >= 0.9 * FRAMES, withLens + " of " + FRAMES);
    }

    private static final int FRAMES = 28;

    private static int count(CameraIntrinsics k) {
        // The lens changes neither the pinhole's focal lengths nor so the markers' placement.
        MarkerShots shots = MarkerShots.inView(k, FarTiltedDetectionTest.SIZE);
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(FarTiltedDetectionTest.SIZE), k);
        Random random = new Random(1804);
        int hits = 0;
        for (int i = 0; i < FRAMES; i++) {
            MarkerShot shot = FarTiltedDetectionTest.shot(shots, random, i % FarTiltedDetectionTest.BINS);
            for (MarkerDetection d : tracker.detect(shot.image())) {
                assertEquals(shot.marker().pattern().id(), d.id(), "frame " + i);
                hits++;
            }
        }
        return hits;
    }
}
