package org.skinlab.mixer;

/** How a cross-fade's share of the incoming clip grows with the fraction f of its duration. */
public enum FadeCurve {
    /** The share is f. */
    LINEAR,
    /** The share is 3f^2 - 2f^3 (smoothstep): no sudden change of speed at either end. */
    SMOOTH;

    /**
     * The incoming clip's share at fraction {@code f} of the fade.
     *
     * @param f the fraction of the fade's duration that has passed, clamped to [0, 1]
     * @return the share, from 0 at the start to 1 at the end
     */
    public double share(double f) {
        double x = Math.max(0, Math.min(1, f));
        return this == LINEAR ? x : x * x * (3 - 2 * x);
    }
}
