package org.skinlab.ar;

import java.util.Arrays;

/**
 * One marker found in one image: its id, its four corners in the image and its pose.
 *
 * <p>Conventions: camera x right, y down, z forward; pixel (i, j) has its centre at (i, j). The
 * marker frame has its origin at the centre of the black square, x to the right, y toward the
 * marker's top edge, z out of the printed face; {@code X_cam = R X_marker + t}, in metres. The
 * corners are the printed marker's top-left, top-right, bottom-right, bottom-left, in that order.
 * A marker seen face-on therefore has R = diag(1, -1, -1).
 *
 * <p>Immutable: the accessors return copies.
 */
public final class MarkerDetection {
    private final int id;
    private final double[] corners;
    private final double[] rotation;
    private final double[] translation;
    private final double reprojectionError;

    /**
     * A detection; the arrays are copied, so the caller may reuse them.
     *
     * @param id                the marker's id in its dictionary
     * @param corners           x0, y0, ..., x3, y3: TL, TR, BR, BL in pixels
     * @param rotation          R, 3x3 row-major
     * @param translation       t in metres
     * @param reprojectionError root-mean-square distance, in pixels, between the corners and the
     *                          pose's projection of the marker's corners (NaN when unknown)
     * @throws IllegalArgumentException when {@code corners} is not 8 long, {@code rotation} not 9 or
     *                                  {@code translation} not 3
     */
    public MarkerDetection(int id, double[] corners, double[] rotation, double[] translation,
            double reprojectionError) {
        if (corners.length != 8 || rotation.length != 9 || translation.length != 3) {
            throw new IllegalArgumentException("need 8 corner coordinates, 9 rotation entries and 3 translation entries");
        }
        this.id = id;
        this.corners = corners.clone();
        this.rotation = rotation.clone();
        this.translation = translation.clone();
        this.reprojectionError = reprojectionError;
    }

    /**
     * The marker's id in its dictionary.
     *
     * @return the id: the index of the marker's code in its {@link MarkerDictionary}
     */
    public int id() {
        return id;
    }

    /**
     * x0, y0, ..., x3, y3: TL, TR, BR, BL in pixels.
     *
     * @return a new array of 8: the printed marker's corners in image pixels (x right, y down)
     */
    public double[] corners() {
        return corners.clone();
    }

    /**
     * R, 3x3 row-major.
     *
     * @return a new array of 9: the rotation from marker to camera coordinates, {@code X_cam = R X_marker + t}
     */
    public double[] rotation() {
        return rotation.clone();
    }

    /**
     * t in metres: the marker's centre in camera coordinates.
     *
     * @return a new array of 3: (x, y, z) in metres, z the depth in front of the camera
     */
    public double[] translation() {
        return translation.clone();
    }

    /**
     * Corner x of corner {@code i} (0 TL, 1 TR, 2 BR, 3 BL).
     *
     * @param i the corner, 0 to 3
     * @return the corner's column in pixels
     * @throws ArrayIndexOutOfBoundsException when {@code i} is not 0 to 3
     */
    public double cornerX(int i) {
        return corners[2 * i];
    }

    /**
     * Corner y of corner {@code i} (0 TL, 1 TR, 2 BR, 3 BL).
     *
     * @param i the corner, 0 to 3
     * @return the corner's row in pixels (y down)
     * @throws ArrayIndexOutOfBoundsException when {@code i} is not 0 to 3
     */
    public double cornerY(int i) {
        return corners[2 * i + 1];
    }

    /**
     * Root-mean-square corner reprojection error in pixels (NaN when unknown).
     *
     * @return the error in pixels, 0 or more, or NaN
     */
    public double reprojectionError() {
        return reprojectionError;
    }

    /**
     * Distance from the camera centre to the marker's centre, in metres.
     *
     * @return the length of t in metres
     */
    public double distance() {
        return Math.sqrt(translation[0] * translation[0] + translation[1] * translation[1]
                + translation[2] * translation[2]);
    }

    @Override
    public String toString() {
        return "MarkerDetection[id=" + id + ", t=" + Arrays.toString(translation) + "]";
    }
}
