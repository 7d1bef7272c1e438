package org.skinlab.animation;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.skinlab.animation.DualQuaternions.sameTransform;
import static org.skinlab.animation.DualQuaternions.toMatrix;
import static org.skinlab.animation.MathAssertions.S;
import static org.skinlab.animation.MathAssertions.assertMatrixEquals;
import static org.skinlab.animation.MathAssertions.assertSameRotation;
import static org.skinlab.animation.MathAssertions.axisAngle;
import static org.skinlab.animation.MathAssertions.rows;

import java.util.Random;

import org.joml.Matrix4f;
import org.joml.Quaternionf;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;

/**
 * {@link DualQuaternion} against the matrices it stands for (Kavan et al. 2008, section 3): a unit
 * dual quaternion built from rotation r and translation t moves points as {@code T(t) R(r)} does;
 * products, conjugates, normalisation and blending keep that meaning.
 *
 * <p>Matrix references are JOML's own {@code translation().rotate()}, independent of this class.
 */
class DualQuaternionTest {
    /** Points within 10 units moved by float rotations: ~1e-6 relative, tolerance 1e-5 absolute. */
    private static final float POINT = 1e-5f;

    private static DualQuaternion of(Quaternionf r, Vector3f t) {
        return new DualQuaternion().set(r, t);
    }

    private static DualQuaternion negated(DualQuaternion q) {
        return new DualQuaternion(q).scale(-1);
    }

    private static Vector3f randomVector(Random random, float range) {
        return new Vector3f(range * (2 * random.nextFloat() - 1), range * (2 * random.nextFloat() - 1),
                range * (2 * random.nextFloat() - 1));
    }

    private static void assertPoint(Vector3f expected, Vector3f actual, float eps) {
        assertTrue(expected.distance(actual) <= eps, () -> "expected " + expected + ", got " + actual);
    }

    @Test
    void setThenTransformPositionMovesPointsLikeTheMatrix() {
        Random random = new Random(11);
        for (int trial = 0; trial < 100; trial++) {
            Quaternionf r = AnimationHelperTest.randomRotation(random);
            Vector3f t = randomVector(random, 5);
            DualQuaternion dq = of(r, t);
            Matrix4f m = new Matrix4f().translation(t).rotate(r);
            for (int i = 0; i < 5; i++) {
                Vector3f p = randomVector(random, 3);
                assertPoint(m.transformPosition(new Vector3f(p)), dq.transformPosition(new Vector3f(p)), POINT);
                // Directions ignore the translation.
                assertPoint(m.transformDirection(new Vector3f(p)), dq.transformDirection(new Vector3f(p)), POINT);
            }
        }
    }

    @Test
    void setWritesTheDualPartAsHalfTranslationTimesRotation() {
        // Rz(90) = (0, 0, s, s) with t = (2, 0, 0): d = (t, 0) r / 2. (t,0)(v,w) has vector part
        // w t + t x v = s (2,0,0) + (2,0,0) x (0,0,s) = (2s, -2s, 0), scalar -t.v = 0; halved.
        DualQuaternion dq = of(new Quaternionf(0, 0, S, S), new Vector3f(2, 0, 0));
        assertArrayEquals(new float[] {0, 0, S, S, S, -S, 0, 0}, dq.get(new float[8], 0), 1e-7f);
        assertPoint(new Vector3f(2, 1, 0), dq.transformPosition(new Vector3f(1, 0, 0)), 1e-6f);
    }

    @Test
    void getTranslationReturnsWhatWasSet() {
        Random random = new Random(12);
        for (int trial = 0; trial < 100; trial++) {
            Vector3f t = randomVector(random, 10);
            DualQuaternion dq = of(AnimationHelperTest.randomRotation(random), t);
            assertPoint(t, dq.getTranslation(new Vector3f()), POINT);
        }
    }

