package org.skinlab.ar;

/**
 * The Brown-Conrady lens model of OpenCV, BoofCV ({@code radial}, {@code t1 = p1}, {@code t2 = p2})
 * and Camera2 ({@code LENS_DISTORTION = [k1, k2, k3, p1, p2]}): an ideal point (x, y) in
 * normalised image coordinates ({@code x = X / Z}, {@code y = Y / Z}) appears at
 * <pre>
 *   r^2 = x^2 + y^2,  radial = 1 + k1 r^2 + k2 r^4 + k3 r^6
 *   x_d = x radial + 2 p1 x y + p2 (r^2 + 2 x^2)
 *   y_d = y radial + p1 (r^2 + 2 y^2) + 2 p2 x y
 * </pre>
 * {@link #distort} is that closed form; {@link #undistort} inverts it by Newton's method on the
 * 2x2 Jacobian (a few iterations to 1e-12 for any lens a phone or webcam has).
 *
 * @param k1 radial, r^2
 * @param k2 radial, r^4
 * @param k3 radial, r^6
 * @param p1 tangential (decentring), OpenCV's p1, BoofCV's t1
 * @param p2 tangential, OpenCV's p2, BoofCV's t2
 */
public record LensDistortion(double k1, double k2, double k3, double p1, double p2) {
    /** An ideal lens. */
    public static final LensDistortion NONE = new LensDistortion(0, 0, 0, 0, 0);

    private static final int MAX_ITERATIONS = 30;
    private static final double TOLERANCE = 1e-12;

    /**
     * Checks that every term is finite.
     *
     * @param k1 radial, r^2
     * @param k2 radial, r^4
     * @param k3 radial, r^6
     * @param p1 tangential (decentring), OpenCV's p1, BoofCV's t1
     * @param p2 tangential, OpenCV's p2, BoofCV's t2
     * @throws IllegalArgumentException when a term is NaN or infinite
     */
    public LensDistortion {
        if (!Double.isFinite(k1) || !Double.isFinite(k2) || !Double.isFinite(k3) || !Double.isFinite(p1)
                || !Double.isFinite(p2)) {
            throw new IllegalArgumentException("distortion terms must be finite: k1=" + k1 + " k2=" + k2 + " k3=" + k3
                    + " p1=" + p1 + " p2=" + p2);
        }
    }

    /**
     * Whether every term is zero (an ideal pinhole: nothing to undo).
     *
     * @return true when k1, k2, k3, p1 and p2 are all zero
     */
    public boolean isNone() {
        return k1 == 0 && k2 == 0 && k3 == 0 && p1 == 0 && p2 == 0;
    }

    /**
     * Where the ideal normalised point (x, y) appears: (x_d, y_d) into {@code out[0..1]}.
     *
     * @param x   the ideal point's normalised x, {@code X / Z}
     * @param y   the ideal point's normalised y, {@code Y / Z} (camera y down)
     * @param out receives x_d in {@code out[0]} and y_d in {@code out[1]}, also normalised (multiply by the focal
     *            length and add the principal point for pixels); at least 2 long, other entries untouched
     */
    public void distort(double x, double y, double[] out) {
        double x2 = x * x;
        double y2 = y * y;
        double r2 = x2 + y2;
        double radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3));
        out[0] = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x2);
        out[1] = y * radial + p1 * (r2 + 2 * y2) + 2 * p2 * x * y;
    }

    /**
     * The ideal normalised point that appears at (xd, yd), into {@code out[0..1]}; false when the
     * model cannot be inverted there (the point lies beyond where the lens model folds back, far
     * outside any real image), leaving {@code out} unspecified.
     *
     * @param xd  the distorted (observed) normalised x, {@code (u - cx) / fx} for pixel column u
     * @param yd  the distorted normalised y, {@code (v - cy) / fy} for pixel row v
     * @param out receives the ideal x in {@code out[0]} and y in {@code out[1]}; at least 2 long, other entries
     *            untouched
     * @return true when the inverse converged onto the lens model's true branch, false when it did not (then
     *         {@code out} holds no meaningful point)
     */
    public boolean undistort(double xd, double yd, double[] out) {
        if (isNone()) {
            out[0] = xd;
            out[1] = yd;
            return true;
        }
        double x = xd;
        double y = yd;
        for (int i = 0; i < MAX_ITERATIONS; i++) {
            double x2 = x * x;
            double y2 = y * y;
            double r2 = x2 + y2;
            double radial = 1 + r2 * (k1 + r2 * (k2 + r2 * k3));
            double fx = x * radial + 2 * p1 * x * y + p2 * (r2 + 2 * x2) - xd;
            double fy = y * radial + p1 * (r2 + 2 * y2) + 2 * p2 * x * y - yd;
            // d radial / d(r^2), then the Jacobian of (x_d, y_d) by (x, y).
            double dRadial = k1 + r2 * (2 * k2 + 3 * r2 * k3);
            double a = radial + 2 * x2 * dRadial + 2 * p1 * y + 6 * p2 * x;
            double b = 2 * x * y * dRadial + 2 * p1 * x + 2 * p2 * y;
            double c = 2 * x * y * dRadial + 2 * p1 * x + 2 * p2 * y;
            double d = radial + 2 * y2 * dRadial + 6 * p1 * y + 2 * p2 * x;
            double det = a * d - b * c;
            if (!(Math.abs(det) > 1e-12)) {
                return false;
            }
            double dx = (d * fx - b * fy) / det;
            double dy = (a * fy - c * fx) / det;
            x -= dx;
            y -= dy;
            if (Math.abs(dx) + Math.abs(dy) < TOLERANCE) {
                distort(x, y, out);
                boolean fits = Math.abs(out[0] - xd) + Math.abs(out[1] - yd) < 1e-9;
                out[0] = x;
                out[1] = y;
                // Newton may land on a fold's far branch: the true inverse keeps det > 0 (the lens
                // does not mirror the image) and a positive radial factor. Past a barrel lens' fold
                // det is positive again where the radial factor is negative, on a point mirrored
                // through the centre that maps exactly onto (xd, yd).
                double s2 = x * x + y * y;
                return fits && det > 0 && 1 + s2 * (k1 + s2 * (k2 + s2 * k3)) > 0;
            }
        }
        return false;
    }
}
