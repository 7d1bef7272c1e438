package org.skinlab.simd;

import static org.skinlab.simd.Lanes.S;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;

import org.skinlab.skinning.JointPalette;

/**
 * The passes of {@link VectorSplineSkinner}, the formulas of
 * {@link org.skinlab.skinning.ScalarSplineSkinner} on 8 lanes (one point each). The passes meet
 * in a per-thread scratch array {@code acc} of 8-float rows and take no vector arguments: C2 does
 * not inline large methods, and a vector handed to a method that is not inlined is boxed. Each
 * lane's curve data comes from a per-call table of one 32-float record per curve (copied into
 * the lanes by plain loads: gathers are slow and, on JDK 17, not inlined either).
 */
final class SplineLanes {
    private static final int L = 8;
    /** Floats per record of the curve table ({@link #curveTable}). */
    static final int RECORD = 32;
    /** Rows of {@code acc}: 0..11 the sums (p x y z, the normal matrix row-major), 12..20 a frame F. */
    private static final int FRAME = 12;
    /** 32 rows: one record per lane (or a rigid joint's matrix, 12 rows). */
    private static final int DATA = 21;
    /** f(x) 3, l 3, posed tangent 3, rest tangent 3, Q 4. */
    private static final int CURVE = DATA + RECORD;
    private static final int OFFSET = CURVE + 3;
    private static final int TANGENT = CURVE + 6;
    private static final int REST_TANGENT = CURVE + 9;
    private static final int SLERP = CURVE + 12;
    /** With joint scale: the two joints' scale parts (linear, row-major), then K (S(x) or its cofactor). */
    private static final int SCALES = SLERP + 4;
    private static final int NORMAL_SCALE = SCALES + 18;
    /** Rows of {@code acc} in all. */
    static final int ROWS = NORMAL_SCALE + 9;
    /** Where each linear element of a row-major 3x4 matrix lies. */
    private static final int[] LINEAR = {0, 1, 2, 4, 5, 6, 8, 9, 10};

    private SplineLanes() {
    }

    /**
     * Per joint with a curve across it, this frame's record: posed p2, D12, D23 (0..8), rest ones
     * (9..17), the parent's rotation and the joint's with its sign aligned (18..25), the angle
     * between them (26), 1 / its sine (27, 0 when they are within 0.9999 of each other, where the
     * slerp is a lerp). Record {@code joints} is neutral (identity rotations, zero curve) for lanes
     * without a curve. The arccos is the scalar kernel's polynomial.
     */
    static void curveTable(float[] rows, float[] dq, int[] parents, float[] table) {
        int joints = parents.length;
        for (int c = 0; c < joints; c++) {
            int p = parents[c];
            if (p < 0) {
                continue;
            }
            int r = RECORD * c;
            int b = JointPalette.BONE_FLOATS * c;
            int a = JointPalette.BONE_FLOATS * p;
            for (int e = 0; e < 3; e++) {
                table[r + e] = rows[b + e];
                table[r + 3 + e] = rows[b + e] - 0.5f * (rows[a + e] + rows[a + 4 + e]);
                table[r + 6 + e] = 0.5f * (rows[b + 4 + e] - rows[b + e]);
                table[r + 9 + e] = rows[b + 16 + e];
                table[r + 12 + e] = rows[b + 16 + e] - 0.5f * (rows[a + 16 + e] + rows[a + 20 + e]);
                table[r + 15 + e] = 0.5f * (rows[b + 20 + e] - rows[b + 16 + e]);
            }
            float cos = 0f;
            for (int e = 0; e < 4; e++) {
                cos += dq[8 * p + e] * dq[8 * c + e];
            }
            float sign = cos < 0f ? -1f : 1f;
            cos *= sign;
            for (int e = 0; e < 4; e++) {
                table[r + 18 + e] = dq[8 * p + e];
                table[r + 22 + e] = sign * dq[8 * c + e];
            }
            boolean near = cos > 0.9999f;
            float angle = near ? 0f : acos(Math.min(cos, 1f));
            table[r + 26] = angle;
            table[r + 27] = near ? 0f : 1f / (float) Math.sqrt(1f - cos * cos);
        }
        int n = RECORD * joints;
        java.util.Arrays.fill(table, n, n + RECORD, 0f);
        table[n + 21] = 1f;
        table[n + 25] = 1f;
    }

