package org.skinlab.ar;

import org.skinlab.internal.ar.PoseMath;

/** Pose differences for the tests: the angle of R_a^T R_b, and |t_a - t_b|. */
final class PoseError {
    private PoseError() {
    }

    static double rotationDegrees(double[] a, double[] b) {
        return PoseMath.angleDegrees(a, b);
    }

    static double distance(double[] a, double[] b) {
        return PoseMath.distance(a, b);
    }
}
