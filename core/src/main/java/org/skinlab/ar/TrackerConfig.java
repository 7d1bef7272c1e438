package org.skinlab.ar;

/**
 * What the tracker looks for.
 *
 * @param dictionary         the marker's code dictionary
 * @param markerSizeMetres   the printed black square's width in metres
 * @param targetId           the marker id to report, or -1 for every code of the dictionary
 * @param maxBitErrors       how wrong a square's code bits may be for it to count as a marker: the
 *                           sum over its wrong bits of each one's confidence (a crisp cell 1, a cell
 *                           smeared by blur or cut by an occluder less; {@link CodeReader}); at most
 *                           {@code (minimumHamming - 1) / 2} of the dictionary, which also caps the
 *                           wrong bits counted plainly, so that a read can never be nearer another
 *                           code. BoofCV's own default accepts up to minimumHamming wrong bits (12 of
 *                           36 for 36h12), which reports markers in clutter and in other codes; see
 *                           {@link #DEFAULT_MAX_BIT_ERRORS} and {@link #MAX_UNCERTAIN_BITS}
 * @param searchNearLastPose whether {@link FiducialTracker#track} first searches the image region
 *                           around the last frame's markers (video), before the whole frame
 */
public record TrackerConfig(MarkerDictionary dictionary, double markerSizeMetres, int targetId, double maxBitErrors,
        boolean searchNearLastPose) {

    /**
     * 1: one crisp wrong bit, or several smeared ones whose confidences sum to 1. A random 36-bit
     * pattern (a square of clutter with bits in it) lands within 1 bit of one of 36h12's 250 codes in
     * its 4 rotations with probability {@code 1000 * 37 / 2^36 = 5e-7}; the clutter that matters is
     * crisp, so its wrong bits cost about 1 each. Measured (FarTiltedDetectionTest, docs/ar.md): over
     * 1,000 clutter frames with codes 3-6 bits from ours, limits up to 1.75 give no false marker and
     * 2 gives two, while far, tilted markers are found as often from 1 to 1.75 (97.1% of 150 mm
     * markers at 1.5-2 m, tilt 0-70; BoofCV's rule capped at 2, wrong bits plus half the ambiguous
     * ones, 94.8%).
     */
    public static final double DEFAULT_MAX_BIT_ERRORS = 1;

    /**
     * At most 9 of a read's bits (a quarter of 36h12's) may be uncertain (confidence at most 1/2): a
     * square whose inside is neither black nor white (a picture in a black frame, a blurred
     * pattern) does not show a code whatever code it is nearest to. Measured as above: with 16 or
     * more, limits from 1.25 up let a false marker through.
     */
    public static final int MAX_UNCERTAIN_BITS = 9;

    /**
     * Checks every component.
     *
     * @param dictionary         the marker's code dictionary, not null
     * @param markerSizeMetres   the printed black square's width in metres, positive and finite
     * @param targetId           the marker id to report, 0 to {@code dictionary.codeCount() - 1}, or -1 for every code
     * @param maxBitErrors       the most a square's wrong bits' confidences may sum to, 0 to
     *                           {@code (minimumHamming - 1) / 2} of the dictionary
     * @param searchNearLastPose whether {@link FiducialTracker#track} first searches around the last frame's markers
     * @throws IllegalArgumentException when {@code dictionary} is null, {@code markerSizeMetres} is not positive and
     *                                  finite, {@code targetId} is neither -1 nor one of the dictionary's ids, or
     *                                  {@code maxBitErrors} is outside 0 to {@code (minimumHamming - 1) / 2}
     */
    public TrackerConfig {
        if (dictionary == null) {
            throw new IllegalArgumentException("no marker dictionary");
        }
        if (!(markerSizeMetres > 0) || !Double.isFinite(markerSizeMetres)) {
            throw new IllegalArgumentException("marker size must be positive: " + markerSizeMetres + " m");
        }
        if (targetId < -1 || targetId >= dictionary.codeCount()) {
            throw new IllegalArgumentException("marker id " + targetId + " is not in " + dictionary.key()
                    + " (ids 0 to " + (dictionary.codeCount() - 1) + ", or -1 for any)");
        }
        int limit = (dictionary.minimumHamming() - 1) / 2;
        if (!(maxBitErrors >= 0 && maxBitErrors <= limit)) {
            throw new IllegalArgumentException("bit errors must be in 0.." + limit + " for " + dictionary.key()
                    + " (half its minimum distance " + dictionary.minimumHamming() + "): " + maxBitErrors);
        }
    }

    /**
     * The default dictionary, any id, {@link #DEFAULT_MAX_BIT_ERRORS} (or fewer if the dictionary needs), video
     * search on.
     *
     * @param markerSizeMetres the printed black square's width in metres, positive
     * @return a config for {@link MarkerDictionary#DEFAULT}
     * @throws IllegalArgumentException when the size is not positive and finite
     */
    public static TrackerConfig defaults(double markerSizeMetres) {
        return of(MarkerDictionary.DEFAULT, markerSizeMetres);
    }

    /**
     * {@code dictionary}, any id, {@link #DEFAULT_MAX_BIT_ERRORS} (or fewer if the dictionary needs), video search
     * on.
     *
     * @param dictionary       the marker's code dictionary, not null
     * @param markerSizeMetres the printed black square's width in metres, positive
     * @return a config with target id -1 and {@code min(DEFAULT_MAX_BIT_ERRORS, (minimumHamming - 1) / 2)} bit errors
     * @throws IllegalArgumentException when the size is not positive and finite
     * @throws NullPointerException     when {@code dictionary} is null
     */
    public static TrackerConfig of(MarkerDictionary dictionary, double markerSizeMetres) {
        double errors = Math.min(DEFAULT_MAX_BIT_ERRORS, (dictionary.minimumHamming() - 1) / 2);
        return new TrackerConfig(dictionary, markerSizeMetres, -1, errors, true);
    }

    /**
     * This config reporting only marker {@code id}.
     *
     * @param id the marker id to report, 0 to the dictionary's {@code codeCount() - 1}, or -1 for every code
     * @return a new config, the other components unchanged
     * @throws IllegalArgumentException when {@code id} is neither -1 nor one of the dictionary's ids
     */
    public TrackerConfig withTargetId(int id) {
        return new TrackerConfig(dictionary, markerSizeMetres, id, maxBitErrors, searchNearLastPose);
    }

    /**
     * This config with another limit on a square's wrong bits ({@link #maxBitErrors()}).
     *
     * @param errors the most the wrong bits' confidences may sum to, 0 to {@code (minimumHamming - 1) / 2} of the
     *               dictionary
     * @return a new config, the other components unchanged
     * @throws IllegalArgumentException when {@code errors} is outside that range (or NaN)
     */
    public TrackerConfig withMaxBitErrors(double errors) {
        return new TrackerConfig(dictionary, markerSizeMetres, targetId, errors, searchNearLastPose);
    }

    /**
     * This config with the video search near the last frame's markers switched on or off.
     *
     * @param search whether {@link FiducialTracker#track} first searches around the last frame's markers; false
     *               makes it search the whole frame every time, like {@link FiducialTracker#detect}
     * @return a new config, the other components unchanged
     */
    public TrackerConfig withSearchNearLastPose(boolean search) {
        return new TrackerConfig(dictionary, markerSizeMetres, targetId, maxBitErrors, search);
    }
}
