package org.skinlab.animation;

import org.joml.Matrix3d;
import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.joml.Quaterniond;
import org.joml.Quaternionf;
import org.joml.Quaternionfc;
import org.joml.Vector3f;
import org.joml.Vector3fc;
import org.skinlab.model.TransformElement;

/**
 * Conversions between matrices, quaternions and dual quaternions, and rotation interpolation
 * (the thesis' {@code AnimationHelper}). Every method writes into a caller-supplied {@code dest}
 * and allocates nothing except where noted, so it can run per frame.
 *
 * <p>Matrices follow JOML: column vectors, {@code p' = M p}. Quaternions are (x, y, z, w).
 */
public final class AnimationHelper {
    /** Squared column-length deviation below which a matrix counts as unscaled (as Blender). */
    static final float SCALE_EPSILON_SQ = 1e-8f;
    /**
     * The |cos| of the angle between two rotations above which {@link #slerp} falls back to
     * {@link #nlerp}: the sine of so small an angle (about 0.05 degrees) has lost its precision.
     */
    public static final double SLERP_NLERP_THRESHOLD = 0.9999999;

    private AnimationHelper() {
    }

    /**
     * The rotation of the upper 3x3 of {@code m}, robust to scale, shear and float noise: the
     * orthogonal factor of its polar decomposition (the rotation nearest to it in the Frobenius
     * norm), for a reflection (negative determinant) that of {@code -m}. A singular matrix (a
     * zero scale) falls back to Gram-Schmidt on its non-zero columns, each kept on its own axis;
     * an all-zero one gives the identity. Allocates a few JOML temporaries; meant for offline work and per-joint (not
     * per-vertex) use.
     *
     * @param m the matrix; only its upper 3x3 is read, the translation column and bottom row are ignored
     * @param dest receives the rotation, a unit quaternion
     * @return {@code dest}
     */
    public static Quaternionf rotationOf(Matrix4fc m, Quaternionf dest) {
        Matrix3d a = new Matrix3d(m.m00(), m.m01(), m.m02(), m.m10(), m.m11(), m.m12(), m.m20(), m.m21(), m.m22());
        double det = a.determinant();
        if (det < 0) {
            a.scale(-1);
            det = -det;
        }
        Matrix3d r = polarRotation(a, det);
        Quaterniond q = new Quaterniond().setFromNormalized(r);
        return dest.set((float) q.x, (float) q.y, (float) q.z, (float) q.w).normalize();
    }

    /**
     * Orthogonal polar factor by Newton's iteration {@code X <- (g X + X^-T / g) / 2} with Higham's
     * scaling g = sqrt(|X^-1|_F / |X|_F) (Higham 1986, "Computing the polar decomposition"): it
     * converges quadratically from any non-singular start, so a handful of steps reach double
     * precision even for scales of 1e-3 or 1e3.
     */
    private static Matrix3d polarRotation(Matrix3d a, double det) {
        double norm = frobenius(a);
        if (!(norm > 0) || !(det > 1e-12 * norm * norm * norm)) {
            return gramSchmidt(a);
        }
        Matrix3d x = new Matrix3d(a);
        Matrix3d inv = new Matrix3d();
        for (int i = 0; i < 30; i++) {
            x.invert(inv).transpose();
            double g = Math.sqrt(frobenius(inv) / frobenius(x));
            double change = 0;
            for (int c = 0; c < 3; c++) {
                for (int r = 0; r < 3; r++) {
                    double next = 0.5 * (g * x.get(c, r) + inv.get(c, r) / g);
                    change = Math.max(change, Math.abs(next - x.get(c, r)));
                    x.set(c, r, next);
                }
            }
            if (change < 1e-14) {
                break;
            }
        }
        return x;
    }

    private static double frobenius(Matrix3d m) {
        return Math.sqrt(m.m00 * m.m00 + m.m01 * m.m01 + m.m02 * m.m02 + m.m10 * m.m10 + m.m11 * m.m11
                + m.m12 * m.m12 + m.m20 * m.m20 + m.m21 * m.m21 + m.m22 * m.m22);
    }

