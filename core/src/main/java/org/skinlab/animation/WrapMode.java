package org.skinlab.animation;

/** What playback does past the end of a clip. */
public enum WrapMode {
    /** Start over: time wraps into [start, end). */
    LOOP,
    /** Hold the first or last pose. */
    CLAMP
}
