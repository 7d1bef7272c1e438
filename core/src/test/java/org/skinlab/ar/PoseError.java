package org.skinlab.ar;

/** Pose differences for the tests: the angle of R_a^T R_b, and |t_a - t_b|. */
final class PoseError {
    private PoseError() {
    }

    static double rotationDegrees(double[] a, double[] b) {
        return PoseMath.angleDegrees(a, b);
    }

    static double distance(double[] a, double[] b) {
        double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
