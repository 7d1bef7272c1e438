package org.skinlab.skinning.reference;

/**
 * A second, independent evaluation of stretchable and twistable bones (Jacobson and Sorkine 2011)
 * on LBS and DQS, in double precision, written from the formulas in docs/skinning.md and not
 * calling production code. Its inputs are what a file defines: per joint the skinning matrix M,
 * the bind frame (the inverse of INV_BIND) and the bone (rest head h, tail t, parent). Everything
 * the production palette derives per frame is derived here again, by other routes:
 * <ul>
 * <li>the rigid part D of M: the posed frame X = M B (B the polar rotation of the bind frame, by
 *     Higham's iteration, with its origin), its rotation by keeping X's Y axis and
 *     orthogonalising the others to it (Gram-Schmidt), {@code D = [R | x] B^-1};</li>
 * <li>the twist theta: the relative rotation {@code Q = Dp^T Dc} of the joint to its parent,
 *     split geometrically: the least rotation taking {@code Q a} back to the rest axis a, applied
 *     to {@code Q u} for a u perpendicular to a, gives u turned by theta about a;</li>
 * <li>the endpoint weight {@code e = clamp((p - h).(t - h) / L^2, 0, 1)}, 1 for L = 0; per
 *     influence {@code T(p) = Rot(D a, -(1 - e) theta, about M h) D p + e (M t - D t)};</li>
 * <li>LBS: the matrices T blended linearly, the normal by the cofactor of the linear part; DQS:
 *     each T as a unit dual quaternion, flipped to the dominant influence's side, blended,
 *     normalised, the normal turned by its rotation.</li>
 * </ul>
 */
public final class IndependentStbs {
    private final int joints;
    private final double[][] bindFrames;
    private final double[][] heads;
    private final double[][] tails;
    private final int[] parents;
    /** Per joint this pose's influence data: D (3x4), posed head, posed axis, stretch offset, twist. */
    private final double[][] rigid;
    private final double[][] posedHead;
    private final double[][] posedAxis;
    private final double[][] offset;
    private final double[] twist;

    /**
     * @param inverseBind per joint 16 floats column-major (INV_BIND)
     * @param heads       per joint its bone's rest head, bind space
     * @param tails       per joint its bone's rest tail
     * @param parents     per joint its parent joint, -1 for a root
     */
    public IndependentStbs(float[] inverseBind, double[][] heads, double[][] tails, int[] parents) {
        joints = parents.length;
        bindFrames = new double[joints][];
        for (int j = 0; j < joints; j++) {
            double[] m = new double[12];
            for (int r = 0; r < 3; r++) {
                for (int c = 0; c < 4; c++) {
                    m[4 * r + c] = inverseBind[16 * j + 4 * c + r];
                }
            }
            bindFrames[j] = invert(m);
        }
        this.heads = heads;
        this.tails = tails;
        this.parents = parents.clone();
        rigid = new double[joints][];
        posedHead = new double[joints][];
        posedAxis = new double[joints][];
        offset = new double[joints][];
        twist = new double[joints];
    }

    /** Sets the pose: per joint the skinning matrix, 12 floats row-major 3x4 at {@code 12 j}. */
    public void pose(float[] skinning) {
        double[][] m = new double[joints][12];
        for (int j = 0; j < joints; j++) {
            for (int c = 0; c < 12; c++) {
                m[j][c] = skinning[12 * j + c];
            }
            rigid[j] = rigidPart(m[j], bindFrames[j]);
            posedHead[j] = apply(m[j], heads[j]);
            double[] mt = apply(m[j], tails[j]);
            double[] dt = apply(rigid[j], tails[j]);
            offset[j] = sub(mt, dt);
            posedAxis[j] = linear(rigid[j], restAxis(j));
        }
        for (int j = 0; j < joints; j++) {
            int p = parents[j];
            twist[j] = p < 0 ? 0 : twistAngle(transposeTimes(rigid[p], rigid[j]), restAxis(j));
        }
    }

    /** The unit rest axis of joint j's bone; the bind frame's Y for a point-like bone. */
    private double[] restAxis(int j) {
        double[] a = sub(tails[j], heads[j]);
        double len = norm(a);
        if (len > 0) {
            return scale(a, 1 / len);
        }
        double[] b = polarRotation(bindFrames[j]);
        return normalize(new double[] {b[1], b[4], b[7]});
    }

