package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Arrays;
import java.util.Random;

import org.joml.Matrix3d;
import org.joml.Matrix4d;
import org.joml.Matrix4f;
import org.joml.Quaterniond;
import org.joml.Quaternionf;
import org.joml.Vector3d;
import org.joml.Vector3f;
import org.joml.Vector4d;
import org.junit.jupiter.api.Test;
import org.skinlab.animation.AnimationHelper;
import org.skinlab.animation.DualQuaternion;
import org.skinlab.animation.DualQuaternions;

/**
 * {@link JointPalette#prepare}: the split {@code M = D S} of the class comment,
 * against its definitions evaluated here in double precision, step by step as the comment states
 * them ({@code X = M B}, R from X's Y axis, {@code X = [R|x] S0}, {@code S = B S0 B^-1},
 * {@code D = [R|x] B^-1}), on random joints: rigid, scaled, sheared, mirrored, and the
 * stormtrooper's case of a bind shape matrix that is a mirrored uniform scale.
 *
 * <p>Tolerance 1e-5 of the largest entry involved: the palette works in float from float input
 * (its error against the double evaluation is below 1e-6 on the whole corpus).
 */
class JointPaletteTest {
    private static final double EPS = 1e-5;

    @Test
    void rigidJointsKeepTheirMatrixAsTheRigidPartAndHaveNoScale() {
        Random random = new Random(3);
        float[] bind = new float[16 * 20];
        Matrix4f[] m = new Matrix4f[20];
        for (int j = 0; j < 20; j++) {
            randomAffine(random, true, false).get(bind, 16 * j);
            m[j] = new Matrix4f().translation(randomVector(random)).rotate(randomRotation(random));
        }
        JointPalette palette = palette(bind, m);
        assertFalse(palette.hasScale());
        for (int j = 0; j < 20; j++) {
            assertRigidPart(new Matrix4d(m[j]), palette, j);
            assertArrayEquals(new float[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, row12(palette.scales(), j), 0f);
        }
    }

    @Test
    void scaledShearedAndMirroredJointsSplitAsDefined() {
        Random random = new Random(4);
        int n = 60;
        float[] bind = new float[16 * n];
        Matrix4f[] m = new Matrix4f[n];
        for (int j = 0; j < n; j++) {
            randomAffine(random, j % 3 == 0, j % 5 == 0).get(bind, 16 * j);
            m[j] = randomAffine(random, false, j % 2 == 0);
            if (j % 4 == 1) {
                m[j].mul(new Matrix4f().m10(0.4f).m21(-0.3f)); // shear
            }
        }
        JointPalette palette = palette(bind, m);
        assertTrue(palette.hasScale());
        for (int j = 0; j < n; j++) {
            Matrix4d b = pivot(bind, j);
            Matrix4d[] ds = split(new Matrix4d(m[j]), b);
            assertRigidPart(ds[0], palette, j);
            assertMatrixEquals(ds[1], rowMajor(palette.scales(), j), "scale part of joint " + j);
            // And what the split is for: D S = M, with S centred on the bind frame (fixing its origin).
            Matrix4d d = rigidPart(palette, j);
            Matrix4d s = rowMajor(palette.scales(), j);
            assertMatrixEquals(new Matrix4d(m[j]), new Matrix4d(d).mul(s), "D S of joint " + j);
            Vector3d origin = b.getTranslation(new Vector3d());
            assertEquals(0, s.transformPosition(new Vector3d(origin)).distance(origin), EPS * scale(s), "joint " + j);
        }
    }

    @Test
    void aMirroredUniformBindShapeScaleSplitsIntoARigidPartAndAScaledReflectionAboutTheBindFrame() {
        // The stormtrooper: BIND_SHAPE = 1.662 * diag(1 1 -1), so every posed frame is mirrored
        // and every joint is split. S is then 1.662 times a reflection about a plane through the
        // bind frame's origin (S^2 = 1.662^2 I, det S = -1.662^3), the same every frame.
        Random random = new Random(5);
        float s = 1.662f;
        Matrix4f bindShape = new Matrix4f().scaling(s, s, -s);
        int n = 12;
        float[] bind = new float[16 * n];
        Matrix4f[] m = new Matrix4f[n];
        for (int j = 0; j < n; j++) {
            Matrix4f inverseBind = new Matrix4f().translation(randomVector(random)).rotate(randomRotation(random));
            new Matrix4f(inverseBind).mul(bindShape).get(bind, 16 * j);
            Matrix4f world = new Matrix4f().translation(randomVector(random)).rotate(randomRotation(random));
            m[j] = world.mul(inverseBind).mul(bindShape);
        }
        JointPalette palette = palette(bind, m);
        for (int j = 0; j < n; j++) {
            Matrix4d b = pivot(bind, j);
            Matrix4d[] ds = split(new Matrix4d(m[j]), b);
            assertRigidPart(ds[0], palette, j);
            Matrix4d scale = rowMajor(palette.scales(), j);
            assertMatrixEquals(ds[1], scale, "scale part of joint " + j);
            Matrix3d linear = scale.get3x3(new Matrix3d());
            assertEquals(-s * s * s, linear.determinant(), EPS * s * s * s, "joint " + j);
            assertMatrixEquals(new Matrix4d().scaling(s * s), new Matrix4d().set(new Matrix3d(linear).mul(linear)),
                    "S^2 of joint " + j);
            Vector3d origin = b.getTranslation(new Vector3d());
            assertEquals(0, scale.transformPosition(new Vector3d(origin)).distance(origin), EPS * s, "joint " + j);
        }
    }

    @Test
    void aJointThatStopsScalingGetsTheIdentityScaleAgain() {
        // Per-frame state: after a scaled frame, a rigid one leaves no scale behind.
        float[] bind = new Matrix4f().translation(0, 1, 0).get(new float[16]);
        JointPalette palette = palette(bind, new Matrix4f[] {new Matrix4f().scaling(1, 2, 1)});
        assertTrue(palette.hasScale());
        Matrix4f rigid = new Matrix4f().rotationZ(0.5f).setTranslation(1, 2, 3);
        palette.setMatrix(0, rigid);
        palette.prepareAll();
        assertFalse(palette.hasScale());
        assertArrayEquals(new float[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0}, row12(palette.scales(), 0), 0f);
        assertRigidPart(new Matrix4d(rigid), palette, 0);
    }

    // ------------------------------------------------------------------------------ helpers

    private static JointPalette palette(float[] bind, Matrix4f[] matrices) {
        JointPalette palette = new JointPalette(bind);
        for (int j = 0; j < matrices.length; j++) {
            palette.setMatrix(j, matrices[j]);
        }
        palette.prepareAll();
        return palette;
    }

    /**
     * The class comment's split in double: {@code {D, S}} for skinning matrix m and pivot b.
     */
    private static Matrix4d[] split(Matrix4d m, Matrix4d b) {
        Matrix4d x = new Matrix4d(m).mul(b);
        Vector3d y = x.getColumn(1, new Vector3d()).normalize();
        Vector3d z = x.getColumn(0, new Vector3d()).cross(y).normalize();
        Vector3d a = new Vector3d(y).cross(z);
        Matrix4d rt = new Matrix4d().setColumn(0, new Vector4d(a, 0)).setColumn(1, new Vector4d(y, 0))
                .setColumn(2, new Vector4d(z, 0)).setTranslation(x.getTranslation(new Vector3d()));
        Matrix4d s0 = new Matrix4d(rt).invertAffine().mul(x).setTranslation(0, 0, 0);
        Matrix4d bInverse = new Matrix4d(b).invertAffine();
        Matrix4d d = new Matrix4d(rt).mul(bInverse);
        Matrix4d s = new Matrix4d(b).mul(s0).mul(bInverse);
        return new Matrix4d[] {d, s};
    }

    /** B: the rigid part of inverse(bind), as the class comment defines it. */
    private static Matrix4d pivot(float[] bind, int j) {
        Matrix4f inverse = new Matrix4f().set(bind, 16 * j).invert();
        Quaternionf r = AnimationHelper.rotationOf(inverse, new Quaternionf());
        return new Matrix4d().translationRotate(inverse.m30(), inverse.m31(), inverse.m32(),
                new Quaterniond(r.x, r.y, r.z, r.w));
    }

    /** Joint j's dual quaternion is unit and is the rigid transform {@code expected}. */
    private static void assertRigidPart(Matrix4d expected, JointPalette palette, int j) {
        DualQuaternion dq = new DualQuaternion().set(palette.dualQuaternions(), 8 * j);
        assertEquals(1, Math.sqrt(dq.realDot(dq)), 1e-6, "|real part| of joint " + j);
        assertMatrixEquals(expected, rigidPart(palette, j), "rigid part of joint " + j);
    }

    private static Matrix4d rigidPart(JointPalette palette, int j) {
        DualQuaternion dq = new DualQuaternion().set(palette.dualQuaternions(), 8 * j);
        return new Matrix4d(DualQuaternions.toMatrix(dq, new Matrix4f()));
    }

    private static void assertMatrixEquals(Matrix4d expected, Matrix4d actual, String what) {
        double tolerance = EPS * Math.max(scale(expected), 1);
        for (int c = 0; c < 4; c++) {
            for (int r = 0; r < 3; r++) {
                assertEquals(expected.get(c, r), actual.get(c, r), tolerance, what + ", row " + r + ", column " + c);
            }
        }
    }

    /** The largest entry of the affine part. */
    private static double scale(Matrix4d m) {
        double s = 0;
        for (int c = 0; c < 4; c++) {
            for (int r = 0; r < 3; r++) {
                s = Math.max(s, Math.abs(m.get(c, r)));
            }
        }
        return s;
    }

    private static Matrix4d rowMajor(float[] a, int j) {
        return new Matrix4d(AnimationHelper.getRowMajor3x4(a, 12 * j, new Matrix4f()));
    }

    private static float[] row12(float[] a, int j) {
        return Arrays.copyOfRange(a, 12 * j, 12 * j + 12);
    }

    /** A random affine matrix: rotation, translation, scale (uniform or not, mirrored or not). */
    private static Matrix4f randomAffine(Random random, boolean rigid, boolean mirrored) {
        Matrix4f m = new Matrix4f().translation(randomVector(random)).rotate(randomRotation(random));
        if (!rigid) {
            m.scale(0.3f + 2 * random.nextFloat(), 0.3f + 2 * random.nextFloat(), 0.3f + 2 * random.nextFloat());
        }
        return mirrored ? m.scale(1, 1, -1) : m;
    }

    private static Quaternionf randomRotation(Random random) {
        return new Quaternionf((float) random.nextGaussian(), (float) random.nextGaussian(),
                (float) random.nextGaussian(), (float) random.nextGaussian()).normalize();
    }

    private static Vector3f randomVector(Random random) {
        return new Vector3f(4 * random.nextFloat() - 2, 4 * random.nextFloat() - 2, 4 * random.nextFloat() - 2);
    }
}
