package org.skinlab.internal.synthetic;

import java.util.Random;

import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.MarkerPattern;

/**
 * What a synthetic frame shows behind the markers, drawn in image space: a seeded smooth texture
 * with blocky detail and, with {@link SceneOptions#clutter()}, that many items of what a desk, a
 * wall or a shelf shows and a marker detector may mistake for a marker, each turned and sheared at
 * random (a flat thing seen at a slant), 12 pixels to half the image's smaller side wide:
 * <ul>
 * <li>dark boxes;</li>
 * <li>squares of random bits inside a black border, 8x8 cells like our default code's (not a code
 * of any dictionary by intent);</li>
 * <li>other dictionaries' codes (AprilTag 36h11, ArUco 6x6 and MIP_25h7) on white paper;</li>
 * <li>checkerboards of 3-9 squares a side on white paper;</li>
 * <li>text: lines of glyphs of 2-4 random strokes each (letters as a detector sees them);</li>
 * <li>binary textures: grids of 4-16 random black and white cells, no border;</li>
 * <li>near-codes: a code of our default dictionary with 3-6 of its bits flipped, the worst a
 * square of random bits can be (one within 2 bits of a code is as rare as 1e-5 per square);</li>
 * <li>framed pictures: a black border around smooth gray shapes (a photo, a poster), whose
 * "bits" are neither black nor white.</li>
 * </ul>
 * Immutable once made, shared by the rendering threads.
 */
final class Background {
    private static final int KINDS = 8;
    private static final int BOX = 0, BITS = 1, CODE = 2, CHECKER = 3, TEXT = 4, TEXTURE = 5, NEAR_CODE = 6, PICTURE = 7;
    private static final MarkerDictionary[] OTHER_CODES = {MarkerDictionary.APRILTAG_36H11,
        MarkerDictionary.ARUCO_6X6_1000, MarkerDictionary.ARUCO_MIP_25H7};

    private final double p1, p2, p3;
    private final long salt;
    private final int count;
    /** Per item: kind, bounds x0, y0, x1, y1, then the image-to-item map u = a0 + a1 x + a2 y, v = b0 + b1 x + b2 y. */
    private final double[] items;
    /** Per item: its random bits (bit squares, textures, glyph strokes), its ink and paper grays. */
    private final long[] bits;
    private final int[] grid;
    private final double[] ink;
    private final double[] paper;
    private final MarkerPattern[] codes;
    private static final int STRIDE = 11;

    Background(Random random, int w, int h, int count) {
        p1 = random.nextDouble() * 6.28;
        p2 = random.nextDouble() * 6.28;
        p3 = random.nextDouble() * 6.28;
        salt = random.nextLong();
        this.count = count;
        items = new double[STRIDE * count];
        bits = new long[count];
        grid = new int[count];
        ink = new double[count];
        paper = new double[count];
        codes = new MarkerPattern[count];
        for (int i = 0; i < count; i++) {
            int kind = random.nextInt(KINDS);
            double size = 12 + random.nextDouble() * (Math.min(w, h) / 2.0 - 12);
            double aspect = kind == BOX || kind == TEXT ? 0.3 + random.nextDouble() : 0.6 + 0.8 * random.nextDouble();
            double angle = random.nextDouble() * 2 * Math.PI;
            double shear = (random.nextDouble() - 0.5) * 0.6;
            double cx = random.nextDouble() * w;
            double cy = random.nextDouble() * h;
            // Item (u, v) in [0, 1)^2 to image: centre + R * (S * [[1, shear], [0, 1]]) * (u - 1/2, v - 1/2).
            double sx = size, sy = size * aspect;
            double c = Math.cos(angle), s = Math.sin(angle);
            double m00 = c * sx, m01 = c * shear * sx - s * sy, m10 = s * sx, m11 = s * shear * sx + c * sy;
            double det = m00 * m11 - m01 * m10;
            int o = STRIDE * i;
            items[o] = kind;
            double ex = (Math.abs(m00) + Math.abs(m01)) / 2, ey = (Math.abs(m10) + Math.abs(m11)) / 2;
            items[o + 1] = cx - ex;
            items[o + 2] = cy - ey;
            items[o + 3] = cx + ex;
            items[o + 4] = cy + ey;
            items[o + 6] = m11 / det;
            items[o + 7] = -m01 / det;
            items[o + 5] = 0.5 - items[o + 6] * cx - items[o + 7] * cy;
            items[o + 9] = -m10 / det;
            items[o + 10] = m00 / det;
            items[o + 8] = 0.5 - items[o + 9] * cx - items[o + 10] * cy;
            bits[i] = random.nextLong();
            grid[i] = kind == CHECKER ? 3 + random.nextInt(7) : kind == TEXTURE ? 4 + random.nextInt(13)
                    : kind == TEXT ? 2 + random.nextInt(4) : 0;
            ink[i] = kind == BITS ? SyntheticCamera.INK : 15 + 50 * random.nextDouble();
            paper[i] = 170 + 70 * random.nextDouble();
            if (kind == CODE) {
                MarkerDictionary d = OTHER_CODES[random.nextInt(OTHER_CODES.length)];
                codes[i] = MarkerPattern.of(d, random.nextInt(d.codeCount()));
            } else if (kind == NEAR_CODE) {
                codes[i] = MarkerPattern.of(MarkerDictionary.DEFAULT, random.nextInt(MarkerDictionary.DEFAULT.codeCount()));
                int cells = codes[i].cells();
                long flips = 0;
                for (int k = 3 + random.nextInt(4); Long.bitCount(flips) < k; ) {
                    flips |= 1L << ((1 + random.nextInt(cells - 2)) * cells + 1 + random.nextInt(cells - 2));
                }
                bits[i] = flips;
            }
        }
    }