    @Test
    void mulComposesLikeTheMatrixProduct() {
        Random random = new Random(13);
        for (int trial = 0; trial < 100; trial++) {
            Quaternionf ra = AnimationHelperTest.randomRotation(random);
            Quaternionf rb = AnimationHelperTest.randomRotation(random);
            Vector3f ta = randomVector(random, 5);
            Vector3f tb = randomVector(random, 5);
            DualQuaternion a = of(ra, ta);
            DualQuaternion b = of(rb, tb);
            // a * b applies b first, as the matrix product A B does.
            Matrix4f ab = new Matrix4f().translation(ta).rotate(ra).mul(new Matrix4f().translation(tb).rotate(rb));
            DualQuaternion product = a.mul(b, new DualQuaternion());
            assertMatrixEquals(ab, toMatrix(product, new Matrix4f()), 2e-5);
            Vector3f p = randomVector(random, 3);
            assertPoint(ab.transformPosition(new Vector3f(p)), product.transformPosition(new Vector3f(p)), 2e-5f);
            // JOML style: the destination may be either operand.
            DualQuaternion intoA = new DualQuaternion(a);
            intoA.mul(b, intoA);
            DualQuaternion intoB = new DualQuaternion(b);
            a.mul(intoB, intoB);
            assertArrayEquals(product.get(new float[8], 0), intoA.get(new float[8], 0), 0f);
            assertArrayEquals(product.get(new float[8], 0), intoB.get(new float[8], 0), 0f);
        }
    }

    @Test
    void conjugateIsTheInverse() {
        Random random = new Random(14);
        for (int trial = 0; trial < 100; trial++) {
            DualQuaternion dq = of(AnimationHelperTest.randomRotation(random), randomVector(random, 5));
            DualQuaternion inverse = new DualQuaternion(dq).conjugate();
            assertTrue(sameTransform(dq.mul(inverse, new DualQuaternion()), new DualQuaternion(), 1e-6f));
            assertTrue(sameTransform(inverse.mul(dq, new DualQuaternion()), new DualQuaternion(), 1e-6f));
            Vector3f p = randomVector(random, 3);
            assertPoint(p, inverse.transformPosition(dq.transformPosition(new Vector3f(p))), POINT);
        }
    }

    @Test
    void normalizeMakesTheRealPartUnitAndTheDualPartOrthogonalToIt() {
        Random random = new Random(15);
        for (int trial = 0; trial < 100; trial++) {
            Quaternionf r = AnimationHelperTest.randomRotation(random);
            Vector3f t = randomVector(random, 5);
            DualQuaternion unit = of(r, t);
            // Scale by k and push d off the constraint r.d = 0 by e r: what blending produces.
            float k = 0.2f + 3 * random.nextFloat();
            float e = 2 * random.nextFloat() - 1;
            DualQuaternion dq = new DualQuaternion(unit).scale(k);
            dq.dx += e * r.x;
            dq.dy += e * r.y;
            dq.dz += e * r.z;
            dq.dw += e * r.w;
            dq.normalize();
            double len = Math.sqrt(dq.rx * dq.rx + dq.ry * dq.ry + dq.rz * dq.rz + dq.rw * dq.rw);
            assertEquals(1, len, 1e-6);
            assertEquals(0, dq.rx * dq.dx + dq.ry * dq.dy + dq.rz * dq.dz + dq.rw * dq.dw, 1e-6);
            // Scaling does not change the transform; the part along r is what normalize removes.
            assertTrue(sameTransform(dq, unit, 1e-5f), dq + " vs " + unit);
        }
    }

    @Test
    void normalizeOfZeroIsTheIdentity() {
        DualQuaternion zero = new DualQuaternion().scale(0);
        assertTrue(sameTransform(zero.normalize(), new DualQuaternion(), 0f));
    }

