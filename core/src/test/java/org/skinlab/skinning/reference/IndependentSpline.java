package org.skinlab.skinning.reference;

/**
 * A second, independent evaluation of spline-based skinning (Forstmann et al. 2007, as
 * docs/skinning.md "Spline-based skinning" defines our variant), in double precision, written from
 * the formulas only: it shares no code with {@code org.skinlab.skinning} or
 * {@code org.skinlab.animation} (nor JOML) and represents rotations differently from the kernel
 * (3x3 matrices, slerp as {@code R_p exp(x log(R_p^T R_c))}, the minimal rotation by Rodrigues'
 * formula, where the kernel uses quaternions).
 *
 * <p>Inputs are plain arrays: rest points and normals, influences, per joint its parent, the
 * child its bone ends at (-1 for none), its rest head and tail (the definition of a bone, given),
 * and its bind matrix (column-major, bind space to joint frame); per frame the skinning matrices
 * (row-major 3x4). A joint's rotation is the rotation of its skinning matrix with the scale
 * removed the way Blender's armature does (the posed frame {@code M B} orthonormalised keeping its
 * Y axis, B the bind frame {@code inverse(bind)}), times {@code B}'s rotation transposed; for a
 * joint without scale that is M's linear part. What the rotation leaves, {@code R^T M} (linear),
 * is the joint's scale, interpolated linearly along a curve and applied to the point's offset
 * from the rest curve before the frame; the reference always applies it (the identity for joints
 * without scale), the kernel only in frames with scale.
 */
public final class IndependentSpline {
    private final double[] rest;
    private final double[] restNormals;
    private final int width;
    private final int[] joints;
    private final double[] weights;
    private final int[] parents;
    private final int[] tailJoints;
    private final double[] heads;
    private final double[] tails;
    /** Per joint the rotation of inverse(bind), row-major 3x3. */
    private final double[] bindRotations;
    private final double a;
    private final int[] curve;
    private final double[] x;

    public IndependentSpline(double[] rest, double[] restNormals, int width, int[] joints, double[] weights,
            int[] parents, int[] tailJoints, double[] heads, double[] tails, float[] bindMatrices, double stiffness) {
        this.rest = rest;
        this.restNormals = restNormals;
        this.width = width;
        this.joints = joints;
        this.weights = weights;
        this.parents = parents;
        this.tailJoints = tailJoints;
        this.heads = heads;
        this.tails = tails;
        this.a = stiffness;
        int jointCount = parents.length;
        bindRotations = new double[9 * jointCount];
        for (int j = 0; j < jointCount; j++) {
            // The linear part of bind (column-major: element (r, c) at 4c + r), inverted; its rows
            // normalised to strip a scale (a bind frame is a rotation in our files).
            double[] m = new double[9];
            for (int r = 0; r < 3; r++) {
                for (int c = 0; c < 3; c++) {
                    m[3 * r + c] = bindMatrices[16 * j + 4 * c + r];
                }
            }
            double[] inv = inverse(m);
            orthonormaliseKeepingY(inv);
            System.arraycopy(inv, 0, bindRotations, 9 * j, 9);
        }
        curve = new int[joints.length];
        x = new double[joints.length];
        bind();
    }

    /** The curve across joint c exists: its parent ends at it and both bones have length. */
    private boolean crossed(int c) {
        int p = parents[c];
        return p >= 0 && tailJoints[p] == c && length(p) > 0 && length(c) > 0;
    }

