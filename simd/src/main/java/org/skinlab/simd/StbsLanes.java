package org.skinlab.simd;

import static org.skinlab.simd.Lanes.S;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;

/**
 * The lane passes of {@link VectorStbsSkinner} on one block of 8 points, each a loop of its own
 * (see {@link VectorDqsSkinner}, "Passes"), meeting in a per-thread scratch: first every
 * influence's rigid transformation (core's {@code StbsInfluence}: rotation r, translation x; 7
 * lane vectors per influence at {@code 56 k}), then their linear or dual-quaternion blend applied
 * to the block's points.
 */
final class StbsLanes {
    /** Floats of the scratch per influence: r x, y, z, w, then x x, y, z, 8 lanes each. */
    static final int INFLUENCE_FLOATS = 56;

    // sin and cos of |a| <= pi/2 by their Taylor series to x^11 and x^12: the first term left out
    // is below 6e-8 there (|a| <= pi/2 since the angle is -(1 - e) theta / 2 with |theta| <= pi).
    private static final float S3 = -1f / 6, S5 = 1f / 120, S7 = -1f / 5040, S9 = 1f / 362880, S11 = -1f / 39916800;
    private static final float C2 = -1f / 2, C4 = 1f / 24, C6 = -1f / 720, C8 = 1f / 40320, C10 = -1f / 3628800,
            C12 = 1f / 479001600;

    private StbsLanes() {
    }

    /** sin(a) lane by lane for |a| <= pi/2 (see the constants). */
    static FloatVector sin(FloatVector a) {
        FloatVector a2 = a.mul(a);
        FloatVector p = a2.mul(S11).add(S9);
        p = p.mul(a2).add(S7);
        p = p.mul(a2).add(S5);
        p = p.mul(a2).add(S3);
        return p.mul(a2).add(1f).mul(a);
    }

    /** cos(a) lane by lane for |a| <= pi/2. */
    static FloatVector cos(FloatVector a) {
        FloatVector a2 = a.mul(a);
        FloatVector p = a2.mul(C12).add(C10);
        p = p.mul(a2).add(C8);
        p = p.mul(a2).add(C6);
        p = p.mul(a2).add(C4);
        p = p.mul(a2).add(C2);
        return p.mul(a2).add(1f);
    }

