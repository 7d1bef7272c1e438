package org.skinlab.ar;

/**
 * What the tracker looks for.
 *
 * @param dictionary         the marker's code dictionary
 * @param markerSizeMetres   the printed black square's width in metres
 * @param targetId           the marker id to report, or -1 for every code of the dictionary
 * @param maxBitErrors       how many of the code's bits may be wrong for a square to count as a
 *                           marker; at most {@code (minimumHamming - 1) / 2} of the dictionary, so
 *                           that a read can never be closer to another code. BoofCV's own default
 *                           accepts up to minimumHamming (12 of 36 bits for 36h12), which reports
 *                           markers in clutter and in other codes; see {@link #DEFAULT_MAX_BIT_ERRORS}
 * @param searchNearLastPose whether {@link FiducialTracker#track} first searches the image region
 *                           around the last frame's markers (video), before the whole frame
 */
public record TrackerConfig(MarkerDictionary dictionary, double markerSizeMetres, int targetId, double maxBitErrors,
        boolean searchNearLastPose) {

    /**
     * 2 wrong bits. A random 36-bit pattern (a square of clutter with bits in it) lands within 2
     * bits of one of 36h12's 250 codes in its 4 rotations with probability
     * {@code 1000 * 667 / 2^36 = 1e-5} (667 = the patterns within 2 bits of a code); within 3 bits,
     * 1.1e-4. Measured on the harness (TrackerEvaluationTest): with 3, one false marker in 90
     * cluttered frames (a random bit square read as code 71) at the same detection rates as 2; with
     * 2, none. Occluders of a cell or two and blur still read within 2.
     */
    public static final double DEFAULT_MAX_BIT_ERRORS = 1;

    /** The most uncertain bits a marker's read may have (see ConfidentHammingDetector). */
    public static final int MAX_UNCERTAIN_BITS = 9;

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

    /** The default dictionary, any id, {@link #DEFAULT_MAX_BIT_ERRORS} (or fewer if the dictionary needs), video search on. */
    public static TrackerConfig defaults(double markerSizeMetres) {
        return of(MarkerDictionary.DEFAULT, markerSizeMetres);
    }

    /** {@code dictionary}, any id, {@link #DEFAULT_MAX_BIT_ERRORS} (or fewer if the dictionary needs), video search on. */
    public static TrackerConfig of(MarkerDictionary dictionary, double markerSizeMetres) {
        double errors = Math.min(DEFAULT_MAX_BIT_ERRORS, (dictionary.minimumHamming() - 1) / 2);
        return new TrackerConfig(dictionary, markerSizeMetres, -1, errors, true);
    }

    public TrackerConfig withTargetId(int id) {
        return new TrackerConfig(dictionary, markerSizeMetres, id, maxBitErrors, searchNearLastPose);
    }

    public TrackerConfig withMaxBitErrors(double errors) {
        return new TrackerConfig(dictionary, markerSizeMetres, targetId, errors, searchNearLastPose);
    }

    public TrackerConfig withSearchNearLastPose(boolean search) {
        return new TrackerConfig(dictionary, markerSizeMetres, targetId, maxBitErrors, search);
    }
}