    /** The scalar kernel's arccos (Abramowitz and Stegun 4.4.46), for the table. */
    private static float acos(float c) {
        float poly = -0.0012624911f;
        poly = poly * c + 0.0066700901f;
        poly = poly * c - 0.0170881256f;
        poly = poly * c + 0.0308918810f;
        poly = poly * c - 0.0501743046f;
        poly = poly * c + 0.0889789874f;
        poly = poly * c - 0.2145988016f;
        poly = poly * c + 1.5707963050f;
        return (float) Math.sqrt(1f - c) * poly;
    }

    /** Copies {@code fields} floats of each lane's record (at {@code index[lanes + l]}) into rows DATA... */
    static void load(float[] table, int[] index, int lanes, int fields, float[] acc) {
        loadInto(table, index, lanes, fields, DATA, acc);
    }

    /** Copies the lanes' scale records ({@link #scaleTable}, same offsets as the curve records). */
    static void loadScales(float[] table, int[] index, int lanes, float[] acc) {
        loadInto(table, index, lanes, 18, SCALES, acc);
    }

    private static void loadInto(float[] table, int[] index, int lanes, int fields, int row, float[] acc) {
        for (int l = 0; l < L; l++) {
            int r = index[lanes + l];
            for (int f = 0; f < fields; f++) {
                acc[L * (row + f) + l] = table[r + f];
            }
        }
    }

    /**
     * With joint scale, per joint with a curve: the linear parts of its parent's and its own scale
     * part (row-major, 0..8 and 9..17 of a {@link #RECORD}-float record); the neutral record has
     * identities.
     */
    static void scaleTable(float[] scales, int[] parents, float[] table) {
        int joints = parents.length;
        for (int c = 0; c < joints; c++) {
            int p = parents[c];
            if (p < 0) {
                continue;
            }
            for (int e = 0; e < 9; e++) {
                table[RECORD * c + e] = scales[12 * p + LINEAR[e]];
                table[RECORD * c + 9 + e] = scales[12 * c + LINEAR[e]];
            }
        }
        int n = RECORD * joints;
        java.util.Arrays.fill(table, n, n + RECORD, 0f);
        for (int e = 0; e < 3; e++) {
            table[n + 4 * e] = 1f;
            table[n + 9 + 4 * e] = 1f;
        }
    }

