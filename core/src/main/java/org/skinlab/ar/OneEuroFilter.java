package org.skinlab.ar;

/**
 * The 1-euro filter (Casiez, Roussel and Vogel, CHI 2012) for one noisy signal: a low-pass filter
 * whose cutoff rises with the signal's speed, so that a still signal is smoothed hard (jitter
 * gone) and a moving one followed closely (little lag). Per sample, with {@code dt} the time since
 * the last one:
 * <pre>
 *   alpha(fc) = 1 / (1 + 1 / (2 pi fc dt))
 *   dx'  = lerp(dx'_prev, (x - x'_prev) / dt, alpha(dCutoff))
 *   fc   = minCutoff + beta |dx'|
 *   x'   = lerp(x'_prev, x, alpha(fc))
 * </pre>
 * The first sample passes through. Not thread-safe; allocation-free.
 */
final class OneEuroFilter {
    private final double minCutoff;
    private final double beta;
    private final double dCutoff;
    private boolean started;
    private long lastNanos;
    private double value;
    private double speed;

    /**
     * @param minCutoff the cutoff (Hz) of a still signal: lower is smoother and slower
     * @param beta      how much the cutoff rises per unit of speed (per signal unit per second)
     * @param dCutoff   the cutoff (Hz) of the speed estimate
     */
    public OneEuroFilter(double minCutoff, double beta, double dCutoff) {
        if (!(minCutoff > 0) || !(beta >= 0) || !(dCutoff > 0)) {
            throw new IllegalArgumentException("need minCutoff > 0, beta >= 0, dCutoff > 0: " + minCutoff + ", "
                    + beta + ", " + dCutoff);
        }
        this.minCutoff = minCutoff;
        this.beta = beta;
        this.dCutoff = dCutoff;
    }

    /** The filtered value of {@code x} sampled at {@code timeNanos}. */
    public double filter(double x, long timeNanos) {
        if (!started || timeNanos <= lastNanos) {
            boolean first = !started;
            started = true;
            lastNanos = timeNanos;
            if (first) {
                value = x;
                speed = 0;
            }
            return value;
        }
        double dt = (timeNanos - lastNanos) * 1e-9;
        lastNanos = timeNanos;
        double rawSpeed = (x - value) / dt;
        speed += alpha(dCutoff, dt) * (rawSpeed - speed);
        double cutoff = minCutoff + beta * Math.abs(speed);
        value += alpha(cutoff, dt) * (x - value);
        return value;
    }

    /** The last filtered value. */
    public double value() {
        return value;
    }

    /** The filtered speed (signal units per second). */
    public double speed() {
        return speed;
    }

    /** Forgets the signal: the next sample passes through. */
    public void reset() {
        started = false;
    }

    /** The smoothing factor of a first-order low-pass filter with cutoff {@code hz} at step {@code dt}. */
    static double alpha(double hz, double dt) {
        return 1 / (1 + 1 / (2 * Math.PI * hz * dt));
    }
}
