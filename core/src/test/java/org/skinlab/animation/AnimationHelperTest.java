package org.skinlab.animation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.animation.MathAssertions.S;
import static org.skinlab.animation.MathAssertions.angleBetween;
import static org.skinlab.animation.MathAssertions.assertFinite;
import static org.skinlab.animation.MathAssertions.assertMatrixEquals;
import static org.skinlab.animation.MathAssertions.assertSameRotation;
import static org.skinlab.animation.MathAssertions.assertUnit;
import static org.skinlab.animation.MathAssertions.axisAngle;
import static org.skinlab.animation.MathAssertions.rows;

import java.util.Random;

import org.joml.Matrix3d;
import org.joml.Matrix4f;
import org.joml.Quaternionf;
import org.joml.Quaternionfc;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * {@link AnimationHelper}: rotation extraction (polar decomposition) on known rotations, scaled,
 * mirrored, noisy and singular matrices; the T*R*S split and its inverse; the homogeneous rotation
 * matrix; and the three rotation interpolations on the cases that break naive code (antipodal keys,
 * 180 degrees, tiny angles).
 *
 * <p>Expected quaternions are written from (n sin(a/2), cos(a/2)) by hand or by
 * {@link MathAssertions#axisAngle}; expected matrices are written row by row as on paper.
 */
class AnimationHelperTest {
    /** Quaternions from exact right-angle matrices: float rounding of sqrt(1/2) only. */
    private static final double EXACT_ROTATION = 1e-6;
    /** Quaternions from float matrices with sines and cosines of general angles and scales up to 7. */
    private static final double ROTATION = 1e-5;

    private static Quaternionf rotationOf(Matrix4f m) {
        return AnimationHelper.rotationOf(m, new Quaternionf());
    }

    // ------------------------------------------------------------------------------ rotationOf

    @Test
    void rotationOfNinetyDegreesAboutEachAxis() {
        // Rx(90): y -> z, z -> -y. Quaternion (sin 45, 0, 0, cos 45).
        assertSameRotation(new Quaternionf(S, 0, 0, S), rotationOf(rows(1, 0, 0, 0, 0, 0, -1, 0, 0, 1, 0, 0)),
                EXACT_ROTATION);
        // Ry(90): z -> x, x -> -z.
        assertSameRotation(new Quaternionf(0, S, 0, S), rotationOf(rows(0, 0, 1, 0, 0, 1, 0, 0, -1, 0, 0, 0)),
                EXACT_ROTATION);
        // Rz(90): x -> y, y -> -x.
        assertSameRotation(new Quaternionf(0, 0, S, S), rotationOf(rows(0, -1, 0, 0, 1, 0, 0, 0, 0, 0, 1, 0)),
                EXACT_ROTATION);
    }

    @Test
    void rotationOfHalfTurnsAboutTheAxesAndADiagonal() {
        // 180 degrees about n is 2 n n^T - I, quaternion (n, 0): the trace is -1, where naive
        // trace-based extraction divides by zero.
        assertSameRotation(new Quaternionf(1, 0, 0, 0), rotationOf(rows(1, 0, 0, 0, 0, -1, 0, 0, 0, 0, -1, 0)),
                EXACT_ROTATION);
        assertSameRotation(new Quaternionf(0, 1, 0, 0), rotationOf(rows(-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0)),
                EXACT_ROTATION);
        assertSameRotation(new Quaternionf(0, 0, 1, 0), rotationOf(rows(-1, 0, 0, 0, 0, -1, 0, 0, 0, 0, 1, 0)),
                EXACT_ROTATION);
        // n = (1, 1, 0)/sqrt 2: 2 n n^T - I = [[0 1 0] [1 0 0] [0 0 -1]].
        assertSameRotation(new Quaternionf(S, S, 0, 0), rotationOf(rows(0, 1, 0, 0, 1, 0, 0, 0, 0, 0, -1, 0)),
                EXACT_ROTATION);
    }

    @Test
    void rotationOfIdentityAndOfAPureTranslationIsTheIdentity() {
        assertSameRotation(new Quaternionf(), rotationOf(new Matrix4f()), 0);
        assertSameRotation(new Quaternionf(), rotationOf(new Matrix4f().translation(5, -3, 2)), 0);
    }

    @Test
    void rotationOfATinyAngleKeepsItsSize() {
        // 1e-4 rad about X: quaternion x = sin(5e-5). cos(1e-4) rounds to 1 in float, so the input
        // is not exactly orthonormal (column length 1 + 5e-9): the nearest rotation is still
        // 1e-4 - O(1e-12) rad. Tolerance 1e-10 on x (2e-10 rad), far below the angle itself.
        double a = 1e-4;
        float c = (float) Math.cos(a);
        float s = (float) Math.sin(a);
        Quaternionf q = rotationOf(rows(1, 0, 0, 0, 0, c, -s, 0, 0, s, c, 0));
        assertSameRotation(new Quaternionf((float) Math.sin(a / 2), 0, 0, (float) Math.cos(a / 2)), q, 1e-10);
        assertEquals(a, angleBetween(new Quaternionf(), q), 2e-10);
    }

    @Test
    void rotationOfIgnoresUniformAndNonUniformScale() {
        Quaternionf[] rotations = {axisAngle(40, 1, 2, 3), axisAngle(180, 0, 0, 1), axisAngle(180, 1, 1, 0),
            axisAngle(90, 0, 1, 0), axisAngle(-135, -2, 1, 0.5)};
        float[][] scales = {{3, 3, 3}, {2, 0.5f, 7}, {0.01f, 1, 100}};
        for (Quaternionf r : rotations) {
            for (float[] s : scales) {
                // M = R * S: the columns of R scaled.
                Matrix4f m = new Matrix4f().rotation(r).scale(s[0], s[1], s[2]);
                Quaternionf q = rotationOf(m);
                assertSameRotation(r, q, ROTATION);
                assertUnit(q, 1e-6);
            }
        }
    }

    @Test
    void rotationOfAMirrorIsThatOfItsNegation() {
        // M = Rz(90) * diag(-1, 1, 1): x -> -y, y -> -x, z -> z (det -1). The class doc: the
        // rotation of -M, which maps x -> y, y -> x, z -> -z: 180 degrees about (1, 1, 0)/sqrt 2.
        Matrix4f m = rows(0, -1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0);
        assertSameRotation(new Quaternionf(S, S, 0, 0), rotationOf(m), EXACT_ROTATION);
    }

    @Test
    void rotationOfANoisyMatrixIsTheNearestRotation() {
        // The polar factor U of A is the rotation nearest to A (Frobenius norm); its defining
        // property is that U^T A is symmetric positive definite. Any other rotation (e.g. the
        // Gram-Schmidt one, or the original R) leaves an antisymmetric part of the size of the
        // noise, 1e-3 here; float rounding of U leaves ~1e-6 (tolerance 5e-6).
        Random random = new Random(7);
        for (int trial = 0; trial < 50; trial++) {
            Quaternionf r = randomRotation(random);
            Matrix4f a = new Matrix4f().rotation(r);
            if (trial % 2 == 1) {
                a.scale(0.5f + 3 * random.nextFloat(), 0.5f + 3 * random.nextFloat(), 0.5f + 3 * random.nextFloat());
            }
            float[] v = new float[12];
            for (int row = 0; row < 3; row++) {
                for (int c = 0; c < 3; c++) {
                    v[4 * row + c] = a.getRowColumn(row, c) + (random.nextFloat() * 2 - 1) * 1e-3f;
                }
            }
            a = rows(v);
            Quaternionf u = rotationOf(a);
            assertUnit(u, 1e-6);
            Matrix3d p = new Matrix3d().set(new Matrix4f().rotation(u)).transpose()
                    .mul(new Matrix3d().set(a));
            for (int i = 0; i < 3; i++) {
                for (int j = i + 1; j < 3; j++) {
                    assertEquals(p.getRowColumn(i, j), p.getRowColumn(j, i), 5e-6, "U^T A not symmetric, trial " + trial);
                }
            }
            // Positive definite: Sylvester's criterion on the leading minors.
            double m1 = p.m00;
            double m2 = p.m00 * p.m11 - p.m10 * p.m01;
            assertTrue(m1 > 0 && m2 > 0 && p.determinant() > 0, "U^T A not positive definite, trial " + trial);
            // And the noise only moved the rotation by about its own size.
            assertTrue(angleBetween(r, u) < 5e-3, "trial " + trial);
        }
    }

    @Test
    void rotationOfSingularMatricesIsAFiniteUnitQuaternionThatKeepsTheRemainingAxes() {
        // All zero: nothing is left of the rotation; the identity.
        assertSameRotation(new Quaternionf(), rotationOf(new Matrix4f().zero()), 0);
        // diag(1, 0, 1) (a bone flattened along Y): X and Z are unrotated, so the rotation is the
        // identity; any other answer would move the X and Z columns when recomposed.
        assertSameRotation(new Quaternionf(), rotationOf(new Matrix4f().scaling(1, 0, 1)), EXACT_ROTATION);
        Quaternionf r = axisAngle(30, 0, 0, 1);
        for (float[] s : new float[][] {{0, 1, 1}, {1, 0, 1}, {1, 1, 0}, {0, 2, 3}, {2, 0, 3}, {2, 3, 0}}) {
            Quaternionf q = rotationOf(new Matrix4f().rotation(r).scale(s[0], s[1], s[2]));
            assertUnit(q, 1e-6);
            assertSameRotation(r, q, ROTATION);
        }
        // Rank one: only the Y column (0 2 0) rotated by Rz(30) survives; the rotation must send
        // Y along it, whatever it does about that axis.
        for (float[] s : new float[][] {{0, 2, 0}, {2, 0, 0}, {0, 0, 2}}) {
            Matrix4f m = new Matrix4f().rotation(r).scale(s[0], s[1], s[2]);
            Quaternionf q = rotationOf(m);
            assertUnit(q, 1e-6);
            int axis = s[0] != 0 ? 0 : s[1] != 0 ? 1 : 2;
            Vector3f e = new Vector3f().setComponent(axis, 1);
            Vector3f expected = r.transform(new Vector3f(e));
            Vector3f actual = q.transform(new Vector3f(e));
            assertTrue(expected.distance(actual) < 1e-5f, "axis " + axis + ": " + actual + " vs " + expected);
        }
    }

    @Test
    void rotationOfANearlySingularMatrixStillFindsTheRotation() {
        // Scale 1e-6 on one axis is far above the singular threshold (det > 1e-12 |M|^3).
        Quaternionf r = axisAngle(70, 1, -1, 2);
        assertSameRotation(r, rotationOf(new Matrix4f().rotation(r).scale(1, 1, 1e-6f)), ROTATION);
        assertSameRotation(r, rotationOf(new Matrix4f().rotation(r).scale(1e3f, 1e-3f, 1)), ROTATION);
    }

    @Test
    void rotationOfExtremeScalesConverges() {
        // Unscaled Newton only halves a large singular value per step (X/2 + X^-T/2), so 1e12
        // would need 40 steps before converging; Higham's scaling brings it to 1 at once.
        Quaternionf r = axisAngle(-100, 3, 1, -2);
        for (float s : new float[] {1e12f, 1e-12f}) {
            assertSameRotation(r, rotationOf(new Matrix4f().rotation(r).scale(s)), ROTATION);
        }
        assertSameRotation(r, rotationOf(new Matrix4f().rotation(r).scale(1e12f, 1, 1e-6f)), ROTATION);
    }

    // ------------------------------------------------------------------------ decompose / compose

    @Test
    void composeIsTranslationTimesRotationTimesScale() {
        // T(1 2 3) Rz(90) S(2 3 4): columns Rz*(2 0 0) = (0 2 0), Rz*(0 3 0) = (-3 0 0), (0 0 4).
        Matrix4f m = AnimationHelper.compose(new Vector3f(1, 2, 3), new Quaternionf(0, 0, S, S), new Vector3f(2, 3, 4),
                new Matrix4f());
        assertMatrixEquals(rows(0, -3, 0, 1, 2, 0, 0, 2, 0, 0, 4, 3), m, 1e-6);
    }

    @Test
    void decomposeRecoversTranslationRotationAndPositiveScale() {
        Random random = new Random(42);
        for (int trial = 0; trial < 200; trial++) {
            Vector3f t = new Vector3f(20 * random.nextFloat() - 10, 20 * random.nextFloat() - 10,
                    20 * random.nextFloat() - 10);
            Quaternionf r = randomRotation(random);
            Vector3f s = new Vector3f(0.1f + 10 * random.nextFloat(), 0.1f + 10 * random.nextFloat(),
                    0.1f + 10 * random.nextFloat());
            Matrix4f m = new Matrix4f().translation(t).rotate(r).scale(s);
            Vector3f dt = new Vector3f();
            Quaternionf dr = new Quaternionf();
            Vector3f ds = new Vector3f();
            AnimationHelper.decompose(m, dt, dr, ds);
            assertEquals(0, t.distance(dt), 0, "translation is copied");
            // Scale ratios up to 100: the rotation keeps ~1e-6 rad, the scale ~1e-6 relative.
            assertTrue(angleBetween(r, dr) < 1e-5, "trial " + trial + ": " + r + " vs " + dr);
            assertUnit(dr, 1e-6);
            for (int c = 0; c < 3; c++) {
                assertEquals(s.get(c), ds.get(c), 1e-5 * s.get(c), "scale " + c + ", trial " + trial);
            }
        }
    }

    @Test
    void composeOfDecomposeReproducesMatricesWithNegativeScales() {
        // With mirrors the split is not unique (diag(-1, 1, 1) = Rx(180) diag(-1, -1, -1)), but
        // T*R*S of the parts must give the matrix back. Float products of entries up to 10: 1e-5
        // relative to the largest entry.
        Random random = new Random(43);
        for (int trial = 0; trial < 200; trial++) {
            Quaternionf r = randomRotation(random);
            Vector3f s = new Vector3f(signed(random), signed(random), signed(random));
            Matrix4f m = new Matrix4f().translation(random.nextFloat(), random.nextFloat(), -random.nextFloat())
                    .rotate(r).scale(s);
            assertRoundTrip(m, 1e-5f * Math.max(1, Math.max(Math.abs(s.x), Math.max(Math.abs(s.y), Math.abs(s.z)))));
        }
    }

    @Test
    void composeOfDecomposeReproducesMatricesWithAZeroScale() {
        // A bone scaled to zero on one axis (Blender's way to hide or flatten it): T*R*S must still
        // describe the matrix, so that interpolating from such a key does not spin the bone.
        Quaternionf r = axisAngle(30, 0, 0, 1);
        for (float[] s : new float[][] {{1, 0, 1}, {0, 1, 1}, {1, 1, 0}, {0, -2, 3}, {2, 0, -3}, {0, 0, 2},
            {0, 0, 0}}) {
            Matrix4f m = new Matrix4f().translation(1, 2, 3).rotate(axisAngle(-50, 1, 2, 0)).rotate(r)
                    .scale(s[0], s[1], s[2]);
            assertRoundTrip(m, 1e-5f);
        }
    }

    @Test
    void decomposeOfAMirrorShowsAsNegativeScale() {
        // M = Rz(90) diag(-1, 1, 1): rotation 180 degrees about (1 1 0)/sqrt 2 (see
        // rotationOfAMirrorIsThatOfItsNegation), whose matrix is [[0 1 0] [1 0 0] [0 0 -1]]; the
        // scale is diag(R^T M) = (-1, -1, -1).
        Vector3f t = new Vector3f();
        Quaternionf q = new Quaternionf();
        Vector3f s = new Vector3f();
        AnimationHelper.decompose(rows(0, -1, 0, 0, -1, 0, 0, 0, 0, 0, 1, 0), t, q, s);
        assertSameRotation(new Quaternionf(S, S, 0, 0), q, EXACT_ROTATION);
        assertEquals(0, s.distance(-1, -1, -1), 1e-6);
    }

    private static void assertRoundTrip(Matrix4f m, float eps) {
        Vector3f t = new Vector3f();
        Quaternionf q = new Quaternionf();
        Vector3f s = new Vector3f();
        AnimationHelper.decompose(m, t, q, s);
        assertUnit(q, 1e-6);
        assertMatrixEquals(m, AnimationHelper.compose(t, q, s, new Matrix4f()), eps);
    }

    // ---------------------------------------------------------------------------- rotationMatrix

    @Test
    void rotationMatrixOfAUnitQuaternionIsItsRotation() {
        Random random = new Random(3);
        for (int i = 0; i < 50; i++) {
            Quaternionf q = randomRotation(random);
            // JOML's own quaternion-to-matrix conversion as the reference.
            assertMatrixEquals(new Matrix4f().rotation(q), AnimationHelper.rotationMatrix(q, new Matrix4f()), 1e-6);
        }
    }

    @Test
    void rotationMatrixScalesByTheSquaredLength() {
        // q = 2 (0, 0, sin 45, cos 45): |q|^2 = 4, so 4 Rz(90) = [[0 -4 0] [4 0 0] [0 0 4]].
        Matrix4f m = AnimationHelper.rotationMatrix(new Quaternionf(0, 0, 2 * S, 2 * S), new Matrix4f());
        assertMatrixEquals(rows(0, -4, 0, 0, 4, 0, 0, 0, 0, 0, 4, 0), m, 1e-6);
        Random random = new Random(4);
        for (int i = 0; i < 50; i++) {
            Quaternionf q = randomRotation(random);
            float k = 0.1f + 2 * random.nextFloat();
            Matrix4f expected = new Matrix4f().rotation(q).scale(k * k);
            Quaternionf scaled = new Quaternionf(q.x * k, q.y * k, q.z * k, q.w * k);
            assertMatrixEquals(expected, AnimationHelper.rotationMatrix(scaled, new Matrix4f()), 1e-5);
        }
    }

    // ----------------------------------------------------------------------------- interpolation

    private static Quaternionf interpolate(RotationInterpolation mode, Quaternionfc a, Quaternionfc b, float t) {
        return AnimationHelper.interpolate(mode, a, b, t, new Quaternionf());
    }

    private static Quaternionf normalized(Quaternionf q) {
        return new Quaternionf(q).normalize();
    }

    @Test
    void allModesStartAtTheFirstKeyAndEndAtTheSecond() {
        Quaternionf a = axisAngle(30, 1, 0, 0);
        Quaternionf b = axisAngle(100, 0, 1, 1);
        Quaternionf bNegated = new Quaternionf(-b.x, -b.y, -b.z, -b.w);
        for (RotationInterpolation mode : RotationInterpolation.values()) {
            for (Quaternionf end : new Quaternionf[] {b, bNegated}) {
                assertSameRotation(a, interpolate(mode, a, end, 0), 1e-6);
                assertSameRotation(b, interpolate(mode, a, end, 1), 1e-6);
            }
        }
    }

    @Test
    void slerpAndNlerpMeetHalfWayAtHalfTheAngle() {
        // Identity to Rz(100): half way is Rz(50) for both (nlerp is symmetric about t = 1/2).
        Quaternionf a = new Quaternionf();
        Quaternionf b = axisAngle(100, 0, 0, 1);
        for (RotationInterpolation mode : new RotationInterpolation[] {RotationInterpolation.SLERP,
            RotationInterpolation.NLERP}) {
            Quaternionf m = interpolate(mode, a, b, 0.5f);
            assertUnit(m, 1e-6);
            assertSameRotation(axisAngle(50, 0, 0, 1), m, 1e-6);
        }
        // LERP points the same way (normalised), with length < 1.
        assertSameRotation(axisAngle(50, 0, 0, 1), normalized(interpolate(RotationInterpolation.LERP, a, b, 0.5f)),
                1e-6);
    }

    @Test
    void slerpTurnsAtConstantAngularSpeed() {
        Quaternionf a = axisAngle(30, 1, 0, 0);
        Quaternionf b = axisAngle(-110, 0.3, 1, -0.5);
        double total = angleBetween(a, b);
        for (int i = 0; i <= 20; i++) {
            float t = i / 20f;
            Quaternionf q = interpolate(RotationInterpolation.SLERP, a, b, t);
            assertUnit(q, 1e-6);
            // Both distances proportional to t: on the great arc, at constant speed.
            assertEquals(t * total, angleBetween(a, q), 1e-5, "t = " + t);
            assertEquals((1 - t) * total, angleBetween(q, b), 1e-5, "t = " + t);
        }
    }

    @Test
    void nlerpFollowsTheSamePathAsSlerpAtUnevenSpeed() {
        // Keys Omega apart on the unit sphere (Omega = half the rotation angle): the normalised
        // chord point (1-t) a + t b lies at atan(t sin Omega / (1 - t + t cos Omega)) from a, on
        // the great arc (the distances to both ends add up to Omega).
        Quaternionf a = new Quaternionf();
        Quaternionf b = axisAngle(100, 0, 0, 1);
        double omega = Math.toRadians(50);
        for (int i = 0; i <= 20; i++) {
            float t = i / 20f;
            Quaternionf q = interpolate(RotationInterpolation.NLERP, a, b, t);
            assertUnit(q, 1e-6);
            double expected = 2 * Math.atan(t * Math.sin(omega) / (1 - t + t * Math.cos(omega)));
            assertEquals(expected, angleBetween(a, q), 1e-5, "t = " + t);
            assertEquals(2 * omega, angleBetween(a, q) + angleBetween(q, b), 1e-5, "t = " + t);
        }
        // At t = 1/4 that is 23.75 degrees where slerp has 25: the speed differs, the path not.
        assertEquals(23.75, Math.toDegrees(angleBetween(a, interpolate(RotationInterpolation.NLERP, a, b, 0.25f))),
                0.01);
    }

    @Test
    void lerpShrinksTheMidpointByCosSquaredOfAQuarterOfTheAngle() {
        // |(a + b)/2|^2 = (2 + 2 cos Omega)/4 = cos^2(Omega/2) = cos^2(phi/4) for keys a rotation
        // phi apart (Omega = phi/2); the homogeneous matrix scales the bone by exactly that.
        Quaternionf a = axisAngle(20, 1, 1, 0);
        for (double phi : new double[] {10, 60, 90, 150, 180}) {
            Quaternionf b = new Quaternionf(axisAngle(phi, 0.2, -1, 0.4)).premul(a); // phi from a
            assertEquals(phi, Math.toDegrees(angleBetween(a, b)), 1e-3);
            Quaternionf q = interpolate(RotationInterpolation.LERP, a, b, 0.5f);
            double expected = Math.pow(Math.cos(Math.toRadians(phi) / 4), 2);
            assertEquals(expected, q.lengthSquared(), 1e-6, "phi = " + phi);
            Matrix4f m = AnimationHelper.rotationMatrix(q, new Matrix4f());
            for (int c = 0; c < 3; c++) {
                assertEquals(expected, m.getColumn(c, new Vector3f()).length(), 1e-6, "column " + c + ", phi = " + phi);
            }
        }
    }

    @Test
    void antipodalKeysAreTheSameRotationAndStayPut() {
        // b = -a is the same rotation: every mode must hold it, without NaN (slerp's sin O = 0
        // would divide by zero on the long way round).
        Quaternionf a = axisAngle(75, 1, -2, 0.5);
        Quaternionf b = new Quaternionf(-a.x, -a.y, -a.z, -a.w);
        for (RotationInterpolation mode : RotationInterpolation.values()) {
            for (float t : new float[] {0, 0.1f, 0.5f, 0.9f, 1}) {
                Quaternionf q = interpolate(mode, a, b, t);
                assertUnit(q, 1e-6);
                assertSameRotation(a, q, 1e-6);
            }
        }
    }

    @Test
    void nearlyAntipodalKeysTakeTheShortArc() {
        // a = Rz(10), b = -Rz(20): 10 degrees apart the short way, 350 the long way. Half way is
        // Rz(15) in every mode, not Rz(195).
        Quaternionf a = axisAngle(10, 0, 0, 1);
        Quaternionf r20 = axisAngle(20, 0, 0, 1);
        Quaternionf b = new Quaternionf(-r20.x, -r20.y, -r20.z, -r20.w);
        for (RotationInterpolation mode : RotationInterpolation.values()) {
            assertSameRotation(axisAngle(15, 0, 0, 1), normalized(interpolate(mode, a, b, 0.5f)), 1e-6);
        }
        // Keys written 350 degrees apart (0 and 350 about Z) are -10 apart: half way is Rz(-5).
        for (RotationInterpolation mode : RotationInterpolation.values()) {
            Quaternionf q = normalized(interpolate(mode, new Quaternionf(), axisAngle(350, 0, 0, 1), 0.5f));
            assertSameRotation(axisAngle(-5, 0, 0, 1), q, 1e-6);
        }
    }

    @Test
    void tinyAnglesInterpolateWithoutNaN() {
        // 1e-6 rad apart (below slerp's switch to nlerp) and identical keys: the result sits at
        // t times the angle; the quaternion components are ~1e-7, so compare the angle to 1e-9.
        Quaternionf a = new Quaternionf();
        for (double angle : new double[] {1e-6, 1e-4, 0}) {
            Quaternionf b = new Quaternionf((float) Math.sin(angle / 2), 0, 0, (float) Math.cos(angle / 2));
            for (RotationInterpolation mode : RotationInterpolation.values()) {
                Quaternionf q = interpolate(mode, a, b, 0.25f);
                assertFinite(q);
                assertEquals(0.25 * angle, angleBetween(a, normalized(q)), 1e-9, mode + " at " + angle);
            }
        }
    }

    @Test
    void halfTurnKeysGiveAValidHalfWayRotation() {
        // 180 degrees apart: the quaternions are 90 degrees apart (dot 0), both arcs equally short.
        // Any rotation 90 degrees from each key is a valid midpoint; it must be finite.
        Quaternionf[][] pairs = {{new Quaternionf(), axisAngle(180, 0, 0, 1)},
            {new Quaternionf(), axisAngle(180, 1, 1, 0)},
            {axisAngle(90, 1, 0, 0), new Quaternionf(axisAngle(180, 0, 1, 0)).premul(axisAngle(90, 1, 0, 0))}};
        for (Quaternionf[] p : pairs) {
            for (RotationInterpolation mode : RotationInterpolation.values()) {
                Quaternionf q = interpolate(mode, p[0], p[1], 0.5f);
                assertFinite(q);
                Quaternionf n = normalized(q);
                assertEquals(Math.PI / 2, angleBetween(p[0], n), 1e-5, mode.toString());
                assertEquals(Math.PI / 2, angleBetween(n, p[1]), 1e-5, mode.toString());
            }
            // LERP: cos^2(180/4) = 1/2.
            assertEquals(0.5, interpolate(RotationInterpolation.LERP, p[0], p[1], 0.5f).lengthSquared(), 1e-6);
        }
    }

    @Test
    void interpolationMayWriteIntoEitherKey() {
        // The sampler blends into its first key's scratch quaternion (dest == a).
        Quaternionf a = axisAngle(10, 1, 0, 0);
        Quaternionf b = axisAngle(-80, 0, 1, 0);
        for (RotationInterpolation mode : RotationInterpolation.values()) {
            Quaternionf expected = interpolate(mode, a, b, 0.3f);
            Quaternionf intoA = new Quaternionf(a);
            AnimationHelper.interpolate(mode, intoA, b, 0.3f, intoA);
            Quaternionf intoB = new Quaternionf(b);
            AnimationHelper.interpolate(mode, a, intoB, 0.3f, intoB);
            assertEquals(expected, intoA, mode.toString());
            assertEquals(expected, intoB, mode.toString());
        }
    }

    @Test
    void interpolateDispatchesToTheNamedMethod() {
        Quaternionf a = axisAngle(10, 1, 0, 0);
        Quaternionf b = axisAngle(-80, 0, 1, 0);
        assertEquals(AnimationHelper.lerp(a, b, 0.3f, new Quaternionf()), interpolate(RotationInterpolation.LERP, a, b, 0.3f));
        assertEquals(AnimationHelper.nlerp(a, b, 0.3f, new Quaternionf()),
                interpolate(RotationInterpolation.NLERP, a, b, 0.3f));
        assertEquals(AnimationHelper.slerp(a, b, 0.3f, new Quaternionf()),
                interpolate(RotationInterpolation.SLERP, a, b, 0.3f));
        // And they differ here, so the check above can tell them apart.
        assertTrue(interpolate(RotationInterpolation.LERP, a, b, 0.3f).lengthSquared() < 0.99f);
        assertTrue(angleBetween(interpolate(RotationInterpolation.NLERP, a, b, 0.3f),
                interpolate(RotationInterpolation.SLERP, a, b, 0.3f)) > 1e-3);
    }

    // ------------------------------------------------------------------------------------- util

    /** A uniformly random unit quaternion (normalised 4-D Gaussian). */
    static Quaternionf randomRotation(Random random) {
        return new Quaternionf((float) random.nextGaussian(), (float) random.nextGaussian(),
                (float) random.nextGaussian(), (float) random.nextGaussian()).normalize();
    }

    /** A scale component in [-10, -0.1] or [0.1, 10]. */
    private static float signed(Random random) {
        float s = 0.1f + 9.9f * random.nextFloat();
        return random.nextBoolean() ? s : -s;
    }
}
