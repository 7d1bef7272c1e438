package org.skinlab.ar;

/** What the AR presenter shows about the marker; the apps print it in their status line. */
public enum TrackingState {
    /** No marker seen yet (or since a reset): nothing drawn. */
    SEARCHING,
    /** The marker is in this frame: the model stands on it. */
    TRACKING,
    /** The marker was lost less than the hold time ago: the model stays at its last pose. */
    HOLDING,
    /** The marker has been gone longer than the hold time: the model is hidden. */
    LOST;

    /**
     * Whether the model is drawn in this state.
     *
     * @return true for {@link #TRACKING} and {@link #HOLDING}, false for {@link #SEARCHING} and {@link #LOST}
     */
    public boolean showsModel() {
        return this == TRACKING || this == HOLDING;
    }

    /**
     * Lower-case name for status lines.
     *
     * @return the constant's name in lower case (locale-independent), e.g. "tracking"
     */
    public String label() {
        return name().toLowerCase(java.util.Locale.ROOT);
    }
}
