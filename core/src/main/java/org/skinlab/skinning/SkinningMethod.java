package org.skinlab.skinning;

/** The skinning methods the project compares. */
public enum SkinningMethod {
    /** Linear Blend Skinning: the weighted sum of the joint matrices transforms each point. */
    LBS,
    /**
     * Dual Quaternion Skinning (Kavan et al. 2008): the weighted sum of the joints' unit dual
     * quaternions, normalised, transforms each point; joint scale is blended linearly first
     * (the two-phase split, see {@link JointPalette}).
     */
    DQS,
    /**
     * Skinning with optimized centres of rotation (Le and Hodgins 2016): the rotations blended as
     * in DQS, the translation LBS's at a per-point centre of rotation precomputed from the weights
     * ({@link CentersOfRotation}); see {@link ScalarCorSkinner}.
     */
    COR;

    /** The lower-case name used on the command line and in JSON ("lbs", "dqs", "cor"). */
    public String key() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }

    /** The method for a command-line key, case-insensitive. */
    public static SkinningMethod fromKey(String key) {
        for (SkinningMethod m : values()) {
            if (m.name().equalsIgnoreCase(key)) {
                return m;
            }
        }
        throw new IllegalArgumentException("unknown skinning method \"" + key + "\" (expected lbs, dqs or cor)");
    }
}
