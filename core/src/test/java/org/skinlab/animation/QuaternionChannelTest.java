package org.skinlab.animation;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.List;

import org.joml.Matrix4f;
import org.joml.Quaternionf;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.model.AnimationChannel;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.AssetInfo;
import org.skinlab.model.Interpolation;
import org.skinlab.model.KeyframeTrack;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.model.TransformElement;
import org.skinlab.model.UpAxis;

/**
 * Rotation quaternions (glTF's node rotation, {@link TransformElement.Kind#QUATERNION}): the matrix
 * of one, and what {@link AnimationSampler} writes between keys for LINEAR (by the chosen
 * rotation interpolation), BEZIER (per value, renormalised) and STEP, checked against rotations
 * about Z whose angles are known by hand.
 */
class QuaternionChannelTest {
    /** Float quaternion arithmetic on unit values: 1e-6 per component. */
    private static final float EPS = 1e-6f;

    @Test
    void quaternionElementIsItsRotationAndAZeroAxisRotatesNothing() {
        Quaternionf q = new Quaternionf().rotationAxis(0.7f, 0.3f, -0.5f, 0.8f);
        Matrix4f m = new TransformElement(TransformElement.Kind.QUATERNION, null,
                new float[] {q.x, q.y, q.z, q.w}).multiply(new Matrix4f(), new Matrix4f());
        Vector3f p = m.transformPosition(new Vector3f(1, 2, 3));
        Vector3f expected = q.transform(new Vector3f(1, 2, 3));
        assertEquals(expected.x, p.x, EPS);
        assertEquals(expected.y, p.y, EPS);
        assertEquals(expected.z, p.z, EPS);
        Matrix4f identity = new TransformElement(TransformElement.Kind.QUATERNION, null,
                new float[] {0, 0, 0, 1}).multiply(new Matrix4f(), new Matrix4f());
        assertEquals(new Matrix4f(), identity);
    }

    @Test
    void halfLengthQuaternionScalesByAQuarter() {
        // Homogeneous form: |q|^2 = 0.25.
        Matrix4f m = new TransformElement(TransformElement.Kind.QUATERNION, null,
                new float[] {0, 0, 0, 0.5f}).multiply(new Matrix4f(), new Matrix4f());
        assertEquals(0.25f, m.m00(), EPS);
        assertEquals(0.25f, m.m22(), EPS);
    }

    @Test
    void linearKeysFollowTheChosenRotationInterpolation() {
        // 0 and 120 degrees about Z, sampled a quarter of the way: slerp gives exactly 30 degrees,
        // nlerp the angle of the normalised chord, lerp the chord itself (shorter than 1).
        Pose pose = sample(Interpolation.LINEAR, 0.25f, RotationInterpolation.SLERP);
        assertEquals(Math.toRadians(30), angleAboutZ(pose), 1e-6);
        assertEquals(1.0, length(pose), EPS);

        double nlerp = Math.atan2(0.25 * Math.sin(Math.toRadians(60)), 0.75 + 0.25 * Math.cos(Math.toRadians(60)));
        Pose n = sample(Interpolation.LINEAR, 0.25f, RotationInterpolation.NLERP);
        assertEquals(2 * nlerp, angleAboutZ(n), 1e-6);

        Pose l = sample(Interpolation.LINEAR, 0.5f, RotationInterpolation.LERP);
        assertEquals(Math.cos(Math.toRadians(30)), length(l), EPS); // the chord's midpoint
    }

    @Test
    void bezierKeysAreRenormalisedAndStepKeysHold() {
        // Flat tangents: the cubic's value at the middle is the plain average of the keys, a
        // quaternion of length cos 30 degrees; the sampler renormalises it to 60 degrees.
        Pose b = sample(Interpolation.BEZIER, 0.5f, RotationInterpolation.SLERP);
        assertEquals(1.0, length(b), EPS);
        assertEquals(Math.toRadians(60), angleAboutZ(b), 1e-6);

        Pose s = sample(Interpolation.STEP, 0.9f, RotationInterpolation.SLERP);
        assertEquals(0.0, angleAboutZ(s), 1e-6);
    }

    private static Pose sample(Interpolation how, float time, RotationInterpolation rotations) {
        float s = (float) Math.sin(Math.toRadians(60));
        float c = (float) Math.cos(Math.toRadians(60));
        float[] values = {0, 0, 0, 1, 0, 0, s, c};
        float[] in = null;
        float[] out = null;
        if (how == Interpolation.BEZIER) {
            // Control points a third of the segment in, with the key's own value: flat tangents.
            in = new float[16];
            out = new float[16];
            for (int k = 0; k < 2; k++) {
                for (int v = 0; v < 4; v++) {
                    int o = 2 * (4 * k + v);
                    in[o] = k - 1f / 3;
                    in[o + 1] = values[4 * k + v];
                    out[o] = k + 1f / 3;
                    out[o + 1] = values[4 * k + v];
                }
            }
        }
        KeyframeTrack track = new KeyframeTrack(new float[] {0, 1}, values, 4, new Interpolation[] {how, how}, in, out);
        Model model = new Model("quaternion-test", new AssetInfo(UpAxis.Y_UP, 1, "meter", null, true), List.of(),
                List.of(), List.of(), List.of(), List.of(), List.of(new Node(0, -1, new int[0], "N", null, "N", true,
                        false, List.of(new TransformElement(TransformElement.Kind.QUATERNION, null,
                                new float[] {0, 0, 0, 1})))),
                List.of(), List.of(), List.of());
        Skeleton skeleton = Skeleton.of(model);
        AnimationClip clip = new AnimationClip(null, "turn", 0, 1, List.of(new AnimationChannel(0, 0, 0, track, "N")));
        Pose pose = skeleton.newPose();
        new AnimationSampler(skeleton, clip).sample(time, rotations, pose);
        return pose;
    }

    private static double angleAboutZ(Pose pose) {
        float[] v = pose.values();
        return 2 * Math.atan2(v[2], v[3]);
    }

    private static double length(Pose pose) {
        float[] v = pose.values();
        return Math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
    }
}