    /**
     * With joint scale: {@code S(x) = (1 - x) S_p + x S_c}; the offset becomes {@code S(x) l} and K
     * is S(x)'s cofactor times the sign of its determinant (exact normals) or S(x).
     */
    static void scale(float[] par, int po, boolean exact, float[] acc) {
        FloatVector x = FloatVector.fromArray(S, par, po);
        FloatVector y = x.neg().add(1f);
        FloatVector s0 = FloatVector.fromArray(S, acc, L * (SCALES + 0)).mul(y)
                .add(FloatVector.fromArray(S, acc, L * (SCALES + 9)).mul(x));
        FloatVector s1 = FloatVector.fromArray(S, acc, L * (SCALES + 1)).mul(y)
                .add(FloatVector.fromArray(S, acc, L * (SCALES + 10)).mul(x));
        FloatVector s2 = FloatVector.fromArray(S, acc, L * (SCALES + 2)).mul(y)
                .add(FloatVector.fromArray(S, acc, L * (SCALES + 11)).mul(x));
        FloatVector s3 = FloatVector.fromArray(S, acc, L * (SCALES + 3)).mul(y)
                .add(FloatVector.fromArray(S, acc, L * (SCALES + 12)).mul(x));
        FloatVector s4 = FloatVector.fromArray(S, acc, L * (SCALES + 4)).mul(y)
                .add(FloatVector.fromArray(S, acc, L * (SCALES + 13)).mul(x));
        FloatVector s5 = FloatVector.fromArray(S, acc, L * (SCALES + 5)).mul(y)
                .add(FloatVector.fromArray(S, acc, L * (SCALES + 14)).mul(x));
        FloatVector s6 = FloatVector.fromArray(S, acc, L * (SCALES + 6)).mul(y)
                .add(FloatVector.fromArray(S, acc, L * (SCALES + 15)).mul(x));
        FloatVector s7 = FloatVector.fromArray(S, acc, L * (SCALES + 7)).mul(y)
                .add(FloatVector.fromArray(S, acc, L * (SCALES + 16)).mul(x));
        FloatVector s8 = FloatVector.fromArray(S, acc, L * (SCALES + 8)).mul(y)
                .add(FloatVector.fromArray(S, acc, L * (SCALES + 17)).mul(x));
        FloatVector lx = FloatVector.fromArray(S, acc, L * OFFSET);
        FloatVector ly = FloatVector.fromArray(S, acc, L * (OFFSET + 1));
        FloatVector lz = FloatVector.fromArray(S, acc, L * (OFFSET + 2));
        s0.fma(lx, s1.fma(ly, s2.mul(lz))).intoArray(acc, L * OFFSET);
        s3.fma(lx, s4.fma(ly, s5.mul(lz))).intoArray(acc, L * (OFFSET + 1));
        s6.fma(lx, s7.fma(ly, s8.mul(lz))).intoArray(acc, L * (OFFSET + 2));
        if (exact) {
            FloatVector k0 = s4.mul(s8).sub(s7.mul(s5));
            FloatVector k1 = s5.mul(s6).sub(s8.mul(s3));
            FloatVector k2 = s3.mul(s7).sub(s6.mul(s4));
            FloatVector sign = FloatVector.broadcast(S, 1f)
                    .blend(-1f, s0.mul(k0).add(s1.mul(k1)).add(s2.mul(k2)).compare(VectorOperators.LT, 0f));
            k0.mul(sign).intoArray(acc, L * NORMAL_SCALE);
            k1.mul(sign).intoArray(acc, L * (NORMAL_SCALE + 1));
            k2.mul(sign).intoArray(acc, L * (NORMAL_SCALE + 2));
            s7.mul(s2).sub(s1.mul(s8)).mul(sign).intoArray(acc, L * (NORMAL_SCALE + 3));
            s8.mul(s0).sub(s2.mul(s6)).mul(sign).intoArray(acc, L * (NORMAL_SCALE + 4));
            s6.mul(s1).sub(s0.mul(s7)).mul(sign).intoArray(acc, L * (NORMAL_SCALE + 5));
            s1.mul(s5).sub(s4.mul(s2)).mul(sign).intoArray(acc, L * (NORMAL_SCALE + 6));
            s2.mul(s3).sub(s5.mul(s0)).mul(sign).intoArray(acc, L * (NORMAL_SCALE + 7));
            s0.mul(s4).sub(s3.mul(s1)).mul(sign).intoArray(acc, L * (NORMAL_SCALE + 8));
            return;
        }
        s0.intoArray(acc, L * NORMAL_SCALE);
        s1.intoArray(acc, L * (NORMAL_SCALE + 1));
        s2.intoArray(acc, L * (NORMAL_SCALE + 2));
        s3.intoArray(acc, L * (NORMAL_SCALE + 3));
        s4.intoArray(acc, L * (NORMAL_SCALE + 4));
        s5.intoArray(acc, L * (NORMAL_SCALE + 5));
        s6.intoArray(acc, L * (NORMAL_SCALE + 6));
        s7.intoArray(acc, L * (NORMAL_SCALE + 7));
        s8.intoArray(acc, L * (NORMAL_SCALE + 8));
    }

