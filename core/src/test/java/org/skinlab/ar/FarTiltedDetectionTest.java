package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Random;

import boofcv.alg.fiducial.square.DetectFiducialSquareHamming;
import boofcv.factory.fiducial.ConfigFiducialHammingDetector;
import boofcv.factory.fiducial.ConfigHammingMarker;
import boofcv.factory.filter.binary.FactoryThresholdBinary;
import boofcv.factory.shape.FactoryShapeDetector;
import boofcv.struct.image.GrayF32;
import boofcv.struct.image.GrayU8;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.skinlab.internal.synthetic.MarkerShot;
import org.skinlab.internal.synthetic.MarkerShots;
import org.skinlab.internal.synthetic.NegativeFrames;

/**
 * The goal: markers far away and tilted are found (at least 95% at 1.5-2 m, tilts up to 70
 * degrees) while clutter gives no false marker (1,000 frames), and the decision rule's trade-off.
 *
 * <p><b>The positive set</b>: 210 frames at 1.5-2 m, tilt uniform in 0-70 degrees (seven
 * 10-degree bins of 30) about a random axis in the marker's plane, turned at random about its
 * normal, anywhere in the image with its paper in view; blur sigma 0.5-1.2 px, noise sigma 2-5
 * levels, up to 50% light falloff, every fifth with a disc over the code (radius 0.08 of the
 * marker's width, about 1.3 cells across). Rendered with 2x2 rays per pixel
 * ({@link MarkerShots#inView}). The camera is the app's tracking stream, 640x480 at 60 degrees
 * (fx = 554 px), with a 150 mm marker (the app offers 50-200 mm): 42-55 px wide face-on, 14-19 px
 * across at 70 degrees. The goal is about the marker's size in pixels: a 100 mm marker at 2 m is
 * 28 px face-on and 9-10 px across at 70 degrees, 1.2 px a cell under 0.5-1.2 px of blur, which
 * BoofCV's polygon stage does not outline (it refuses sides under 10 px); the same poses with the
 * 100 mm marker are printed, not claimed (docs/ar.md).
 *
 * <p><b>Clutter</b>: 1,000 frames of 320x240 (the detector's decision is per square; small frames
 * render fast), each with 12 clutter items (the synthetic Background's: dark boxes, squares of
 * random bits, AprilTag 36h11, ArUco 6x6 and MIP_25h7 codes, checkerboards, text, binary textures,
 * our codes with 3-6 bits flipped, pictures in a black frame; 12-120 px, turned and sheared), blur
 * 0.3-1.2 px and noise 2-5 levels ({@link NegativeFrames#clutter}). No marker may be reported with
 * our rule; BoofCV's default cap reports some.
 *
 * <p><b>Trade-off</b>: each candidate square's read (CodeReader: its best code, the sum of its
 * wrong bits' confidences, its uncertain bits) is recorded once, and the detection rate and false
 * markers are counted for each limit; printed, and in docs/ar.md.
 */
class FarTiltedDetectionTest {
    static final CameraIntrinsics K = CameraIntrinsics.fromHorizontalFov(640, 480, 60);
    static final CameraIntrinsics CLUTTER_K = CameraIntrinsics.fromHorizontalFov(320, 240, 60);
    /** The claimed set's marker: the black square's width in metres. */
    static final double SIZE = 0.15;
    static final int BINS = 7;
    /** Frames per tilt bin: the claimed 200 mm set, the reported 100 mm set. */
    static final int[] PER_BIN = {30, 30};
    static final int CLUTTER_FRAMES = 1000;
    /** BoofCV's rule (wrong bits plus half the ambiguous ones) capped at 2, for the trade-off table. */
    static final int OLD_CAP = 2;

    /** The true marker's best read per positive frame (cost, uncertain; NaN: no square read as its code). */
    private static double[][] truthReads;
    private static double[][] truthReadsSmall;
    /** Every square read as a code in the clutter frames: cost, uncertain. */
    private static final List<double[]> clutterReads = new ArrayList<>();
    private static final int[][] found = new int[2][BINS];
    private static final int[][] boofFound = new int[2][BINS];
    private static final int[][] oldFound = new int[2][BINS];
    private static int wrongIds;
    private static int falseOurs;
    private static int falseBoofDefault;
    private static int falseOldCap;

