package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Locale;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.synthetic.DetectionTally;
import org.skinlab.internal.synthetic.MarkerShot;
import org.skinlab.internal.synthetic.MarkerShots;
import org.skinlab.internal.synthetic.NegativeFrames;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.SceneOptions;
import org.skinlab.internal.synthetic.SyntheticCamera;

/**
 * The tracker on synthetic camera frames of known pose: a 10 cm ArUco
 * MIP_36h12 marker seen by a 640x480 camera with a 60 degree horizontal field of view (fx = 554 px,
 * a phone's main camera at VGA), anywhere in the image, turned about its normal at random, tilted
 * about a random axis in its plane; every frame blurred (sigma 0.5-1.2 px), noisy (sigma 2-5 gray
 * levels), lit unevenly (up to 50% falloff), every fifth with an occluder (a disc of 1.6 cm, about
 * 1.3 code cells) over the code ({@link MarkerShots#central}). Frames and their degradations come
 * from one seed: the counts below are deterministic.
 *
 * <p><b>Rates</b> (the goals): at least 99% found up to 1.5 m and 85% at 1.5-2 m, for tilts
 * up to 60 degrees. Between 60 and 70 degrees of tilt BoofCV's square detector itself loses markers
 * beyond about a metre (measured with its own default settings too: 9 of 16 at 70 degrees and
 * 1.25 m), so that band is held to 85% up to 1 m and reported, not claimed, beyond
 * (docs/ar.md). No frame may report a wrong id.
 *
 * <p><b>Accuracy at about 1 m</b> (goals: median position error at most 2 mm, rotation at most 0.4
 * degrees). The bounds follow from the corner noise: BoofCV fits each edge to about 0.05-0.1 px
 * here; the marker is 55 px wide at 1 m, so its apparent size, and with it the depth, is known to
 * about 0.1 / 55 = 0.2% (2 mm at 1 m), while x and y are 10x better (0.1 px at fx = 554 is 0.2 mm).
 * The tilt is read from the perspective difference between the near and far edges, about
 * {@code (size/2) sin(tilt) / d} of the width: the normal's error is about 0.1 px over half the
 * width's 27 px, 0.2 degrees, growing toward face-on where the perspective cue vanishes (the planar
 * ambiguity: 0.9 degrees median face-on at 1 m).
 *
 * <p><b>Negative frames</b>: clutter (the synthetic Background's: dark boxes, squares of random
 * bits, other codes, checkerboards, text, ...) and codes of other dictionaries (AprilTag 36h11,
 * ArUco 6x6 and MIP_25h7, which our 36h12 dictionary must not read), 0.3-1 m away
 * ({@link NegativeFrames#mixed}): no detection at
 * all with our rule (FiducialTracker's "False markers"); BoofCV's default cap
 * (minimumHamming, 12 of 36 bits) on the same frames reports markers that are not there, which this
 * test shows.
 */
class TrackerEvaluationTest {
    static final CameraIntrinsics K = CameraIntrinsics.fromHorizontalFov(640, 480, 60);
    static final double SIZE = 0.10;

    private static String line(DetectionTally t, String name) {
        return String.format(Locale.ROOT, "%-34s found %3d of %3d (%.1f%%), wrong ids %d, median error %.2f mm %.2f deg",
                name, t.found(), t.frames(), 100 * t.rate(), t.wrongIds(), 1000 * t.positionError(0.5),
                t.rotationError(0.5));
    }