    /**
     * Rotation from the usable columns of a singular matrix, each kept in its own slot: a zero
     * scale on one axis says nothing about that axis, but the other columns still fix the rotation
     * (diag(1, 0, 1) is the identity with Y flattened, not a turn about X), so T*R*S still holds.
     */
    private static Matrix3d gramSchmidt(Matrix3d a) {
        double[][] c = {{a.m00, a.m01, a.m02}, {a.m10, a.m11, a.m12}, {a.m20, a.m21, a.m22}};
        double[][] u = new double[3][];
        int first = -1;
        int second = -1;
        for (int i = 0; i < 3 && second < 0; i++) {
            double[] v = c[i].clone();
            if (first >= 0) {
                double d = dot(v, u[first]);
                for (int j = 0; j < 3; j++) {
                    v[j] -= d * u[first][j];
                }
            }
            double len = Math.sqrt(dot(v, v));
            if (len > 1e-9) {
                for (int j = 0; j < 3; j++) {
                    v[j] /= len;
                }
                u[i] = v;
                if (first < 0) {
                    first = i;
                } else {
                    second = i;
                }
            }
        }
        if (first < 0) {
            return new Matrix3d();
        }
        if (second < 0) {
            // One direction left: any unit vector perpendicular to it completes the frame.
            double[] k = u[first];
            double[] e = Math.abs(k[0]) < 0.9 ? new double[] {1, 0, 0} : new double[] {0, 1, 0};
            double d = dot(e, k);
            double[] v = {e[0] - d * k[0], e[1] - d * k[1], e[2] - d * k[2]};
            double len = Math.sqrt(dot(v, v));
            second = (first + 1) % 3;
            u[second] = new double[] {v[0] / len, v[1] / len, v[2] / len};
        }
        // The lost axis k completes a right-handed frame: column k = column k+1 x column k+2.
        int k = 3 - first - second;
        double[] p = u[(k + 1) % 3];
        double[] q = u[(k + 2) % 3];
        u[k] = new double[] {p[1] * q[2] - p[2] * q[1], p[2] * q[0] - p[0] * q[2], p[0] * q[1] - p[1] * q[0]};
        return new Matrix3d(u[0][0], u[0][1], u[0][2], u[1][0], u[1][1], u[1][2], u[2][0], u[2][1], u[2][2]);
    }

    private static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    /**
     * Splits an affine matrix into translation, rotation and per-axis scale so that
     * {@code m = T * R * S} ({@link #compose}). The rotation is {@link #rotationOf}; the scale is
     * the diagonal of {@code R^T M}, so column noise does not leak into it and a reflection shows
     * as negative scales. Shear has no place in T*R*S and is dropped.
     *
     * @param m the affine matrix to split; its bottom row is ignored
     * @param translation receives the translation column of {@code m}
     * @param rotation receives the rotation R, a unit quaternion
     * @param scale receives the per-axis scale along R's axes, negative on a reflection
     */
    public static void decompose(Matrix4fc m, Vector3f translation, Quaternionf rotation, Vector3f scale) {
        m.getTranslation(translation);
        rotationOf(m, rotation);
        // Columns of R from the unit quaternion, dotted with the columns of M.
        float x = rotation.x();
        float y = rotation.y();
        float z = rotation.z();
        float w = rotation.w();
        float r00 = 1 - 2 * (y * y + z * z);
        float r10 = 2 * (x * y + w * z);
        float r20 = 2 * (x * z - w * y);
        float r01 = 2 * (x * y - w * z);
        float r11 = 1 - 2 * (x * x + z * z);
        float r21 = 2 * (y * z + w * x);
        float r02 = 2 * (x * z + w * y);
        float r12 = 2 * (y * z - w * x);
        float r22 = 1 - 2 * (x * x + y * y);
        scale.set(r00 * m.m00() + r10 * m.m01() + r20 * m.m02(),
                r01 * m.m10() + r11 * m.m11() + r21 * m.m12(),
                r02 * m.m20() + r12 * m.m21() + r22 * m.m22());
    }

