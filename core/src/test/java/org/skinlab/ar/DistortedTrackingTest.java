package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.synthetic.DetectionTally;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.SceneOptions;
import org.skinlab.internal.synthetic.SyntheticCamera;

/**
 * The tracker on frames seen through a lens ({@link SyntheticCamera} renders each sample's ray
 * through {@link LensDistortion}): a strong webcam lens (k1 = -0.32, k2 = 0.12, k3 = -0.02,
 * p1 = 0.0012, p2 = -0.0008 at 640x480, fx = 520: what the image's corners show, a pinhole would
 * put about 110 px farther out) and a mild phone lens. A 10 cm marker is put anywhere in the image
 * where its sheet stays in view (its centre drawn uniformly over the distorted image, so near the
 * borders and corners too, where the lens moves points most), 0.3-1.5 m away, tilted 0-60 degrees,
 * with TrackerEvaluationTest's blur, noise and light falloff.
 *
 * <p>With the lens given, at about 1 m in TrackerEvaluationTest's part of the image (its 3x3
 * samples per pixel), every marker is found and the accuracy goals of undistorted frames hold
 * (median error at most 2 mm and 0.4 degrees; measured 1.1 mm, 0.37 degrees). All over the image
 * the corners land where {@link SyntheticCamera#projectCorners} puts them (median at most 0.25 px,
 * 95% at most 0.6 px; measured 0.18 and 0.45 px) and at least 90% are found (measured 34 of 36:
 * the misses are at the image's border, 1.2-1.4 m away, where the lens squeezes the marker to
 * 13-18 px across; through the pinhole of the same camera, 30 markers placed so at about 1 m were
 * all found, measured once). With the lens ignored
 * (the same frames, a pinhole tracker) the poses are measurably wrong (median 48 mm and 7 degrees
 * all over, 12 mm at 1 m in the middle): the lens matters. And the video search near the last
 * markers ({@link FiducialTracker#track}, which looks at a part of the frame) must see through the
 * lens as the whole-frame search does ({@link RegionLens}).
  */
class DistortedTrackingTest {
    static final CameraIntrinsics WEBCAM = new CameraIntrinsics(640, 480, 520, 521, 322.3, 236.9,
            new LensDistortion(-0.32, 0.12, -0.02, 0.0012, -0.0008));
    static final CameraIntrinsics PHONE = CameraIntrinsics.fromHorizontalFov(640, 480, 65)
            .withDistortion(new LensDistortion(0.06, -0.12, 0.04, -0.0004, 0.0006));
    static final double SIZE = 0.10;

    /** One rendered frame with its truth. */
    private record Shot(GrayImage image, PlacedMarker marker, double[] corners) {
    }

    /**
     * A marker whose whole sheet is in view (every sheet corner inside the image and within the
     * lens' invertible range), its centre anywhere in the distorted image or, with {@code middle},
     * where TrackerEvaluationTest puts it.
     */
    private static PlacedMarker place(CameraIntrinsics k, Random random, double distance, double tilt,
            boolean middle) {
        double half = SIZE / 2 * SyntheticCamera.PAPER_SCALE;
        double[] ray = new double[2];
        double[] pixel = new double[2];
        double[] back = new double[2];
        for (int attempt = 0; ; attempt++) {
            double axis = random.nextDouble() * 2 * Math.PI;
            double[] r = PlacedMarker.facingCamera(tilt * Math.cos(axis), tilt * Math.sin(axis),
                    random.nextDouble() * 360);
            if (middle) {
                // TrackerEvaluationTest's area: x within 22.5% of the distance, y within 15%.
                ray[0] = (random.nextDouble() - 0.5) * 0.45;
                ray[1] = (random.nextDouble() - 0.5) * 0.3;
            } else if (!k.toNormalized(random.nextDouble() * k.width() - 0.5, random.nextDouble() * k.height() - 0.5,
                    ray)) {
                continue;
            }
            double[] t = {ray[0] * distance, ray[1] * distance, distance};
            boolean inView = true;
            for (int c = 0; c < 4 && inView; c++) {
                double mx = (c == 0 || c == 3) ? -half : half;
                double my = c < 2 ? half : -half;
                double x = r[0] * mx + r[1] * my + t[0];
                double y = r[3] * mx + r[4] * my + t[1];
                double z = r[6] * mx + r[7] * my + t[2];
                k.toPixel(x, y, z, pixel);
                // Inside the image, 3 px from its edge, and on the lens' monotonic side: the
                // pixel maps back to the same ray.
                inView = z > 0 && pixel[0] > 2 && pixel[0] < k.width() - 3 && pixel[1] > 2 && pixel[1] < k.height() - 3
                        && k.toNormalized(pixel[0], pixel[1], back)
                        && Math.abs(back[0] - x / z) + Math.abs(back[1] - y / z) < 1e-6;
            }
            if (inView) {
                return PlacedMarker.of(MarkerPattern.of(MarkerDictionary.DEFAULT,
                        random.nextInt(MarkerDictionary.DEFAULT.codeCount())), SIZE, r, t);
            }
            if (attempt > 10_000) {
                throw new AssertionError("no place for a marker at " + distance + " m");
            }
        }
    }