    private double length(int j) {
        double dx = tails[3 * j] - heads[3 * j], dy = tails[3 * j + 1] - heads[3 * j + 1], dz = tails[3 * j + 2] - heads[3 * j + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    /** Per influence: the curve (projection below or above the bone's middle) and x by bisection. */
    private void bind() {
        int points = rest.length / 3;
        for (int i = 0; i < points; i++) {
            for (int k = 0; k < width; k++) {
                int s = width * i + k;
                int j = joints[s];
                curve[s] = -1;
                double len = length(j);
                if (len == 0) {
                    continue;
                }
                double along = 0;
                for (int e = 0; e < 3; e++) {
                    along += (rest[3 * i + e] - heads[3 * j + e]) * (tails[3 * j + e] - heads[3 * j + e]);
                }
                int c = along / (len * len) < 0.5 ? j : tailJoints[j];
                if (c < 0 || !crossed(c)) {
                    continue;
                }
                curve[s] = c;
                double[][] ctl = controls(c, heads, tails);
                double lo = 0, hi = 1, mid = 0.5;
                for (int step = 0; step < 200; step++) {
                    mid = 0.5 * (lo + hi);
                    double g = dot(sub(point(rest, i), curvePoint(ctl, mid)), curveTangent(ctl, mid));
                    if (Math.abs(g) < 1e-15 || hi - lo < 1e-15) {
                        break;
                    }
                    if (g > 0) {
                        lo = mid;
                    } else {
                        hi = mid;
                    }
                }
                x[s] = mid;
            }
        }
    }

    /** The curve parameter of influence slot s (for tests of the binding). */
    public double parameter(int s) {
        return x[s];
    }

    /** The joint whose curve influence slot s follows, or -1. */
    public int curveOf(int s) {
        return curve[s];
    }

    /** p1, p2, p3 of the curve across c for segments (head, tail) per joint. */
    private static double[][] controls(int c, double[] h, double[] t, int parent) {
        double[] p1 = new double[3], p2 = new double[3], p3 = new double[3];
        for (int e = 0; e < 3; e++) {
            p1[e] = (h[3 * parent + e] + t[3 * parent + e]) / 2;
            p2[e] = h[3 * c + e];
            p3[e] = (h[3 * c + e] + t[3 * c + e]) / 2;
        }
        return new double[][] {p1, p2, p3};
    }

    private double[][] controls(int c, double[] h, double[] t) {
        return controls(c, h, t, parents[c]);
    }

    private double[] curvePoint(double[][] p, double u) {
        double b1 = 1 - Math.pow(1 - u, a), b2 = Math.pow(u, a);
        double[] f = new double[3];
        for (int e = 0; e < 3; e++) {
            f[e] = p[0][e] + (p[1][e] - p[0][e]) * b1 + (p[2][e] - p[1][e]) * b2;
        }
        return f;
    }

    private double[] curveTangent(double[][] p, double u) {
        double d1 = a * Math.pow(1 - u, a - 1), d2 = a * Math.pow(u, a - 1);
        double[] f = new double[3];
        for (int e = 0; e < 3; e++) {
            f[e] = (p[1][e] - p[0][e]) * d1 + (p[2][e] - p[1][e]) * d2;
        }
        return f;
    }

    /**
     * Deforms every point with the skinning matrices (12 doubles per joint, row-major 3x4): 3
     * doubles per point into each output.
     */
    public void deform(double[] matrices, double[] outPositions, double[] outNormals) {
        int jointCount = parents.length;
        double[] posedHeads = new double[3 * jointCount];
        double[] posedTails = new double[3 * jointCount];
        double[][] rotations = new double[jointCount][];
        for (int j = 0; j < jointCount; j++) {
            System.arraycopy(apply(matrices, j, heads, j), 0, posedHeads, 3 * j, 3);
            System.arraycopy(apply(matrices, j, tails, j), 0, posedTails, 3 * j, 3);
            rotations[j] = rigidRotation(matrices, j);
        }
        int points = rest.length / 3;
        for (int i = 0; i < points; i++) {
            double[] p = new double[3];
            double[] n = new double[9];
            double[] q = point(rest, i);
            for (int k = 0; k < width; k++) {
                int s = width * i + k;
                double w = weights[s];
                if (w == 0) {
                    continue;
                }
                double[] pk;
                double[] nk;
                if (curve[s] < 0) {
                    pk = apply(matrices, joints[s], rest, i);
                    nk = signedCofactor(linear(matrices, joints[s]));
                } else {
                    int c = curve[s];
                    double[][] posed = controls(c, posedHeads, posedTails);
                    double[][] restCurve = controls(c, heads, tails);
                    double u = x[s];
                    double[] rp = rotations[parents[c]];
                    double[] slerped = mul(rp, exp(log(mul(transpose(rp), rotations[c])), u));
                    double[] turned = apply3(slerped, curveTangent(restCurve, u));
                    double[] f = mul(minimalRotation(turned, curveTangent(posed, u)), slerped);
                    // The scale left in each matrix once its rotation is taken out, R^T M, blended along the curve.
                    double[] scale = lerp(mul(transpose(rp), linear(matrices, parents[c])),
                            mul(transpose(rotations[c]), linear(matrices, c)), u);
                    pk = add(curvePoint(posed, u), apply3(mul(f, scale), sub(q, curvePoint(restCurve, u))));
                    nk = mul(f, signedCofactor(scale));
                }
                for (int e = 0; e < 3; e++) {
                    p[e] += w * pk[e];
                }
                for (int e = 0; e < 9; e++) {
                    n[e] += w * nk[e];
                }
            }
            double[] normal = apply3(n, point(restNormals, i));
            double len = Math.sqrt(dot(normal, normal));
            for (int e = 0; e < 3; e++) {
                outPositions[3 * i + e] = p[e];
                outNormals[3 * i + e] = len > 0 ? normal[e] / len : 0;
            }
        }
    }

    /** The rotation of joint j: its posed frame M B orthonormalised keeping Y, times B's rotation transposed. */
    private double[] rigidRotation(double[] matrices, int j) {
        double[] b = new double[9];
        System.arraycopy(bindRotations, 9 * j, b, 0, 9);
        double[] frame = mul(linear(matrices, j), b);
        orthonormaliseKeepingY(frame);
        return mul(frame, transpose(b));
    }

    /** Columns of m made orthonormal: y = Y/|Y|, z = X x y normalised, x = y x z. */
    private static void orthonormaliseKeepingY(double[] m) {
        double[] xc = {m[0], m[3], m[6]};
        double[] yc = {m[1], m[4], m[7]};
        double[] y = scale(yc, 1 / Math.sqrt(dot(yc, yc)));
        double[] z = cross(xc, y);
        z = scale(z, 1 / Math.sqrt(dot(z, z)));
        double[] xn = cross(y, z);
        for (int r = 0; r < 3; r++) {
            m[3 * r] = xn[r];
            m[3 * r + 1] = y[r];
            m[3 * r + 2] = z[r];
        }
    }

    /** The rotation taking direction v onto direction t by the smallest angle (Rodrigues). */
    private static double[] minimalRotation(double[] v, double[] t) {
        double[] axis = cross(v, t);
        double sin = Math.sqrt(dot(axis, axis));
        double cos = dot(v, t);
        if (sin == 0 || cos + Math.sqrt(dot(v, v) * dot(t, t)) < 1e-9) {
            return identity();
        }
        return rodrigues(scale(axis, 1 / sin), Math.atan2(sin, cos));
    }

    /** log of a rotation matrix as axis * angle (angle in [0, pi)). */
    private static double[] log(double[] r) {
        double cos = Math.max(-1, Math.min(1, (r[0] + r[4] + r[8] - 1) / 2));
        double angle = Math.acos(cos);
        double[] v = {r[7] - r[5], r[2] - r[6], r[3] - r[1]};
        double len = Math.sqrt(dot(v, v));
        return len == 0 ? new double[3] : scale(v, angle / len);
    }

    /** exp of u times an axis-angle vector. */
    private static double[] exp(double[] axisAngle, double u) {
        double angle = Math.sqrt(dot(axisAngle, axisAngle));
        return angle == 0 ? identity() : rodrigues(scale(axisAngle, 1 / angle), u * angle);
    }

    private static double[] rodrigues(double[] k, double angle) {
        double c = Math.cos(angle), s = Math.sin(angle), t = 1 - c;
        return new double[] {
            c + t * k[0] * k[0], t * k[0] * k[1] - s * k[2], t * k[0] * k[2] + s * k[1],
            t * k[1] * k[0] + s * k[2], c + t * k[1] * k[1], t * k[1] * k[2] - s * k[0],
            t * k[2] * k[0] - s * k[1], t * k[2] * k[1] + s * k[0], c + t * k[2] * k[2]};
    }

    private static double[] signedCofactor(double[] m) {
        double[] k = {
            m[4] * m[8] - m[5] * m[7], m[5] * m[6] - m[3] * m[8], m[3] * m[7] - m[4] * m[6],
            m[2] * m[7] - m[1] * m[8], m[0] * m[8] - m[2] * m[6], m[1] * m[6] - m[0] * m[7],
            m[1] * m[5] - m[2] * m[4], m[2] * m[3] - m[0] * m[5], m[0] * m[4] - m[1] * m[3]};
        double det = m[0] * k[0] + m[1] * k[1] + m[2] * k[2];
        return det < 0 ? scale(k, -1) : k;
    }

    private static double[] inverse(double[] m) {
        double[] k = {
            m[4] * m[8] - m[5] * m[7], m[2] * m[7] - m[1] * m[8], m[1] * m[5] - m[2] * m[4],
            m[5] * m[6] - m[3] * m[8], m[0] * m[8] - m[2] * m[6], m[2] * m[3] - m[0] * m[5],
            m[3] * m[7] - m[4] * m[6], m[1] * m[6] - m[0] * m[7], m[0] * m[4] - m[1] * m[3]};
        double det = m[0] * k[0] + m[1] * k[3] + m[2] * k[6];
        return scale(k, 1 / det);
    }

    private static double[] linear(double[] matrices, int j) {
        int o = 12 * j;
        return new double[] {matrices[o], matrices[o + 1], matrices[o + 2], matrices[o + 4], matrices[o + 5],
            matrices[o + 6], matrices[o + 8], matrices[o + 9], matrices[o + 10]};
    }

    private static double[] apply(double[] matrices, int j, double[] points, int i) {
        int o = 12 * j;
        double[] r = new double[3];
        for (int e = 0; e < 3; e++) {
            r[e] = matrices[o + 4 * e] * points[3 * i] + matrices[o + 4 * e + 1] * points[3 * i + 1]
                    + matrices[o + 4 * e + 2] * points[3 * i + 2] + matrices[o + 4 * e + 3];
        }
        return r;
    }

    private static double[] apply3(double[] m, double[] v) {
        return new double[] {m[0] * v[0] + m[1] * v[1] + m[2] * v[2], m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
            m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
    }

    private static double[] mul(double[] a, double[] b) {
        double[] r = new double[9];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                r[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
            }
        }
        return r;
    }

    private static double[] lerp(double[] a, double[] b, double u) {
        double[] r = new double[a.length];
        for (int e = 0; e < a.length; e++) {
            r[e] = (1 - u) * a[e] + u * b[e];
        }
        return r;
    }

    private static double[] transpose(double[] m) {
        return new double[] {m[0], m[3], m[6], m[1], m[4], m[7], m[2], m[5], m[8]};
    }

    private static double[] identity() {
        return new double[] {1, 0, 0, 0, 1, 0, 0, 0, 1};
    }

    private static double[] point(double[] a, int i) {
        return new double[] {a[3 * i], a[3 * i + 1], a[3 * i + 2]};
    }

    private static double[] add(double[] u, double[] v) {
        return new double[] {u[0] + v[0], u[1] + v[1], u[2] + v[2]};
    }

    private static double[] sub(double[] u, double[] v) {
        return new double[] {u[0] - v[0], u[1] - v[1], u[2] - v[2]};
    }

    private static double[] scale(double[] v, double s) {
        double[] r = new double[v.length];
        for (int e = 0; e < v.length; e++) {
            r[e] = v[e] * s;
        }
        return r;
    }

    private static double dot(double[] u, double[] v) {
        return u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
    }

    private static double[] cross(double[] u, double[] v) {
        return new double[] {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    }
}
