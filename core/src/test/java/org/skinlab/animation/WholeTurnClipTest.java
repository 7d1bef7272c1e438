package org.skinlab.animation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Locale;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.testing.TestPaths;

/**
 * The whole-turn cylinders (assets/README.md): {@code upper} turns relative to {@code lower} by
 * 60 t degrees, 0 to 360 over 6 s, about its own axis (twist) or its local X axis (bend), and the
 * clip, sampled with SLERP, follows that angle between the keys too, past the half turn included.
 *
 * <p>What could go wrong there: a key matrix of 195 degrees is the matrix of -165, so the importer's
 * decomposition hands the sampler a quaternion that may lie in the other hemisphere from the
 * 180-degree key's (the .glb's keys do change hemisphere at 3 s); a sampler that did not take the
 * shorter of the two arcs between them would turn back through 0 instead of on through 187.5.
 *
 * <p>The angle, from the formulas: D(t) = Rel(rest)⁻¹ Rel(t), Rel = World(lower)⁻¹ World(upper),
 * is {@code upper}'s pose rotation in its own frame; for a rotation by θ about the unit axis a,
 * cos θ = (tr D − 1) / 2 and sin θ = a · (D₃₂ − D₂₃, D₁₃ − D₃₁, D₂₁ − D₁₂) / 2, and D a = a. Sampled
 * at 30 per second, consecutive angles are 2 degrees apart, so unwrapping (adding the step wrapped
 * into (−180, 180]) is unambiguous. Tolerance 0.01 degrees: both keys of a segment turn about the
 * same axis, so SLERP's constant angular speed gives exactly 60 t; the files' 7 digits and float
 * arithmetic leave about 1e-5 degrees.
 */
class WholeTurnClipTest {
    private static final double DEGREES_PER_SECOND = 60;
    private static final int SAMPLES_PER_SECOND = 30;
    private static final double ANGLE_TOLERANCE = 0.01;
    private static final double AXIS_TOLERANCE = 1e-5;

    @ParameterizedTest(name = "{0}")
    @CsvSource({"cylinders/cylinder-twist-full.dae, 1", "cylinders/cylinder-twist-full.glb, 1",
        "cylinders/cylinder-bend-full.dae, 0", "cylinders/cylinder-bend-full.glb, 0"})
    void upperTurnsSixtyDegreesASecondUnwrappedOverTheWholeClip(String asset, int localAxis) throws Exception {
        Model model = ModelImporter.read(TestPaths.asset(asset));
        Skeleton skeleton = Skeleton.of(model);
        AnimationSampler sampler = new AnimationSampler(skeleton, model.clips().get(0));
        assertEquals(6.0f, sampler.end(), 1e-6f, "a 6 s clip");
        int lower = node(model, "lower");
        int upper = node(model, "upper");
        Pose pose = skeleton.newPose();
        Matrix4f restInverse = relative(pose, lower, upper).invert();
        Vector3f axis = new Vector3f(localAxis == 0 ? 1 : 0, localAxis == 1 ? 1 : 0, 0);

        double unwrapped = 0;
        double previous = 0;
        double worst = 0;
        int samples = 6 * SAMPLES_PER_SECOND;
        for (int i = 0; i <= samples; i++) {
            float t = (float) i / SAMPLES_PER_SECOND;
            sampler.sample(t, RotationInterpolation.SLERP, pose);
            skeleton.evaluate(pose);
            Matrix4f d = new Matrix4f(restInverse).mul(relative(pose, lower, upper));
            double angle = angleAbout(d, axis, asset, t);
            unwrapped += i == 0 ? angle : wrap(angle - previous);
            previous = angle;
            double expected = DEGREES_PER_SECOND * t;
            worst = Math.max(worst, Math.abs(unwrapped - expected));
            if (Math.abs(unwrapped - expected) > ANGLE_TOLERANCE) {
                throw new AssertionError(String.format(Locale.ROOT, "%s t=%s: upper has turned %.4f degrees, "
                        + "expected %.4f", asset, t, unwrapped, expected));
            }
        }
        System.out.printf(Locale.ROOT, "%-36s unwrapped angle vs 60 t over %d samples: worst %.1e degrees%n", asset,
                samples + 1, worst);
        assertTrue(Math.abs(unwrapped - 360) <= ANGLE_TOLERANCE, "a whole turn at the end: " + unwrapped);
    }

    /** World(lower)⁻¹ World(upper) in the evaluated pose. */
    private static Matrix4f relative(Pose pose, int lower, int upper) {
        return pose.world(lower, new Matrix4f()).invert().mul(pose.world(upper, new Matrix4f()));
    }

    /** The angle (degrees, in (−180, 180]) of rotation d about unit axis a; d must turn about a. */
    private static double angleAbout(Matrix4f d, Vector3f a, String asset, float t) {
        Vector3f turned = d.transformDirection(new Vector3f(a));
        assertTrue(turned.distance(a) < AXIS_TOLERANCE,
                () -> asset + " t=" + t + ": the pose rotation does not turn about " + a + " (it moves it to " + turned
                        + ")");
        // JOML's mCR is column C, row R, from 0: the formula's D₃₂ (row 3, column 2) is m12
        double cos = (d.m00() + d.m11() + d.m22() - 1) / 2;
        double sin = (a.x * (d.m12() - d.m21()) + a.y * (d.m20() - d.m02()) + a.z * (d.m01() - d.m10())) / 2;
        return Math.toDegrees(Math.atan2(sin, cos));
    }

    /** An angle difference wrapped into (−180, 180]. */
    private static double wrap(double degrees) {
        double w = degrees % 360;
        return w > 180 ? w - 360 : w <= -180 ? w + 360 : w;
    }

    private static int node(Model model, String name) {
        List<Node> nodes = model.nodes();
        for (int i = 0; i < nodes.size(); i++) {
            if (name.equals(nodes.get(i).name())) {
                return i;
            }
        }
        throw new AssertionError("no node " + name);
    }
}
