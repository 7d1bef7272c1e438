package org.skinlab.skinning.reference;

/**
 * A second, plain implementation of bulge-free DQS's positions, in double precision, written from
 * the formulas in docs/skinning.md ("Bulge-free DQS") and "Dual Quaternion Skinning" (the
 * two-phase split) without calling production code. Its inputs are data: rest points, influences,
 * the inverse bind matrices, one pose's skinning matrices and the bones' rest heads and tails.
 *
 * <ol>
 * <li>Per joint, M = D S: X = M B with B = inverse(bind) (rigid in our assets; its 3x3 is taken
 *     orthonormal by Gram-Schmidt keeping Y); when X's columns are unit (sum of (|c|^2 - 1)^2 at
 *     most 4e-8) and det X > 0, D = M, S = I; else R keeps X's Y axis (y = Y/|Y|,
 *     z = X x Y/|X x Y|, x = y x z), D = [R Bl^T | x_t - R Bl^T b], S = D^-1 M.</li>
 * <li>DQS: S blended linearly and applied, D's unit dual quaternions blended with signs against
 *     the first (heaviest) influence, normalised by the real part, applied.</li>
 * <li>Bone: of the influences with weight > 0 (the first always), the one whose rest segment is
 *     nearest the rest point, a later one only when nearer than (1 - 1e-4) times the best; r its
 *     distance, or, when some joint of the pose has a scale part, |M_k (p - c_rest)|.</li>
 * <li>Pull: c the nearest point to the DQS point q on the posed segment (M_k h, M_k t), d = |q - c|;
 *     when d > r, q' = c + (q - c) d'/d with d' = r + e a / sqrt(a^2 + e^2), e = d - r,
 *     a = 0.05 s r, s = sqrt(1 - (r_0 . r_1)^2) the sine of half the angle between the rotations
 *     (real parts) of the two heaviest influences (0 with one influence of weight > 0).</li>
 * </ol>
 */
public final class IndependentBulgeFreeDqs {
    private static final double ALLOWANCE = 0.05;
    private static final double TIE = 1e-4;

    private IndependentBulgeFreeDqs() {
    }

