package org.skinlab.desktop.eval;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;

import org.joml.Matrix3f;
import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.animation.AnimationHelper;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.model.Model;
import org.skinlab.internal.metrics.MethodComparison;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.internal.metrics.RestPose;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * Where and from where the pictures section shows an asset: the clip's sample at which LBS and
 * DQS lie furthest apart (over the model's size, {@link MethodComparison}, what the viewer's
 * difference view measures; a pose whose joint is within a hair of a half turn, where DQS has no
 * sign, is passed over), and the camera's yaw. A joint that bends (its axis of motion lies
 * level) is seen along that axis, so the fold shows in profile; one that twists (its axis
 * upright: a twist about a standing bone) from the side square to where the methods differ
 * most, so the difference shows in the outline; the checker pattern shows the twist itself.
 *
 * @param elapsed     the pose's time from the clip's start
 * @param relative    LBS to DQS at most there, over the model's size
 * @param clipSeconds the clip's length
 * @param yawDegrees  {@code skinlab view --yaw}: 0 from the front (+z), positive towards +x
 * @param rule        which rule chose the yaw: "along the joint's axis" or "across the difference"
 */
record PicturePose(double elapsed, double relative, double clipSeconds, double yawDegrees, String rule) {
    static final String ALONG_AXIS = "along the joint's axis";
    static final String ACROSS = "across the difference";
    /** An axis whose upward part is below this (of its length) lies level enough to look along. */
    static final double LEVEL = 0.7;

    /** The extreme pose of {@code model}'s first clip sampled at {@code perSecond}, and its camera. */
    static PicturePose of(Model model, int perSecond) {
        SkinnedModel skinned = new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0),
                NormalTransform.INVERSE_TRANSPOSE, EnumSet.of(SkinningMethod.LBS)); // poses; the comparisons skin
        float start = skinned.sampler().start();
        float end = skinned.sampler().end();
        float[] times = EvalQualitySection.times(start, end, perSecond);
        List<MethodComparison> comparisons = comparisons(skinned);
        MeasuredJoint joint = MeasuredJoint.choose(skinned, times);
        float bestTime = start;
        double best = -1;
        for (float t : times) {
            double d = lbsDqs(skinned, comparisons, t);
            // A pose within a hair of a half turn has no sign: DQS is ill-defined there, so not shown.
            if (d > best && (joint == null || JointAngle.degrees(skinned.palette(joint.geometry).matrices(),
                    joint.parent, joint.joint) < 180 - MeasuredJoint.HALF_TURN_DEGREES)) {
                best = d;
                bestTime = t;
            }
        }
        // The joint's axis as of the whole clip (its first turn), then the pose itself.
        if (joint != null) {
            for (float t : times) {
                skinned.pose(t, RotationInterpolation.SLERP);
                joint.angle.signedDegrees(skinned.palette(joint.geometry).matrices());
            }
        }
        lbsDqs(skinned, comparisons, bestTime);
        Vector3f axis = joint == null ? null : sceneAxis(model, skinned, joint);
        if (axis != null && Math.abs(axis.y) < LEVEL * axis.length()) {
            return new PicturePose(bestTime - start, Math.max(0, best), end - start, levelYaw(axis.x, axis.z),
                    ALONG_AXIS);
        }
        return new PicturePose(bestTime - start, Math.max(0, best), end - start, yawAcross(model, comparisons),
                ACROSS);
    }

    /** The LBS-DQS distance of the bind pose (every joint at its bind frame), over the model's size. */
    static double bindPose(Model model) {
        SkinnedModel skinned = new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0),
                NormalTransform.INVERSE_TRANSPOSE, EnumSet.of(SkinningMethod.LBS)); // poses; the comparisons skin
        skinned.poseBind();
        return compareCurrent(skinned, comparisons(skinned));
    }

    /**
     * The joint's axis of motion in the scene (Y-up metres), in the current pose: its reference axis
     * in bind space, turned by the parent's skinning matrix and the file's frame.
     */
    private static Vector3f sceneAxis(Model model, SkinnedModel skinned, MeasuredJoint joint) {
        double[] a = joint.angle.axis();
        if (a == null) {
            return null;
        }
        Matrix4f parent = AnimationHelper.getRowMajor3x4(skinned.palette(joint.geometry).matrices(),
                12 * joint.parent, new Matrix4f());
        Vector3f axis = new Vector3f((float) a[0], (float) a[1], (float) a[2]);
        parent.get3x3(new Matrix3f()).transform(axis);
        model.asset().toYUpMeters(new Matrix4f()).transformDirection(axis);
        return axis.lengthSquared() > 0 ? axis.normalize() : null;
    }

    /** The yaw whose eye lies along the level direction (x, z), within 90 degrees of the front. */
    private static double levelYaw(double x, double z) {
        return within90(Math.toDegrees(Math.atan2(x, z)));
    }

    /**
     * The yaw whose view direction is square to the largest LBS-DQS displacement of the pose the
     * comparisons last measured, in the scene's Y-up frame; 0 when that displacement is vertical.
     */
    private static double yawAcross(Model model, List<MethodComparison> comparisons) {
        MethodComparison widest = null;
        for (MethodComparison c : comparisons) {
            if (widest == null || c.maxDistance() > widest.maxDistance()) {
                widest = c;
            }
        }
        if (widest == null || !(widest.maxDistance() > 0)) {
            return 0;
        }
        float[] d = widest.distances();
        int far = 0;
        for (int i = 1; i < d.length; i++) {
            if (d[i] > d[far]) {
                far = i;
            }
        }
        float[] lbs = widest.lbsPositions();
        float[] dqs = widest.dqsPositions();
        Vector3f v = new Vector3f(dqs[3 * far] - lbs[3 * far], dqs[3 * far + 1] - lbs[3 * far + 1],
                dqs[3 * far + 2] - lbs[3 * far + 2]);
        model.asset().toYUpMeters(new Matrix4f()).transformDirection(v);
        double horizontal = Math.hypot(v.x, v.z);
        if (horizontal < 1e-3 * v.length()) {
            return 0;
        }
        // The eye at (sin yaw, cos yaw) around the target is square to v when sin(yaw) v.x + cos(yaw) v.z = 0.
        return within90(Math.toDegrees(Math.atan2(-v.z, v.x)));
    }

    private static double within90(double yaw) {
        if (yaw > 90) {
            return yaw - 180;
        }
        if (yaw <= -90) {
            return yaw + 180;
        }
        return yaw;
    }

    private static List<MethodComparison> comparisons(SkinnedModel skinned) {
        RestPose rest = RestPose.of(skinned);
        List<MethodComparison> comparisons = new ArrayList<>();
        for (int g = 0; g < skinned.geometries().size(); g++) {
            comparisons.add(new MethodComparison(rest, g));
        }
        return comparisons;
    }

    /** The largest LBS-DQS distance over all geometries at clip time t, over the model's size. */
    private static double lbsDqs(SkinnedModel skinned, List<MethodComparison> comparisons, float t) {
        skinned.pose(t, RotationInterpolation.SLERP);
        return compareCurrent(skinned, comparisons);
    }

    private static double compareCurrent(SkinnedModel skinned, List<MethodComparison> comparisons) {
        double max = 0;
        double size = 0;
        for (int g = 0; g < comparisons.size(); g++) {
            MethodComparison c = comparisons.get(g);
            c.compare(skinned.palette(g).matrices());
            max = Math.max(max, c.maxDistance());
            size = c.size();
        }
        return size > 0 ? max / size : 0;
    }
}