    /**
     * {@code dest = T * R * S}. The rotation uses the homogeneous form (entries like
     * {@code w^2 + x^2 - y^2 - z^2}), which equals the usual one for unit quaternions and scales
     * by {@code |q|^2} otherwise, so an un-normalised {@link RotationInterpolation#LERP} result
     * shows as the shrinking it is rather than as a shear.
     *
     * @param translation the translation T
     * @param rotation the rotation R; unit for a pure rotation, otherwise it scales by {@code |rotation|^2}
     * @param scale the per-axis scale S, applied first, along the local axes
     * @param dest receives the affine matrix; all 16 entries are overwritten
     * @return {@code dest}
     */
    public static Matrix4f compose(Vector3fc translation, Quaternionfc rotation, Vector3fc scale, Matrix4f dest) {
        rotationMatrix(rotation, dest);
        float sx = scale.x();
        float sy = scale.y();
        float sz = scale.z();
        return dest.set(dest.m00() * sx, dest.m01() * sx, dest.m02() * sx, 0f,
                dest.m10() * sy, dest.m11() * sy, dest.m12() * sy, 0f,
                dest.m20() * sz, dest.m21() * sz, dest.m22() * sz, 0f,
                translation.x(), translation.y(), translation.z(), 1f);
    }

    /**
     * {@link #compose} written as a row-major 4x4 matrix (the layout of a COLLADA
     * {@code <matrix>}, bottom row 0 0 0 1) at {@code dest[offset]}, with the same operations, so
     * the same values to the bit. For the per-frame path, which has its values in locals.
     *
     * @param tx the x of the translation T
     * @param ty the y of the translation T
     * @param tz the z of the translation T
     * @param qx the x of the rotation quaternion R (unit for a pure rotation, as in {@link #compose})
     * @param qy the y of the rotation quaternion R
     * @param qz the z of the rotation quaternion R
     * @param qw the w (real part) of the rotation quaternion R
     * @param sx the scale S along the local x axis
     * @param sy the scale S along the local y axis
     * @param sz the scale S along the local z axis
     * @param dest receives the 16 floats of the matrix, row by row, at {@code dest[offset .. offset + 15]}
     * @param offset the index in {@code dest} of the first (top-left) entry
     */
    public static void composeRowMajor(float tx, float ty, float tz, float qx, float qy, float qz, float qw,
            float sx, float sy, float sz, float[] dest, int offset) {
        float ww = qw * qw;
        float xx = qx * qx;
        float yy = qy * qy;
        float zz = qz * qz;
        int o = offset;
        dest[o] = (ww + xx - yy - zz) * sx;
        dest[o + 1] = 2 * (qx * qy - qw * qz) * sy;
        dest[o + 2] = 2 * (qx * qz + qw * qy) * sz;
        dest[o + 3] = tx;
        dest[o + 4] = 2 * (qx * qy + qw * qz) * sx;
        dest[o + 5] = (ww - xx + yy - zz) * sy;
        dest[o + 6] = 2 * (qy * qz - qw * qx) * sz;
        dest[o + 7] = ty;
        dest[o + 8] = 2 * (qx * qz - qw * qy) * sx;
        dest[o + 9] = 2 * (qy * qz + qw * qx) * sy;
        dest[o + 10] = (ww - xx - yy + zz) * sz;
        dest[o + 11] = tz;
        dest[o + 12] = 0f;
        dest[o + 13] = 0f;
        dest[o + 14] = 0f;
        dest[o + 15] = 1f;
    }

    /**
     * The rotation matrix of {@code q} in homogeneous form: {@code |q|^2} times that of q/|q|.
     *
     * @param q the rotation quaternion, not necessarily unit
     * @param dest receives the matrix; all 16 entries are overwritten, the translation becomes zero
     * @return {@code dest}
     */
    public static Matrix4f rotationMatrix(Quaternionfc q, Matrix4f dest) {
        return TransformElement.quaternionMatrix(q.x(), q.y(), q.z(), q.w(), dest);
    }

    /**
     * Writes the affine part of {@code m} as a row-major 3x4 matrix (r00 r01 r02 tx, r10 ...) at
     * {@code dest[offset]}: the layout of COLLADA's rows and of the skinning kernels' joints.
     *
     * @param m the matrix; its bottom row is not written (taken as 0 0 0 1)
     * @param dest receives 12 floats at {@code dest[offset .. offset + 11]}
     * @param offset the index in {@code dest} of the first entry (r00)
     */
    public static void putRowMajor3x4(Matrix4fc m, float[] dest, int offset) {
        dest[offset] = m.m00();
        dest[offset + 1] = m.m10();
        dest[offset + 2] = m.m20();
        dest[offset + 3] = m.m30();
        dest[offset + 4] = m.m01();
        dest[offset + 5] = m.m11();
        dest[offset + 6] = m.m21();
        dest[offset + 7] = m.m31();
        dest[offset + 8] = m.m02();
        dest[offset + 9] = m.m12();
        dest[offset + 10] = m.m22();
        dest[offset + 11] = m.m32();
    }