    /**
     * @param rest       3 per point, bind space
     * @param joints     {@code width} per point, heaviest first
     * @param weights    {@code width} per point
     * @param bind       16 per joint, column-major (the inverse bind matrix)
     * @param matrices   12 per joint, row-major 3x4 skinning matrices
     * @param heads      3 per joint, the bones' rest heads
     * @param tails      3 per joint, the bones' rest tails
     * @return 3 per point, the deformed positions
     */
    public static double[] skin(float[] rest, int[] joints, float[] weights, int width, float[] bind,
            float[] matrices, float[] heads, float[] tails) {
        int jointCount = matrices.length / 12;
        double[][] d = new double[jointCount][];
        double[][] s = new double[jointCount][];
        boolean anyScale = false;
        for (int j = 0; j < jointCount; j++) {
            double[] m = new double[12];
            for (int k = 0; k < 12; k++) {
                m[k] = matrices[12 * j + k];
            }
            double[] b = rigidBindFrame(bind, j);
            double[] x = multiply(m, b);
            double l0 = sq(x[0], x[4], x[8]) - 1, l1 = sq(x[1], x[5], x[9]) - 1, l2 = sq(x[2], x[6], x[10]) - 1;
            if (l0 * l0 + l1 * l1 + l2 * l2 <= 4e-8 && det(x) > 0) {
                d[j] = m;
                s[j] = new double[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0};
            } else {
                anyScale = true;
                d[j] = rigidPart(x, b);
                s[j] = multiply(inverseRigid(d[j]), m);
            }
        }
        double[][] q = new double[jointCount][];
        for (int j = 0; j < jointCount; j++) {
            q[j] = dualQuaternion(d[j]);
        }
        int points = rest.length / 3;
        double[] out = new double[3 * points];
        for (int i = 0; i < points; i++) {
            double[] p = {rest[3 * i], rest[3 * i + 1], rest[3 * i + 2]};
            double[] sb = new double[12];
            double[] real = new double[4];
            double[] dual = new double[4];
            double[] pivot = q[joints[width * i]];
            for (int k = 0; k < width; k++) {
                int j = joints[width * i + k];
                double w = weights[width * i + k];
                for (int e = 0; e < 12; e++) {
                    sb[e] += w * s[j][e];
                }
                double sign = pivot[0] * q[j][0] + pivot[1] * q[j][1] + pivot[2] * q[j][2] + pivot[3] * q[j][3] < 0 ? -1 : 1;
                for (int e = 0; e < 4; e++) {
                    real[e] += sign * w * q[j][e];
                    dual[e] += sign * w * q[j][4 + e];
                }
            }
            double[] p1 = anyScale ? apply(sb, p) : p;
            double len = Math.sqrt(real[0] * real[0] + real[1] * real[1] + real[2] * real[2] + real[3] * real[3]);
            for (int e = 0; e < 4; e++) {
                real[e] /= len;
                dual[e] /= len;
            }
            // t = 2 dual conj(real), vector part; p' = real p1 conj(real) + t
            double[] t = product(dual, new double[] {-real[0], -real[1], -real[2], real[3]});
            double[] rotated = product(product(real, new double[] {p1[0], p1[1], p1[2], 0}),
                    new double[] {-real[0], -real[1], -real[2], real[3]});
            double[] qd = {rotated[0] + 2 * t[0], rotated[1] + 2 * t[1], rotated[2] + 2 * t[2]};
            int bone = bone(p, joints, weights, width, i, heads, tails);
            double r = nearestOnSegment(p, head(heads, bone), head(tails, bone))[3];
            if (anyScale) {
                double[] c = nearestOnSegment(p, head(heads, bone), head(tails, bone));
                double[] u = {p[0] - c[0], p[1] - c[1], p[2] - c[2]};
                double[] mu = applyLinear(matrixOf(matrices, bone), u);
                r = Math.sqrt(sq(mu[0], mu[1], mu[2]));
            }
            double[] mk = matrixOf(matrices, bone);
            double[] c = nearestOnSegment(qd, apply(mk, head(heads, bone)), apply(mk, head(tails, bone)));
            double dist = c[3];
            if (dist > r) {
                double[] q0 = q[joints[width * i]];
                double[] q1 = width > 1 && weights[width * i + 1] > 0 ? q[joints[width * i + 1]] : q0;
                double dot = q0[0] * q1[0] + q0[1] * q1[1] + q0[2] * q1[2] + q0[3] * q1[3];
                double a = ALLOWANCE * Math.sqrt(Math.max(0, 1 - dot * dot)) * r;
                double e = dist - r;
                double pulled = r + (a == 0 ? 0 : e * a / Math.sqrt(a * a + e * e));
                for (int k = 0; k < 3; k++) {
                    qd[k] = c[k] + (qd[k] - c[k]) * pulled / dist;
                }
            }
            System.arraycopy(qd, 0, out, 3 * i, 3);
        }
        return out;
    }

    private static int bone(double[] p, int[] joints, float[] weights, int width, int i, float[] heads,
            float[] tails) {
        int best = joints[width * i];
        double nearest = Double.POSITIVE_INFINITY;
        for (int k = 0; k < width; k++) {
            if (k > 0 && !(weights[width * i + k] > 0)) {
                continue;
            }
            int j = joints[width * i + k];
            double dist = nearestOnSegment(p, head(heads, j), head(tails, j))[3];
            if (dist < (1 - TIE) * nearest) {
                nearest = dist;
                best = j;
            }
        }
        return best;
    }

    private static double[] head(float[] a, int j) {
        return new double[] {a[3 * j], a[3 * j + 1], a[3 * j + 2]};
    }