    /** Adds w M p and w N (M's linear part or its cofactor) for matrices loaded by {@link #load}. */
    static void addRigid(float[] weights, int lanes, float[] points, int pb, boolean exact, float[] acc) {
        FloatVector px = FloatVector.fromArray(S, points, pb);
        FloatVector py = FloatVector.fromArray(S, points, pb + L);
        FloatVector pz = FloatVector.fromArray(S, points, pb + 2 * L);
        FloatVector w = FloatVector.fromArray(S, weights, lanes);
        FloatVector a0 = FloatVector.fromArray(S, acc, L * DATA);
        FloatVector a1 = FloatVector.fromArray(S, acc, L * (DATA + 1));
        FloatVector a2 = FloatVector.fromArray(S, acc, L * (DATA + 2));
        FloatVector a3 = FloatVector.fromArray(S, acc, L * (DATA + 4));
        FloatVector a4 = FloatVector.fromArray(S, acc, L * (DATA + 5));
        FloatVector a5 = FloatVector.fromArray(S, acc, L * (DATA + 6));
        FloatVector a6 = FloatVector.fromArray(S, acc, L * (DATA + 8));
        FloatVector a7 = FloatVector.fromArray(S, acc, L * (DATA + 9));
        FloatVector a8 = FloatVector.fromArray(S, acc, L * (DATA + 10));
        FloatVector t0 = FloatVector.fromArray(S, acc, L * (DATA + 3));
        FloatVector t1 = FloatVector.fromArray(S, acc, L * (DATA + 7));
        FloatVector t2 = FloatVector.fromArray(S, acc, L * (DATA + 11));
        w.fma(a0.fma(px, a1.fma(py, a2.fma(pz, t0))), FloatVector.fromArray(S, acc, 0))
                .intoArray(acc, 0);
        w.fma(a3.fma(px, a4.fma(py, a5.fma(pz, t1))), FloatVector.fromArray(S, acc, 8))
                .intoArray(acc, L);
        w.fma(a6.fma(px, a7.fma(py, a8.fma(pz, t2))), FloatVector.fromArray(S, acc, 16))
                .intoArray(acc, 2 * L);
        if (exact) {
            FloatVector k0 = a4.mul(a8).sub(a7.mul(a5));
            FloatVector k1 = a5.mul(a6).sub(a8.mul(a3));
            FloatVector k2 = a3.mul(a7).sub(a6.mul(a4));
            FloatVector k3 = a7.mul(a2).sub(a1.mul(a8));
            FloatVector k4 = a8.mul(a0).sub(a2.mul(a6));
            FloatVector k5 = a6.mul(a1).sub(a0.mul(a7));
            FloatVector k6 = a1.mul(a5).sub(a4.mul(a2));
            FloatVector k7 = a2.mul(a3).sub(a5.mul(a0));
            FloatVector k8 = a0.mul(a4).sub(a3.mul(a1));
            a0 = k0;
            a1 = k1;
            a2 = k2;
            a3 = k3;
            a4 = k4;
            a5 = k5;
            a6 = k6;
            a7 = k7;
            a8 = k8;
        }
        w.fma(a0, FloatVector.fromArray(S, acc, 24)).intoArray(acc, 3 * L);
        w.fma(a1, FloatVector.fromArray(S, acc, 32)).intoArray(acc, 4 * L);
        w.fma(a2, FloatVector.fromArray(S, acc, 40)).intoArray(acc, 5 * L);
        w.fma(a3, FloatVector.fromArray(S, acc, 48)).intoArray(acc, 6 * L);
        w.fma(a4, FloatVector.fromArray(S, acc, 56)).intoArray(acc, 7 * L);
        w.fma(a5, FloatVector.fromArray(S, acc, 64)).intoArray(acc, 8 * L);
        w.fma(a6, FloatVector.fromArray(S, acc, 72)).intoArray(acc, 9 * L);
        w.fma(a7, FloatVector.fromArray(S, acc, 80)).intoArray(acc, 10 * L);
        w.fma(a8, FloatVector.fromArray(S, acc, 88)).intoArray(acc, 11 * L);
    }