    /** Records every square's read and accepts none (BoofCV's polygons, undistortion and border check). */
    static final class Recorder extends DetectFiducialSquareHamming<GrayU8> {
        final CodeReader reader;
        final List<double[]> reads = new ArrayList<>();

        Recorder() {
            this(MarkerDictionary.DEFAULT.config(), new ConfigFiducialHammingDetector());
        }

        private Recorder(ConfigHammingMarker code, ConfigFiducialHammingDetector c) {
            super(code, c.minimumBlackBorderFraction, FactoryThresholdBinary.threshold(c.configThreshold, GrayU8.class),
                    FactoryShapeDetector.polygon(c.squareDetector, GrayU8.class), GrayU8.class);
            reader = new CodeReader(code);
        }

        @Override
        protected boolean processSquare(GrayF32 square, Result result, double edgeInside, double edgeOutside) {
            if (reader.read(square, edgeInside, edgeOutside)) {
                reads.add(new double[] {reader.id(), reader.cost(), reader.uncertain()});
            }
            return false;
        }
    }

    static GrayU8 gray(GrayImage image) {
        GrayU8 g = new GrayU8(image.width(), image.height());
        g.data = image.pixels();
        return g;
    }

    /** One positive frame: 1.5-2 m, tilt in bin b, the degradations of the class comment. */
    static MarkerShot shot(MarkerShots shots, Random random, int bin) {
        return shots.shot(random, 1.5, 2.0, 10 * bin, 10 * bin + 10);
    }

