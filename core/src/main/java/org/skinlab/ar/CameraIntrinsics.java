package org.skinlab.ar;

/**
 * A camera's intrinsics in pixels: the pinhole (focal lengths, principal point) and the lens'
 * distortion ({@link LensDistortion}, {@link LensDistortion#NONE} for an ideal or already
 * undistorted image).
 *
 * <p>Conventions (the ones {@code skinlab track} writes and other tools score): camera x to the
 * right, y down, z forward; pixel (i, j) has its centre at (i, j), so the image spans
 * [-0.5, width - 0.5] in x. A point (X, Y, Z) appears at pixel {@code u = fx x_d + cx},
 * {@code v = fy y_d + cy}, where (x_d, y_d) is (X / Z, Y / Z) distorted ({@link #toPixel}).
 *
 * @param width  image width in pixels
 * @param height image height in pixels
 * @param fx     focal length along x, in pixels
 * @param fy     focal length along y, in pixels
 * @param cx     principal point x (pixel-centre-at-integer convention)
 * @param cy     principal point y
 * @param distortion the lens' Brown-Conrady terms, in normalised coordinates (so they hold at any
 *                   resolution of the same sensor area)
 */
public record CameraIntrinsics(int width, int height, double fx, double fy, double cx, double cy,
        LensDistortion distortion) {

    /**
     * Checks the components; see the record's comment for what each one means.
     *
     * @param width      image width in pixels
     * @param height     image height in pixels
     * @param fx         focal length along x, in pixels
     * @param fy         focal length along y, in pixels
     * @param cx         principal point x, in pixels (pixel-centre-at-integer convention)
     * @param cy         principal point y, in pixels
     * @param distortion the lens, {@link LensDistortion#NONE} for none; not null
     * @throws IllegalArgumentException when the image size is not positive, a focal length is not
     *                                  positive and finite, the principal point is not finite, or
     *                                  {@code distortion} is null
     */
    public CameraIntrinsics {
        if (width <= 0 || height <= 0) {
            throw new IllegalArgumentException("image size must be positive: " + width + "x" + height);
        }
        if (!(fx > 0) || !(fy > 0) || !Double.isFinite(fx) || !Double.isFinite(fy)) {
            throw new IllegalArgumentException("focal lengths must be positive and finite: fx=" + fx + " fy=" + fy);
        }
        if (!Double.isFinite(cx) || !Double.isFinite(cy)) {
            throw new IllegalArgumentException("principal point must be finite: cx=" + cx + " cy=" + cy);
        }
        if (distortion == null) {
            throw new IllegalArgumentException("no lens distortion (LensDistortion.NONE for none)");
        }
    }

    /**
     * A pinhole camera without distortion ({@link LensDistortion#NONE}).
     *
     * @param width  image width in pixels, positive
     * @param height image height in pixels, positive
     * @param fx     focal length along x, in pixels, positive
     * @param fy     focal length along y, in pixels, positive
     * @param cx     principal point x, in pixels (pixel-centre-at-integer convention)
     * @param cy     principal point y, in pixels
     * @throws IllegalArgumentException as the canonical constructor
     */
    public CameraIntrinsics(int width, int height, double fx, double fy, double cx, double cy) {
        this(width, height, fx, fy, cx, cy, LensDistortion.NONE);
    }

    /**
     * The same pinhole with {@code d} as its lens.
     *
     * @param d the lens' distortion, in normalised coordinates; {@link LensDistortion#NONE} for none
     * @return new intrinsics with this size, focal lengths and principal point
     * @throws IllegalArgumentException when {@code d} is null
     */
    public CameraIntrinsics withDistortion(LensDistortion d) {
        return new CameraIntrinsics(width, height, fx, fy, cx, cy, d);
    }

    /**
     * Whether the image is distorted (the lens has a term that is not zero).
     *
     * @return false for {@link LensDistortion#NONE}, true otherwise
     */
    public boolean isDistorted() {
        return !distortion.isNone();
    }

    /**
     * The pixel where the camera-frame point (x, y, z), z > 0, appears, into {@code out[0..1]}.
     *
     * @param x   camera-frame x (right), in any unit: only x / z counts
     * @param y   camera-frame y (down), in the unit of {@code x}
     * @param z   camera-frame z (forward, depth), in the unit of {@code x}; must be positive (not checked)
     * @param out receives the pixel (u, v) in {@code out[0]} and {@code out[1]} (distorted, as the
     *            image shows it); at least 2 long, other elements untouched
     */
    public void toPixel(double x, double y, double z, double[] out) {
        distortion.distort(x / z, y / z, out);
        out[0] = fx * out[0] + cx;
        out[1] = fy * out[1] + cy;
    }

    /**
     * The ideal normalised coordinates (x / z, y / z) of what appears at pixel (u, v), into
     * {@code out[0..1]}; false where the lens model cannot be inverted ({@link LensDistortion#undistort}).
     *
     * @param u   pixel x, in pixels (pixel-centre-at-integer convention)
     * @param v   pixel y, in pixels
     * @param out receives (x / z, y / z) in {@code out[0]} and {@code out[1]}: the ray through the
     *            pixel, undistorted; at least 2 long; unspecified when this returns false
     * @return true when {@code out} holds the point, false where the lens cannot be inverted
     */
    public boolean toNormalized(double u, double v, double[] out) {
        return distortion.undistort((u - cx) / fx, (v - cy) / fy, out);
    }

    /**
     * Intrinsics estimated from a horizontal field of view: square pixels, principal point at the
     * image centre. Good enough for a phone whose calibration is unknown; poses then carry the
     * error of the field-of-view guess mostly in depth.
     *
     * @param width                image width in pixels, positive
     * @param height               image height in pixels, positive
     * @param horizontalFovDegrees the angle the image's width spans, in degrees, in (1, 179)
     * @return intrinsics with fx = fy, the principal point at ((width - 1) / 2, (height - 1) / 2)
     *         and no distortion
     * @throws IllegalArgumentException when the field of view is outside (1, 179) degrees (or NaN),
     *                                  or the image size is not positive
     */
    public static CameraIntrinsics fromHorizontalFov(int width, int height, double horizontalFovDegrees) {
        if (!(horizontalFovDegrees > 1 && horizontalFovDegrees < 179)) {
            throw new IllegalArgumentException("horizontal field of view must be in (1, 179) degrees: "
                    + horizontalFovDegrees);
        }
        double f = 0.5 * width / Math.tan(Math.toRadians(horizontalFovDegrees) / 2);
        return new CameraIntrinsics(width, height, f, f, (width - 1) / 2.0, (height - 1) / 2.0);
    }

    /**
     * The same camera at another resolution (a preview stream scaled from the sensor's).
     *
     * @param newWidth  the new image width in pixels, positive; scales fx and cx
     * @param newHeight the new image height in pixels, positive; scales fy and cy (an aspect other
     *                  than this one's stretches the image, with fx and fy scaled apart)
     * @return new intrinsics mapping pixel edges to pixel edges, with the same lens distortion
     *         (which is in normalised coordinates and so holds at any resolution)
     * @throws IllegalArgumentException when the new size is not positive
     */
    public CameraIntrinsics scaledTo(int newWidth, int newHeight) {
        double sx = (double) newWidth / width;
        double sy = (double) newHeight / height;
        // Scaling maps pixel edges to pixel edges: x_edge = x_centre + 0.5.
        return new CameraIntrinsics(newWidth, newHeight, fx * sx, fy * sy,
                (cx + 0.5) * sx - 0.5, (cy + 0.5) * sy - 0.5, distortion);
    }

    /**
     * Horizontal field of view in degrees.
     *
     * @return the angle {@code 2 atan(width / (2 fx))}, in degrees, from the pinhole alone (as if
     *         the principal point were centred, lens distortion ignored)
     */
    public double horizontalFovDegrees() {
        return Math.toDegrees(2 * Math.atan(0.5 * width / fx));
    }
}