    /**
     * Writes the affine part of the column-major 4x4 matrix at {@code src[srcOffset]} (16 floats,
     * JOML's and OpenGL's layout) as a row-major 3x4 matrix at {@code dest[offset]}.
     *
     * @param src holds the column-major 4x4 matrix; only its first three rows are read
     * @param srcOffset the index in {@code src} of the matrix's first entry (m00)
     * @param dest receives 12 floats at {@code dest[offset .. offset + 11]}
     * @param offset the index in {@code dest} of the first entry (r00)
     */
    public static void putRowMajor3x4(float[] src, int srcOffset, float[] dest, int offset) {
        for (int r = 0; r < 3; r++) {
            dest[offset + 4 * r] = src[srcOffset + r];
            dest[offset + 4 * r + 1] = src[srcOffset + 4 + r];
            dest[offset + 4 * r + 2] = src[srcOffset + 8 + r];
            dest[offset + 4 * r + 3] = src[srcOffset + 12 + r];
        }
    }

    /**
     * Reads a row-major 3x4 matrix from {@code src[offset]} into {@code dest} (bottom row 0 0 0 1).
     *
     * @param src holds the 12 floats of the matrix, row by row, as {@link #putRowMajor3x4} writes them
     * @param offset the index in {@code src} of the first entry (r00)
     * @param dest receives the matrix; all 16 entries are overwritten
     * @return {@code dest}
     */
    public static Matrix4f getRowMajor3x4(float[] src, int offset, Matrix4f dest) {
        float[] a = src;
        int o = offset;
        return dest.set(a[o], a[o + 4], a[o + 8], 0f, a[o + 1], a[o + 5], a[o + 9], 0f,
                a[o + 2], a[o + 6], a[o + 10], 0f, a[o + 3], a[o + 7], a[o + 11], 1f);
    }

    /**
     * Interpolates from {@code a} (t = 0) to {@code b} (t = 1) the way {@code mode} says.
     *
     * @param mode which of {@link #lerp}, {@link #nlerp} or {@link #slerp} to use
     * @param a the rotation at t = 0
     * @param b the rotation at t = 1
     * @param t the interpolation parameter, normally in [0, 1]
     * @param dest receives the interpolated rotation
     * @return {@code dest}
     */
    public static Quaternionf interpolate(RotationInterpolation mode, Quaternionfc a, Quaternionfc b, float t,
            Quaternionf dest) {
        switch (mode) {
            case LERP:
                return lerp(a, b, t, dest);
            case SLERP:
                return slerp(a, b, t, dest);
            case NLERP:
                return nlerp(a, b, t, dest);
            default:
                throw new IllegalArgumentException(String.valueOf(mode));
        }
    }

    /**
     * Component-wise blend along the shortest arc, not renormalised.
     *
     * @param a the rotation at t = 0
     * @param b the rotation at t = 1; negated first when it lies in the other hemisphere from {@code a}
     * @param t the interpolation parameter, normally in [0, 1]
     * @param dest receives {@code (1 - t) a + t b}, shorter than unit length between two distinct rotations; may be
     *     {@code a} or {@code b}
     * @return {@code dest}
     */
    public static Quaternionf lerp(Quaternionfc a, Quaternionfc b, float t, Quaternionf dest) {
        float s = 1 - t;
        // copySign rather than a branch: same result, and the sign of a dot of exactly 0 (90
        // degrees apart either way) stays deterministic.
        float u = Math.copySign(t, a.x() * b.x() + a.y() * b.y() + a.z() * b.z() + a.w() * b.w());
        return dest.set(s * a.x() + u * b.x(), s * a.y() + u * b.y(), s * a.z() + u * b.z(), s * a.w() + u * b.w());
    }

