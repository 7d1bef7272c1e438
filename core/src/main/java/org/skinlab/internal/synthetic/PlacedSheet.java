package org.skinlab.internal.synthetic;

/**
 * A sheet of paper lying in the synthetic scene: its pose and what is printed on it. The sheet's
 * frame has its origin at the centre of the print, x to the right, y toward the print's top edge,
 * z out of the printed face, and {@code X_cam = R X_sheet + t} (the marker's conventions,
 * {@link org.skinlab.ar.MarkerDetection}). {@link PlacedMarker} and {@link PlacedTarget} are the
 * two kinds the tests print.
 */
public interface PlacedSheet {
    /** R, 3x3 row-major (a copy). */
    double[] rotation();

    /** t in metres (a copy). */
    double[] translation();

    /** Half the paper's width in metres: the sheet spans [-w, w] in x. */
    double paperHalfWidth();

    /** Half the paper's height in metres: the sheet spans [-h, h] in y. */
    double paperHalfHeight();

    /**
     * The gray level at (x, y) of the sheet's frame (metres), a point on the paper: ink, paper or
     * whatever lies on it. Called for every ray that meets the sheet, from several threads.
     */
    int grayAt(double x, double y);
}
