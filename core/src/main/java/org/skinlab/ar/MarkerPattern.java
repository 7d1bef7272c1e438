package org.skinlab.ar;

import boofcv.alg.drawing.FiducialImageEngine;
import boofcv.alg.fiducial.square.FiducialSquareHammingGenerator;
import boofcv.factory.fiducial.ConfigHammingMarker;
import boofcv.struct.image.GrayU8;

/**
 * The printed marker of one code: a square grid of black and white cells, the outer ring of cells
 * black (the border the detector finds), the inner {@code gridWidth x gridWidth} cells the code's
 * bits. The black square, all cells together, is the marker's size: a "100 mm marker" has a black
 * square 100 mm wide. Printed, it needs a white quiet zone around it (at least one cell; we print
 * two) so that the border's outer edge shows.
 *
 * <p>The one home of the pattern: the printable marker, the synthetic camera and the tests draw
 * from here. The cells are read from BoofCV's own marker generator, so they are the detector's
 * notion of the code (bit order, orientation) by construction.
 */
public final class MarkerPattern {
    /** Generator pixels per cell: cell centres are then far from every edge. */
    private static final int PIXELS_PER_CELL = 16;

    private final MarkerDictionary dictionary;
    private final int id;
    private final int cells;
    private final boolean[] black;

    private MarkerPattern(MarkerDictionary dictionary, int id, int cells, boolean[] black) {
        this.dictionary = dictionary;
        this.id = id;
        this.cells = cells;
        this.black = black;
    }

    /**
     * The pattern of code {@code id} of {@code dictionary}.
     *
     * @param dictionary the dictionary the code belongs to
     * @param id         the code's id, 0 to {@code dictionary.codeCount() - 1}
     * @return a new pattern whose cells are read from BoofCV's marker generator
     * @throws IllegalArgumentException when {@code id} is not in the dictionary
     */
    public static MarkerPattern of(MarkerDictionary dictionary, int id) {
        ConfigHammingMarker config = dictionary.config();
        if (id < 0 || id >= config.encoding.size()) {
            throw new IllegalArgumentException("marker id " + id + " is not in " + dictionary.key() + " (ids 0 to "
                    + (config.encoding.size() - 1) + ")");
        }
        int cells = config.gridWidth + 2;
        int px = cells * PIXELS_PER_CELL;
        FiducialImageEngine engine = new FiducialImageEngine();
        engine.configure(0, px);
        FiducialSquareHammingGenerator generator = new FiducialSquareHammingGenerator(config);
        generator.setRenderer(engine);
        generator.setMarkerWidth(px);
        generator.generate(id);
        GrayU8 image = engine.getGray();
        boolean[] black = new boolean[cells * cells];
        for (int row = 0; row < cells; row++) {
            for (int col = 0; col < cells; col++) {
                int x = col * PIXELS_PER_CELL + PIXELS_PER_CELL / 2;
                int y = row * PIXELS_PER_CELL + PIXELS_PER_CELL / 2;
                black[row * cells + col] = image.get(x, y) < 128;
            }
        }
        return new MarkerPattern(dictionary, id, cells, black);
    }

    /**
     * The dictionary whose code this is.
     *
     * @return the dictionary given to {@link #of}
     */
    public MarkerDictionary dictionary() {
        return dictionary;
    }

    /**
     * The code's id in its dictionary.
     *
     * @return the id given to {@link #of}, 0 to {@code dictionary().codeCount() - 1}
     */
    public int id() {
        return id;
    }

    /**
     * Cells per side of the black square, border included (8 for 36h12).
     *
     * @return the dictionary's {@link MarkerDictionary#gridWidth()} plus 2
     */
    public int cells() {
        return cells;
    }

    /**
     * Whether the cell at {@code row} (0 = the printed marker's top) and {@code col} (0 = left) is black.
     *
     * @param row the cell's row, 0 to {@link #cells()} - 1, counted down from the top edge
     * @param col the cell's column, 0 to {@link #cells()} - 1, counted from the left edge
     * @return true for a black cell (always for the border ring), false for a white one
     * @throws IndexOutOfBoundsException when the cell is outside the grid
     */
    public boolean isBlack(int row, int col) {
        if (row < 0 || row >= cells || col < 0 || col >= cells) {
            throw new IndexOutOfBoundsException("cell (" + row + ", " + col + ") outside " + cells + "x" + cells);
        }
        return black[row * cells + col];
    }

    /**
     * Whether the point (u, v) of the black square, both in [0, 1) from its top-left corner (u to
     * the right, v down), is black; outside the square: false (white paper).
     *
     * @param u the horizontal position as a fraction of the square's width, 0 at its left edge
     * @param v the vertical position as a fraction of the square's height, 0 at its top edge
     * @return true when the cell containing (u, v) is black, false when it is white or (u, v) lies outside
     *         [0, 1) x [0, 1) (NaN included)
     */
    public boolean isBlackAt(double u, double v) {
        if (!(u >= 0 && u < 1 && v >= 0 && v < 1)) {
            return false;
        }
        return black[(int) (v * cells) * cells + (int) (u * cells)];
    }
}