    /** The nearest point of segment [a, b] to p (a when a = b), and its distance as element 3. */
    private static double[] nearestOnSegment(double[] p, double[] a, double[] b) {
        double ex = b[0] - a[0], ey = b[1] - a[1], ez = b[2] - a[2];
        double len2 = sq(ex, ey, ez);
        double t = len2 > 0 ? ((p[0] - a[0]) * ex + (p[1] - a[1]) * ey + (p[2] - a[2]) * ez) / len2 : 0;
        t = Math.max(0, Math.min(1, t));
        double cx = a[0] + t * ex, cy = a[1] + t * ey, cz = a[2] + t * ez;
        return new double[] {cx, cy, cz, Math.sqrt(sq(p[0] - cx, p[1] - cy, p[2] - cz))};
    }

    private static double[] matrixOf(float[] matrices, int j) {
        double[] m = new double[12];
        for (int k = 0; k < 12; k++) {
            m[k] = matrices[12 * j + k];
        }
        return m;
    }

    /** inverse(bind) as row-major 3x4 with its 3x3 made orthonormal (Gram-Schmidt, Y first). */
    private static double[] rigidBindFrame(float[] bind, int j) {
        double[] a = new double[16];
        for (int r = 0; r < 4; r++) {
            for (int c = 0; c < 4; c++) {
                a[4 * r + c] = bind[16 * j + 4 * c + r];
            }
        }
        double[] inv = invert4(a);
        double[] y = normalise(inv[1], inv[5], inv[9]);
        double[] x = {inv[0], inv[4], inv[8]};
        double dot = x[0] * y[0] + x[1] * y[1] + x[2] * y[2];
        x = normalise(x[0] - dot * y[0], x[1] - dot * y[1], x[2] - dot * y[2]);
        double[] z = cross(x, y);
        return new double[] {x[0], y[0], z[0], inv[3], x[1], y[1], z[1], inv[7], x[2], y[2], z[2], inv[11]};
    }

    /** D = [R Bl^T | x_t - R Bl^T b] with R keeping X's Y axis. */
    private static double[] rigidPart(double[] x, double[] b) {
        double[] y = normalise(x[1], x[5], x[9]);
        double[] z = normalise(cross(new double[] {x[0], x[4], x[8]}, new double[] {x[1], x[5], x[9]}));
        double[] xa = cross(y, z);
        double[] r = {xa[0], y[0], z[0], 0, xa[1], y[1], z[1], 0, xa[2], y[2], z[2], 0};
        double[] bt = inverseRigid(b);
        double[] rb = multiply(r, new double[] {bt[0], bt[1], bt[2], 0, bt[4], bt[5], bt[6], 0, bt[8], bt[9], bt[10], 0});
        double[] bb = {b[3], b[7], b[11]};
        double[] rbb = applyLinear(rb, bb);
        rb[3] = x[3] - rbb[0];
        rb[7] = x[7] - rbb[1];
        rb[11] = x[11] - rbb[2];
        return rb;
    }

    /** The unit dual quaternion (real x y z w, dual x y z w) of a rigid 3x4. */
    private static double[] dualQuaternion(double[] m) {
        double[] r = rotationQuaternion(m);
        double[] t = product(new double[] {m[3], m[7], m[11], 0}, r);
        return new double[] {r[0], r[1], r[2], r[3], 0.5 * t[0], 0.5 * t[1], 0.5 * t[2], 0.5 * t[3]};
    }

    private static double[] rotationQuaternion(double[] m) {
        double trace = m[0] + m[5] + m[10];
        double x, y, z, w;
        if (trace > 0) {
            double s = 2 * Math.sqrt(trace + 1);
            w = s / 4;
            x = (m[9] - m[6]) / s;
            y = (m[2] - m[8]) / s;
            z = (m[4] - m[1]) / s;
        } else if (m[0] > m[5] && m[0] > m[10]) {
            double s = 2 * Math.sqrt(1 + m[0] - m[5] - m[10]);
            x = s / 4;
            y = (m[1] + m[4]) / s;
            z = (m[2] + m[8]) / s;
            w = (m[9] - m[6]) / s;
        } else if (m[5] > m[10]) {
            double s = 2 * Math.sqrt(1 + m[5] - m[0] - m[10]);
            y = s / 4;
            x = (m[1] + m[4]) / s;
            z = (m[6] + m[9]) / s;
            w = (m[2] - m[8]) / s;
        } else {
            double s = 2 * Math.sqrt(1 + m[10] - m[0] - m[5]);
            z = s / 4;
            x = (m[2] + m[8]) / s;
            y = (m[6] + m[9]) / s;
            w = (m[4] - m[1]) / s;
        }
        double n = Math.sqrt(x * x + y * y + z * z + w * w);
        return new double[] {x / n, y / n, z / n, w / n};
    }