    @Test
    void blendEndsAtItsInputs() {
        DualQuaternion a = of(axisAngle(40, 1, 0, 0), new Vector3f(1, 2, 3));
        DualQuaternion b = of(axisAngle(-70, 0, 1, 1), new Vector3f(-3, 0, 2));
        assertTrue(sameTransform(a.blend(b, 0, new DualQuaternion()), a, 1e-6f));
        assertTrue(sameTransform(a.blend(b, 1, new DualQuaternion()), b, 1e-6f));
        assertTrue(sameTransform(a.blend(negated(b), 1, new DualQuaternion()), b, 1e-6f));
    }

    @Test
    void blendOfTranslationsIsTheirAverage() {
        // Same rotation: the real parts agree, the dual parts (t r / 2) are linear in t.
        Quaternionf r = axisAngle(30, 0, 1, 0);
        DualQuaternion a = of(r, new Vector3f(0, 0, 0));
        DualQuaternion b = of(r, new Vector3f(2, 4, 6));
        DualQuaternion m = a.blend(b, 0.5f, new DualQuaternion());
        assertPoint(new Vector3f(1, 2, 3), m.getTranslation(new Vector3f()), POINT);
        assertSameRotation(r, new Quaternionf(m.rx, m.ry, m.rz, m.rw), 1e-6);
    }

    @Test
    void blendOfRotationsAboutTheOriginIsTheirNlerp() {
        // No translation: DLB reduces to normalised quaternion blending; half way from the
        // identity to Rz(90) is Rz(45).
        DualQuaternion a = new DualQuaternion();
        DualQuaternion b = of(axisAngle(90, 0, 0, 1), new Vector3f());
        DualQuaternion m = a.blend(b, 0.5f, new DualQuaternion());
        assertTrue(sameTransform(m, of(axisAngle(45, 0, 0, 1), new Vector3f()), 1e-6f), m.toString());
    }

    @Test
    void blendTakesTheShortArcWhenTheSecondIsNegated() {
        // q and -q are the same transform; blending towards either must give the same result, and
        // towards -q it must not pass through the zero dual quaternion at t = 1/2.
        DualQuaternion a = of(axisAngle(20, 1, 2, 3), new Vector3f(1, 0, 0));
        DualQuaternion b = of(axisAngle(150, -1, 0, 2), new Vector3f(0, 3, -1));
        for (float t : new float[] {0.1f, 0.5f, 0.8f}) {
            DualQuaternion direct = a.blend(b, t, new DualQuaternion());
            DualQuaternion viaNegated = a.blend(negated(b), t, new DualQuaternion());
            assertTrue(sameTransform(direct, viaNegated, 1e-6f), direct + " vs " + viaNegated);
        }
        // a with -a: the same transform throughout.
        for (float t : new float[] {0.25f, 0.5f, 0.75f}) {
            assertTrue(sameTransform(a.blend(negated(a), t, new DualQuaternion()), a, 1e-6f));
        }
    }

    @Test
    void blendMayWriteIntoEitherInput() {
        DualQuaternion a = of(axisAngle(20, 1, 2, 3), new Vector3f(1, 0, 0));
        DualQuaternion b = of(axisAngle(150, -1, 0, 2), new Vector3f(0, 3, -1));
        float[] expected = a.blend(b, 0.3f, new DualQuaternion()).get(new float[8], 0);
        DualQuaternion intoA = new DualQuaternion(a);
        intoA.blend(b, 0.3f, intoA);
        DualQuaternion intoB = new DualQuaternion(b);
        a.blend(intoB, 0.3f, intoB);
        assertArrayEquals(expected, intoA.get(new float[8], 0), 0f);
        assertArrayEquals(expected, intoB.get(new float[8], 0), 0f);
    }

    @Test
    void sameTransformTreatsNegationAsEqualAndHonoursTheTolerance() {
        DualQuaternion a = of(axisAngle(20, 1, 2, 3), new Vector3f(1, 0, 0));
        assertTrue(sameTransform(a, negated(a), 0f));
        DualQuaternion moved = new DualQuaternion(a);
        moved.dz += 1e-3f;
        assertTrue(sameTransform(a, moved, 2e-3f));
        assertFalse(sameTransform(a, moved, 5e-4f));
        assertFalse(sameTransform(a, of(axisAngle(21, 1, 2, 3), new Vector3f(1, 0, 0)), 1e-3f));
    }

