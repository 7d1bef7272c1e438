package org.skinlab.ar;

import java.util.List;
import java.util.Objects;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Function;

/**
 * The AR pipeline between a camera and a renderer, safe across their threads: the camera's (or a
 * tracking) thread calls {@link #onCameraFrame} with each gray frame, which runs the detector (for
 * example {@link FiducialTracker#track}) and {@link MarkerTracking}, and publishes an immutable
 * {@link ArPose}; the render thread reads the latest with {@link #current()}, one volatile read, so
 * it never sees half of one frame's pose and half of another's.
 *
 * <p>Frames must come from one thread (the detector and the tracking keep state); a second caller
 * is refused rather than silently interleaved. A camera reopened on a new thread gets a new
 * session, which also starts the tracking over.
 */
public final class ArSession {
    private final Function<GrayImage, List<MarkerDetection>> detector;
    private final MarkerTracking tracking;
    private final double[] rotation = new double[9];
    private final double[] translation = new double[3];
    private volatile ArPose current = ArPose.NONE;
    private final AtomicReference<Thread> feeder = new AtomicReference<>();
    private long frames;

    /**
     * A session over any detector; both are used only from the thread that feeds frames.
     *
     * @param detector finds the markers in one frame (of any id, possibly none; never null), e.g.
     *                 {@code tracker::track}; it may keep state between frames
     * @param tracking follows one marker over the frames; owned by this session from now on
     * @throws NullPointerException when either is null
     */
    public ArSession(Function<GrayImage, List<MarkerDetection>> detector, MarkerTracking tracking) {
        this.detector = Objects.requireNonNull(detector, "detector");
        this.tracking = Objects.requireNonNull(tracking, "tracking");
    }

    /**
     * A session over a tracker's video search and the default tracking (any id, 0.5 s hold).
     *
     * @param tracker the detector, {@link FiducialTracker#track} each frame; its config's target id (-1 for any)
     *                is the marker followed
     * @return a new session, SEARCHING until the first frame
     */
    public static ArSession of(FiducialTracker tracker) {
        return new ArSession(tracker::track, new MarkerTracking(tracker.config().targetId(),
                MarkerTracking.DEFAULT_HOLD_NANOS));
    }

    /**
     * Tracks one camera frame taken at {@code timeNanos} and publishes the result, which it returns.
     *
     * @param image     the frame's gray (luminance) image, handed to the detector during this call; the session
     *                  keeps no reference to it
     * @param timeNanos the frame's timestamp in nanoseconds, on one monotonic clock for all frames (the camera's
     *                  sensor timestamp, or {@link System#nanoTime()}); it goes into the pose unchanged
     * @return the new pose, the one {@link #current()} returns from now on
     * @throws IllegalStateException when called from a thread other than the one that fed the first frame
     */
    public ArPose onCameraFrame(GrayImage image, long timeNanos) {
        Thread me = Thread.currentThread();
        // compareAndSet, not compareAndExchange: the latter is Android 13+ (core runs on Android 8).
        Thread owner = feeder.compareAndSet(null, me) ? me : feeder.get();
        if (owner != me) {
            throw new IllegalStateException("camera frames from " + me.getName() + " while " + owner.getName()
                    + " feeds this session; a new camera stream needs a new session");
        }
        long start = System.nanoTime();
        List<MarkerDetection> found = detector.apply(image);
        double millis = (System.nanoTime() - start) * 1e-6;
        TrackingState state = tracking.update(timeNanos, found);
        tracking.rotation(rotation);
        tracking.translation(translation);
        ArPose pose = new ArPose(state, rotation, translation, tracking.followedId(), found.size(), millis, timeNanos,
                ++frames);
        current = pose;
        return pose;
    }

    /**
     * The latest published pose; from any thread.
     *
     * @return the pose of the last frame tracked, or {@link ArPose#NONE} before the first
     */
    public ArPose current() {
        return current;
    }
}
