package org.skinlab.animation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Quaternionf;
import org.joml.Quaternionfc;

/**
 * Expected values and comparisons for the animation math tests, written from the textbook
 * formulas in doubles so that they share nothing with the code under test.
 */
final class MathAssertions {
    /** sqrt(1/2), the quaternion components of 90 and 180 degree rotations. */
    static final float S = (float) Math.sqrt(0.5);

    private MathAssertions() {
    }

    /** The unit quaternion of a rotation by {@code degrees} about (x, y, z): (n sin(a/2), cos(a/2)). */
    static Quaternionf axisAngle(double degrees, double x, double y, double z) {
        double len = Math.sqrt(x * x + y * y + z * z);
        double half = Math.toRadians(degrees) / 2;
        double s = Math.sin(half) / len;
        return new Quaternionf((float) (x * s), (float) (y * s), (float) (z * s), (float) Math.cos(half));
    }

    /** An affine matrix from its top three rows as written on paper (12 values; bottom row 0 0 0 1). */
    static Matrix4f rows(float... v) {
        if (v.length != 12) {
            throw new IllegalArgumentException("12 values");
        }
        // JOML's set() takes columns, and recomputes the matrix properties it uses to take shortcuts
        // (setRowColumn would not).
        return new Matrix4f().set(v[0], v[4], v[8], 0f, v[1], v[5], v[9], 0f, v[2], v[6], v[10], 0f,
                v[3], v[7], v[11], 1f);
    }

    /** Angle (radians) of the rotation taking a to b, for unit quaternions; exact for tiny angles too. */
    static double angleBetween(Quaternionfc a, Quaternionfc b) {
        double aw = a.w();
        double ax = -a.x();
        double ay = -a.y();
        double az = -a.z();
        // conj(a) * b, written out in doubles.
        double x = aw * b.x() + ax * b.w() + ay * b.z() - az * b.y();
        double y = aw * b.y() - ax * b.z() + ay * b.w() + az * b.x();
        double z = aw * b.z() + ax * b.y() - ay * b.x() + az * b.w();
        double w = aw * b.w() - ax * b.x() - ay * b.y() - az * b.z();
        return 2 * Math.atan2(Math.sqrt(x * x + y * y + z * z), Math.abs(w));
    }

    /** Same rotation: components equal to within {@code eps} after matching the sign (q and -q agree). */
    static void assertSameRotation(Quaternionfc expected, Quaternionfc actual, double eps) {
        assertFinite(actual);
        double dot = expected.x() * actual.x() + expected.y() * actual.y() + expected.z() * actual.z()
                + expected.w() * actual.w();
        double s = dot < 0 ? -1 : 1;
        String message = "expected " + expected + " (or its negation), got " + actual;
        assertEquals(expected.x(), s * actual.x(), eps, message);
        assertEquals(expected.y(), s * actual.y(), eps, message);
        assertEquals(expected.z(), s * actual.z(), eps, message);
        assertEquals(expected.w(), s * actual.w(), eps, message);
    }

    static void assertUnit(Quaternionfc q, double eps) {
        assertFinite(q);
        assertEquals(1.0, Math.sqrt(q.lengthSquared()), eps, () -> "not unit: " + q);
    }

    static void assertFinite(Quaternionfc q) {
        assertTrue(Float.isFinite(q.x()) && Float.isFinite(q.y()) && Float.isFinite(q.z()) && Float.isFinite(q.w()),
                () -> "not finite: " + q);
    }

    /** All 16 entries within {@code eps}. */
    static void assertMatrixEquals(Matrix4fc expected, Matrix4fc actual, double eps) {
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 4; c++) {
                int row = r;
                int col = c;
                assertEquals(expected.getRowColumn(r, c), actual.getRowColumn(r, c), eps,
                        () -> "row " + row + " column " + col + ": expected\n" + expected + "got\n" + actual);
            }
        }
    }
}
