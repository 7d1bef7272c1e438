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
     * ({@link CentresOfRotation}); see {@link ScalarCorSkinner}.
     */
    COR,
    /**
     * Bulge-free DQS (Kim and Han 2014, as the thesis' section "DQS - Wölbungen" describes it): DQS,
     * then a point that ended up farther from its bone segment than at rest is pulled back
     * towards it; see docs/skinning.md.
     */
    BFDQS,
    /**
     * Stretchable and twistable bones (Jacobson and Sorkine 2011) on top of LBS: each influence's
     * transformation takes its bone's stretch and twist in proportion to the point's endpoint
     * weight along the bone; see docs/skinning.md.
     */
    STBS_LBS,
    /** Stretchable and twistable bones on top of DQS (as {@link #STBS_LBS}, blended as dual quaternions). */
    STBS_DQS,
    /**
     * Spline-based skinning (Forstmann et al. 2007): the bones of a chain become a curve, each
     * point is bound to a point of the curve and follows its frame; see docs/skinning.md.
     */
    SPLINE;

    /**
     * The lower-case name used on the command line and in JSON ("lbs", "dqs", "cor", "bfdqs",
     * "stbs-lbs", "stbs-dqs", "spline").
     *
     * @return the key, the constant's name in lower case with '-' for '_'
     */
    public String key() {
        return name().toLowerCase(java.util.Locale.ROOT).replace('_', '-');
    }

    /**
     * Whether the method reads its bones ({@link JointPalette#prepare}, after the dual
     * quaternions) besides the skinning matrices.
     *
     * @return true for BFDQS, STBS_LBS, STBS_DQS and SPLINE, which need a palette made with bones
     */
    public boolean usesBones() {
        return this == BFDQS || this == STBS_LBS || this == STBS_DQS || this == SPLINE;
    }

    /**
     * Whether the method's kernels skin positions only ({@link NormalTransform#NONE}): LBS and DQS,
     * scalar and SIMD. The others refuse that rule.
     *
     * @return true for LBS and DQS
     */
    public boolean skinsPositionsOnly() {
        return this == LBS || this == DQS;
    }

    /**
     * Whether the method reads the palette's dual quaternions ({@link JointPalette#prepare}).
     *
     * @return true for every method but LBS
     */
    public boolean usesDualQuaternions() {
        return this != LBS;
    }

    /**
     * The method for a command-line key, case-insensitive ("stbs_lbs" is taken for "stbs-lbs").
     *
     * @param key a {@link #key()} or a constant's name, in any case
     * @return the matching method
     * @throws IllegalArgumentException for any other key, listing the valid ones
     */
    public static SkinningMethod fromKey(String key) {
        for (SkinningMethod m : values()) {
            if (m.key().equalsIgnoreCase(key) || m.name().equalsIgnoreCase(key)) {
                return m;
            }
        }
        StringBuilder keys = new StringBuilder();
        for (SkinningMethod m : values()) {
            keys.append(keys.length() == 0 ? "" : ", ").append(m.key());
        }
        throw new IllegalArgumentException("unknown skinning method \"" + key + "\" (expected one of " + keys + ")");
    }
}