    /** Hamilton product of quaternions (x y z w). */
    private static double[] product(double[] a, double[] b) {
        return new double[] {
            a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
            a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
            a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
            a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
    }

    private static double[] multiply(double[] a, double[] b) {
        double[] c = new double[12];
        for (int r = 0; r < 3; r++) {
            for (int k = 0; k < 4; k++) {
                c[4 * r + k] = a[4 * r] * b[k] + a[4 * r + 1] * b[4 + k] + a[4 * r + 2] * b[8 + k] + (k == 3 ? a[4 * r + 3] : 0);
            }
        }
        return c;
    }

    private static double[] inverseRigid(double[] m) {
        double[] t = {m[0], m[4], m[8], 0, m[1], m[5], m[9], 0, m[2], m[6], m[10], 0};
        double[] tt = applyLinear(t, new double[] {m[3], m[7], m[11]});
        t[3] = -tt[0];
        t[7] = -tt[1];
        t[11] = -tt[2];
        return t;
    }

    private static double[] apply(double[] m, double[] p) {
        double[] l = applyLinear(m, p);
        return new double[] {l[0] + m[3], l[1] + m[7], l[2] + m[11]};
    }

    private static double[] applyLinear(double[] m, double[] p) {
        return new double[] {m[0] * p[0] + m[1] * p[1] + m[2] * p[2], m[4] * p[0] + m[5] * p[1] + m[6] * p[2],
            m[8] * p[0] + m[9] * p[1] + m[10] * p[2]};
    }

    private static double det(double[] m) {
        return m[0] * (m[5] * m[10] - m[6] * m[9]) - m[1] * (m[4] * m[10] - m[6] * m[8])
                + m[2] * (m[4] * m[9] - m[5] * m[8]);
    }

    private static double sq(double x, double y, double z) {
        return x * x + y * y + z * z;
    }

    private static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    private static double[] normalise(double[] v) {
        return normalise(v[0], v[1], v[2]);
    }

    private static double[] normalise(double x, double y, double z) {
        double l = Math.sqrt(sq(x, y, z));
        return new double[] {x / l, y / l, z / l};
    }

    /** Inverse of a row-major 4x4 by Gauss-Jordan elimination with partial pivoting. */
    private static double[] invert4(double[] a) {
        double[] m = a.clone();
        double[] inv = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        for (int c = 0; c < 4; c++) {
            int pivot = c;
            for (int r = c + 1; r < 4; r++) {
                if (Math.abs(m[4 * r + c]) > Math.abs(m[4 * pivot + c])) {
                    pivot = r;
                }
            }
            for (int k = 0; k < 4; k++) {
                double tmp = m[4 * c + k];
                m[4 * c + k] = m[4 * pivot + k];
                m[4 * pivot + k] = tmp;
                tmp = inv[4 * c + k];
                inv[4 * c + k] = inv[4 * pivot + k];
                inv[4 * pivot + k] = tmp;
            }
            double diag = m[4 * c + c];
            for (int k = 0; k < 4; k++) {
                m[4 * c + k] /= diag;
                inv[4 * c + k] /= diag;
            }
            for (int r = 0; r < 4; r++) {
                if (r != c) {
                    double f = m[4 * r + c];
                    for (int k = 0; k < 4; k++) {
                        m[4 * r + k] -= f * m[4 * c + k];
                        inv[4 * r + k] -= f * inv[4 * c + k];
                    }
                }
            }
        }
        return inv;
    }
}