    /**
     * {@link #lerp}, then normalised.
     *
     * @param a the rotation at t = 0, unit
     * @param b the rotation at t = 1, unit
     * @param t the interpolation parameter, normally in [0, 1]
     * @param dest receives the unit result; a copy of {@code a} in the degenerate case where the blend is zero
     * @return {@code dest}
     */
    public static Quaternionf nlerp(Quaternionfc a, Quaternionfc b, float t, Quaternionf dest) {
        lerp(a, b, t, dest);
        float len = (float) Math.sqrt(dest.lengthSquared());
        return len > 0 ? dest.div(len) : dest.set(a);
    }

    /**
     * sin(x) for x in [0, pi/2], the range of every angle of a shortest-arc slerp, by its Taylor
     * series to x^13 (within 1e-9 there): the per-frame blends' sine, a few multiplications where
     * {@code Math.sin} costs more than the rest of a slerp. Far below a float's resolution.
     *
     * @param x the angle in radians, in [0, pi/2]
     * @return sin(x) within 1e-9
     */
    public static double sinFast(double x) {
        double x2 = x * x;
        double p = 1.0 / 6227020800.0;
        p = p * x2 - 1.0 / 39916800.0;
        p = p * x2 + 1.0 / 362880.0;
        p = p * x2 - 1.0 / 5040.0;
        p = p * x2 + 1.0 / 120.0;
        p = p * x2 - 1.0 / 6.0;
        p = p * x2 + 1.0;
        return x * p;
    }

    /**
     * acos(x) for x in [0, 1] (Abramowitz and Stegun 4.4.46, within 2e-8 rad): the per-frame
     * blends' arc cosine, with {@link #sinFast}.
     *
     * @param x the cosine, in [0, 1]
     * @return acos(x) within 2e-8
     */
    public static double acosFast(double x) {
        double p = -0.0012624911;
        p = p * x + 0.0066700901;
        p = p * x - 0.0170881256;
        p = p * x + 0.0308918810;
        p = p * x - 0.0501743046;
        p = p * x + 0.0889789874;
        p = p * x - 0.2145988016;
        p = p * x + 1.5707963050;
        return Math.sqrt(1 - x) * p;
    }

    /**
     * Spherical interpolation along the shortest arc: {@code (sin((1-t)O) a + sin(tO) b) / sin O}
     * with O the angle between a and b (Shoemake 1985). Falls back to {@link #nlerp} when
     * |a.b| > 0.9999999 (keys less than about 0.05 degrees of rotation apart), where sin O loses
     * its precision.
     *
     * @param a the rotation at t = 0, unit
     * @param b the rotation at t = 1, unit
     * @param t the interpolation parameter, normally in [0, 1]
     * @param dest receives the interpolated rotation, unit when {@code a} and {@code b} are; may be {@code a} or
     *     {@code b}
     * @return {@code dest}
     */
    public static Quaternionf slerp(Quaternionfc a, Quaternionfc b, float t, Quaternionf dest) {
        double dot = (double) a.x() * b.x() + (double) a.y() * b.y() + (double) a.z() * b.z() + (double) a.w() * b.w();
        double sign = dot < 0 ? -1 : 1;
        double cos = Math.min(1.0, Math.abs(dot));
        if (cos > SLERP_NLERP_THRESHOLD) {
            return nlerp(a, b, t, dest);
        }
        double angle = Math.acos(cos);
        double sin = Math.sin(angle);
        double wa = Math.sin((1 - t) * angle) / sin;
        double wb = sign * Math.sin(t * angle) / sin;
        return dest.set((float) (wa * a.x() + wb * b.x()), (float) (wa * a.y() + wb * b.y()),
                (float) (wa * a.z() + wb * b.z()), (float) (wa * a.w() + wb * b.w()));
    }

    /**
     * The unit dual quaternion of the rigid part of {@code m}: rotation {@link #rotationOf}, and
     * the translation column. Exact for rigid matrices; for others it keeps the rotation and
     * translation and drops scale (use the two-phase split of the DQS skinner for those).
     * Allocates (through {@link #rotationOf}).
     *
     * @param m the matrix; its upper 3x3 gives the rotation and its translation column the translation
     * @param dest receives the unit dual quaternion
     * @return {@code dest}
     */
    public static DualQuaternion toDualQuaternion(Matrix4fc m, DualQuaternion dest) {
        Quaternionf r = rotationOf(m, new Quaternionf());
        return dest.set(r.x, r.y, r.z, r.w, m.m30(), m.m31(), m.m32());
    }
}
