package org.skinlab.ar;

import java.util.List;
import org.skinlab.internal.ar.PoseMath;

/**
 * One marker followed over the frames of a video: which detection is the marker, its filtered pose
 * ({@link PoseFilter}), and the {@link TrackingState} the presenter shows. Fed once per frame by
 * the tracking thread; not thread-safe ({@link ArSession} publishes its results).
 *
 * <ul>
 * <li>The marker is the detection of the target id, whatever else is in view. With id -1 it is the
 *     nearest marker when the search starts, and from then on that marker's id ({@link
 *     #followedId()}): a second marker that comes nearer does not take the model over, which
 *     would otherwise jump between two markers at similar distances from frame to frame. The
 *     choice is made anew only once the followed marker is LOST (or after {@link #reset()}).</li>
 * <li>Missing from a frame, the last pose is held for {@link #holdNanos()} (state HOLDING), then
 *     the model is hidden (LOST); found again, the filter restarts at the new pose.</li>
 * <li><b>The planar ambiguity.</b> A square seen nearly face-on has two poses that explain its
 *     corners almost equally well, mirror images about the line of sight; from one frame to the
 *     next the estimator may pick the other, a jump of tens of degrees. A rotation more than
 *     {@link #FLIP_DEGREES} away from the filtered one is therefore not believed at once: the
 *     position is updated, the rotation kept, until {@link #FLIP_FRAMES} frames in a row agree
 *     (within {@link #FLIP_DEGREES} of each other) on the new rotation, which is then taken as
 *     it is. A real fast turn costs those frames of lag; a flip of a frame or two never shows.</li>
 * </ul>
 */
public final class MarkerTracking {
    /** How long the last pose is held after the marker disappears, unless told otherwise. */
    public static final long DEFAULT_HOLD_NANOS = 500_000_000L;
    /** A rotation jump beyond this (degrees) between frames is not believed at once. */
    public static final double FLIP_DEGREES = 25;
    /** Frames a jumped-to rotation must persist before it is taken. */
    public static final int FLIP_FRAMES = 3;

    private final int targetId;
    private final long holdNanos;
    private final PoseFilter filter = new PoseFilter();
    private final double[] rotation = new double[9];
    private final double[] translation = new double[3];
    private final double[] candidate = new double[9];
    private int candidateFrames;
    private TrackingState state = TrackingState.SEARCHING;
    private long lastSeenNanos;
    private MarkerDetection last;
    /** The id the model is on while it is shown; with target id -1, the marker locked on to. */
    private int followedId = -1;

    /**
     * @param targetId  the marker's id, or -1 for the nearest marker of any id
     * @param holdNanos how long a lost marker's pose is held
     * @throws IllegalArgumentException when {@code holdNanos} is negative
     */
    public MarkerTracking(int targetId, long holdNanos) {
        if (holdNanos < 0) {
            throw new IllegalArgumentException("hold time must not be negative: " + holdNanos);
        }
        this.targetId = targetId;
        this.holdNanos = holdNanos;
    }

    /** Any id, the default hold. */
    public MarkerTracking() {
        this(-1, DEFAULT_HOLD_NANOS);
    }

    /**
     * How long the last pose is held (state HOLDING) after the marker disappears, before LOST.
     *
     * @return the hold time in nanoseconds, 0 or more
     */
    public long holdNanos() {
        return holdNanos;
    }

    /**
     * One frame's detections (possibly none), taken at {@code timeNanos}; returns the new state.
     *
     * @param timeNanos  the frame's timestamp in nanoseconds, on one monotonic clock for all frames (the hold time
     *                   and the filter measure differences of it)
     * @param detections what the detector found in the frame, of any id, in any order; may be empty, not null; read,
     *                   not kept
     * @return the state after this frame: TRACKING when the followed marker is among the detections, else
     *         HOLDING or LOST after TRACKING (by the hold time), else unchanged (SEARCHING or LOST)
     */
    public TrackingState update(long timeNanos, List<MarkerDetection> detections) {
        MarkerDetection d = pick(detections);
        if (d == null) {
            if (state == TrackingState.TRACKING || state == TrackingState.HOLDING) {
                state = timeNanos - lastSeenNanos < holdNanos ? TrackingState.HOLDING : TrackingState.LOST;
            }
            return state;
        }
        if (!state.showsModel()) {
            filter.reset();
            candidateFrames = 0;
            followedId = d.id();
        }
        double[] r = d.rotation();
        if (state.showsModel() && PoseMath.angleDegrees(rotation, r) > FLIP_DEGREES) {
            // A jump: believed only once it persists.
            if (candidateFrames > 0 && PoseMath.angleDegrees(candidate, r) <= FLIP_DEGREES) {
                candidateFrames++;
            } else {
                candidateFrames = 1;
            }
            System.arraycopy(r, 0, candidate, 0, 9);
            if (candidateFrames >= FLIP_FRAMES) {
                filter.reset();
                candidateFrames = 0;
            } else {
                // The filter holds this rotation: fed itself, it stays.
                filter.update(rotation, d.translation(), timeNanos, rotation, translation);
                lastSeenNanos = timeNanos;
                last = d;
                state = TrackingState.TRACKING;
                return state;
            }
        } else {
            candidateFrames = 0;
        }
        filter.update(r, d.translation(), timeNanos, rotation, translation);
        lastSeenNanos = timeNanos;
        last = d;
        state = TrackingState.TRACKING;
        return state;
    }

    /**
     * The state after the last {@link #update}.
     *
     * @return the current state; SEARCHING before the first detection and after {@link #reset()}
     */
    public TrackingState state() {
        return state;
    }

    /**
     * The id of the marker the model is on while it is shown (TRACKING, HOLDING), else -1.
     *
     * @return the followed marker's id, or -1 while the model is not shown
     */
    public int followedId() {
        return state.showsModel() ? followedId : -1;
    }

    /**
     * The filtered rotation (row-major) into {@code dest}; meaningful while {@link TrackingState#showsModel()}.
     *
     * @param dest at least 9 doubles; entries 0..8 receive R ({@code X_cam = R X_marker + t}), the rest untouched
     * @return {@code dest}
     */
    public double[] rotation(double[] dest) {
        System.arraycopy(rotation, 0, dest, 0, 9);
        return dest;
    }

    /**
     * The filtered translation into {@code dest}.
     *
     * @param dest at least 3 doubles; entries 0..2 receive t in metres, the rest untouched; meaningful while
     *             {@link TrackingState#showsModel()}
     * @return {@code dest}
     */
    public double[] translation(double[] dest) {
        System.arraycopy(translation, 0, dest, 0, 3);
        return dest;
    }

    /** Back to SEARCHING (a new video, the camera reopened). */
    public void reset() {
        state = TrackingState.SEARCHING;
        filter.reset();
        candidateFrames = 0;
        last = null;
        followedId = -1;
    }

    /** The followed marker's detection (the nearest, should its id be seen twice), or null. */
    private MarkerDetection pick(List<MarkerDetection> detections) {
        int id = targetId >= 0 ? targetId : state.showsModel() ? followedId : -1;
        MarkerDetection best = null;
        for (MarkerDetection d : detections) {
            if (id >= 0 && d.id() != id) {
                continue;
            }
            if (best == null || d.distance() < best.distance()) {
                best = d;
            }
        }
        return best;
    }
}