    /** f(x), the offset l = p - f0(x) and both tangents, from the records and the binding's powers. */
    static void curve(float[] par, int po, float[] points, int pb, float[] acc) {
        FloatVector b1 = FloatVector.fromArray(S, par, po + L);
        FloatVector b2 = FloatVector.fromArray(S, par, po + 2 * L);
        FloatVector d1 = FloatVector.fromArray(S, par, po + 3 * L);
        FloatVector d2 = FloatVector.fromArray(S, par, po + 4 * L);
        FloatVector c1 = b1.neg().add(1f);
        for (int e = 0; e < 3; e++) {
            FloatVector p2 = FloatVector.fromArray(S, acc, L * (DATA + e));
            FloatVector e12 = FloatVector.fromArray(S, acc, L * (DATA + 3 + e));
            FloatVector e23 = FloatVector.fromArray(S, acc, L * (DATA + 6 + e));
            FloatVector r2 = FloatVector.fromArray(S, acc, L * (DATA + 9 + e));
            FloatVector g12 = FloatVector.fromArray(S, acc, L * (DATA + 12 + e));
            FloatVector g23 = FloatVector.fromArray(S, acc, L * (DATA + 15 + e));
            e23.fma(b2, p2.sub(e12.mul(c1))).intoArray(acc, L * (CURVE + e));
            FloatVector p = FloatVector.fromArray(S, points, pb + L * e);
            p.sub(g23.fma(b2, r2.sub(g12.mul(c1)))).intoArray(acc, L * (OFFSET + e));
            e12.fma(d1, e23.mul(d2)).intoArray(acc, L * (TANGENT + e));
            g12.fma(d1, g23.mul(d2)).intoArray(acc, L * (REST_TANGENT + e));
        }
    }

    /** Q = slerp of the records' rotations by x, normalised. */
    static void slerp(float[] par, int po, float[] acc) {
        FloatVector x = FloatVector.fromArray(S, par, po);
        FloatVector angle = FloatVector.fromArray(S, acc, L * (DATA + 26));
        FloatVector invSin = FloatVector.fromArray(S, acc, L * (DATA + 27));
        VectorMask<Float> near = invSin.compare(VectorOperators.EQ, 0f);
        FloatVector y = x.neg().add(1f);
        // sin by its Taylor series to y^11 (angles of a slerp lie in [0, pi/2]: error below 4e-8),
        // written out twice: a call would box its vectors.
        FloatVector a = y.mul(angle);
        FloatVector a2 = a.mul(a);
        FloatVector sa = a2.fma(-1f / 39916800f, 1f / 362880f);
        sa = sa.fma(a2, FloatVector.broadcast(S, -1f / 5040f));
        sa = sa.fma(a2, FloatVector.broadcast(S, 1f / 120f));
        sa = sa.fma(a2, FloatVector.broadcast(S, -1f / 6f));
        sa = sa.fma(a2, FloatVector.broadcast(S, 1f)).mul(a);
        FloatVector b = x.mul(angle);
        FloatVector b2 = b.mul(b);
        FloatVector sb = b2.fma(-1f / 39916800f, 1f / 362880f);
        sb = sb.fma(b2, FloatVector.broadcast(S, -1f / 5040f));
        sb = sb.fma(b2, FloatVector.broadcast(S, 1f / 120f));
        sb = sb.fma(b2, FloatVector.broadcast(S, -1f / 6f));
        sb = sb.fma(b2, FloatVector.broadcast(S, 1f)).mul(b);
        FloatVector s0 = sa.mul(invSin).blend(y, near);
        FloatVector s1 = sb.mul(invSin).blend(x, near);
        FloatVector qx = s0.mul(FloatVector.fromArray(S, acc, L * (DATA + 18)))
                .add(s1.mul(FloatVector.fromArray(S, acc, L * (DATA + 22))));
        FloatVector qy = s0.mul(FloatVector.fromArray(S, acc, L * (DATA + 19)))
                .add(s1.mul(FloatVector.fromArray(S, acc, L * (DATA + 23))));
        FloatVector qz = s0.mul(FloatVector.fromArray(S, acc, L * (DATA + 20)))
                .add(s1.mul(FloatVector.fromArray(S, acc, L * (DATA + 24))));
        FloatVector qw = s0.mul(FloatVector.fromArray(S, acc, L * (DATA + 21)))
                .add(s1.mul(FloatVector.fromArray(S, acc, L * (DATA + 25))));
        FloatVector inv = FloatVector.broadcast(S, 1f)
                .div(qx.mul(qx).add(qy.mul(qy)).add(qz.mul(qz)).add(qw.mul(qw)).sqrt());
        qx.mul(inv).intoArray(acc, L * SLERP);
        qy.mul(inv).intoArray(acc, L * (SLERP + 1));
        qz.mul(inv).intoArray(acc, L * (SLERP + 2));
        qw.mul(inv).intoArray(acc, L * (SLERP + 3));
    }