    /** The gray level at image point (x, y). */
    double at(double x, double y) {
        for (int i = count - 1; i >= 0; i--) {
            int o = STRIDE * i;
            if (x < items[o + 1] || x >= items[o + 3] || y < items[o + 2] || y >= items[o + 4]) {
                continue;
            }
            double u = items[o + 5] + items[o + 6] * x + items[o + 7] * y;
            double v = items[o + 8] + items[o + 9] * x + items[o + 10] * y;
            if (u < 0 || u >= 1 || v < 0 || v >= 1) {
                continue;
            }
            return item(i, (int) items[o], u, v);
        }
        double smooth = 125 + 45 * Math.sin(0.031 * x + p1) * Math.sin(0.027 * y + p2)
                + 15 * Math.sin(0.11 * x + 0.07 * y + p3);
        long block = ((long) Math.floor(x / 7) * 73856093L) ^ ((long) Math.floor(y / 7) * 19349663L) ^ salt;
        block = block * 0x9E3779B97F4A7C15L;
        return smooth + ((block >>> 40) & 31) - 16;
    }

    private double item(int i, int kind, double u, double v) {
        switch (kind) {
            case BOX:
                return ink[i] + 20;
            case BITS: {
                // A black-bordered square of 8x8 cells whose inner 6x6 are random bits.
                int cx = (int) (u * 8), cy = (int) (v * 8);
                if (cx == 0 || cy == 0 || cx == 7 || cy == 7) {
                    return ink[i];
                }
                return (bits[i] >>> ((cy - 1) * 6 + cx - 1) & 1) == 0 ? ink[i] : paper[i];
            }
            case CODE: {
                // The code on paper with a quiet zone of a fifth of its width each side.
                double cu = (u - 0.2) / 0.6, cv = (v - 0.2) / 0.6;
                return codes[i].isBlackAt(cu, cv) ? ink[i] : paper[i];
            }
            case CHECKER: {
                double cu = (u - 0.1) / 0.8, cv = (v - 0.1) / 0.8;
                if (cu < 0 || cu >= 1 || cv < 0 || cv >= 1) {
                    return paper[i];
                }
                int n = grid[i];
                return (((int) (cu * n) + (int) (cv * n)) & 1) == 0 ? ink[i] : paper[i];
            }
            case NEAR_CODE: {
                double cu = (u - 0.2) / 0.6, cv = (v - 0.2) / 0.6;
                MarkerPattern code = codes[i];
                if (cu < 0 || cu >= 1 || cv < 0 || cv >= 1) {
                    return paper[i];
                }
                int n = code.cells();
                int cell = (int) (cv * n) * n + (int) (cu * n);
                return code.isBlackAt(cu, cv) ^ (bits[i] >>> cell & 1) != 0 ? ink[i] : paper[i];
            }
            case PICTURE: {
                if (u < 0.125 || u >= 0.875 || v < 0.125 || v >= 0.875) {
                    return ink[i];
                }
                double a = (bits[i] & 0xFFFF) / 65536.0 * 6.28, b = (bits[i] >>> 16 & 0xFFFF) / 65536.0 * 6.28;
                double f = 4 + (bits[i] >>> 32 & 7);
                return (ink[i] + paper[i]) / 2 + (paper[i] - ink[i]) * 0.3 * Math.sin(f * u + a) * Math.sin(f * v + b);
            }
            case TEXT:
                return glyphInk(i, u, v) ? ink[i] : paper[i];
            default: {
                int n = grid[i];
                long cell = hash(bits[i], (int) (v * n) * 64 + (int) (u * n));
                return (cell & 1) == 0 ? ink[i] : paper[i];
            }
        }
    }

    /** Whether (u, v) of a text item is on a glyph's stroke: lines of glyphs half as wide as high. */
    private boolean glyphInk(int i, double u, double v) {
        int lines = grid[i];
        double lv = v * lines;
        int line = (int) lv;
        double gv = (lv - line) / 0.8 - 0.1;
        int perLine = 2 * (int) Math.max(1, Math.round(lines * (items[STRIDE * i + 3] - items[STRIDE * i + 1])
                / (items[STRIDE * i + 4] - items[STRIDE * i + 2])));
        double lu = u * perLine;
        int column = (int) lu;
        double gu = (lu - column) / 0.8 - 0.1;
        if (gu < 0 || gu >= 1 || gv < 0 || gv >= 1) {
            return false;
        }
        long h = hash(bits[i], line * 1024 + column);
        int strokes = 2 + (int) ((h >>> 60) % 3);
        // Strokes between points of a 3x4 grid over the glyph box; 0.09 of its height half-thick.
        for (int k = 0; k < strokes; k++) {
            long s = h >>> (k * 14);
            double ax = (s & 3) % 3 / 2.0, ay = (s >>> 2 & 3) / 3.0;
            double bx = (s >>> 4 & 3) % 3 / 2.0, by = (s >>> 6 & 3) / 3.0;
            if (segmentDistance(gu, gv, ax, ay, bx, by) < 0.09) {
                return true;
            }
        }
        return false;
    }

    private static double segmentDistance(double px, double py, double ax, double ay, double bx, double by) {
        double dx = bx - ax, dy = by - ay;
        double len = dx * dx + dy * dy;
        double t = len == 0 ? 0 : Math.max(0, Math.min(1, ((px - ax) * dx + (py - ay) * dy) / len));
        return Math.hypot(px - ax - t * dx, py - ay - t * dy);
    }

    private static long hash(long seed, int key) {
        long z = seed + key * 0x9E3779B97F4A7C15L;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }
}