    /**
     * Each influence of block {@code b} for its points at {@code blk[48 b ..]} (px py pz, 8 lanes
     * each): joints through {@code rowIndex} (24 j) and {@code dqIndex} (8 j), 8 lanes per
     * influence at {@code 8 (b width + k)}; r and x of the first {@code active} into {@code s[56 k ..]}.
     */
    static void influences(float[] rows, float[] dq, int[] rowIndex, int[] dqIndex, float[] blk, int b, int width,
            int active, float[] s) {
        final FloatVector one = FloatVector.broadcast(S, 1f);
        final FloatVector zero = FloatVector.zero(S);
        int fo = VectorStbsSkinner.BLOCK_FLOATS * b;
        FloatVector px = FloatVector.fromArray(S, blk, fo);
        FloatVector py = FloatVector.fromArray(S, blk, fo + 8);
        FloatVector pz = FloatVector.fromArray(S, blk, fo + 16);
        for (int k = 0; k < active; k++) {
            int m = 8 * (b * width + k);
            FloatVector hx = FloatVector.fromArray(S, rows, 16, rowIndex, m);
            FloatVector hy = FloatVector.fromArray(S, rows, 17, rowIndex, m);
            FloatVector hz = FloatVector.fromArray(S, rows, 18, rowIndex, m);
            FloatVector length = FloatVector.fromArray(S, rows, 19, rowIndex, m);
            FloatVector along = px.sub(hx).mul(FloatVector.fromArray(S, rows, 20, rowIndex, m).sub(hx))
                    .add(py.sub(hy).mul(FloatVector.fromArray(S, rows, 21, rowIndex, m).sub(hy)))
                    .add(pz.sub(hz).mul(FloatVector.fromArray(S, rows, 22, rowIndex, m).sub(hz)));
            VectorMask<Float> point = length.compare(VectorOperators.GT, 0f);
            FloatVector e = one.blend(along.div(length.mul(length)).max(zero).min(one), point);
            FloatVector half = e.sub(one).mul(FloatVector.fromArray(S, rows, 3, rowIndex, m)).mul(0.5f);
            FloatVector sin = sin(half);
            FloatVector uw = cos(half);
            FloatVector ux = FloatVector.fromArray(S, rows, 12, rowIndex, m).mul(sin);
            FloatVector uy = FloatVector.fromArray(S, rows, 13, rowIndex, m).mul(sin);
            FloatVector uz = FloatVector.fromArray(S, rows, 14, rowIndex, m).mul(sin);
            FloatVector qx = FloatVector.fromArray(S, dq, 0, dqIndex, m);
            FloatVector qy = FloatVector.fromArray(S, dq, 1, dqIndex, m);
            FloatVector qz = FloatVector.fromArray(S, dq, 2, dqIndex, m);
            FloatVector qw = FloatVector.fromArray(S, dq, 3, dqIndex, m);
            FloatVector rx = uw.mul(qx).add(ux.mul(qw)).add(uy.mul(qz).sub(uz.mul(qy)));
            FloatVector ry = uw.mul(qy).add(uy.mul(qw)).add(uz.mul(qx).sub(ux.mul(qz)));
            FloatVector rz = uw.mul(qz).add(uz.mul(qw)).add(ux.mul(qy).sub(uy.mul(qx)));
            FloatVector rw = uw.mul(qw).sub(ux.mul(qx).add(uy.mul(qy)).add(uz.mul(qz)));
            FloatVector cx = ry.mul(hz).sub(rz.mul(hy)).add(rw.mul(hx));
            FloatVector cy = rz.mul(hx).sub(rx.mul(hz)).add(rw.mul(hy));
            FloatVector cz = rx.mul(hy).sub(ry.mul(hx)).add(rw.mul(hz));
            FloatVector gx = ry.mul(cz).sub(rz.mul(cy));
            FloatVector gy = rz.mul(cx).sub(rx.mul(cz));
            FloatVector gz = rx.mul(cy).sub(ry.mul(cx));
            int so = INFLUENCE_FLOATS * k;
            rx.intoArray(s, so);
            ry.intoArray(s, so + 8);
            rz.intoArray(s, so + 16);
            rw.intoArray(s, so + 24);
            e.fma(FloatVector.fromArray(S, rows, 8, rowIndex, m), FloatVector.fromArray(S, rows, 0, rowIndex, m))
                    .sub(hx.add(gx.add(gx))).intoArray(s, so + 32);
            e.fma(FloatVector.fromArray(S, rows, 9, rowIndex, m), FloatVector.fromArray(S, rows, 1, rowIndex, m))
                    .sub(hy.add(gy.add(gy))).intoArray(s, so + 40);
            e.fma(FloatVector.fromArray(S, rows, 10, rowIndex, m), FloatVector.fromArray(S, rows, 2, rowIndex, m))
                    .sub(hz.add(gz.add(gz))).intoArray(s, so + 48);
        }
    }