    private static List<Shot> shots(CameraIntrinsics k, int frames, long seed, double minDistance,
            double maxDistance, boolean middle, int supersampling) {
        SyntheticCamera camera = new SyntheticCamera(k);
        Random random = new Random(seed);
        List<Shot> shots = new ArrayList<>();
        for (int i = 0; i < frames; i++) {
            double d = minDistance + (maxDistance - minDistance) * random.nextDouble();
            PlacedMarker m = place(k, random, d, 60 * random.nextDouble(), middle);
            SceneOptions options = new SceneOptions(0.5 + 0.7 * random.nextDouble(), 2 + 3 * random.nextDouble(),
                    0.5 * random.nextDouble(), 0, supersampling, random.nextLong());
            shots.add(new Shot(camera.render(List.of(m), options), m, camera.projectCorners(m)));
        }
        return shots;
    }

    private static String line(DetectionTally t, String name) {
        return String.format(Locale.ROOT, "%-36s found %3d of %3d (%.1f%%), wrong ids %d, median error %.2f mm"
                + " %.2f deg, corners median %.3f px, 95%% %.3f px, max %.3f px", name, t.found(), t.frames(),
                100 * t.rate(), t.wrongIds(), 1000 * t.positionError(0.5), t.rotationError(0.5), t.cornerError(0.5),
                t.cornerError(0.95), t.cornerError(1));
    }