    @BeforeAll
    static void run() {
        long start = System.nanoTime();
        truthReads = positives(0, SIZE, 1801);
        truthReadsSmall = positives(1, 0.10, 1801);
        System.out.println(table(0, "150 mm marker, 640x480, 1.5-2 m"));
        System.out.println(table(1, "100 mm marker, 640x480, 1.5-2 m (reported, not claimed)"));
        long positives = System.nanoTime();
        NegativeFrames negatives = new NegativeFrames(CLUTTER_K);
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(0.1), CLUTTER_K);
        BoofSquareHamming boofDefault = BoofSquareHamming.capped(MarkerDictionary.DEFAULT,
                MarkerDictionary.DEFAULT.minimumHamming());
        BoofSquareHamming oldCap = BoofSquareHamming.capped(MarkerDictionary.DEFAULT, OLD_CAP);
        Recorder recorder = new Recorder();
        Random random = new Random(1803);
        for (int i = 0; i < CLUTTER_FRAMES; i++) {
            GrayImage image = negatives.clutter(random);
            falseOurs += tracker.detect(image).size();
            falseBoofDefault += boofDefault.detect(image);
            falseOldCap += oldCap.detect(image);
            recorder.reads.clear();
            recorder.process(gray(image));
            for (double[] read : recorder.reads) {
                clutterReads.add(new double[] {read[1], read[2]});
            }
        }
        System.out.printf(Locale.ROOT, "positives %.1f s, %d clutter frames %.1f s%n", (positives - start) * 1e-9,
                CLUTTER_FRAMES, (System.nanoTime() - positives) * 1e-9);
    }

    private static double[][] positives(int set, double size, long seed) {
        MarkerShots shots = MarkerShots.inView(K, size);
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(size), K);
        BoofSquareHamming boofDefault = BoofSquareHamming.capped(MarkerDictionary.DEFAULT,
                MarkerDictionary.DEFAULT.minimumHamming());
        BoofSquareHamming oldCap = BoofSquareHamming.capped(MarkerDictionary.DEFAULT, OLD_CAP);
        Recorder recorder = new Recorder();
        Random random = new Random(seed);
        int per = PER_BIN[set];
        double[][] reads = new double[BINS * per][];
        for (int bin = 0; bin < BINS; bin++) {
            for (int i = 0; i < per; i++) {
                MarkerShot shot = shot(shots, random, bin);
                GrayImage image = shot.image();
                int id = shot.marker().pattern().id();
                for (MarkerDetection d : tracker.detect(image)) {
                    if (d.id() == id) {
                        found[set][bin]++;
                    } else {
                        wrongIds++;
                    }
                }
                int n = boofDefault.detect(image);
                for (int k = 0; k < n; k++) {
                    boofFound[set][bin] += boofDefault.id(k) == id ? 1 : 0;
                }
                n = oldCap.detect(image);
                for (int k = 0; k < n; k++) {
                    oldFound[set][bin] += oldCap.id(k) == id ? 1 : 0;
                }
                recorder.reads.clear();
                recorder.process(gray(image));
                double[] best = {Double.NaN, Double.NaN};
                for (double[] read : recorder.reads) {
                    if (read[0] == id && !(read[1] >= best[0])) {
                        best = new double[] {read[1], read[2]};
                    }
                }
                reads[bin * per + i] = best;
            }
        }
        return reads;
    }

    private static int total(int[] bins) {
        int sum = 0;
        for (int b : bins) {
            sum += b;
        }
        return sum;
    }

    private static String table(int set, String name) {
        int per = PER_BIN[set];
        StringBuilder s = new StringBuilder(name + "\n| tilt (degrees) | found, our rule | cap 2 with BoofCV's rule"
                + " | BoofCV's default |\n|---|---|---|---|\n");
        for (int b = 0; b < BINS; b++) {
            s.append(String.format(Locale.ROOT, "| %d-%d | %d of %d | %d | %d |%n", 10 * b, 10 * b + 10, found[set][b], per,
                    oldFound[set][b], boofFound[set][b]));
        }
        int n = BINS * per;
        s.append(String.format(Locale.ROOT, "| all | %d of %d (%.1f%%) | %d (%.1f%%) | %d (%.1f%%) |%n", total(found[set]), n,
                100.0 * total(found[set]) / n, total(oldFound[set]), 100.0 * total(oldFound[set]) / n,
                total(boofFound[set]), 100.0 * total(boofFound[set]) / n));
        return s.toString();
    }

    @Test
    void farTiltedMarkersAreFound() {
        assertEquals(0, wrongIds, "wrong ids");
        assertTrue(total(found[0]) >= 0.95 * BINS * PER_BIN[0], "found " + total(found[0]) + " of " + BINS * PER_BIN[0]);
    }

    @Test
    void clutterGivesNoFalseMarkerWhileBoofCvsDefaultCapGivesSome() {
        System.out.printf("clutter frames: %d, squares read as a code within 5 bits: %d, false markers: ours %d,"
                + " BoofCV's default cap %d, cap 2 with BoofCV's rule %d%n", CLUTTER_FRAMES, clutterReads.size(), falseOurs,
                falseBoofDefault, falseOldCap);
        assertEquals(0, falseOurs, "false markers with our rule");
        assertTrue(falseBoofDefault > 0, "BoofCV's default cap reports false markers on these frames");
    }

    @Test
    void tradeOff() {
        StringBuilder s = new StringBuilder("| weighted errors at most | uncertain bits at most | found, 150 mm | found,"
                + " 100 mm | false markers in 1,000 clutter frames |\n|---|---|---|---|---|\n");
        double[] limits = {0, 0.5, 0.75, 1, 1.25, 1.5, 1.75, 2, 2.5, 3, 5};
        int[] uncertain = {4, 9, 16, 36};
        int ourFalse = -1;
        for (int u : uncertain) {
            for (double l : limits) {
                int f = 0;
                for (double[] c : clutterReads) {
                    f += c[0] <= l && c[1] <= u ? 1 : 0;
                }
                if (l == TrackerConfig.DEFAULT_MAX_BIT_ERRORS && u == TrackerConfig.MAX_UNCERTAIN_BITS) {
                    ourFalse = f;
                }
                s.append(String.format(Locale.ROOT, "| %.2f | %d | %.1f%% | %.1f%% | %d |%n", l, u,
                        100 * rate(truthReads, l, u), 100 * rate(truthReadsSmall, l, u), f));
            }
        }
        System.out.print(s);
        // The recorded reads predict what the tracker does with the default rule.
        assertEquals(falseOurs, ourFalse, "the recorder agrees with the tracker on clutter");
        double predicted = rate(truthReads, TrackerConfig.DEFAULT_MAX_BIT_ERRORS, TrackerConfig.MAX_UNCERTAIN_BITS);
        assertEquals(predicted, total(found[0]) / (double) (BINS * PER_BIN[0]), 0.01, "the recorder agrees with the tracker");
    }

    private static double rate(double[][] reads, double limit, int uncertain) {
        int n = 0;
        for (double[] r : reads) {
            n += r[0] <= limit && r[1] <= uncertain ? 1 : 0;
        }
        return n / (double) reads.length;
    }
}
