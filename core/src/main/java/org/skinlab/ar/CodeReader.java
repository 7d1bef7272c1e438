package org.skinlab.ar;

import boofcv.alg.fiducial.qrcode.PackedBits32;
import boofcv.alg.misc.ImageMiscOps;
import boofcv.factory.fiducial.ConfigHammingMarker;
import boofcv.struct.image.GrayF32;

/**
 * Reads a candidate square's code bits with a confidence each and finds the code that explains
 * them best: the one home of the read that {@link ConfidentHammingDetector} judges.
 *
 * <p>BoofCV hands over each candidate square undistorted (perspective and lens removed), its code
 * cells {@value #CELL} pixels wide in the middle, with the mean gray just inside and just outside
 * its black border. A cell's value is the mean of its central samples (BoofCV's own window, 2
 * pixels in from each side, away from the neighbours); the threshold is halfway between the two
 * edge grays, and a cell's <i>confidence</i> is its distance from the threshold in units of half
 * that contrast, at most 1: a crisp cell is 1, a cell smeared with its neighbours by blur or cut
 * by an occluder is near 0.
 *
 * <p>The best code is the one whose wrong bits have the smallest sum of confidences (a soft
 * decision: a wrong uncertain bit costs little) over every code and rotation, among those within
 * the dictionary's correctable distance {@code (minimumHamming - 1) / 2}; beyond that a read may be
 * nearer another code than the printed one. Mutable, one per detector; allocation-free.
 */
final class CodeReader {
    /** BoofCV's undistorted square: pixels per code cell (DetectFiducialSquareHamming.w). */
    static final int CELL = 10;
    /** A bit this far from the threshold, in half-contrasts, or less, is uncertain. */
    static final double UNCERTAIN = 0.5;

    private final int gridWidth;
    private final int maxErrors;
    /** Each code's bits in BoofCV's order: bit k of the long is the code's bit k. */
    private final long[] codes;
    /** The cells' signed confidence (+ white), row by row, and a copy for rotating. */
    private final GrayF32 cells;
    private final GrayF32 rotated;
    private final float[][] confidence = new float[4][];
    private final long[] bits = new long[4];

    private int id;
    private int errors;
    private double cost;
    private int uncertain;

    CodeReader(ConfigHammingMarker dictionary) {
        gridWidth = dictionary.gridWidth;
        int n = gridWidth * gridWidth;
        if (n > 64) {
            throw new IllegalArgumentException("codes of more than 64 bits: " + gridWidth + "x" + gridWidth);
        }
        maxErrors = (dictionary.minimumHamming - 1) / 2;
        codes = new long[dictionary.encoding.size()];
        for (int m = 0; m < codes.length; m++) {
            PackedBits32 p = dictionary.encoding.get(m).pattern;
            for (int k = 0; k < n; k++) {
                codes[m] |= (long) p.get(k) << k;
            }
        }
        cells = new GrayF32(gridWidth, gridWidth);
        rotated = new GrayF32(gridWidth, gridWidth);
        for (int o = 0; o < 4; o++) {
            confidence[o] = new float[n];
        }
    }

    /**
     * Reads {@code square} (BoofCV's undistorted square, black border included) whose border's
     * inner and outer edges average {@code edgeInside} and {@code edgeOutside}; false when no code
     * is within the correctable distance (or the border shows no contrast).
     */
    boolean read(GrayF32 square, double edgeInside, double edgeOutside) {
        id = -1;
        errors = Integer.MAX_VALUE;
        cost = Double.POSITIVE_INFINITY;
        uncertain = gridWidth * gridWidth;
        double threshold = (edgeInside + edgeOutside) / 2;
        double half = (edgeOutside - edgeInside) / 2;
        if (!(half > 0)) {
            return false;
        }
        int off = (square.width - CELL * gridWidth) / 2;
        int window = CELL - 4;
        uncertain = 0;
        for (int row = 0; row < gridWidth; row++) {
            for (int col = 0; col < gridWidth; col++) {
                double sum = 0;
                for (int y = off + row * CELL + 2; y < off + (row + 1) * CELL - 2; y++) {
                    int index = square.startIndex + y * square.stride + off + col * CELL + 2;
                    for (int x = 0; x < window; x++) {
                        sum += square.data[index + x];
                    }
                }
                double z = Math.max(-1, Math.min(1, (sum / (window * window) - threshold) / half));
                uncertain += Math.abs(z) <= UNCERTAIN ? 1 : 0;
                cells.data[row * gridWidth + col] = (float) z;
            }
        }
        // The read in BoofCV's four rotations and bit order (white = 1, the grid's last cell is bit 0).
        int n = gridWidth * gridWidth;
        for (int o = 0; o < 4; o++) {
            long value = 0;
            float[] conf = confidence[o];
            for (int i = 0; i < n; i++) {
                float z = cells.data[i];
                int k = n - 1 - i;
                value |= (z > 0 ? 1L : 0L) << k;
                conf[k] = Math.abs(z);
            }
            bits[o] = value;
            ImageMiscOps.rotateCW(cells, rotated);
            cells.setTo(rotated);
        }
        for (int m = 0; m < codes.length; m++) {
            for (int o = 0; o < 4; o++) {
                long wrong = bits[o] ^ codes[m];
                int e = Long.bitCount(wrong);
                if (e > maxErrors) {
                    continue;
                }
                double c = 0;
                for (long rest = wrong; rest != 0; rest &= rest - 1) {
                    c += confidence[o][Long.numberOfTrailingZeros(rest)];
                }
                if (c < cost || (c == cost && e < errors)) {
                    cost = c;
                    errors = e;
                    id = m;
                }
            }
        }
        return id >= 0;
    }

    /** The best code of the last read, or -1. */
    int id() {
        return id;
    }

    /** Its wrong bits, counted plainly. */
    int errors() {
        return errors;
    }

    /** The sum of its wrong bits' confidences (each 0 to 1). */
    double cost() {
        return cost;
    }

    /** How many of the last read's bits were uncertain (confidence at most {@link #UNCERTAIN}). */
    int uncertain() {
        return uncertain;
    }
}