    /** Every shot through a tracker for camera {@code k}; the shots without a detection go to {@code missed}. */
    private static DetectionTally detectAll(List<Shot> shots, CameraIntrinsics k, List<Shot> missed) {
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(SIZE), k);
        DetectionTally t = new DetectionTally();
        for (Shot s : shots) {
            List<MarkerDetection> found = tracker.detect(s.image());
            t.add(s.marker(), s.corners(), found);
            if (found.isEmpty()) {
                missed.add(s);
            }
        }
        return t;
    }

    /** How the misses looked (the lens squeezes markers at the image's border). */
    private static void printMisses(List<Shot> missed, String name) {
        for (Shot s : missed) {
            double[] c = s.corners();
            double shortest = Double.POSITIVE_INFINITY;
            for (int i = 0; i < 4; i++) {
                int j = (i + 1) % 4;
                shortest = Math.min(shortest, Math.hypot(c[2 * j] - c[2 * i], c[2 * j + 1] - c[2 * i + 1]));
            }
            System.out.printf(Locale.ROOT, "%s missed: %.2f m, shortest side %.1f px, corner 0 at (%.0f, %.0f)%n", name,
                    s.marker().translation()[2], shortest, c[0], c[1]);
        }
    }

    @Test
    void throughAWebcamLensTheGoalsOfUndistortedFramesHoldAndIgnoringTheLensDoesNot() {
        CameraIntrinsics pinhole = WEBCAM.withDistortion(LensDistortion.NONE);
        List<Shot> all = shots(WEBCAM, 36, 11, 0.3, 1.5, false, 2);
        List<Shot> missed = new ArrayList<>();
        DetectionTally given = detectAll(all, WEBCAM, missed);
        DetectionTally ignored = detectAll(all, pinhole, new ArrayList<>());
        System.out.println(line(given, "webcam, all over, 0.3-1.5 m, lens given"));
        System.out.println(line(ignored, "webcam, all over, 0.3-1.5 m, lens ignored"));
        printMisses(missed, "webcam");
        assertEquals(0, given.wrongIds(), "wrong ids");
        assertTrue(given.rate() >= 0.9, line(given, "lens given"));
        assertTrue(given.cornerError(0.5) <= 0.25 && given.cornerError(0.95) <= 0.6, line(given, "corners"));
        assertTrue(given.positionError(0.5) <= 0.002, line(given, "all over"));
        assertTrue(ignored.positionError(0.5) >= 10 * given.positionError(0.5), line(ignored, "lens ignored"));

        // TrackerEvaluationTest's 3x3 samples per pixel, as its accuracy goals were measured with.
        List<Shot> near1m = shots(WEBCAM, 24, 12, 0.95, 1.05, true, 3);
        DetectionTally at1m = detectAll(near1m, WEBCAM, new ArrayList<>());
        DetectionTally at1mIgnored = detectAll(near1m, pinhole, new ArrayList<>());
        System.out.println(line(at1m, "webcam, middle, 0.95-1.05 m, lens given"));
        System.out.println(line(at1mIgnored, "webcam, middle, 0.95-1.05 m, lens ignored"));
        assertEquals(at1m.frames(), at1m.found(), line(at1m, "about 1 m"));
        assertTrue(at1m.positionError(0.5) <= 0.002, line(at1m, "about 1 m"));
        assertTrue(at1m.rotationError(0.5) <= 0.4, line(at1m, "about 1 m"));
        // Ignoring the lens, the detector finds nearly the same corners (they are pixels either
        // way); the pose read from them is what goes wrong.
        assertTrue(at1mIgnored.positionError(0.5) >= 5 * at1m.positionError(0.5), line(at1mIgnored, "lens ignored"));
        assertTrue(at1mIgnored.rotationError(0.5) >= 2 * at1m.rotationError(0.5), line(at1mIgnored, "lens ignored"));
    }

    @Test
    void throughAPhoneLensToo() {
        List<Shot> all = shots(PHONE, 20, 21, 0.3, 1.5, false, 2);
        List<Shot> missed = new ArrayList<>();
        DetectionTally given = detectAll(all, PHONE, missed);
        DetectionTally ignored = detectAll(all, PHONE.withDistortion(LensDistortion.NONE), new ArrayList<>());
        System.out.println(line(given, "phone, all over, 0.3-1.5 m, lens given"));
        System.out.println(line(ignored, "phone, all over, 0.3-1.5 m, lens ignored"));
        printMisses(missed, "phone");
        assertEquals(0, given.wrongIds(), "wrong ids");
        assertTrue(given.rate() >= 0.9, line(given, "lens given"));
        assertTrue(given.cornerError(0.5) <= 0.25 && given.cornerError(0.95) <= 0.6, line(given, "corners"));
        assertTrue(ignored.positionError(0.5) >= 2 * given.positionError(0.5), line(ignored, "lens ignored"));
    }

    /**
     * A marker moving along the image's border and through a corner, tracked as video: the search
     * near the last markers looks at a part of the frame, and what it finds must be what the
     * whole-frame search finds there (same corners, same pose).
     */
    @Test
    void theSearchNearTheLastMarkersSeesThroughTheLensAsTheWholeFrameSearchDoes() {
        SyntheticCamera camera = new SyntheticCamera(WEBCAM);
        FiducialTracker video = new FiducialTracker(TrackerConfig.defaults(SIZE), WEBCAM);
        FiducialTracker whole = new FiducialTracker(TrackerConfig.defaults(SIZE), WEBCAM);
        MarkerPattern pattern = MarkerPattern.of(MarkerDictionary.DEFAULT, 7);
        double[] ray = new double[2];
        int frames = 12;
        int inRegion = 0;
        double worstCorner = 0;
        double worstPosition = 0;
        for (int i = 0; i < frames; i++) {
            // From the top edge's middle to the top-left corner, then down the left edge.
            double s = (double) i / (frames - 1);
            double u = s < 0.5 ? 320 - 2 * s * 230 : 90;
            double v = s < 0.5 ? 85 : 85 + (2 * s - 1) * 300;
            WEBCAM.toNormalized(u, v, ray);
            double d = 0.8;
            PlacedMarker m = PlacedMarker.of(pattern, SIZE, PlacedMarker.facingCamera(20, 10 + i, 15),
                    new double[] {ray[0] * d, ray[1] * d, d});
            GrayImage image = camera.render(List.of(m), new SceneOptions(0.8, 3, 0.3, 0, 2, 100 + i));
            List<MarkerDetection> tracked = video.track(image);
            List<MarkerDetection> detected = whole.detect(image);
            assertEquals(1, detected.size(), "frame " + i + ": whole-frame search");
            assertEquals(1, tracked.size(), "frame " + i + ": video search");
            if (video.lastFoundInRegion()) {
                inRegion++;
            }
            MarkerDetection a = tracked.get(0);
            MarkerDetection b = detected.get(0);
            for (int c = 0; c < 4; c++) {
                worstCorner = Math.max(worstCorner, Math.hypot(a.cornerX(c) - b.cornerX(c), a.cornerY(c) - b.cornerY(c)));
            }
            worstPosition = Math.max(worstPosition, PoseError.distance(a.translation(), b.translation()));
        }
        System.out.printf(Locale.ROOT, "video search through the webcam lens: %d of %d frames in the region,"
                + " worst corner difference %.4f px, worst position difference %.3f mm%n", inRegion, frames,
                worstCorner, 1000 * worstPosition);
        assertTrue(inRegion >= frames - 3, "the region search found the marker in " + inRegion + " of " + frames);
        // The same edges fitted through the same lens: the same corners to rounding (with the
        // frame's lens applied to the region's coordinates they were up to 0.63 px and 5.2 mm off).
        assertTrue(worstCorner <= 0.01, "corner difference " + worstCorner + " px");
        assertTrue(worstPosition <= 1e-4, "position difference " + worstPosition + " m");
    }
}
