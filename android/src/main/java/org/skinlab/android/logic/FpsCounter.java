package org.skinlab.android.logic;

/** Frames per second over the last second or so, from frame timestamps; allocation-free. */
public final class FpsCounter {
    private long windowStart = -1;
    private int frames;
    private double fps;

    /** Counts a frame drawn at {@code nanos}; returns the current estimate. */
    public double frame(long nanos) {
        if (windowStart < 0) {
            windowStart = nanos;
        }
        frames++;
        long span = nanos - windowStart;
        if (span >= 500_000_000L) {
            fps = frames * 1e9 / span;
            frames = 0;
            windowStart = nanos;
        }
        return fps;
    }

    public double fps() {
        return fps;
    }
}
