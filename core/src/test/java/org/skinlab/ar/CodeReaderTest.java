package org.skinlab.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import boofcv.alg.fiducial.square.DetectFiducialSquareHamming;
import boofcv.alg.fiducial.square.FoundFiducial;
import boofcv.factory.fiducial.ConfigFiducialHammingDetector;
import boofcv.factory.fiducial.ConfigHammingMarker;
import boofcv.factory.filter.binary.FactoryThresholdBinary;
import boofcv.factory.shape.FactoryShapeDetector;
import boofcv.struct.image.GrayF32;
import boofcv.struct.image.GrayU8;
import org.junit.jupiter.api.Test;

/**
 * CodeReader against BoofCV's own decoder on crisp, face-on codes with known bits flipped (drawn
 * cell by cell, in all four orientations): the same code, the same count of wrong bits, and each
 * crisp wrong bit costing nearly 1; faint cells are uncertain. And the tracker's rule on them.
 */
class CodeReaderTest {
    static final int CELL = 12;
    static final int W = 240;
    static final int H = 200;

    /** BoofCV's decoder with a limit of 5 wrong bits and no charge for ambiguous ones, and our read of the same squares. */
    static final class Both extends DetectFiducialSquareHamming<GrayU8> {
        final CodeReader reader;
        final List<double[]> ours = new ArrayList<>();

        Both() {
            this(MarkerDictionary.DEFAULT.config(), new ConfigFiducialHammingDetector());
        }

        private Both(ConfigHammingMarker code, ConfigFiducialHammingDetector c) {
            super(code, c.minimumBlackBorderFraction, FactoryThresholdBinary.threshold(c.configThreshold, GrayU8.class),
                    FactoryShapeDetector.polygon(c.squareDetector, GrayU8.class), GrayU8.class);
            reader = new CodeReader(code);
            description.minimumHamming = 5;
            setAmbiguousPenaltyFrac(0);
        }

        @Override
        protected boolean processSquare(GrayF32 square, Result result, double edgeInside, double edgeOutside) {
            boolean read = reader.read(square, edgeInside, edgeOutside);
            boolean boof = super.processSquare(square, result, edgeInside, edgeOutside);
            if (boof) {
                ours.add(read ? new double[] {reader.id(), reader.errors(), reader.cost(), reader.uncertain()} : null);
            }
            return boof;
        }
    }

    /**
     * Code {@code id} drawn face-on, turned by {@code quarter} quarter turns, with the inner cells in
     * {@code flipped} inverted and those in {@code faint} near the threshold (cells numbered row * 8 +
     * col).
     */
    static GrayImage draw(int id, int quarter, List<Integer> flipped, List<Integer> faint) {
        MarkerPattern p = MarkerPattern.of(MarkerDictionary.DEFAULT, id);
        int n = p.cells();
        byte[] pixels = new byte[W * H];
        java.util.Arrays.fill(pixels, (byte) 220);
        int x0 = (W - n * CELL) / 2;
        int y0 = (H - n * CELL) / 2;
        for (int row = 0; row < n; row++) {
            for (int col = 0; col < n; col++) {
                int cell = row * n + col;
                int level = p.isBlack(row, col) ^ flipped.contains(cell) ? 30 : 220;
                if (faint.contains(cell)) {
                    // On the right side of the threshold (125) but only 15 levels from it.
                    level = level < 125 ? 110 : 140;
                }
                // Turned: the cell (row, col) lands at (r, c) after `quarter` clockwise quarter turns.
                int r = row;
                int c = col;
                for (int q = 0; q < quarter; q++) {
                    int t = r;
                    r = c;
                    c = n - 1 - t;
                }
                for (int y = 0; y < CELL; y++) {
                    for (int x = 0; x < CELL; x++) {
                        pixels[(y0 + r * CELL + y) * W + x0 + c * CELL + x] = (byte) level;
                    }
                }
            }
        }
        return new GrayImage(W, H, W, pixels);
    }

    static List<Integer> innerCells(Random random, int count) {
        List<Integer> cells = new ArrayList<>();
        while (cells.size() < count) {
            int cell = (1 + random.nextInt(6)) * 8 + 1 + random.nextInt(6);
            if (!cells.contains(cell)) {
                cells.add(cell);
            }
        }
        return cells;
    }

    @Test
    void theReadAgreesWithBoofCvsDecoderAndCrispWrongBitsCostNearlyOne() {
        Random random = new Random(5);
        Both both = new Both();
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(W, H, 60);
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(0.1), k);
        for (int flips = 0; flips <= 5; flips++) {
            for (int quarter = 0; quarter < 4; quarter++) {
                int id = random.nextInt(250);
                GrayImage image = draw(id, quarter, innerCells(random, flips), List.of());
                GrayU8 gray = new GrayU8(W, H);
                gray.data = image.pixels();
                both.ours.clear();
                both.process(gray);
                String where = flips + " flipped, " + quarter + " quarter turns";
                assertEquals(1, both.getFound().size, where);
                FoundFiducial f = both.getFound().get(0);
                double[] read = both.ours.get(0);
                assertEquals(id, f.id, where);
                assertEquals(flips, (int) f.encodingError, where);
                assertEquals(id, (int) read[0], where);
                assertEquals(flips, (int) read[1], where);
                // Crisp cells: each wrong bit costs its confidence, within 5% of 1; none uncertain.
                assertEquals(flips, read[2], 0.05 * flips + 1e-9, where);
                assertEquals(0, (int) read[3], where);
                // The rule: no wrong crisp bit beyond DEFAULT_MAX_BIT_ERRORS (1).
                int found = tracker.detect(image).size();
                assertEquals(flips <= TrackerConfig.DEFAULT_MAX_BIT_ERRORS ? 1 : 0, found, where);
            }
        }
    }

    @Test
    void faintCellsAreUncertainAndTooManyRejectTheSquare() {
        Random random = new Random(6);
        Both both = new Both();
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(W, H, 60);
        FiducialTracker tracker = new FiducialTracker(TrackerConfig.defaults(0.1), k);
        for (int faint : new int[] {2, TrackerConfig.MAX_UNCERTAIN_BITS, TrackerConfig.MAX_UNCERTAIN_BITS + 1, 16}) {
            GrayImage image = draw(random.nextInt(250), 0, List.of(), innerCells(random, faint));
            GrayU8 gray = new GrayU8(W, H);
            gray.data = image.pixels();
            both.ours.clear();
            both.process(gray);
            // 15 levels of a contrast of 190: confidence 0.16, uncertain, and right.
            assertEquals(1, both.ours.size(), faint + " faint cells");
            double[] read = both.ours.get(0);
            assertEquals(faint, (int) read[3], faint + " faint cells");
            assertEquals(0, (int) read[1], faint + " faint cells");
            int found = tracker.detect(image).size();
            assertEquals(faint <= TrackerConfig.MAX_UNCERTAIN_BITS ? 1 : 0, found, faint + " faint cells");
        }
    }
}
