package org.skinlab.ar;

/** Pose differences for the tests: the angle of R_a^T R_b, and |t_a - t_b|. */
final class PoseError {
    private PoseError() {
    }

    static double rotationDegrees(double[] a, double[] b) {
        double trace = 0;
        for (int i = 0; i < 3; i++) {
            for (int k = 0; k < 3; k++) {
                trace += a[3 * k + i] * b[3 * k + i];
            }
        }
        return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, (trace - 1) / 2))));
    }

    static double distance(double[] a, double[] b) {
        double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
