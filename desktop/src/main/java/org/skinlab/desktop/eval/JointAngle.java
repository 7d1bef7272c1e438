package org.skinlab.desktop.eval;

/**
 * A joint's rotation from its bind pose relative to its parent, as one signed, unwrapped angle
 * over a clip, so that a twist from 0 to 360 degrees reads 0 to 360 rather than 0 to 180 and back.
 * The rotation between the parent's and the joint's skinning matrices has an angle in [0, 180]
 * degrees and an axis; the sign is the axis' side of the first axis the joint turned about
 * (more than {@value #AXIS_DEGREES} degrees), and consecutive samples are joined by the shortest
 * step, so samples must be close (the quality section's 30 a second move our assets' joints by
 * at most a few degrees). For a joint that turns about one axis (our cylinders' twist and bend)
 * this is the angle the clip animates; for one whose axis wanders it is the signed size of the
 * rotation about its first axis.
 */
final class JointAngle {
    /** The smallest rotation whose axis is taken as the reference. */
    static final double AXIS_DEGREES = 1;

    private final int parent;
    private final int joint;
    private double[] axis;

    /** The angle of palette joint {@code joint} relative to palette joint {@code parent}. */
    JointAngle(int parent, int joint) {
        this.parent = parent;
        this.joint = joint;
    }

    /**
     * The angle in degrees, in (-180, 180], of a pose (its skinning matrices: 12 floats per joint,
     * row-major 3x4); the first pose turned more than {@value #AXIS_DEGREES} degrees fixes the
     * reference axis.
     */
    double signedDegrees(float[] skinningMatrices) {
        return Math.toDegrees(signed(skinningMatrices));
    }

    /**
     * The unwrapped angle of a sample whose signed angle is {@code signed}, continuing from the
     * previous sample's unwrapped and signed angles by the shortest step (degrees throughout).
     */
    static double continued(double previousUnwrapped, double previousSigned, double signed) {
        return previousUnwrapped + Math.toDegrees(wrap(Math.toRadians(signed - previousSigned)));
    }

    /** The reference axis in bind space (a unit vector), or null while the joint has not turned. */
    double[] axis() {
        return axis == null ? null : axis.clone();
    }

    /** The rotation's angle in radians, negative when its axis points away from the reference axis. */
    private double signed(float[] m) {
        double[] r = relative(m, parent, joint);
        // Angle from the trace, axis from the antisymmetric part (Rodrigues).
        double trace = r[0] + r[4] + r[8];
        double angle = Math.acos(Math.max(-1, Math.min(1, (trace - 1) / 2)));
        double[] a = {r[7] - r[5], r[2] - r[6], r[3] - r[1]};
        double length = Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        if (length < 1e-9 && angle > Math.PI / 2) {
            // Near a half turn the antisymmetric part vanishes: the axis is the column of R + I
            // of largest length (R + I = 2 a a^T there).
            a = halfTurnAxis(r);
            length = Math.sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
        }
        if (length < 1e-12) {
            return 0;
        }
        for (int i = 0; i < 3; i++) {
            a[i] /= length;
        }
        if (axis == null) {
            if (Math.toDegrees(angle) < AXIS_DEGREES) {
                return angle;
            }
            axis = a;
        }
        double side = a[0] * axis[0] + a[1] * axis[1] + a[2] * axis[2];
        return side < 0 ? -angle : angle;
    }

    private double[] halfTurnAxis(double[] r) {
        double[] best = null;
        double bestLength = -1;
        for (int c = 0; c < 3; c++) {
            double[] col = {r[c] + (c == 0 ? 1 : 0), r[3 + c] + (c == 1 ? 1 : 0), r[6 + c] + (c == 2 ? 1 : 0)};
            double l = col[0] * col[0] + col[1] * col[1] + col[2] * col[2];
            if (l > bestLength) {
                bestLength = l;
                best = col;
            }
        }
        // A half turn's axis has no sign of its own: take the reference axis' side.
        if (axis != null && best[0] * axis[0] + best[1] * axis[1] + best[2] * axis[2] < 0) {
            best[0] = -best[0];
            best[1] = -best[1];
            best[2] = -best[2];
        }
        return best;
    }

    /** The size in degrees (0 to 180) of the rotation from palette joint p to joint j in a pose. */
    static double degrees(float[] m, int p, int j) {
        double[] r = relative(m, p, j);
        return Math.toDegrees(Math.acos(Math.max(-1, Math.min(1, (r[0] + r[4] + r[8] - 1) / 2))));
    }

    /** Rp^T Rj, row-major 3x3, with each matrix's columns normalised (bone scale removed). */
    static double[] relative(float[] m, int p, int j) {
        double[] rp = rotation(m, p);
        double[] rj = rotation(m, j);
        double[] out = new double[9];
        for (int row = 0; row < 3; row++) {
            for (int col = 0; col < 3; col++) {
                double s = 0;
                for (int k = 0; k < 3; k++) {
                    s += rp[3 * k + row] * rj[3 * k + col];
                }
                out[3 * row + col] = s;
            }
        }
        return out;
    }

    private static double[] rotation(float[] m, int j) {
        double[] r = new double[9];
        for (int c = 0; c < 3; c++) {
            double n = 0;
            for (int row = 0; row < 3; row++) {
                double v = m[12 * j + 4 * row + c];
                n += v * v;
            }
            n = n > 0 ? Math.sqrt(n) : 1;
            for (int row = 0; row < 3; row++) {
                r[3 * row + c] = m[12 * j + 4 * row + c] / n;
            }
        }
        return r;
    }

    /** {@code a} moved into (-pi, pi] by whole turns. */
    private static double wrap(double a) {
        double w = a % (2 * Math.PI);
        if (w > Math.PI) {
            w -= 2 * Math.PI;
        } else if (w <= -Math.PI) {
            w += 2 * Math.PI;
        }
        return w;
    }
}
