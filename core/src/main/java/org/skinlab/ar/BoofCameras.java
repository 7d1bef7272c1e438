package org.skinlab.ar;

import boofcv.struct.calib.CameraPinholeBrown;

/**
 * Our {@link CameraIntrinsics} to and from BoofCV's {@link CameraPinholeBrown}: the one place that
 * knows BoofCV's pixel convention. BoofCV puts a pixel's centre at (x + 0.5, y + 0.5), ours at
 * (x, y), so its principal point is ours plus 0.5; the lens terms are the same numbers
 * ({@code radial = [k1, k2, k3]}, {@code t1 = p1}, {@code t2 = p2}).
 */
public final class BoofCameras {
    private BoofCameras() {
    }

    /**
     * BoofCV's model of {@code k}.
     *
     * @param k our intrinsics (pixel centres at integers)
     * @return a new BoofCV camera: the principal point moved by half a pixel, the lens terms copied
     */
    public static CameraPinholeBrown toBoof(CameraIntrinsics k) {
        CameraPinholeBrown c = new CameraPinholeBrown(k.fx(), k.fy(), 0, k.cx() + 0.5, k.cy() + 0.5, k.width(),
                k.height());
        LensDistortion d = k.distortion();
        if (!d.isNone()) {
            c.fsetRadial(d.k1(), d.k2(), d.k3());
            c.fsetTangential(d.p1(), d.p2());
        }
        return c;
    }

    /**
     * Ours of BoofCV's {@code c}.
     *
     * @param c a BoofCV camera (pixel centres at half-integers)
     * @return our intrinsics of the same camera
     * @throws IllegalArgumentException when it has a skew (no camera we support has one) or more
     *                                  than three radial terms
     */
    public static CameraIntrinsics fromBoof(CameraPinholeBrown c) {
        if (Math.abs(c.skew) > 1e-9 * Math.max(c.fx, c.fy)) {
            throw new IllegalArgumentException("a camera with skew " + c.skew + " (only skew 0 is supported)");
        }
        double[] radial = c.radial == null ? new double[0] : c.radial;
        if (radial.length > 3) {
            throw new IllegalArgumentException(radial.length + " radial terms (at most 3: k1, k2, k3)");
        }
        LensDistortion d = new LensDistortion(radial.length > 0 ? radial[0] : 0, radial.length > 1 ? radial[1] : 0,
                radial.length > 2 ? radial[2] : 0, c.t1, c.t2);
        return new CameraIntrinsics(c.width, c.height, c.fx, c.fy, c.cx - 0.5, c.cy - 0.5, d);
    }
}
