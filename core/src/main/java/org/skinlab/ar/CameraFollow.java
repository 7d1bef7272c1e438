package org.skinlab.ar;

/**
 * "Follow the camera" (the thesis' interaction): the model on the marker turns about the marker's
 * normal to face the camera. The line of sight, from the marker's origin to the camera centre
 * {@code c = -R^T t} in the marker frame, is projected onto the marker plane; the yaw turns the
 * model's front ({@link MarkerScene}: the marker's -y at yaw 0) onto that direction:
 * {@code yaw = atan2(c_x, -c_y)}. The up axis stays the marker's normal.
 *
 * <p>Seen from (almost) straight above, the projected direction is noise: within
 * {@link #OVERHEAD_DEGREES} of the normal the last yaw is kept. One instance per presenter (it
 * keeps that yaw); not thread-safe.
 */
public final class CameraFollow {
    /** How close to the marker's normal the camera may be before the yaw stops following. */
    public static final double OVERHEAD_DEGREES = 3.0;

    private double yaw;

    /**
     * The yaw that faces the camera of pose (R, t), or the last one when the camera is overhead.
     *
     * @param r the marker's rotation R, 3x3 row-major ({@code X_cam = R X_marker + t}); read only
     * @param t the marker's translation t in metres; read only
     * @return the new current yaw in radians ({@link #yawTowardCamera}), also kept for {@link #yaw()}
     */
    public double update(double[] r, double[] t) {
        yaw = yawTowardCamera(r, t, yaw);
        return yaw;
    }

    /**
     * The current yaw in radians.
     *
     * @return the yaw the last {@link #update} returned, in [-pi, pi], or 0 before any (or after {@link #reset()})
     */
    public double yaw() {
        return yaw;
    }

    /** Starts again from yaw 0 (a new marker, follow switched on again). */
    public void reset() {
        yaw = 0;
    }

    /**
     * The yaw (radians, about the marker's +z, counter-clockwise seen from above) that turns the
     * model's front toward the camera of pose (R row-major, t), or {@code fallback} when the
     * camera is within {@link #OVERHEAD_DEGREES} of the marker's normal (or behind its plane's edge-on).
     *
     * @param r        the marker's rotation R, 3x3 row-major ({@code X_cam = R X_marker + t}); read only
     * @param t        the marker's translation t in metres; read only
     * @param fallback the yaw in radians to return when the camera is overhead (usually the last one)
     * @return the yaw in radians, in [-pi, pi] ({@code atan2(c_x, -c_y)}), or {@code fallback}
     */
    public static double yawTowardCamera(double[] r, double[] t, double fallback) {
        // c = -R^T t: the camera centre in the marker frame.
        double cx = -(r[0] * t[0] + r[3] * t[1] + r[6] * t[2]);
        double cy = -(r[1] * t[0] + r[4] * t[1] + r[7] * t[2]);
        double cz = -(r[2] * t[0] + r[5] * t[1] + r[8] * t[2]);
        double horizontal = Math.hypot(cx, cy);
        if (horizontal < Math.tan(Math.toRadians(OVERHEAD_DEGREES)) * Math.abs(cz) || horizontal == 0) {
            return fallback;
        }
        return Math.atan2(cx, -cy);
    }
}
