package org.skinlab.internal.ar;

import java.util.Locale;

/**
 * A printed planar target for camera calibration: a chessboard ({@code rows x cols} squares
 * alternating black and white, the top-left square black; its inner corners are the calibration
 * points) or a square grid ({@code rows x cols} black squares {@code space} apart on white; their
 * corners are the points). Sizes in metres.
 *
 * <p>The one home of the target's geometry: the printable page, the detector's configuration and
 * the synthetic camera all read it from here, so a target prints, renders and is detected as the
 * same thing.
 *
 * @param kind          chessboard or square grid
 * @param rows          squares per column of the pattern
 * @param cols          squares per row of the pattern
 * @param squareMetres  a square's side
 * @param spaceMetres   the white gap between a grid's squares (0 for a chessboard)
 */
public record CalibrationTarget(Kind kind, int rows, int cols, double squareMetres, double spaceMetres) {
    /** The most squares per side we accept: beyond it no A4 page or webcam resolves the squares. */
    public static final int MAX_SQUARES = 40;

    /** The target's kinds, with their command-line names. */
    public enum Kind {
        CHESSBOARD("chessboard"), GRID("grid");

        private final String key;

        Kind(String key) {
            this.key = key;
        }

        public String key() {
            return key;
        }

        /** The kind named {@code key}; IllegalArgumentException listing the names otherwise. */
        public static Kind byKey(String key) {
            for (Kind k : values()) {
                if (k.key.equals(key)) {
                    return k;
                }
            }
            throw new IllegalArgumentException("unknown calibration target \"" + key + "\" (chessboard or grid)");
        }
    }

    public CalibrationTarget {
        if (kind == null) {
            throw new IllegalArgumentException("no target kind (chessboard or grid)");
        }
        // A chessboard of 3x3 squares has 2x2 inner corners: the fewest that fix a homography with
        // a check; a 2x2 grid has 16 corners.
        int min = kind == Kind.CHESSBOARD ? 3 : 2;
        if (rows < min || cols < min || rows > MAX_SQUARES || cols > MAX_SQUARES) {
            throw new IllegalArgumentException(kind.key + " needs " + min + " to " + MAX_SQUARES + " rows and columns of "
                    + "squares: " + rows + "x" + cols);
        }
        if (!(squareMetres > 0) || !Double.isFinite(squareMetres)) {
            throw new IllegalArgumentException("square size must be positive: " + squareMetres);
        }
        if (kind == Kind.CHESSBOARD ? spaceMetres != 0 : !(spaceMetres > 0) || !Double.isFinite(spaceMetres)) {
            throw new IllegalArgumentException(kind == Kind.CHESSBOARD ? "a chessboard has no space between squares"
                    : "a grid's space between squares must be positive: " + spaceMetres);
        }
    }

    /** A chessboard of {@code rows x cols} squares of {@code squareMetres}. */
    public static CalibrationTarget chessboard(int rows, int cols, double squareMetres) {
        return new CalibrationTarget(Kind.CHESSBOARD, rows, cols, squareMetres, 0);
    }

    /** A grid of {@code rows x cols} black squares of {@code squareMetres}, {@code spaceMetres} apart. */
    public static CalibrationTarget grid(int rows, int cols, double squareMetres, double spaceMetres) {
        return new CalibrationTarget(Kind.GRID, rows, cols, squareMetres, spaceMetres);
    }

    /** The pattern's width: from the left edge of the first column of squares to the right edge of the last. */
    public double width() {
        return cols * squareMetres + (cols - 1) * spaceMetres;
    }

    /** The pattern's height. */
    public double height() {
        return rows * squareMetres + (rows - 1) * spaceMetres;
    }

    /** How many calibration points a full view of the target gives. */
    public int points() {
        return kind == Kind.CHESSBOARD ? (rows - 1) * (cols - 1) : 4 * rows * cols;
    }

    /**
     * Whether the point (x, y) of the pattern is black, in metres from its top-left corner (x to the
     * right, y down); outside the pattern: false (white paper).
     */
    public boolean isBlackAt(double x, double y) {
        if (!(x >= 0 && x < width() && y >= 0 && y < height())) {
            return false;
        }
        double pitch = squareMetres + spaceMetres;
        int col = (int) (x / pitch);
        int row = (int) (y / pitch);
        if (kind == Kind.CHESSBOARD) {
            return (row + col) % 2 == 0;
        }
        return x - col * pitch < squareMetres && y - row * pitch < squareMetres;
    }

    /** What the printed page says: "chessboard, 7 x 10 squares of 20 mm". */
    public String describe() {
        String s = kind.key + ", " + rows + " x " + cols + " squares of " + millimetres(squareMetres) + " mm";
        return kind == Kind.GRID ? s + ", " + millimetres(spaceMetres) + " mm apart" : s;
    }

    /** The options that name this target to {@code skinlab calibrate}. */
    public String options() {
        String s = "--target " + kind.key + " --rows " + rows + " --cols " + cols + " --square-mm "
                + millimetres(squareMetres);
        return kind == Kind.GRID ? s + " --space-mm " + millimetres(spaceMetres) : s;
    }

    private static String millimetres(double metres) {
        double mm = metres * 1000;
        double whole = Math.rint(mm);
        return Math.abs(mm - whole) < 1e-9 ? Long.toString((long) whole)
                : String.format(Locale.ROOT, "%.3f", mm).replaceAll("0+$", "");
    }
}
