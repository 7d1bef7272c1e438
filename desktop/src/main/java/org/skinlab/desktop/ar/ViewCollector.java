package org.skinlab.desktop.ar;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import boofcv.alg.geo.calibration.CalibrationObservation;
import boofcv.struct.geo.PointIndex2D_F64;

import org.skinlab.ar.GrayImage;

/**
 * Picks calibration views from a live camera without a key press: a frame is kept when the whole
 * target is in it and the view differs from every view kept so far, in where the target is, how
 * large it appears or how it is tilted. The comparison uses the points' centroid, spread and
 * normalised second moments (the foreshortening of a tilt), which do not depend on the order in
 * which the detector numbered the points.
 */
public final class ViewCollector {
    /** A view is new when its centroid moved by this fraction of the image diagonal... */
    static final double MOVE = 0.10;
    /** ...or its size changed by this factor (log difference)... */
    static final double SCALE = Math.log(1.25);
    /**
     * ...or its normalised second moments changed by this much in sum: a turn of the 7 x 10 board
     * by 20 degrees about an axis changes them by about 0.05, a turn in the image plane by more.
     */
    static final double SHAPE = 0.05;

    private final TargetDetector detector;
    private final List<double[]> kept = new ArrayList<>();
    private final List<CalibrationObservation> views = new ArrayList<>();

    /** What became of an offered frame. */
    public record Offer(boolean kept, String reason) {
    }

    public ViewCollector(TargetDetector detector) {
        this.detector = detector;
    }

    /** Looks for the target in {@code frame} and keeps the view when it is new. */
    public Offer offer(GrayImage frame) {
        TargetDetector.View v = detector.detect(frame);
        if (!v.found()) {
            return new Offer(false, v.problem());
        }
        double[] d = describe(v.points());
        double diagonal = Math.hypot(frame.width(), frame.height());
        for (double[] k : kept) {
            boolean moved = Math.hypot(d[0] - k[0], d[1] - k[1]) > MOVE * diagonal;
            boolean resized = Math.abs(Math.log(d[2] / k[2])) > SCALE;
            boolean reshaped = Math.abs(d[3] - k[3]) + Math.abs(d[4] - k[4]) + Math.abs(d[5] - k[5]) > SHAPE;
            if (!moved && !resized && !reshaped) {
                return new Offer(false, "the same view as one already kept: move or tilt the target");
            }
        }
        kept.add(d);
        views.add(v.points());
        return new Offer(true, null);
    }

    /** The views kept, in the order they were taken. */
    public List<CalibrationObservation> views() {
        return Collections.unmodifiableList(views);
    }

    /** Centroid x, y; spread s (RMS distance from the centroid); second moments xx, xy, yy over s^2. */
    private static double[] describe(CalibrationObservation o) {
        double sx = 0;
        double sy = 0;
        for (PointIndex2D_F64 p : o.points) {
            sx += p.p.x;
            sy += p.p.y;
        }
        int n = o.points.size();
        double cx = sx / n;
        double cy = sy / n;
        double xx = 0;
        double xy = 0;
        double yy = 0;
        for (PointIndex2D_F64 p : o.points) {
            double dx = p.p.x - cx;
            double dy = p.p.y - cy;
            xx += dx * dx;
            xy += dx * dy;
            yy += dy * dy;
        }
        double s2 = (xx + yy) / n;
        return new double[] {cx, cy, Math.sqrt(s2), xx / n / s2, xy / n / s2, yy / n / s2};
    }
}