    /**
     * STBS on LBS for block b: the influences' [R(r) | x] blended with the weights at
     * {@code 8 (b width + k)}, applied to the block's points; normals by the blend's cofactor
     * (renormalised) or its linear part; x y z interleaved into the outputs at {@code 24 b}.
     */
    static void linear(float[] s, float[] weights, float[] blk, int b, int width, int active, boolean exact,
            float[] outPositions, float[] outNormals) {
        FloatVector b0 = FloatVector.zero(S), b1 = b0, b2 = b0, b3 = b0, b4 = b0, b5 = b0;
        FloatVector b6 = b0, b7 = b0, b8 = b0, b9 = b0, b10 = b0, b11 = b0;
        for (int k = 0; k < active; k++) {
            int so = INFLUENCE_FLOATS * k;
            FloatVector w = FloatVector.fromArray(S, weights, 8 * (b * width + k));
            FloatVector x = FloatVector.fromArray(S, s, so);
            FloatVector y = FloatVector.fromArray(S, s, so + 8);
            FloatVector z = FloatVector.fromArray(S, s, so + 16);
            FloatVector q = FloatVector.fromArray(S, s, so + 24);
            FloatVector w2 = w.add(w);
            FloatVector xx = x.mul(x), yy = y.mul(y), zz = z.mul(z);
            FloatVector xy = x.mul(y), xz = x.mul(z), yz = y.mul(z);
            FloatVector xw = x.mul(q), yw = y.mul(q), zw = z.mul(q);
            b0 = w.sub(w2.mul(yy.add(zz))).add(b0);
            b1 = w2.fma(xy.sub(zw), b1);
            b2 = w2.fma(xz.add(yw), b2);
            b3 = w.fma(FloatVector.fromArray(S, s, so + 32), b3);
            b4 = w2.fma(xy.add(zw), b4);
            b5 = w.sub(w2.mul(xx.add(zz))).add(b5);
            b6 = w2.fma(yz.sub(xw), b6);
            b7 = w.fma(FloatVector.fromArray(S, s, so + 40), b7);
            b8 = w2.fma(xz.sub(yw), b8);
            b9 = w2.fma(yz.add(xw), b9);
            b10 = w.sub(w2.mul(xx.add(yy))).add(b10);
            b11 = w.fma(FloatVector.fromArray(S, s, so + 48), b11);
        }
        int fo = VectorStbsSkinner.BLOCK_FLOATS * b;
        FloatVector px = FloatVector.fromArray(S, blk, fo);
        FloatVector py = FloatVector.fromArray(S, blk, fo + 8);
        FloatVector pz = FloatVector.fromArray(S, blk, fo + 16);
        FloatVector nx = FloatVector.fromArray(S, blk, fo + 24);
        FloatVector ny = FloatVector.fromArray(S, blk, fo + 32);
        FloatVector nz = FloatVector.fromArray(S, blk, fo + 40);
        store(b0.mul(px).add(b1.mul(py)).add(b2.mul(pz)).add(b3), b4.mul(px).add(b5.mul(py)).add(b6.mul(pz)).add(b7),
                b8.mul(px).add(b9.mul(py)).add(b10.mul(pz)).add(b11), outPositions, 24 * b);
        FloatVector mx;
        FloatVector my;
        FloatVector mz;
        if (exact) {
            mx = b5.mul(b10).sub(b9.mul(b6)).mul(nx).add(b6.mul(b8).sub(b10.mul(b4)).mul(ny))
                    .add(b4.mul(b9).sub(b8.mul(b5)).mul(nz));
            my = b9.mul(b2).sub(b1.mul(b10)).mul(nx).add(b10.mul(b0).sub(b2.mul(b8)).mul(ny))
                    .add(b8.mul(b1).sub(b0.mul(b9)).mul(nz));
            mz = b1.mul(b6).sub(b5.mul(b2)).mul(nx).add(b2.mul(b4).sub(b6.mul(b0)).mul(ny))
                    .add(b0.mul(b5).sub(b4.mul(b1)).mul(nz));
            FloatVector len2 = mx.mul(mx).add(my.mul(my)).add(mz.mul(mz));
            FloatVector inv = FloatVector.zero(S).blend(FloatVector.broadcast(S, 1f).div(len2.sqrt()), len2.compare(VectorOperators.GT, 0f));
            mx = mx.mul(inv);
            my = my.mul(inv);
            mz = mz.mul(inv);
        } else {
            mx = b0.mul(nx).add(b1.mul(ny)).add(b2.mul(nz));
            my = b4.mul(nx).add(b5.mul(ny)).add(b6.mul(nz));
            mz = b8.mul(nx).add(b9.mul(ny)).add(b10.mul(nz));
        }
        store(mx, my, mz, outNormals, 24 * b);
    }

