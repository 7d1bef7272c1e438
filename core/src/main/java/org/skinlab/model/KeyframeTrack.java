package org.skinlab.model;

import java.util.Arrays;

/**
 * A COLLADA {@code <sampler>}: key times in seconds, {@link #width()} values per key, and how each
 * segment interpolates. Times never decrease (equal neighbours are allowed: a jump).
 *
 * <p>Tangents ({@code BEZIER}/{@code HERMITE} keys) are kept in one form: the control points of
 * the cubic Bezier of each segment, {@code (time, value)} for key {@code k} and value component
 * {@code c} at index {@code 2 * (k * width + c)}. Segment [k, k+1] is the Bezier through
 * {@code (t_k, v_k)}, key k's out-tangent, key k+1's in-tangent and {@code (t_k+1, v_k+1)}, for
 * BEZIER and HERMITE keys alike. The importer converts what the file writes into this form
 * (HERMITE derivatives T become {@code P + T/3} and {@code P - T/3}; 1-D tangents get their time a
 * third of the way to the neighbouring key): see {@code CurveTangents.controlPoints} and
 * docs/animation.md. The interpolation names stay as the file gives them.
 */
public final class KeyframeTrack {
    private final float[] times;
    private final float[] values;
    private final int width;
    private final Interpolation[] interpolations;
    private final float[] inTangents;
    private final float[] outTangents;

    /**
     * @param interpolations one per key (the segment that starts at the key)
     * @param inTangents     Bezier control points, 2 floats per value component per key, or null
     * @param outTangents    Bezier control points, 2 floats per value component per key, or null
     */
    public KeyframeTrack(float[] times, float[] values, int width, Interpolation[] interpolations,
            float[] inTangents, float[] outTangents) {
        int keys = times.length;
        if (width <= 0 || values.length != keys * width || interpolations.length != keys) {
            throw new IllegalArgumentException("track arrays disagree with " + keys + " keys of width " + width);
        }
        if ((inTangents != null && inTangents.length != 2 * keys * width)
                || (outTangents != null && outTangents.length != 2 * keys * width)) {
            throw new IllegalArgumentException("tangents need 2 floats per value per key");
        }
        if (inTangents == null || outTangents == null) {
            for (Interpolation i : interpolations) {
                if (i == Interpolation.BEZIER || i == Interpolation.HERMITE) {
                    // The sampler needs both tangent arrays for curved keys; the importer reads such
                    // keys without tangents as LINEAR, so only hand-built tracks can get here.
                    throw new IllegalArgumentException(i + " keys need in- and out-tangents");
                }
            }
        }
        for (int k = 1; k < keys; k++) {
            if (times[k] < times[k - 1]) {
                throw new IllegalArgumentException("key times decrease at key " + k);
            }
        }
        this.times = times.clone();
        this.values = values.clone();
        this.width = width;
        this.interpolations = interpolations.clone();
        this.inTangents = inTangents == null ? null : inTangents.clone();
        this.outTangents = outTangents == null ? null : outTangents.clone();
    }

    public int keyCount() {
        return times.length;
    }

    /** Values per key. */
    public int width() {
        return width;
    }

    public float time(int k) {
        return times[k];
    }

    /** A copy of the key times (seconds). */
    public float[] times() {
        return times.clone();
    }

    /** Value component {@code c} of key {@code k}. */
    public float value(int k, int c) {
        return values[k * width + c];
    }

    /** A copy of all values, {@link #width()} per key. */
    public float[] values() {
        return values.clone();
    }

    public Interpolation interpolation(int k) {
        return interpolations[k];
    }

    public boolean hasTangents() {
        return inTangents != null && outTangents != null;
    }

    /** A copy of the in-tangents (see the class comment), or null. */
    public float[] inTangents() {
        return inTangents == null ? null : inTangents.clone();
    }

    /** A copy of the out-tangents (see the class comment), or null. */
    public float[] outTangents() {
        return outTangents == null ? null : outTangents.clone();
    }

    public float startTime() {
        return times.length == 0 ? 0f : times[0];
    }

    public float endTime() {
        return times.length == 0 ? 0f : times[times.length - 1];
    }

    @Override
    public String toString() {
        return "KeyframeTrack[" + keyCount() + " keys x " + width + ", " + Arrays.toString(
                Arrays.stream(interpolations).distinct().toArray()) + "]";
    }
}
