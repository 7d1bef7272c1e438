package org.skinlab.desktop.ar;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import boofcv.struct.geo.PointIndex2D_F64;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.ar.CalibrationTarget;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.PlacedTarget;
import org.skinlab.internal.synthetic.SceneOptions;
import org.skinlab.internal.synthetic.SyntheticCamera;

/**
 * The detector's points are in BoofCV's pixel convention, the calibration's input: on a sharp,
 * noise-free synthetic frame through an ideal lens, every point is its true corner's projection
 * (our convention, pixel centres at integers) plus half a pixel, within 0.05 px (the X-corner and
 * polygon refinements' accuracy on clean edges). Were the detector in our convention, every point
 * would be 0.5 px off and the calibration's principal point with it.
 */
class TargetDetectorTest {
    private static final CameraIntrinsics K = new CameraIntrinsics(640, 480, 600, 600, 319.5, 239.5);

    /** The target's true corners (chessboard: inner corners; grid: every square's four) in our pixels. */
    private static double[] truth(PlacedTarget placed) {
        CalibrationTarget t = placed.target();
        double pitch = t.squareMetres() + t.spaceMetres();
        int n = t.points();
        double[] out = new double[2 * n];
        double[] cam = new double[3];
        double[] px = new double[2];
        int i = 0;
        for (int r = 0; r < t.rows() + 1; r++) {
            for (int c = 0; c < t.cols() + 1; c++) {
                for (int corner = 0; corner < 4; corner++) {
                    double x;
                    double y;
                    if (t.kind() == CalibrationTarget.Kind.CHESSBOARD) {
                        if (corner > 0 || r == 0 || c == 0 || r == t.rows() || c == t.cols()) {
                            continue;
                        }
                        x = c * pitch;
                        y = r * pitch;
                    } else {
                        if (r == t.rows() || c == t.cols()) {
                            continue;
                        }
                        x = c * pitch + (corner == 1 || corner == 2 ? t.squareMetres() : 0);
                        y = r * pitch + (corner >= 2 ? t.squareMetres() : 0);
                    }
                    CalibrationPhotos.toCamera(placed, x, y, cam);
                    K.toPixel(cam[0], cam[1], cam[2], px);
                    out[2 * i] = px[0];
                    out[2 * i + 1] = px[1];
                    i++;
                }
            }
        }
        assertEquals(n, i);
        return out;
    }

    private static void check(CalibrationTarget target) {
        PlacedTarget placed = new PlacedTarget(target, PlacedMarker.facingCamera(20, -15, 10),
                new double[] {0.01, -0.005, 0.45});
        TargetDetector.View v = new TargetDetector(target).detect(
                new SyntheticCamera(K).render(List.of(placed), SceneOptions.clean(5)));
        assertTrue(v.found(), () -> v.problem());
        double[] truth = truth(placed);
        double sx = 0;
        double sy = 0;
        for (PointIndex2D_F64 p : v.points().points) {
            double best = Double.POSITIVE_INFINITY;
            int at = -1;
            for (int i = 0; i < truth.length / 2; i++) {
                double d = Math.hypot(p.p.x - 0.5 - truth[2 * i], p.p.y - 0.5 - truth[2 * i + 1]);
                if (d < best) {
                    best = d;
                    at = i;
                }
            }
            assertTrue(best < 0.15, target.kind() + " point " + p.index + " is " + best + " px from its corner");
            sx += p.p.x - truth[2 * at];
            sy += p.p.y - truth[2 * at + 1];
        }
        int n = v.points().size();
        assertEquals(0.5, sx / n, 0.05, target.kind() + ": mean x offset from our convention");
        assertEquals(0.5, sy / n, 0.05, target.kind() + ": mean y offset from our convention");
    }

    @Test
    void chessboardPointsAreHalfAPixelFromOurs() {
        check(CalibrationTarget.chessboard(7, 10, 0.020));
    }

    @Test
    void gridPointsAreHalfAPixelFromOurs() {
        check(CalibrationTarget.grid(5, 7, 0.020, 0.010));
    }
}