    @Test
    void arrayRoundTripKeepsTheComponentOrder() {
        float[] v = {1, 2, 3, 4, 5, 6, 7, 8};
        DualQuaternion dq = new DualQuaternion().set(new float[] {0, 0, 1, 2, 3, 4, 5, 6, 7, 8}, 2);
        assertArrayEquals(new float[] {1, 2, 3, 4}, new float[] {dq.rx, dq.ry, dq.rz, dq.rw});
        assertArrayEquals(new float[] {5, 6, 7, 8}, new float[] {dq.dx, dq.dy, dq.dz, dq.dw});
        float[] out = dq.get(new float[9], 1);
        assertArrayEquals(v, java.util.Arrays.copyOfRange(out, 1, 9));
        assertEquals(0f, out[0]);
    }

    // --------------------------------------------------------- toDualQuaternion / toMatrix

    @Test
    void matrixToDualQuaternionAndBackIsExactForRigidMatrices() {
        // Identity, tiny and general angles, and the half turns where the trace is -1.
        Quaternionf[] rotations = {new Quaternionf(), axisAngle(180, 1, 0, 0), axisAngle(180, 0, 1, 0),
            axisAngle(180, 0, 0, 1), axisAngle(180, 1, 1, 0), axisAngle(90, 0, 0, 1), axisAngle(0.01, 1, 1, 1),
            axisAngle(123, -2, 0.5, 1)};
        Vector3f[] translations = {new Vector3f(), new Vector3f(1, -2, 3), new Vector3f(0, 0, -100)};
        for (Quaternionf r : rotations) {
            for (Vector3f t : translations) {
                Matrix4f m = new Matrix4f().translation(t).rotate(r);
                DualQuaternion dq = AnimationHelper.toDualQuaternion(m, new DualQuaternion());
                assertTrue(sameTransform(dq, of(r, t), 1e-6f * Math.max(1, t.length())), r + " " + t + ": " + dq);
                assertMatrixEquals(m, toMatrix(dq, new Matrix4f()), 1e-6 * Math.max(1, t.length()));
            }
        }
    }

    @Test
    void toMatrixOfTheIdentityIsTheIdentityMatrix() {
        assertMatrixEquals(new Matrix4f(), toMatrix(new DualQuaternion(), new Matrix4f()), 0);
    }

    @Test
    void toMatrixNormalisesFirst() {
        // A blend result that is not unit: 2.5 (r + e d). The matrix is that of r + e d, not 6.25 R.
        DualQuaternion unit = of(axisAngle(90, 0, 0, 1), new Vector3f(2, 0, 0));
        Matrix4f expected = rows(0, -1, 0, 2, 1, 0, 0, 0, 0, 0, 1, 0);
        assertMatrixEquals(expected, toMatrix(new DualQuaternion(unit).scale(2.5f), new Matrix4f()),
                1e-6);
        assertMatrixEquals(expected, toMatrix(unit, new Matrix4f()), 1e-6);
    }

    @Test
    void toDualQuaternionOfAScaledMatrixKeepsRotationAndTranslation() {
        // T(1 2 3) Rz(90) S(2 3 4): the rigid part is T(1 2 3) Rz(90); scale is dropped.
        Matrix4f m = AnimationHelper.compose(new Vector3f(1, 2, 3), new Quaternionf(0, 0, S, S),
                new Vector3f(2, 3, 4), new Matrix4f());
        DualQuaternion dq = AnimationHelper.toDualQuaternion(m, new DualQuaternion());
        assertTrue(sameTransform(dq, of(new Quaternionf(0, 0, S, S), new Vector3f(1, 2, 3)), 1e-6f), dq.toString());
    }
}