    /** F = T Q (T the minimal rotation from Q u to t) as a row-major matrix into rows FRAME... */
    static void frame(float[] acc) {
        FloatVector qx = FloatVector.fromArray(S, acc, L * SLERP);
        FloatVector qy = FloatVector.fromArray(S, acc, L * (SLERP + 1));
        FloatVector qz = FloatVector.fromArray(S, acc, L * (SLERP + 2));
        FloatVector qw = FloatVector.fromArray(S, acc, L * (SLERP + 3));
        FloatVector ux = FloatVector.fromArray(S, acc, L * REST_TANGENT);
        FloatVector uy = FloatVector.fromArray(S, acc, L * (REST_TANGENT + 1));
        FloatVector uz = FloatVector.fromArray(S, acc, L * (REST_TANGENT + 2));
        FloatVector tx = FloatVector.fromArray(S, acc, L * TANGENT);
        FloatVector ty = FloatVector.fromArray(S, acc, L * (TANGENT + 1));
        FloatVector tz = FloatVector.fromArray(S, acc, L * (TANGENT + 2));
        FloatVector cx = qy.mul(uz).sub(qz.mul(uy)).add(qw.mul(ux));
        FloatVector cy = qz.mul(ux).sub(qx.mul(uz)).add(qw.mul(uy));
        FloatVector cz = qx.mul(uy).sub(qy.mul(ux)).add(qw.mul(uz));
        FloatVector vx = qy.mul(cz).sub(qz.mul(cy)).mul(2f).add(ux);
        FloatVector vy = qz.mul(cx).sub(qx.mul(cz)).mul(2f).add(uy);
        FloatVector vz = qx.mul(cy).sub(qy.mul(cx)).mul(2f).add(uz);
        FloatVector vl = vx.mul(vx).add(vy.mul(vy)).add(vz.mul(vz)).mul(tx.mul(tx).add(ty.mul(ty)).add(tz.mul(tz)))
                .sqrt();
        FloatVector mw = vl.add(vx.mul(tx)).add(vy.mul(ty)).add(vz.mul(tz));
        FloatVector mx = vy.mul(tz).sub(vz.mul(ty)), my = vz.mul(tx).sub(vx.mul(tz)), mz = vx.mul(ty).sub(vy.mul(tx));
        FloatVector ml2 = mw.mul(mw).add(mx.mul(mx)).add(my.mul(my)).add(mz.mul(mz));
        VectorMask<Float> undefined = mw.compare(VectorOperators.GT, vl.mul(1e-6f))
                .and(ml2.compare(VectorOperators.GT, 0f)).not();
        FloatVector ml = FloatVector.broadcast(S, 1f).div(ml2.blend(1f, undefined).sqrt());
        mw = mw.mul(ml).blend(1f, undefined);
        mx = mx.mul(ml).blend(0f, undefined);
        my = my.mul(ml).blend(0f, undefined);
        mz = mz.mul(ml).blend(0f, undefined);
        FloatVector fx = mw.mul(qx).add(mx.mul(qw)).add(my.mul(qz)).sub(mz.mul(qy));
        FloatVector fy = mw.mul(qy).add(my.mul(qw)).add(mz.mul(qx)).sub(mx.mul(qz));
        FloatVector fz = mw.mul(qz).add(mz.mul(qw)).add(mx.mul(qy)).sub(my.mul(qx));
        FloatVector fw = mw.mul(qw).sub(mx.mul(qx)).sub(my.mul(qy)).sub(mz.mul(qz));
        FloatVector xx = fx.mul(fx), yy = fy.mul(fy), zz = fz.mul(fz);
        FloatVector xy = fx.mul(fy), xz = fx.mul(fz), yz = fy.mul(fz);
        FloatVector wx = fw.mul(fx), wy = fw.mul(fy), wz = fw.mul(fz);
        yy.add(zz).mul(-2f).add(1f).intoArray(acc, L * FRAME);
        xy.sub(wz).mul(2f).intoArray(acc, L * (FRAME + 1));
        xz.add(wy).mul(2f).intoArray(acc, L * (FRAME + 2));
        xy.add(wz).mul(2f).intoArray(acc, L * (FRAME + 3));
        xx.add(zz).mul(-2f).add(1f).intoArray(acc, L * (FRAME + 4));
        yz.sub(wx).mul(2f).intoArray(acc, L * (FRAME + 5));
        xz.sub(wy).mul(2f).intoArray(acc, L * (FRAME + 6));
        yz.add(wx).mul(2f).intoArray(acc, L * (FRAME + 7));
        xx.add(yy).mul(-2f).add(1f).intoArray(acc, L * (FRAME + 8));
    }

