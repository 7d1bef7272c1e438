package org.skinlab.ar;

import org.joml.Matrix3d;
import org.joml.Quaterniond;

/**
 * Smooths a marker's pose over time without lagging behind fast moves: a {@link OneEuroFilter} on
 * each coordinate of the position, and the same rule on the rotation, whose speed is the angle
 * between the last output and the new measurement per second; the rotation moves toward the
 * measurement by the filter's factor along the shorter arc (nlerp of quaternions in one
 * hemisphere, so a measurement's sign flip q = -q never spins the model).
 *
 * <p>Defaults, for a 10 cm marker at 0.3-1.5 m: position minCutoff 1 Hz, beta 20 per m/s, rotation
 * minCutoff 1 Hz, beta 1.5 per rad/s, speed cutoffs 1 Hz. Still, at 30 frames per second, the
 * alpha of 1 Hz is 0.17: white noise's standard deviation drops by {@code sqrt((2 - a) / a)} =
 * 3.2x (measured 2.9x: the noise's own speed raises the cutoff a little, PoseFilterTest). Moving
 * at 0.3 m/s, the cutoff
 * rises to 7 Hz: the lag of a first-order filter, {@code 1 / (2 pi fc)}, falls from 159 ms at rest
 * to 23 ms. Not thread-safe; allocation-free per update.
 */
final class PoseFilter {
    private final OneEuroFilter x;
    private final OneEuroFilter y;
    private final OneEuroFilter z;
    private final double rotationMinCutoff;
    private final double rotationBeta;
    private final double rotationDCutoff;
    private final Quaterniond rotation = new Quaterniond();
    private final Quaterniond measured = new Quaterniond();
    private final Matrix3d matrix = new Matrix3d();
    private double angularSpeed;
    private long lastNanos;
    private boolean started;

    public PoseFilter(double positionMinCutoff, double positionBeta, double rotationMinCutoff, double rotationBeta) {
        this.x = new OneEuroFilter(positionMinCutoff, positionBeta, 1.0);
        this.y = new OneEuroFilter(positionMinCutoff, positionBeta, 1.0);
        this.z = new OneEuroFilter(positionMinCutoff, positionBeta, 1.0);
        if (!(rotationMinCutoff > 0) || !(rotationBeta >= 0)) {
            throw new IllegalArgumentException("need rotation minCutoff > 0 and beta >= 0");
        }
        this.rotationMinCutoff = rotationMinCutoff;
        this.rotationBeta = rotationBeta;
        this.rotationDCutoff = 1.0;
    }

    /** The defaults above. */
    public PoseFilter() {
        this(1.0, 20, 1.0, 1.5);
    }

    /**
     * Filters the measured pose (R row-major, t) taken at {@code timeNanos}; the result goes into
     * {@code outRotation} (row-major, orthonormal) and {@code outTranslation}.
     */
    public void update(double[] r, double[] t, long timeNanos, double[] outRotation, double[] outTranslation) {
        outTranslation[0] = x.filter(t[0], timeNanos);
        outTranslation[1] = y.filter(t[1], timeNanos);
        outTranslation[2] = z.filter(t[2], timeNanos);
        // JOML's Matrix3d.set(...) takes columns: pass R's transpose layout.
        matrix.set(r[0], r[3], r[6], r[1], r[4], r[7], r[2], r[5], r[8]);
        measured.setFromNormalized(matrix);
        if (!started || timeNanos <= lastNanos) {
            if (!started) {
                rotation.set(measured);
                angularSpeed = 0;
            }
            started = true;
            lastNanos = timeNanos;
        } else {
            double dt = (timeNanos - lastNanos) * 1e-9;
            lastNanos = timeNanos;
            if (rotation.dot(measured) < 0) {
                measured.set(-measured.x, -measured.y, -measured.z, -measured.w);
            }
            double angle = 2 * Math.acos(Math.min(1, Math.abs(rotation.dot(measured))));
            angularSpeed += OneEuroFilter.alpha(rotationDCutoff, dt) * (angle / dt - angularSpeed);
            double cutoff = rotationMinCutoff + rotationBeta * angularSpeed;
            double a = OneEuroFilter.alpha(cutoff, dt);
            rotation.set(rotation.x + a * (measured.x - rotation.x), rotation.y + a * (measured.y - rotation.y),
                    rotation.z + a * (measured.z - rotation.z), rotation.w + a * (measured.w - rotation.w)).normalize();
        }
        rotation.get(matrix);
        outRotation[0] = matrix.m00;
        outRotation[1] = matrix.m10;
        outRotation[2] = matrix.m20;
        outRotation[3] = matrix.m01;
        outRotation[4] = matrix.m11;
        outRotation[5] = matrix.m21;
        outRotation[6] = matrix.m02;
        outRotation[7] = matrix.m12;
        outRotation[8] = matrix.m22;
    }

    /** Forgets the past: the next pose passes through. */
    public void reset() {
        x.reset();
        y.reset();
        z.reset();
        started = false;
    }
}
