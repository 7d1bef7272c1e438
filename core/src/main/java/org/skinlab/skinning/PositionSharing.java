package org.skinlab.skinning;

/**
 * Whether {@link Skinners#create(SkinningMethod, SkinnedGeometry, NormalTransform, PositionSharing)}
 * skins each shared position once ({@link SkinnedGeometry#sharedPositions()}) or every point.
 */
public enum PositionSharing {
    /** Share where it pays for the method ({@link SharedPositionSkinner#pays}): what the runtime uses. */
    AUTO,
    /** Share whenever the geometry has positions carried by several points (e.g. to compare routes). */
    ALWAYS,
    /** Skin every point on its own. */
    NEVER;

    /**
     * The lower-case name used on the command line.
     *
     * @return "auto", "always" or "never"
     */
    public String key() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }

    /**
     * The sharing for a command-line key, case-insensitive.
     *
     * @param key "auto", "always" or "never", in any case
     * @return the matching constant
     * @throws IllegalArgumentException for any other key
     */
    public static PositionSharing fromKey(String key) {
        for (PositionSharing s : values()) {
            if (s.name().equalsIgnoreCase(key)) {
                return s;
            }
        }
        throw new IllegalArgumentException("unknown position sharing \"" + key + "\" (expected auto, always or never)");
    }
}
