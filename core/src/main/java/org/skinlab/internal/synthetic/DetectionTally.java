package org.skinlab.internal.synthetic;

import java.util.Arrays;
import java.util.List;

import org.skinlab.ar.MarkerDetection;
import org.skinlab.internal.ar.PoseMath;

/**
 * What a detector made of frames of one known marker each: frames, markers found with the right id,
 * detections with a wrong id, and the position and rotation errors of the found (and, given the
 * true corners, their corners' distances from them).
 */
public final class DetectionTally {
    private int frames;
    private int found;
    private int wrong;
    private double[] position = new double[16];
    private double[] rotation = new double[16];
    private int corners;
    private double[] corner = new double[64];

    /** One frame's detections of {@code truth}. */
    public void add(PlacedMarker truth, List<MarkerDetection> detections) {
        add(truth, null, detections);
    }

    /**
     * One frame's detections of {@code truth}, whose corners are at {@code trueCorners} (x0, y0, ...,
     * x3, y3 in pixels, {@link SyntheticCamera#projectCorners}; null: not counted).
     */
    public void add(PlacedMarker truth, double[] trueCorners, List<MarkerDetection> detections) {
        frames++;
        for (MarkerDetection d : detections) {
            if (d.id() != truth.pattern().id()) {
                wrong++;
                continue;
            }
            if (found == position.length) {
                position = Arrays.copyOf(position, 2 * found);
                rotation = Arrays.copyOf(rotation, 2 * found);
            }
            position[found] = PoseMath.distance(d.translation(), truth.translation());
            rotation[found] = PoseMath.angleDegrees(d.rotation(), truth.rotation());
            found++;
            if (trueCorners != null) {
                if (corners + 4 > corner.length) {
                    corner = Arrays.copyOf(corner, 2 * corner.length);
                }
                for (int i = 0; i < 4; i++) {
                    corner[corners++] = Math.hypot(d.cornerX(i) - trueCorners[2 * i],
                            d.cornerY(i) - trueCorners[2 * i + 1]);
                }
            }
        }
    }

    public int frames() {
        return frames;
    }

    /** Detections with the frame's id. */
    public int found() {
        return found;
    }

    /** Detections with another id. */
    public int wrongIds() {
        return wrong;
    }

    /** Found over frames. */
    public double rate() {
        return frames == 0 ? 0 : (double) found / frames;
    }

    /** The q-quantile (0 to 1; the median is 0.5) of the found markers' position errors in metres, NaN for none. */
    public double positionError(double q) {
        return quantile(position, q);
    }

    /** The q-quantile of the found markers' rotation errors in degrees, NaN for none. */
    public double rotationError(double q) {
        return quantile(rotation, q);
    }

    /** The q-quantile of the found markers' corners' distances from the true corners in pixels, NaN for none. */
    public double cornerError(double q) {
        return quantile(corner, corners, q);
    }

    private double quantile(double[] values, double q) {
        return quantile(values, found, q);
    }

    private static double quantile(double[] values, int n, double q) {
        if (n == 0) {
            return Double.NaN;
        }
        double[] sorted = Arrays.copyOf(values, n);
        Arrays.sort(sorted);
        return sorted[(int) Math.min(n - 1, Math.floor(q * n))];
    }
}