    /**
     * STBS on DQS for block b: the influences as dual quaternions (r, (x, 0) r / 2), flipped onto
     * the first influence's side, blended, normalised by the real part and applied; the normal
     * rotated (renormalised under the exact rule).
     */
    static void dualQuaternion(float[] s, float[] weights, float[] blk, int b, int width, int active, boolean exact,
            float[] outPositions, float[] outNormals) {
        FloatVector p0 = FloatVector.fromArray(S, s, 0);
        FloatVector p1 = FloatVector.fromArray(S, s, 8);
        FloatVector p2 = FloatVector.fromArray(S, s, 16);
        FloatVector p3 = FloatVector.fromArray(S, s, 24);
        FloatVector r0 = FloatVector.zero(S), r1 = r0, r2 = r0, r3 = r0, d0 = r0, d1 = r0, d2 = r0, d3 = r0;
        for (int k = 0; k < active; k++) {
            int so = INFLUENCE_FLOATS * k;
            FloatVector x = FloatVector.fromArray(S, s, so);
            FloatVector y = FloatVector.fromArray(S, s, so + 8);
            FloatVector z = FloatVector.fromArray(S, s, so + 16);
            FloatVector q = FloatVector.fromArray(S, s, so + 24);
            FloatVector w = FloatVector.fromArray(S, weights, 8 * (b * width + k));
            w = w.blend(w.neg(), p0.mul(x).add(p1.mul(y)).add(p2.mul(z)).add(p3.mul(q)).compare(VectorOperators.LT, 0f));
            FloatVector ex = FloatVector.fromArray(S, s, so + 32);
            FloatVector ey = FloatVector.fromArray(S, s, so + 40);
            FloatVector ez = FloatVector.fromArray(S, s, so + 48);
            r0 = w.fma(x, r0);
            r1 = w.fma(y, r1);
            r2 = w.fma(z, r2);
            r3 = w.fma(q, r3);
            FloatVector hw = w.mul(0.5f);
            d0 = hw.fma(q.mul(ex).add(ey.mul(z).sub(ez.mul(y))), d0);
            d1 = hw.fma(q.mul(ey).add(ez.mul(x).sub(ex.mul(z))), d1);
            d2 = hw.fma(q.mul(ez).add(ex.mul(y).sub(ey.mul(x))), d2);
            d3 = hw.neg().fma(ex.mul(x).add(ey.mul(y)).add(ez.mul(z)), d3);
        }
        FloatVector inv = FloatVector.broadcast(S, 1f).div(r0.mul(r0).add(r1.mul(r1)).add(r2.mul(r2)).add(r3.mul(r3)).sqrt());
        FloatVector rx = r0.mul(inv), ry = r1.mul(inv), rz = r2.mul(inv), rw = r3.mul(inv);
        FloatVector dx = d0.mul(inv), dy = d1.mul(inv), dz = d2.mul(inv), dw = d3.mul(inv);
        FloatVector tx = rw.mul(dx).sub(dw.mul(rx)).add(ry.mul(dz).sub(rz.mul(dy)));
        FloatVector ty = rw.mul(dy).sub(dw.mul(ry)).add(rz.mul(dx).sub(rx.mul(dz)));
        FloatVector tz = rw.mul(dz).sub(dw.mul(rz)).add(rx.mul(dy).sub(ry.mul(dx)));
        int fo = VectorStbsSkinner.BLOCK_FLOATS * b;
        FloatVector px = FloatVector.fromArray(S, blk, fo);
        FloatVector py = FloatVector.fromArray(S, blk, fo + 8);
        FloatVector pz = FloatVector.fromArray(S, blk, fo + 16);
        FloatVector cx = ry.mul(pz).sub(rz.mul(py)).add(rw.mul(px));
        FloatVector cy = rz.mul(px).sub(rx.mul(pz)).add(rw.mul(py));
        FloatVector cz = rx.mul(py).sub(ry.mul(px)).add(rw.mul(pz));
        FloatVector ex = ry.mul(cz).sub(rz.mul(cy));
        FloatVector ey = rz.mul(cx).sub(rx.mul(cz));
        FloatVector ez = rx.mul(cy).sub(ry.mul(cx));
        store(px.add(ex.add(ex)).add(tx.add(tx)), py.add(ey.add(ey)).add(ty.add(ty)), pz.add(ez.add(ez)).add(tz.add(tz)),
                outPositions, 24 * b);
        FloatVector nx = FloatVector.fromArray(S, blk, fo + 24);
        FloatVector ny = FloatVector.fromArray(S, blk, fo + 32);
        FloatVector nz = FloatVector.fromArray(S, blk, fo + 40);
        cx = ry.mul(nz).sub(rz.mul(ny)).add(rw.mul(nx));
        cy = rz.mul(nx).sub(rx.mul(nz)).add(rw.mul(ny));
        cz = rx.mul(ny).sub(ry.mul(nx)).add(rw.mul(nz));
        ex = ry.mul(cz).sub(rz.mul(cy));
        ey = rz.mul(cx).sub(rx.mul(cz));
        ez = rx.mul(cy).sub(ry.mul(cx));
        FloatVector mx = nx.add(ex.add(ex));
        FloatVector my = ny.add(ey.add(ey));
        FloatVector mz = nz.add(ez.add(ez));
        if (exact) {
            FloatVector len2 = mx.mul(mx).add(my.mul(my)).add(mz.mul(mz));
            FloatVector scale = FloatVector.zero(S).blend(FloatVector.broadcast(S, 1f).div(len2.sqrt()), len2.compare(VectorOperators.GT, 0f));
            mx = mx.mul(scale);
            my = my.mul(scale);
            mz = mz.mul(scale);
        }
        store(mx, my, mz, outNormals, 24 * b);
    }

    /** x, y, z lanes interleaved into {@code out[o .. o + 24)} (see {@link Lanes}). */
    private static void store(FloatVector x, FloatVector y, FloatVector z, float[] out, int o) {
        x.rearrange(Lanes.X0).blend(y.rearrange(Lanes.Y0), Lanes.MY0).blend(z.rearrange(Lanes.Z0), Lanes.MZ0).intoArray(out, o);
        x.rearrange(Lanes.X1).blend(y.rearrange(Lanes.Y1), Lanes.MY1).blend(z.rearrange(Lanes.Z1), Lanes.MZ1).intoArray(out, o + 8);
        x.rearrange(Lanes.X2).blend(y.rearrange(Lanes.Y2), Lanes.MY2).blend(z.rearrange(Lanes.Z2), Lanes.MZ2).intoArray(out, o + 16);
    }
}