    /** With joint scale: adds w (f + F l) (l already through S(x)) and w F K to the sums. */
    static void accumulateScaled(float[] weights, int lanes, float[] acc) {
        FloatVector w = FloatVector.fromArray(S, weights, lanes);
        FloatVector lx = FloatVector.fromArray(S, acc, L * OFFSET);
        FloatVector ly = FloatVector.fromArray(S, acc, L * (OFFSET + 1));
        FloatVector lz = FloatVector.fromArray(S, acc, L * (OFFSET + 2));
        for (int r = 0; r < 3; r++) {
            FloatVector f0 = FloatVector.fromArray(S, acc, L * (FRAME + 3 * r));
            FloatVector f1 = FloatVector.fromArray(S, acc, L * (FRAME + 3 * r + 1));
            FloatVector f2 = FloatVector.fromArray(S, acc, L * (FRAME + 3 * r + 2));
            FloatVector f = FloatVector.fromArray(S, acc, L * (CURVE + r));
            w.fma(f0.fma(lx, f1.fma(ly, f2.fma(lz, f))), FloatVector.fromArray(S, acc, L * r))
                    .intoArray(acc, L * r);
            for (int c = 0; c < 3; c++) {
                FloatVector k0 = FloatVector.fromArray(S, acc, L * (NORMAL_SCALE + c));
                FloatVector k1 = FloatVector.fromArray(S, acc, L * (NORMAL_SCALE + 3 + c));
                FloatVector k2 = FloatVector.fromArray(S, acc, L * (NORMAL_SCALE + 6 + c));
                int n = L * (3 + 3 * r + c);
                w.fma(f0.fma(k0, f1.fma(k1, f2.mul(k2))), FloatVector.fromArray(S, acc, n)).intoArray(acc, n);
            }
        }
    }

    /** Adds w (f + F l) and w F to the sums. */
    static void accumulate(float[] weights, int lanes, float[] acc) {
        FloatVector w = FloatVector.fromArray(S, weights, lanes);
        FloatVector lx = FloatVector.fromArray(S, acc, L * OFFSET);
        FloatVector ly = FloatVector.fromArray(S, acc, L * (OFFSET + 1));
        FloatVector lz = FloatVector.fromArray(S, acc, L * (OFFSET + 2));
        for (int r = 0; r < 3; r++) {
            FloatVector f0 = FloatVector.fromArray(S, acc, L * (FRAME + 3 * r));
            FloatVector f1 = FloatVector.fromArray(S, acc, L * (FRAME + 3 * r + 1));
            FloatVector f2 = FloatVector.fromArray(S, acc, L * (FRAME + 3 * r + 2));
            FloatVector f = FloatVector.fromArray(S, acc, L * (CURVE + r));
            w.fma(f0.fma(lx, f1.fma(ly, f2.fma(lz, f))), FloatVector.fromArray(S, acc, L * r))
                    .intoArray(acc, L * r);
            w.fma(f0, FloatVector.fromArray(S, acc, L * (3 + 3 * r))).intoArray(acc, L * (3 + 3 * r));
            w.fma(f1, FloatVector.fromArray(S, acc, L * (4 + 3 * r))).intoArray(acc, L * (4 + 3 * r));
            w.fma(f2, FloatVector.fromArray(S, acc, L * (5 + 3 * r))).intoArray(acc, L * (5 + 3 * r));
        }
    }

