package org.skinlab.internal.ar;

/** Small pose helpers on row-major 3x3 rotations and translations. */
public final class PoseMath {
    private PoseMath() {
    }

    /** The angle of {@code a^T b} in degrees: how far apart two rotations are. */
    public static double angleDegrees(double[] a, double[] b) {
        double trace = 0;
        for (int i = 0; i < 3; i++) {
            for (int k = 0; k < 3; k++) {
                trace += a[3 * k + i] * b[3 * k + i];
            }
        }
        return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, (trace - 1) / 2))));
    }

    /** |a - b| of two translations. */
    public static double distance(double[] a, double[] b) {
        double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
