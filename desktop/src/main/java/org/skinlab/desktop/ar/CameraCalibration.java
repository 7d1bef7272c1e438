package org.skinlab.desktop.ar;

import java.util.ArrayList;
import java.util.List;

import boofcv.abst.geo.calibration.CalibrateMonoPlanar;
import boofcv.abst.geo.calibration.ImageResults;
import boofcv.alg.geo.calibration.CalibrationObservation;
import boofcv.struct.calib.CameraPinholeBrown;
import boofcv.struct.geo.PointIndex2D_F64;
import georegression.struct.point.Point2D_F64;
import georegression.struct.se.Se3_F64;

import org.skinlab.ar.BoofCameras;
import org.skinlab.ar.CameraIntrinsics;

/**
 * Camera calibration from views of a planar target: BoofCV's {@link CalibrateMonoPlanar} (Zhang's
 * method, then bundle adjustment of all views) for a pinhole without skew and a Brown-Conrady lens
 * (radial k1, k2 and optionally k3; tangential p1, p2), converted to our conventions by
 * {@link BoofCameras#fromBoof}. Reports each view's reprojection error and what the views miss
 * ({@link CalibrationCoverage}).
 */
public final class CameraCalibration {
    /**
     * Fewer views are refused: two views fix the pinhole only with the lens held ideal, a third
     * gives the lens terms something to be measured against.
     */
    public static final int MIN_VIEWS = 3;

    private CameraCalibration() {
    }

    /**
     * What a calibration found.
     *
     * @param intrinsics  the camera, in our conventions
     * @param rms         per view, the root mean square reprojection error of its points (pixels)
     * @param maxError    per view, its largest point error (pixels)
     * @param warnings    what the views miss (empty: nothing)
     */
    public record Result(CameraIntrinsics intrinsics, double[] rms, double[] maxError, List<String> warnings) {
        /** The mean over the views of their RMS error. */
        public double meanRms() {
            double s = 0;
            for (double r : rms) {
                s += r;
            }
            return s / rms.length;
        }

        /** The largest RMS error of a view. */
        public double maxRms() {
            double m = 0;
            for (double r : rms) {
                m = Math.max(m, r);
            }
            return m;
        }

        /** The view with the largest RMS error. */
        public int worstView() {
            int w = 0;
            for (int i = 1; i < rms.length; i++) {
                if (rms[i] > rms[w]) {
                    w = i;
                }
            }
            return w;
        }
    }

    /**
     * Calibrates a {@code width x height} camera from {@code views} of a target whose points lie at
     * {@code layout} ({@link TargetDetector}); IllegalArgumentException when there are fewer than
     * {@link #MIN_VIEWS} or the optimisation fails.
     */
    public static Result calibrate(List<Point2D_F64> layout, List<CalibrationObservation> views, int width, int height,
            boolean k3) {
        if (views.size() < MIN_VIEWS) {
            throw new IllegalArgumentException("too few views of the target: " + views.size() + ", at least " + MIN_VIEWS
                    + " needed (10 to 20 recommended)");
        }
        CalibrateMonoPlanar calibration = new CalibrateMonoPlanar();
        calibration.initialize(width, height, List.of(layout));
        calibration.configurePinhole(true, k3 ? 3 : 2, true);
        for (CalibrationObservation v : views) {
            calibration.addImage(v);
        }
        CameraPinholeBrown model;
        try {
            model = calibration.process();
        } catch (RuntimeException e) {
            // BoofCV's "Zhang99 algorithm failed!": the views are degenerate (all parallel, or too few points).
            throw new IllegalArgumentException("the calibration failed on these " + views.size()
                    + " views (are they all nearly parallel to the image? tilt the target in some): " + e.getMessage(), e);
        }
        List<ImageResults> errors = calibration.getErrors();
        double[] rms = new double[views.size()];
        double[] max = new double[views.size()];
        List<double[]> points = new ArrayList<>();
        List<double[]> normals = new ArrayList<>();
        for (int v = 0; v < views.size(); v++) {
            double[] e = errors.get(v).pointError;
            double s = 0;
            for (double x : e) {
                s += x * x;
            }
            rms[v] = Math.sqrt(s / e.length);
            max[v] = errors.get(v).maxError;
            List<PointIndex2D_F64> p = views.get(v).points;
            double[] xy = new double[2 * p.size()];
            for (int i = 0; i < p.size(); i++) {
                // BoofCV's pixel centres are at +0.5: back to ours, the coverage's frame.
                xy[2 * i] = p.get(i).p.x - 0.5;
                xy[2 * i + 1] = p.get(i).p.y - 0.5;
            }
            points.add(xy);
            Se3_F64 pose = calibration.getTargetToView(v);
            normals.add(new double[] {pose.R.get(0, 2), pose.R.get(1, 2), pose.R.get(2, 2)});
        }
        CameraIntrinsics k = BoofCameras.fromBoof(model);
        return new Result(k, rms, max, CalibrationCoverage.warnings(width, height, points, normals));
    }

    /**
     * How far {@code k}'s lens moves the image's corner pixels, in pixels: per corner (top-left,
     * top-right, bottom-right, bottom-left), the distance from where it appears to where an ideal
     * pinhole would show it. NaN where the lens model does not invert.
     */
    public static double[] cornerShift(CameraIntrinsics k) {
        double[] u = {0, k.width() - 1, k.width() - 1, 0};
        double[] v = {0, 0, k.height() - 1, k.height() - 1};
        double[] out = new double[4];
        double[] ideal = new double[2];
        for (int i = 0; i < 4; i++) {
            out[i] = k.toNormalized(u[i], v[i], ideal)
                    ? Math.hypot(k.fx() * ideal[0] + k.cx() - u[i], k.fy() * ideal[1] + k.cy() - v[i]) : Double.NaN;
        }
        return out;
    }
}
