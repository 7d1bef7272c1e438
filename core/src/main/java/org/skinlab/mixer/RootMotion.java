package org.skinlab.mixer;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.animation.LocalPose;
import org.skinlab.animation.Pose;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.Skeleton;
import org.skinlab.animation.WrapMode;

/**
 * Root motion: the root joint's horizontal translation and its yaw (rotation about the up axis),
 * taken out of a clip's pose so that the character animates in place, and delivered as the
 * placement the character moves by.
 *
 * <p>Everything is computed in the root's parent space (the armature's, usually), where the up
 * axis is the model's up axis carried by the parent's rest world matrix. For a clip at elapsed
 * time e the root's horizontal position is h(e) and its heading psi(e) (the twist of its rotation
 * about up). In place, the root keeps the horizontal position and heading of the clip's start.
 * Between two elapsed times a and b of one pass through the clip the character moves by
 * {@code R(psi(0) - psi(a)) (h(b) - h(a))} in its own frame and turns by psi(b) - psi(a); a step
 * that crosses the clip's end is split there, so a looping walk keeps walking (the loop's
 * displacement accumulates) with no jump at the boundary. The placement is the product of these
 * moves, kept in double precision.
 */
final class RootMotion {
    private static final double TWO_PI = 2 * Math.PI;
    /** At most this many whole loops are walked segment by segment in one step (then the step is cut). */
    private static final int MAX_LOOPS_PER_STEP = 64;

    final int root;
    /** The up axis in the root's parent space, unit. */
    private final double ux;
    private final double uy;
    private final double uz;
    private final Matrix4f parentWorld;
    private final Matrix4f parentWorldInverse;
    /** Accumulated placement in the root's parent space: position and heading. */
    private double px;
    private double py;
    private double pz;
    private double heading;
    /** The last step's move, in the frame at the step's start. */
    private final double[] last = new double[4];
    /** Scratch: the root's horizontal position and heading at two times. */
    private final double[] a = new double[4];
    private final double[] b = new double[4];
    /** Scratch for sampling the root alone at any time. */
    private final Pose values;
    private final LocalPose local;

    /**
     * @param skeleton the skeleton
     * @param root the root joint's node, or -1 for none (no root motion)
     * @param up the model's up axis in world space, unit
     * @param parentWorld the root's parent's rest world matrix (identity for a root without a parent)
     */
    RootMotion(Skeleton skeleton, int root, Vector3f up, Matrix4f parentWorld) {
        this.root = root;
        this.values = skeleton.newPose();
        this.local = skeleton.newLocalPose();
        this.parentWorld = new Matrix4f(parentWorld);
        this.parentWorldInverse = new Matrix4f(parentWorld).invertAffine();
        Vector3f u = parentWorldInverse.transformDirection(new Vector3f(up)).normalize();
        this.ux = u.x;
        this.uy = u.y;
        this.uz = u.z;
    }

    /** Root motion within one clip state during one step: elapsed time from {@code e0} by {@code step}. */
    void step(ClipState s, double e0, double step, WrapMode wrap) {
        double[] m = s.motion;
        m[0] = m[1] = m[2] = m[3] = 0;
        MixerClip c = s.clip;
        double d = c.duration;
        if (c.rootSampler == null || !(d > 0) || step == 0) {
            return;
        }
        double[] start = startOf(c);
        if (wrap == WrapMode.CLAMP) {
            segment(s, e0, Math.max(0, Math.min(d, e0 + step)), start, m);
            return;
        }
        double e = e0;
        double left = step;
        for (int loops = 0; loops <= MAX_LOOPS_PER_STEP && left != 0; loops++) {
            if (left > 0) {
                double to = Math.min(d, e + left);
                segment(s, e, to, start, m);
                left -= to - e;
                e = to >= d ? 0 : to;
            } else {
                double to = Math.max(0, e + left);
                segment(s, e, to, start, m);
                left -= to - e;
                e = to <= 0 ? d : to;
            }
        }
    }

    /** Composes the move from elapsed {@code from} to {@code to} (one pass) onto {@code m}. */
    private void segment(ClipState s, double from, double to, double[] start, double[] m) {
        if (from == to) {
            return;
        }
        sample(s.clip, from, a);
        sample(s.clip, to, b);
        // The move in the in-place character's frame (heading of the clip's start).
        double[] v = rotate(b[0] - a[0], b[1] - a[1], b[2] - a[2], start[3] - a[3]);
        // Onto the step so far: translate in its current frame, then turn.
        double[] w = rotate(v[0], v[1], v[2], m[3]);
        m[0] += w[0];
        m[1] += w[1];
        m[2] += w[2];
        m[3] += wrapAngle(b[3] - a[3]);
    }

    /** The root's horizontal position and heading at the clip's start, sampled once per clip. */
    private double[] startOf(MixerClip c) {
        if (!c.rootStartKnown) {
            sample(c, 0, c.rootStart);
            c.rootStartKnown = true;
        }
        return c.rootStart;
    }

