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
     * A track of the given keys; all arrays are copied.
     *
     * @param times          key times in seconds, one per key, never decreasing
     * @param values         {@code width} values per key, key after key: component {@code c} of key
     *                       {@code k} at {@code k * width + c}
     * @param width          values per key, at least 1 (e.g. 1 for an angle, 3 for a translation, 16 for a
     *                       matrix)
     * @param interpolations one per key (the segment that starts at the key)
     * @param inTangents     Bezier control points, 2 floats per value component per key, or null
     * @param outTangents    Bezier control points, 2 floats per value component per key, or null
     * @throws IllegalArgumentException when {@code width} is not positive, the array lengths disagree with
     *                                  the number of keys, the times decrease, or a BEZIER or HERMITE key
     *                                  comes without both tangent arrays
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

    /**
     * The number of keys.
     *
     * @return the key count, 0 or more
     */
    public int keyCount() {
        return times.length;
    }

    /**
     * Values per key.
     *
     * @return the number of value components of each key, at least 1
     */
    public int width() {
        return width;
    }

    /**
     * The time of one key, without copying the array.
     *
     * @param k the key's index, 0 to {@code keyCount() - 1}
     * @return the key's time in seconds
     * @throws ArrayIndexOutOfBoundsException when there is no key {@code k}
     */
    public float time(int k) {
        return times[k];
    }

    /**
     * A copy of the key times (seconds).
     *
     * @return a new array of {@link #keyCount()} times, never decreasing
     */
    public float[] times() {
        return times.clone();
    }

    /**
     * Value component {@code c} of key {@code k}.
     *
     * @param k the key's index, 0 to {@code keyCount() - 1}
     * @param c the component's index, 0 to {@code width() - 1}
     * @return the value, in the unit of what the track animates (e.g. degrees for an angle)
     * @throws ArrayIndexOutOfBoundsException when the index {@code k * width() + c} is out of the values
     */
    public float value(int k, int c) {
        return values[k * width + c];
    }

    /**
     * A copy of all values, {@link #width()} per key.
     *
     * @return a new array of {@code keyCount() * width()} floats, component {@code c} of key {@code k} at
     *         {@code k * width() + c}
     */
    public float[] values() {
        return values.clone();
    }

    /**
     * How the segment that starts at key {@code k} interpolates (the last key's is not used).
     *
     * @param k the key's index, 0 to {@code keyCount() - 1}
     * @return the interpolation as the file names it
     * @throws ArrayIndexOutOfBoundsException when there is no key {@code k}
     */
    public Interpolation interpolation(int k) {
        return interpolations[k];
    }

    /**
     * Whether the track has both tangent arrays, as it must when a key is BEZIER or HERMITE.
     *
     * @return true when {@link #inTangents()} and {@link #outTangents()} are not null
     */
    public boolean hasTangents() {
        return inTangents != null && outTangents != null;
    }

    /**
     * A copy of the in-tangents (see the class comment), or null.
     *
     * @return a new array of {@code 2 * keyCount() * width()} floats, (time, value) pairs; or null
     */
    public float[] inTangents() {
        return inTangents == null ? null : inTangents.clone();
    }

    /**
     * A copy of the out-tangents (see the class comment), or null.
     *
     * @return a new array of {@code 2 * keyCount() * width()} floats, (time, value) pairs; or null
     */
    public float[] outTangents() {
        return outTangents == null ? null : outTangents.clone();
    }

    /**
     * The first key's time.
     *
     * @return the time in seconds of key 0, or 0 when the track has no keys
     */
    public float startTime() {
        return times.length == 0 ? 0f : times[0];
    }

    /**
     * The last key's time.
     *
     * @return the time in seconds of the last key, or 0 when the track has no keys
     */
    public float endTime() {
        return times.length == 0 ? 0f : times[times.length - 1];
    }

    @Override
    public String toString() {
        return "KeyframeTrack[" + keyCount() + " keys x " + width + ", " + Arrays.toString(
                Arrays.stream(interpolations).distinct().toArray()) + "]";
    }
}
