package org.skinlab.ar;

/**
 * What the renderer reads each frame: one consistent, immutable result of one camera frame's
 * tracking ({@link ArSession#current()}). The arrays are copies nobody else writes.
 *
 * @param state          tracking state (the model is drawn when {@link TrackingState#showsModel()})
 * @param rotation       the filtered marker pose R (row-major; {@code X_cam = R X_marker + t})
 * @param translation    the filtered t in metres
 * @param markerId       the id of the marker the model is on ({@link MarkerTracking#followedId()}),
 *                       -1 while the model is not shown
 * @param markers        how many markers the frame's detector reported (of any id, unless the
 *                       tracker's config names one)
 * @param trackerMillis  the detector's time on this frame
 * @param timeNanos      the camera frame's timestamp
 * @param frameNumber    1 for the first frame tracked, counting up
 */
public record ArPose(TrackingState state, double[] rotation, double[] translation, int markerId, int markers,
        double trackerMillis, long timeNanos, long frameNumber) {

    /** Before the first frame. */
    public static final ArPose NONE = new ArPose(TrackingState.SEARCHING, new double[] {1, 0, 0, 0, -1, 0, 0, 0, -1},
            new double[] {0, 0, 1}, -1, 0, 0, 0, 0);

    /**
     * Copies the arrays, so the caller may reuse its own.
     *
     * @param state         tracking state
     * @param rotation      the filtered marker pose R, 9 entries row-major (copied)
     * @param translation   the filtered t in metres, 3 entries (copied)
     * @param markerId      the id of the marker the model is on, -1 while the model is not shown
     * @param markers       how many markers the frame's detector reported
     * @param trackerMillis the detector's time on this frame, in milliseconds
     * @param timeNanos     the camera frame's timestamp in nanoseconds
     * @param frameNumber   1 for the first frame tracked, counting up (0 for {@link #NONE})
     * @throws NullPointerException when {@code rotation} or {@code translation} is null
     */
    public ArPose {
        rotation = rotation.clone();
        translation = translation.clone();
    }

    /**
     * The filtered marker pose R.
     *
     * @return a new array of 9: R row-major, {@code X_cam = R X_marker + t}
     */
    @Override
    public double[] rotation() {
        return rotation.clone();
    }

    /**
     * The filtered marker position t.
     *
     * @return a new array of 3: the marker's centre in camera coordinates, in metres
     */
    @Override
    public double[] translation() {
        return translation.clone();
    }

    /**
     * The marker part of a status line: the state, the followed id while the model is shown, and
     * how many markers the frame shows, e.g. "tracking id 3, 2 in view", "holding id 3", "searching".
     *
     * @return the label, lower case, without a final period
     */
    public String markerLabel() {
        StringBuilder s = new StringBuilder(state.label());
        if (visible() && markerId >= 0) {
            s.append(" id ").append(markerId);
        }
        if (markers > 0) {
            s.append(", ").append(markers).append(" in view");
        }
        return s.toString();
    }

    /**
     * Whether the model is drawn.
     *
     * @return true while TRACKING or HOLDING ({@link TrackingState#showsModel()})
     */
    public boolean visible() {
        return state.showsModel();
    }

    /**
     * The marker's OpenGL model-view ({@link ArCamera#markerModelView}) into {@code dest}.
     *
     * @param dest receives the matrix from marker coordinates (metres) to OpenGL eye coordinates (y up, looking
     *             down -z)
     * @return {@code dest}
     */
    public org.joml.Matrix4f markerModelView(org.joml.Matrix4f dest) {
        return ArCamera.markerModelView(rotation, translation, dest);
    }

    /**
     * The yaw that faces the camera from this pose ({@link CameraFollow#yawTowardCamera}).
     *
     * @param fallback the yaw in radians to return when the camera is overhead (within
     *                 {@link CameraFollow#OVERHEAD_DEGREES} of the marker's normal)
     * @return the yaw in radians about the marker's +z, or {@code fallback}
     */
    public double yawTowardCamera(double fallback) {
        return CameraFollow.yawTowardCamera(rotation, translation, fallback);
    }
}