    /** The root's horizontal position and heading at elapsed time {@code e} of the clip. */
    private void sample(MixerClip c, double e, double[] dest) {
        // Shared by every clip: values another clip's root channels left must not leak into this one's.
        values.skeleton().reset(values);
        c.rootSampler.sampleLocal(c.clipTime(e), RotationInterpolation.SLERP, values, local);
        read(local.array(), LocalPose.STRIDE * root, dest);
    }

    private void read(float[] trs, int o, double[] dest) {
        double tx = trs[o];
        double ty = trs[o + 1];
        double tz = trs[o + 2];
        double up = tx * ux + ty * uy + tz * uz;
        dest[0] = tx - up * ux;
        dest[1] = ty - up * uy;
        dest[2] = tz - up * uz;
        dest[3] = yaw(trs[o + 3], trs[o + 4], trs[o + 5], trs[o + 6]);
    }

    /** The angle of the twist of rotation q about the up axis, in (-pi, pi]. */
    private double yaw(double x, double y, double z, double w) {
        return wrapAngle(2 * Math.atan2(x * ux + y * uy + z * uz, w));
    }

    /**
     * Puts the root of {@code trs} (the clip {@code c} just sampled) in place: its horizontal
     * position and heading those of the clip's start.
     */
    void makeInPlace(MixerClip c, float[] trs) {
        if (c.rootSampler == null) {
            return;
        }
        double[] start = startOf(c);
        int o = LocalPose.STRIDE * root;
        read(trs, o, a);
        trs[o] += (float) (start[0] - a[0]);
        trs[o + 1] += (float) (start[1] - a[1]);
        trs[o + 2] += (float) (start[2] - a[2]);
        // q' = twist(start heading - heading) * q: the heading of the clip's start.
        double half = 0.5 * wrapAngle(start[3] - a[3]);
        double sin = Math.sin(half);
        double cos = Math.cos(half);
        double rx = ux * sin;
        double ry = uy * sin;
        double rz = uz * sin;
        double qx = trs[o + 3];
        double qy = trs[o + 4];
        double qz = trs[o + 5];
        double qw = trs[o + 6];
        trs[o + 3] = (float) (cos * qx + rx * qw + ry * qz - rz * qy);
        trs[o + 4] = (float) (cos * qy + ry * qw + rz * qx - rx * qz);
        trs[o + 5] = (float) (cos * qz + rz * qw + rx * qy - ry * qx);
        trs[o + 6] = (float) (cos * qw - rx * qx - ry * qy - rz * qz);
    }

    /** Applies a step's move (weighted sum of the clip states' moves) to the placement. */
    void apply(double dx, double dy, double dz, double dyaw) {
        last[0] = dx;
        last[1] = dy;
        last[2] = dz;
        last[3] = dyaw;
        double[] w = rotate(dx, dy, dz, heading);
        px += w[0];
        py += w[1];
        pz += w[2];
        heading = wrapAngle(heading + dyaw);
    }

    /** Turns the placement by {@code angle} radians about up, where it stands (a steering correction). */
    void turn(double angle) {
        heading = wrapAngle(heading + angle);
    }

    void reset() {
        px = py = pz = heading = 0;
        last[0] = last[1] = last[2] = last[3] = 0;
    }

    /** The placement in the model's space: parentWorld * T(p) * R(heading) * parentWorld^-1. */
    Matrix4f placement(Matrix4f dest) {
        return inModelSpace(px, py, pz, heading, dest);
    }

    /** The last step's move in the model's space, to post-multiply the placement before it by. */
    Matrix4f lastMove(Matrix4f dest) {
        return inModelSpace(last[0], last[1], last[2], last[3], dest);
    }

    private Matrix4f inModelSpace(double x, double y, double z, double angle, Matrix4f dest) {
        return dest.set(parentWorld).translate((float) x, (float) y, (float) z)
                .rotate((float) angle, (float) ux, (float) uy, (float) uz).mul(parentWorldInverse);
    }

    /** The placement's position in the root's parent space, and its heading: x, y, z, radians. */
    void position(double[] dest) {
        dest[0] = px;
        dest[1] = py;
        dest[2] = pz;
        dest[3] = heading;
    }

    /** v rotated by {@code angle} about up (v horizontal: u.v = 0 up to rounding). */
    private double[] rotate(double x, double y, double z, double angle) {
        double c = Math.cos(angle);
        double sn = Math.sin(angle);
        double cx = uy * z - uz * y;
        double cy = uz * x - ux * z;
        double cz = ux * y - uy * x;
        double[] r = rotated;
        r[0] = x * c + cx * sn;
        r[1] = y * c + cy * sn;
        r[2] = z * c + cz * sn;
        return r;
    }

    private final double[] rotated = new double[3];

    static double wrapAngle(double angle) {
        double r = angle % TWO_PI;
        if (r > Math.PI) {
            r -= TWO_PI;
        } else if (r <= -Math.PI) {
            r += TWO_PI;
        }
        return r;
    }
}
