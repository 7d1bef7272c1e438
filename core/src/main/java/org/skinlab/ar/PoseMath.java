package org.skinlab.ar;

/** Small rotation helpers on row-major 3x3 arrays. */
final class PoseMath {
    private PoseMath() {
    }

    /** The angle of {@code a^T b} in degrees: how far apart two rotations are. */
    static double angleDegrees(double[] a, double[] b) {
        double trace = 0;
        for (int i = 0; i < 3; i++) {
            for (int k = 0; k < 3; k++) {
                trace += a[3 * k + i] * b[3 * k + i];
            }
        }
        return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, (trace - 1) / 2))));
    }
}