    /** The endpoint weight of point p on joint j's bone. */
    public double endpointWeight(int j, double[] p) {
        double[] a = sub(tails[j], heads[j]);
        double l2 = dot(a, a);
        if (!(l2 > 0)) {
            return 1;
        }
        return Math.min(1, Math.max(0, dot(sub(p, heads[j]), a) / l2));
    }

    /** This pose's twist of joint j (radians), derived geometrically. */
    public double twist(int j) {
        return twist[j];
    }

    /** Joint j's transformation of rest point p, 3x4 row-major. */
    public double[] influence(int j, double[] p) {
        double e = endpointWeight(j, p);
        double[] rot = rotation(posedAxis[j], -(1 - e) * twist[j]);
        double[] h = posedHead[j];
        double[] d = rigid[j];
        double[] out = new double[12];
        double[] tr = new double[] {d[3] - h[0], d[7] - h[1], d[11] - h[2]};
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                out[4 * r + c] = rot[3 * r] * d[c] + rot[3 * r + 1] * d[4 + c] + rot[3 * r + 2] * d[8 + c];
            }
            out[4 * r + 3] = rot[3 * r] * tr[0] + rot[3 * r + 1] * tr[1] + rot[3 * r + 2] * tr[2] + h[r] + e * offset[j][r];
        }
        return out;
    }

    /**
     * Point p with normal n, influences {@code joints[k]}, {@code weights[k]} (the first the
     * heaviest): returns {x, y, z, nx, ny, nz}, the normal of unit length.
     */
    public double[] skin(double[] p, double[] n, int[] js, double[] ws, boolean dualQuaternions) {
        return dualQuaternions ? dqs(p, n, js, ws) : lbs(p, n, js, ws);
    }

    private double[] lbs(double[] p, double[] n, int[] js, double[] ws) {
        double[] b = new double[12];
        for (int k = 0; k < js.length; k++) {
            double[] t = influence(js[k], p);
            for (int c = 0; c < 12; c++) {
                b[c] += ws[k] * t[c];
            }
        }
        double[] c0 = cross(row(b, 1), row(b, 2));
        double[] c1 = cross(row(b, 2), row(b, 0));
        double[] c2 = cross(row(b, 0), row(b, 1));
        double[] normal = normalize(new double[] {dot(c0, n), dot(c1, n), dot(c2, n)});
        double[] q = apply(b, p);
        return new double[] {q[0], q[1], q[2], normal[0], normal[1], normal[2]};
    }

    private double[] dqs(double[] p, double[] n, int[] js, double[] ws) {
        double[] real = new double[4];
        double[] dual = new double[4];
        double[] pivot = null;
        for (int k = 0; k < js.length; k++) {
            double[] t = influence(js[k], p);
            double[] q = quaternion(t);
            if (pivot == null) {
                pivot = q;
            }
            double w = dot4(pivot, q) < 0 ? -ws[k] : ws[k];
            // dual = (translation, 0) q / 2
            double[] tq = multiply(new double[] {t[3], t[7], t[11], 0}, q);
            for (int c = 0; c < 4; c++) {
                real[c] += w * q[c];
                dual[c] += w * 0.5 * tq[c];
            }
        }
        double len = Math.sqrt(dot4(real, real));
        for (int c = 0; c < 4; c++) {
            real[c] /= len;
            dual[c] /= len;
        }
        // translation = 2 dual conj(real)
        double[] tr = multiply(dual, new double[] {-real[0], -real[1], -real[2], real[3]});
        double[] r = rotationMatrix(real);
        double[] q = new double[3];
        double[] normal = new double[3];
        for (int i = 0; i < 3; i++) {
            q[i] = r[3 * i] * p[0] + r[3 * i + 1] * p[1] + r[3 * i + 2] * p[2] + 2 * tr[i];
            normal[i] = r[3 * i] * n[0] + r[3 * i + 1] * n[1] + r[3 * i + 2] * n[2];
        }
        normal = normalize(normal);
        return new double[] {q[0], q[1], q[2], normal[0], normal[1], normal[2]};
    }

    /** D = [R | x] B^-1 with X = M B, R X's frame with its Y axis kept (see the class comment). */
    static double[] rigidPart(double[] m, double[] bindFrame) {
        double[] br = polarRotation(bindFrame);
        double[] b = new double[] {br[0], br[1], br[2], bindFrame[3], br[3], br[4], br[5], bindFrame[7], br[6], br[7],
            br[8], bindFrame[11]};
        double[] x = compose(m, b);
        double[] y = normalize(new double[] {x[1], x[5], x[9]});
        double[] z = normalize(cross(new double[] {x[0], x[4], x[8]}, y));
        double[] xx = cross(y, z);
        double[] rx = new double[] {xx[0], y[0], z[0], x[3], xx[1], y[1], z[1], x[7], xx[2], y[2], z[2], x[11]};
        return compose(rx, invert(b));
    }

    /** The rotation of a 3x4 matrix's linear part by Higham's iteration R = (R + R^-T) / 2. */
    static double[] polarRotation(double[] m) {
        double[] r = new double[] {m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]};
        for (int it = 0; it < 100; it++) {
            double[] inv = invert3(r);
            double change = 0;
            for (int i = 0; i < 3; i++) {
                for (int j = 0; j < 3; j++) {
                    double v = 0.5 * (r[3 * i + j] + inv[3 * j + i]);
                    change = Math.max(change, Math.abs(v - r[3 * i + j]));
                    r[3 * i + j] = v;
                }
            }
            if (change < 1e-15) {
                break;
            }
        }
        return r;
    }

    /** The twist of rotation q (3x3 row-major) about unit axis a, by the least swing back onto a. */
    static double twistAngle(double[] q, double[] a) {
        double[] u = normalize(cross(a, Math.abs(a[0]) < 0.9 ? new double[] {1, 0, 0} : new double[] {0, 1, 0}));
        double[] qa = times3(q, a);
        double[] qu = times3(q, u);
        double[] axis = cross(qa, a);
        double s = norm(axis);
        double c = dot(qa, a);
        if (s > 1e-15) {
            qu = times3(rotation(scale(axis, 1 / s), Math.atan2(s, c)), qu);
        }
        return Math.atan2(dot(cross(u, qu), a), dot(u, qu));
    }

    /** Rodrigues: the rotation by {@code angle} about unit axis a, 3x3 row-major. */
    static double[] rotation(double[] a, double angle) {
        double c = Math.cos(angle);
        double s = Math.sin(angle);
        double t = 1 - c;
        return new double[] {
            c + t * a[0] * a[0], t * a[0] * a[1] - s * a[2], t * a[0] * a[2] + s * a[1],
            t * a[0] * a[1] + s * a[2], c + t * a[1] * a[1], t * a[1] * a[2] - s * a[0],
            t * a[0] * a[2] - s * a[1], t * a[1] * a[2] + s * a[0], c + t * a[2] * a[2]};
    }

    /** The unit quaternion (x y z w) of a 3x4 matrix's rotation, from its largest component. */
    static double[] quaternion(double[] m) {
        double m00 = m[0], m11 = m[5], m22 = m[10];
        double w2 = 1 + m00 + m11 + m22;
        double x2 = 1 + m00 - m11 - m22;
        double y2 = 1 - m00 + m11 - m22;
        double z2 = 1 - m00 - m11 + m22;
        double[] q = new double[4];
        if (w2 >= x2 && w2 >= y2 && w2 >= z2) {
            double w = 0.5 * Math.sqrt(w2);
            q = new double[] {(m[9] - m[6]) / (4 * w), (m[2] - m[8]) / (4 * w), (m[4] - m[1]) / (4 * w), w};
        } else if (x2 >= y2 && x2 >= z2) {
            double x = 0.5 * Math.sqrt(x2);
            q = new double[] {x, (m[1] + m[4]) / (4 * x), (m[2] + m[8]) / (4 * x), (m[9] - m[6]) / (4 * x)};
        } else if (y2 >= z2) {
            double y = 0.5 * Math.sqrt(y2);
            q = new double[] {(m[1] + m[4]) / (4 * y), y, (m[6] + m[9]) / (4 * y), (m[2] - m[8]) / (4 * y)};
        } else {
            double z = 0.5 * Math.sqrt(z2);
            q = new double[] {(m[2] + m[8]) / (4 * z), (m[6] + m[9]) / (4 * z), z, (m[4] - m[1]) / (4 * z)};
        }
        double len = Math.sqrt(dot4(q, q));
        for (int c = 0; c < 4; c++) {
            q[c] /= len;
        }
        return q;
    }

    static double[] rotationMatrix(double[] q) {
        double x = q[0], y = q[1], z = q[2], w = q[3];
        return new double[] {
            1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w),
            2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w),
            2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)};
    }

    /** Hamilton product of quaternions (x y z w). */
    static double[] multiply(double[] a, double[] b) {
        return new double[] {
            a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
            a[3] * b[1] + a[1] * b[3] + a[2] * b[0] - a[0] * b[2],
            a[3] * b[2] + a[2] * b[3] + a[0] * b[1] - a[1] * b[0],
            a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2]};
    }

    /** a b for 3x4 affine matrices. */
    static double[] compose(double[] a, double[] b) {
        double[] out = new double[12];
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 4; c++) {
                double v = a[4 * r] * b[c] + a[4 * r + 1] * b[4 + c] + a[4 * r + 2] * b[8 + c];
                out[4 * r + c] = c == 3 ? v + a[4 * r + 3] : v;
            }
        }
        return out;
    }

    /** The linear part of a^T b for 3x4 matrices with orthonormal linear parts, 3x3. */
    static double[] transposeTimes(double[] a, double[] b) {
        double[] out = new double[9];
        for (int r = 0; r < 3; r++) {
            for (int c = 0; c < 3; c++) {
                out[3 * r + c] = a[r] * b[c] + a[4 + r] * b[4 + c] + a[8 + r] * b[8 + c];
            }
        }
        return out;
    }

    static double[] invert(double[] m) {
        double[] l = invert3(new double[] {m[0], m[1], m[2], m[4], m[5], m[6], m[8], m[9], m[10]});
        double[] out = new double[12];
        for (int r = 0; r < 3; r++) {
            out[4 * r] = l[3 * r];
            out[4 * r + 1] = l[3 * r + 1];
            out[4 * r + 2] = l[3 * r + 2];
            out[4 * r + 3] = -(l[3 * r] * m[3] + l[3 * r + 1] * m[7] + l[3 * r + 2] * m[11]);
        }
        return out;
    }

    static double[] invert3(double[] a) {
        double c00 = a[4] * a[8] - a[5] * a[7];
        double c01 = a[5] * a[6] - a[3] * a[8];
        double c02 = a[3] * a[7] - a[4] * a[6];
        double det = a[0] * c00 + a[1] * c01 + a[2] * c02;
        return new double[] {
            c00 / det, (a[2] * a[7] - a[1] * a[8]) / det, (a[1] * a[5] - a[2] * a[4]) / det,
            c01 / det, (a[0] * a[8] - a[2] * a[6]) / det, (a[2] * a[3] - a[0] * a[5]) / det,
            c02 / det, (a[1] * a[6] - a[0] * a[7]) / det, (a[0] * a[4] - a[1] * a[3]) / det};
    }

    static double[] apply(double[] m, double[] p) {
        return new double[] {
            m[0] * p[0] + m[1] * p[1] + m[2] * p[2] + m[3],
            m[4] * p[0] + m[5] * p[1] + m[6] * p[2] + m[7],
            m[8] * p[0] + m[9] * p[1] + m[10] * p[2] + m[11]};
    }

    static double[] linear(double[] m, double[] v) {
        return new double[] {
            m[0] * v[0] + m[1] * v[1] + m[2] * v[2],
            m[4] * v[0] + m[5] * v[1] + m[6] * v[2],
            m[8] * v[0] + m[9] * v[1] + m[10] * v[2]};
    }

    static double[] times3(double[] m, double[] v) {
        return new double[] {
            m[0] * v[0] + m[1] * v[1] + m[2] * v[2],
            m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
            m[6] * v[0] + m[7] * v[1] + m[8] * v[2]};
    }

    static double[] row(double[] m, int r) {
        return new double[] {m[4 * r], m[4 * r + 1], m[4 * r + 2]};
    }

    static double[] sub(double[] a, double[] b) {
        return new double[] {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    }

    static double[] scale(double[] a, double s) {
        return new double[] {a[0] * s, a[1] * s, a[2] * s};
    }

    static double dot(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    }

    static double dot4(double[] a, double[] b) {
        return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
    }

    static double[] cross(double[] a, double[] b) {
        return new double[] {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    }

    static double norm(double[] a) {
        return Math.sqrt(dot(a, a));
    }

    static double[] normalize(double[] a) {
        double n = norm(a);
        return n > 0 ? scale(a, 1 / n) : a;
    }
}