    private static DetectionTally run(int frames, long seed, double minDistance, double maxDistance, double minTilt,
            double maxTilt) {
        MarkerShots shots = MarkerShots.central(K, MarkerDictionary.DEFAULT, SIZE);
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(SIZE), K);
        Random random = new Random(seed);
        DetectionTally tally = new DetectionTally();
        for (int i = 0; i < frames; i++) {
            MarkerShot s = shots.shot(random, minDistance, maxDistance, minTilt, maxTilt);
            tally.add(s.marker(), tracker.detect(s.image()));
        }
        return tally;
    }

    @Test
    void upTo1_5MetresNearlyEveryMarkerIsFound() {
        DetectionTally t = run(300, 101, 0.3, 1.5, 0, 60);
        System.out.println(line(t, "0.3-1.5 m, tilt 0-60"));
        assertEquals(0, t.wrongIds(), "wrong ids");
        assertTrue(t.rate() >= 0.99, line(t, "0.3-1.5 m"));
    }

    @Test
    void from1_5To2MetresMostMarkersAreFound() {
        DetectionTally t = run(120, 202, 1.5, 2.0, 0, 60);
        System.out.println(line(t, "1.5-2 m, tilt 0-60"));
        assertEquals(0, t.wrongIds(), "wrong ids");
        assertTrue(t.rate() >= 0.85, line(t, "1.5-2 m"));
    }

    @Test
    void steepTiltsUpTo1Metre() {
        DetectionTally t = run(80, 303, 0.3, 1.0, 60, 70);
        System.out.println(line(t, "0.3-1 m, tilt 60-70"));
        assertEquals(0, t.wrongIds(), "wrong ids");
        assertTrue(t.rate() >= 0.85, line(t, "0.3-1 m, steep"));
    }

    @Test
    void atAboutOneMetreTheErrorsAreWithinTheirBounds() {
        DetectionTally t = run(80, 404, 0.95, 1.05, 0, 60);
        System.out.println(line(t, "0.95-1.05 m, tilt 0-60"));
        assertTrue(t.positionError(0.5) <= 0.002, line(t, "about 1 m"));
        assertTrue(t.rotationError(0.5) <= 0.4, line(t, "about 1 m"));
    }

    @Test
    void negativeFramesReportNothingWhileBoofCvsDefaultCapReportsMarkersThatAreNotThere() {
        NegativeFrames negatives = new NegativeFrames(K);
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(SIZE), K);
        BoofSquareHamming boofDefault = BoofSquareHamming.capped(MarkerDictionary.DEFAULT,
                MarkerDictionary.DEFAULT.minimumHamming());
        Random random = new Random(505);
        int ours = 0;
        int theirs = 0;
        int frames = 90;
        for (int i = 0; i < frames; i++) {
            GrayImage image = negatives.mixed(random, i);
            ours += tracker.detect(image).size();
            theirs += boofDefault.detect(image);
        }
        System.out.println("negative frames: " + frames + ", false markers: ours " + ours + ", BoofCV's default cap "
                + theirs);
        assertEquals(0, ours, "false markers with our cap");
        assertTrue(theirs > 0, "BoofCV's default cap reports false markers on these frames");
    }

    @Test
    void videoSearchNearTheLastMarkerGivesTheWholeFramePoses() {
        SyntheticCamera camera = new SyntheticCamera(K);
        FiducialTracker video = new FiducialTracker(TrackerConfig.defaults(SIZE), K);
        FiducialTracker still = new FiducialTracker(TrackerConfig.defaults(SIZE), K);
        MarkerPattern pattern = MarkerPattern.of(MarkerDictionary.DEFAULT, 42);
        int inRegion = 0;
        int frames = 60;
        for (int i = 0; i < frames; i++) {
            double s = i / (double) frames;
            double[] r = PlacedMarker.facingCamera(25 + 15 * Math.sin(2 * Math.PI * s), 10 * Math.cos(2 * Math.PI * s),
                    40 * s);
            double[] t = {0.12 * Math.sin(2 * Math.PI * s), 0.05 * Math.cos(2 * Math.PI * s), 0.6 + 0.2 * s};
            GrayImage image = camera.render(List.of(PlacedMarker.of(pattern, SIZE, r, t)),
                    SceneOptions.camera(1000 + i));
            List<MarkerDetection> a = video.track(image);
            boolean region = video.lastFoundInRegion();
            List<MarkerDetection> b = still.detect(image);
            assertEquals(1, a.size(), "frame " + i);
            assertEquals(1, b.size(), "frame " + i);
            inRegion += region ? 1 : 0;
            assertTrue(PoseError.distance(a.get(0).translation(), b.get(0).translation()) < 5e-4, "frame " + i);
            assertTrue(PoseError.rotationDegrees(a.get(0).rotation(), b.get(0).rotation()) < 0.1, "frame " + i);
        }
        // Every FULL_FRAME_EVERY-th frame searches the whole frame on purpose, and so does the first.
        assertTrue(inRegion >= frames - frames / FiducialTracker.FULL_FRAME_EVERY - 2, "in the region: " + inRegion);
    }
}
