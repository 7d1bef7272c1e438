package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;

import boofcv.abst.fiducial.FiducialDetector;
import boofcv.factory.fiducial.ConfigFiducialHammingDetector;
import boofcv.factory.fiducial.ConfigHammingMarker;
import boofcv.factory.fiducial.FactoryFiducial;
import boofcv.factory.fiducial.HammingDictionary;
import boofcv.struct.image.GrayU8;
import org.junit.jupiter.api.Test;
import org.skinlab.ar.synthetic.PlacedMarker;
import org.skinlab.ar.synthetic.SceneOptions;
import org.skinlab.ar.synthetic.SyntheticCamera;

/**
 * The tracker on synthetic camera frames of known pose (issue 10's harness): a 10 cm ArUco
 * MIP_36h12 marker seen by a 640x480 camera with a 60 degree horizontal field of view (fx = 554 px,
 * a phone's main camera at VGA), anywhere in the image, turned about its normal at random, tilted
 * about a random axis in its plane; every frame blurred (sigma 0.5-1.2 px), noisy (sigma 2-5 gray
 * levels), lit unevenly (up to 50% falloff), every fifth with an occluder (a disc of 1.6 cm, about
 * 1.3 code cells) over the code. Frames and their degradations come from one seed: the counts below
 * are deterministic.
 *
 * <p><b>Rates</b> (issue 10's goals): at least 99% found up to 1.5 m and 85% at 1.5-2 m, for tilts
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
 * ArUco 6x6 and MIP_25h7, which our 36h12 dictionary must not read), 0.3-1 m away: no detection at
 * all with our rule (FiducialTracker's "False markers"); BoofCV's default cap
 * (minimumHamming, 12 of 36 bits) on the same frames reports markers that are not there, which this
 * test shows.
 */
class TrackerEvaluationTest {
    static final CameraIntrinsics K = CameraIntrinsics.fromHorizontalFov(640, 480, 60);
    static final double SIZE = 0.10;

    /** One rendered frame with its truth. */
    private record Shot(GrayImage image, PlacedMarker marker, double distance, double tilt) {
    }

    private static Shot shot(SyntheticCamera camera, Random random, MarkerDictionary dictionary, double distance,
            double tilt) {
        int id = random.nextInt(dictionary.codeCount());
        double axis = random.nextDouble() * 2 * Math.PI;
        double[] r = PlacedMarker.facingCamera(tilt * Math.cos(axis), tilt * Math.sin(axis), random.nextDouble() * 360);
        // Anywhere the whole sheet stays in view: within about 40% of the half-width and 30% of the half-height.
        double x = (random.nextDouble() - 0.5) * 0.45 * distance;
        double y = (random.nextDouble() - 0.5) * 0.3 * distance;
        PlacedMarker m = PlacedMarker.of(MarkerPattern.of(dictionary, id), SIZE, r, new double[] {x, y, distance});
        if (random.nextInt(5) == 0) {
            m = m.occludedBy((random.nextDouble() - 0.5) * 0.05, (random.nextDouble() - 0.5) * 0.05, 0.008);
        }
        SceneOptions options = new SceneOptions(0.5 + 0.7 * random.nextDouble(), 2 + 3 * random.nextDouble(),
                0.5 * random.nextDouble(), 0, 3, random.nextLong());
        return new Shot(camera.render(List.of(m), options), m, distance, tilt);
    }

    /** Found count, wrong ids, and the errors of the found. */
    private static final class Tally {
        int frames;
        int found;
        int wrong;
        final List<Double> position = new ArrayList<>();
        final List<Double> rotation = new ArrayList<>();

        void add(Shot s, List<MarkerDetection> detections) {
            frames++;
            for (MarkerDetection d : detections) {
                if (d.id() != s.marker().pattern().id()) {
                    wrong++;
                    continue;
                }
                found++;
                position.add(PoseError.distance(d.translation(), s.marker().translation()));
                rotation.add(PoseError.rotationDegrees(d.rotation(), s.marker().rotation()));
            }
        }

        double rate() {
            return (double) found / frames;
        }

        static double median(List<Double> values) {
            List<Double> sorted = new ArrayList<>(values);
            sorted.sort(null);
            return sorted.get(sorted.size() / 2);
        }