    /**
     * The normals (the sums' matrix times the rest normal, renormalised under exact normals), and
     * positions and normals stored interleaved.
     */
    static void store(float[] points, int pb, boolean exact, float[] acc, float[] outPositions, float[] outNormals,
            int o) {
        FloatVector nx = FloatVector.fromArray(S, points, pb + 3 * L);
        FloatVector ny = FloatVector.fromArray(S, points, pb + 4 * L);
        FloatVector nz = FloatVector.fromArray(S, points, pb + 5 * L);
        FloatVector mx = FloatVector.fromArray(S, acc, 24).mul(nx).add(FloatVector.fromArray(S, acc, 32).mul(ny))
                .add(FloatVector.fromArray(S, acc, 40).mul(nz));
        FloatVector my = FloatVector.fromArray(S, acc, 48).mul(nx).add(FloatVector.fromArray(S, acc, 56).mul(ny))
                .add(FloatVector.fromArray(S, acc, 64).mul(nz));
        FloatVector mz = FloatVector.fromArray(S, acc, 72).mul(nx).add(FloatVector.fromArray(S, acc, 80).mul(ny))
                .add(FloatVector.fromArray(S, acc, 88).mul(nz));
        if (exact) {
            FloatVector len2 = mx.mul(mx).add(my.mul(my)).add(mz.mul(mz));
            FloatVector inv = FloatVector.broadcast(S, 1f).div(len2.sqrt())
                    .blend(0f, len2.compare(VectorOperators.LE, 0f));
            mx = mx.mul(inv);
            my = my.mul(inv);
            mz = mz.mul(inv);
        }
        // x0 y0 z0 x1 ... z7 by Lanes' interleaving permutations, written out (no vector arguments).
        FloatVector x = FloatVector.fromArray(S, acc, 0);
        FloatVector y = FloatVector.fromArray(S, acc, 8);
        FloatVector z = FloatVector.fromArray(S, acc, 16);
        x.rearrange(Lanes.X0).blend(y.rearrange(Lanes.Y0), Lanes.MY0).blend(z.rearrange(Lanes.Z0), Lanes.MZ0)
                .intoArray(outPositions, o);
        x.rearrange(Lanes.X1).blend(y.rearrange(Lanes.Y1), Lanes.MY1).blend(z.rearrange(Lanes.Z1), Lanes.MZ1)
                .intoArray(outPositions, o + L);
        x.rearrange(Lanes.X2).blend(y.rearrange(Lanes.Y2), Lanes.MY2).blend(z.rearrange(Lanes.Z2), Lanes.MZ2)
                .intoArray(outPositions, o + 2 * L);
        mx.rearrange(Lanes.X0).blend(my.rearrange(Lanes.Y0), Lanes.MY0).blend(mz.rearrange(Lanes.Z0), Lanes.MZ0)
                .intoArray(outNormals, o);
        mx.rearrange(Lanes.X1).blend(my.rearrange(Lanes.Y1), Lanes.MY1).blend(mz.rearrange(Lanes.Z1), Lanes.MZ1)
                .intoArray(outNormals, o + L);
        mx.rearrange(Lanes.X2).blend(my.rearrange(Lanes.Y2), Lanes.MY2).blend(mz.rearrange(Lanes.Z2), Lanes.MZ2)
                .intoArray(outNormals, o + 2 * L);
    }

    /**
     * The sums as deformations ({@code Skinner#skinDeformations}: the columns of N, then p, then N's
     * last column, each padded to four), 16 floats per point from {@code o}; plain stores.
     */
    static void storeDeformations(float[] acc, float[] out, int o) {
        for (int l = 0; l < L; l++) {
            int f = o + 16 * l;
            out[f] = acc[3 * L + l];
            out[f + 1] = acc[6 * L + l];
            out[f + 2] = acc[9 * L + l];
            out[f + 3] = 0f;
            out[f + 4] = acc[4 * L + l];
            out[f + 5] = acc[7 * L + l];
            out[f + 6] = acc[10 * L + l];
            out[f + 7] = 0f;
            out[f + 8] = acc[l];
            out[f + 9] = acc[L + l];
            out[f + 10] = acc[2 * L + l];
            out[f + 11] = 0f;
            out[f + 12] = acc[5 * L + l];
            out[f + 13] = acc[8 * L + l];
            out[f + 14] = acc[11 * L + l];
            out[f + 15] = 0f;
        }
    }
}
