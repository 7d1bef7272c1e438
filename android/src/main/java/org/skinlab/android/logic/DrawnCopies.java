package org.skinlab.android.logic;

import java.util.List;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import org.skinlab.internal.bench.DeviceResults;
import org.skinlab.simulation.SkeletalAnimatedMesh;

/**
 * The GPU part of the app's measurement, between the measuring thread and the GL thread: the
 * measuring thread asks for copies of a model to be drawn for a time ({@link #draw}, which waits),
 * the GL thread draws the request it finds at each frame ({@link #current}) and reports each frame
 * it finished ({@link #drawn}); the frames per second are the frames finished over the time they
 * took, after a few warm-up frames. GLSurfaceView swaps each frame with vsync, so no rate exceeds
 * the display's refresh rate.
 *
 * <p>The GL thread also leaves the driver's strings here ({@link #glStrings}) when it makes a
 * context. Where no GL thread draws (the app left the screen, or a platform whose GLSurfaceView
 * renders nothing, as Robolectric's), {@link #draw} gives up after {@code noFrameSeconds} without
 * a frame and says so.
 */
public final class DrawnCopies {
    /** How long the app's measuring thread waits for a frame before it calls the GPU part unavailable. */
    public static final double NO_FRAME_SECONDS = 5;

    /** The frames a request took once warm: how many and over how long. */
    public record Run(int frames, double seconds) {
        public double fps() {
            return frames / seconds;
        }
    }

    /** Why the GPU part cannot be measured: nothing was drawn for a while, or the GL thread cannot draw. */
    public static final class Undrawable extends Exception {
        private static final long serialVersionUID = 1L;

        Undrawable(String message) {
            super(message);
        }
    }

    /**
     * Copies to draw, each its own simulation (not started: the GL thread steps each once a frame,
     * so every copy is posed and its palette uploaded each frame, as each character of a crowd is).
     */
    public static final class Request {
        private final List<SkeletalAnimatedMesh> copies;
        private final int warmupFrames;
        private final long nanos;
        private final CountDownLatch done = new CountDownLatch(1);
        /** GL thread only. */
        private int frames;
        private long start;
        private volatile long lastFrame;
        private volatile Run run;
        private volatile String undrawable;
        private volatile boolean cancelled;

        Request(List<SkeletalAnimatedMesh> copies, int warmupFrames, double seconds) {
            this.copies = List.copyOf(copies);
            this.warmupFrames = warmupFrames;
            this.nanos = (long) (seconds * 1e9);
        }

        /** The copies, in grid order. */
        public List<SkeletalAnimatedMesh> copies() {
            return copies;
        }
    }

    private final double noFrameSeconds;
    private volatile Request current;
    private volatile DeviceResults.Gpu gpu;
    private volatile boolean measuring;

    /** Waits at most {@code noFrameSeconds} for a frame before {@link #draw} gives up. */
    public DrawnCopies(double noFrameSeconds) {
        this.noFrameSeconds = noFrameSeconds;
    }

    // --- the GL thread ---

    /** The request to draw this frame, or null (then the GL thread draws what it otherwise does). */
    public Request current() {
        Request r = current;
        return r == null || r.cancelled || r.done.getCount() == 0 ? null : r;
    }

    /**
     * The GL thread finished a frame of {@code r} at {@code nanos} ({@code System.nanoTime()}). The
     * timing starts when the last warm-up frame ends (the first frame's end without warm-up frames).
     */
    public void drawn(Request r, long nanos) {
        r.lastFrame = nanos;
        r.frames++;
        int anchor = Math.max(1, r.warmupFrames);
        if (r.frames <= anchor) {
            r.start = nanos;
            return;
        }
        int timed = r.frames - anchor;
        if (timed >= 5 && nanos - r.start >= r.nanos) {
            r.run = new Run(timed, (nanos - r.start) / 1e9);
            r.done.countDown();
        }
    }

    /** The GL thread cannot draw {@code r}, for the reason given (e.g. the driver refused the shaders). */
    public void undrawable(Request r, String why) {
        r.undrawable = why;
        r.done.countDown();
    }

    /** Whether a measurement may still ask for copies: while it does, the GL thread keeps their buffers. */
    public boolean measuring() {
        return measuring;
    }

    /** The driver's strings, read on the GL thread when it makes a context. */
    public void glStrings(String renderer, String vendor, String version) {
        gpu = DeviceResults.Gpu.of(renderer, vendor, version);
    }

    // --- the measuring thread ---

    /** A measurement starts asking for copies ({@link #measuring}). */
    public void begin() {
        measuring = true;
    }

    /** The measurement asks for no more copies: the GL thread may release their buffers. */
    public void end() {
        measuring = false;
    }

    /**
     * Has {@code copies} drawn for at least {@code seconds} (and 5 frames) after
     * {@code warmupFrames} frames; waits for the GL thread.
     *
     * @throws Undrawable          when no frame was drawn for {@code noFrameSeconds}, or the GL thread cannot draw
     * @throws InterruptedException when the measuring thread is interrupted (the request is withdrawn)
     */
    public Run draw(List<SkeletalAnimatedMesh> copies, int warmupFrames, double seconds)
            throws Undrawable, InterruptedException {
        Request r = new Request(copies, warmupFrames, seconds);
        r.lastFrame = System.nanoTime();
        current = r;
        try {
            long patience = (long) (noFrameSeconds * 1e9);
            while (!r.done.await(50, TimeUnit.MILLISECONDS)) {
                long waited = System.nanoTime() - r.lastFrame;
                if (waited > patience) {
                    throw new Undrawable("the GL view drew no frame in " + format(noFrameSeconds)
                            + " s: nothing could be drawn (the app not on screen, or a platform whose GLSurfaceView"
                            + " does not render)");
                }
            }
            if (r.undrawable != null) {
                throw new Undrawable(r.undrawable);
            }
            return r.run;
        } finally {
            r.cancelled = true;
            current = null;
        }
    }

    /** The driver's strings, or why they are unknown (no GL context was made while the app measured). */
    public DeviceResults.Gpu gpu() {
        DeviceResults.Gpu g = gpu;
        return g != null ? g : DeviceResults.Gpu.unavailable("no GL context was made: GL_RENDERER, GL_VENDOR and"
                + " GL_VERSION are read on the GL thread");
    }

    private static String format(double seconds) {
        return seconds == Math.rint(seconds) ? String.valueOf((long) seconds) : String.valueOf(seconds);
    }
}