        String line(String name) {
            return String.format(Locale.ROOT, "%-34s found %3d of %3d (%.1f%%), wrong ids %d, median error %.2f mm %.2f deg",
                    name, found, frames, 100 * rate(), wrong, 1000 * median(position), median(rotation));
        }
    }

    private static Tally run(int frames, long seed, double minDistance, double maxDistance, double minTilt,
            double maxTilt) {
        SyntheticCamera camera = new SyntheticCamera(K);
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(SIZE), K);
        Random random = new Random(seed);
        Tally tally = new Tally();
        for (int i = 0; i < frames; i++) {
            double d = minDistance + (maxDistance - minDistance) * random.nextDouble();
            double tilt = minTilt + (maxTilt - minTilt) * random.nextDouble();
            Shot s = shot(camera, random, MarkerDictionary.DEFAULT, d, tilt);
            tally.add(s, tracker.detect(s.image()));
        }
        return tally;
    }

    @Test
    void upTo1_5MetresNearlyEveryMarkerIsFound() {
        Tally t = run(300, 101, 0.3, 1.5, 0, 60);
        System.out.println(t.line("0.3-1.5 m, tilt 0-60"));
        assertEquals(0, t.wrong, "wrong ids");
        assertTrue(t.rate() >= 0.99, t.line("0.3-1.5 m"));
    }

    @Test
    void from1_5To2MetresMostMarkersAreFound() {
        Tally t = run(120, 202, 1.5, 2.0, 0, 60);
        System.out.println(t.line("1.5-2 m, tilt 0-60"));
        assertEquals(0, t.wrong, "wrong ids");
        assertTrue(t.rate() >= 0.85, t.line("1.5-2 m"));
    }

    @Test
    void steepTiltsUpTo1Metre() {
        Tally t = run(80, 303, 0.3, 1.0, 60, 70);
        System.out.println(t.line("0.3-1 m, tilt 60-70"));
        assertEquals(0, t.wrong, "wrong ids");
        assertTrue(t.rate() >= 0.85, t.line("0.3-1 m, steep"));
    }

    @Test
    void atAboutOneMetreTheErrorsAreWithinTheirBounds() {
        Tally t = run(80, 404, 0.95, 1.05, 0, 60);
        System.out.println(t.line("0.95-1.05 m, tilt 0-60"));
        assertTrue(Tally.median(t.position) <= 0.002, t.line("about 1 m"));
        assertTrue(Tally.median(t.rotation) <= 0.4, t.line("about 1 m"));
    }

    @Test
    void negativeFramesReportNothingWhileBoofCvsDefaultCapReportsMarkersThatAreNotThere() {
        SyntheticCamera camera = new SyntheticCamera(K);
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(SIZE), K);
        ConfigHammingMarker code = ConfigHammingMarker.loadDictionary(HammingDictionary.ARUCO_MIP_36h12);
        FiducialDetector<GrayU8> boofDefault = FactoryFiducial.squareHamming(code, new ConfigFiducialHammingDetector(),
                GrayU8.class);
        MarkerDictionary[] others = {MarkerDictionary.APRILTAG_36H11, MarkerDictionary.ARUCO_6X6_1000,
            MarkerDictionary.ARUCO_MIP_25H7};
        Random random = new Random(505);
        int ours = 0;
        int theirs = 0;
        int frames = 90;
        for (int i = 0; i < frames; i++) {
            GrayImage image;
            if (i % 3 == 0) {
                image = camera.render(List.of(), SceneOptions.camera(random.nextLong()).withClutter(14));
            } else {
                List<PlacedMarker> markers = new ArrayList<>();
                for (int k = 0; k < 2; k++) {
                    Shot s = shot(camera, random, others[random.nextInt(others.length)], 0.3 + 0.7 * random.nextDouble(),
                            50 * random.nextDouble());
                    double[] t = s.marker().translation();
                    t[0] += k == 0 ? -0.12 * t[2] : 0.12 * t[2];
                    markers.add(PlacedMarker.of(s.marker().pattern(), SIZE, s.marker().rotation(), t));
                }
                image = camera.render(markers, SceneOptions.camera(random.nextLong()).withClutter(6));
            }
            ours += tracker.detect(image).size();
            GrayU8 gray = new GrayU8(image.width(), image.height());
            gray.data = image.pixels();
            boofDefault.detect(gray);
            theirs += boofDefault.totalFound();
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
