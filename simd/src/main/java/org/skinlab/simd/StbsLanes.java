package org.skinlab.simd;

import static org.skinlab.simd.Lanes.S;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;

/**
 * The blend passes of {@link VectorStbsSkinner} on one block of 8 points, each a loop of its own
 * (see {@link VectorDqsSkinner}, "Passes"), meeting in a per-thread scratch: after
 * {@link StbsInfluenceLanes} has written every influence's rigid transformation (core's
 * {@code StbsInfluence}: rotation r, translation x; 7 lane vectors per influence at {@code 56 k}),
 * their linear or dual-quaternion blend applied to the block's points.
 *
 * <p><b>No vector crosses a call of ours</b>, not even into {@link #interleave}, which meets its
 * callers in the scratch: C2 inlines our methods only up to a node budget per
 * compilation (NodeCountInliningCutoff; Vector API methods are force-inlined), and a vector passed
 * to or returned by a call it did not inline is boxed. One method per step with vector-valued sin,
 * cos and store helpers went past the budget: about 1.6 KB of garbage per block. Only arrays and
 * ints cross between passes; the joints' data is copied and transposed, not gathered
 * ({@link StbsInfluenceLanes}).
 */
final class StbsLanes {
    /**
     * Floats of the scratch after the influences: the blend, 12 lane vectors (LBS) or 8 (DQS), then
     * at {@link #LANES} the x y z lanes of the result before they are interleaved.
     */
    static final int BLEND_FLOATS = 120;
    private static final int LANES = 96;

    private StbsLanes() {
    }

    /**
     * STBS on LBS for block b: the influences' [R(r) | x] blended with the weights at
     * {@code 8 (b width + k)} into {@code s[o ..]} (12 lane vectors, row-major 3x4), then applied to
     * the block's points; normals by the blend's cofactor (renormalised) or its linear part; x y z
     * interleaved into the outputs at {@code 24 b}.
     */
    static void linear(float[] s, int o, float[] weights, float[] blk, int b, int width, int active, boolean exact,
            float[] outPositions, float[] outNormals) {
        linearBlend(s, o, weights, b, width, active);
        linearPositions(s, o, blk, b, outPositions);
        linearNormals(s, o, blk, b, exact, outNormals);
    }

    private static void linearBlend(float[] s, int o, float[] weights, int b, int width, int active) {
        FloatVector b0 = FloatVector.zero(S), b1 = b0, b2 = b0, b3 = b0, b4 = b0, b5 = b0;
        FloatVector b6 = b0, b7 = b0, b8 = b0, b9 = b0, b10 = b0, b11 = b0;
        for (int k = 0; k < active; k++) {
            int so = StbsInfluenceLanes.INFLUENCE_FLOATS * k;
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
        b0.intoArray(s, o);
        b1.intoArray(s, o + 8);
        b2.intoArray(s, o + 16);
        b3.intoArray(s, o + 24);
        b4.intoArray(s, o + 32);
        b5.intoArray(s, o + 40);
        b6.intoArray(s, o + 48);
        b7.intoArray(s, o + 56);
        b8.intoArray(s, o + 64);
        b9.intoArray(s, o + 72);
        b10.intoArray(s, o + 80);
        b11.intoArray(s, o + 88);
    }

    private static void linearPositions(float[] s, int o, float[] blk, int b, float[] outPositions) {
        int fo = VectorStbsSkinner.BLOCK_FLOATS * b;
        FloatVector px = FloatVector.fromArray(S, blk, fo);
        FloatVector py = FloatVector.fromArray(S, blk, fo + 8);
        FloatVector pz = FloatVector.fromArray(S, blk, fo + 16);
        FloatVector x = FloatVector.fromArray(S, s, o).mul(px).add(FloatVector.fromArray(S, s, o + 8).mul(py))
                .add(FloatVector.fromArray(S, s, o + 16).mul(pz)).add(FloatVector.fromArray(S, s, o + 24));
        FloatVector y = FloatVector.fromArray(S, s, o + 32).mul(px).add(FloatVector.fromArray(S, s, o + 40).mul(py))
                .add(FloatVector.fromArray(S, s, o + 48).mul(pz)).add(FloatVector.fromArray(S, s, o + 56));
        FloatVector z = FloatVector.fromArray(S, s, o + 64).mul(px).add(FloatVector.fromArray(S, s, o + 72).mul(py))
                .add(FloatVector.fromArray(S, s, o + 80).mul(pz)).add(FloatVector.fromArray(S, s, o + 88));
        x.intoArray(s, o + LANES);
        y.intoArray(s, o + LANES + 8);
        z.intoArray(s, o + LANES + 16);
        interleave(s, o + LANES, outPositions, 24 * b);
    }

    private static void linearNormals(float[] s, int o, float[] blk, int b, boolean exact, float[] outNormals) {
        FloatVector b0 = FloatVector.fromArray(S, s, o);
        FloatVector b1 = FloatVector.fromArray(S, s, o + 8);
        FloatVector b2 = FloatVector.fromArray(S, s, o + 16);
        FloatVector b4 = FloatVector.fromArray(S, s, o + 32);
        FloatVector b5 = FloatVector.fromArray(S, s, o + 40);
        FloatVector b6 = FloatVector.fromArray(S, s, o + 48);
        FloatVector b8 = FloatVector.fromArray(S, s, o + 64);
        FloatVector b9 = FloatVector.fromArray(S, s, o + 72);
        FloatVector b10 = FloatVector.fromArray(S, s, o + 80);
        int fo = VectorStbsSkinner.BLOCK_FLOATS * b;
        FloatVector nx = FloatVector.fromArray(S, blk, fo + 24);
        FloatVector ny = FloatVector.fromArray(S, blk, fo + 32);
        FloatVector nz = FloatVector.fromArray(S, blk, fo + 40);
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
        mx.intoArray(s, o + LANES);
        my.intoArray(s, o + LANES + 8);
        mz.intoArray(s, o + LANES + 16);
        interleave(s, o + LANES, outNormals, 24 * b);
    }

    /**
     * STBS on DQS for block b: the influences as dual quaternions (r, (x, 0) r / 2), flipped onto
     * the first influence's side, blended into {@code s[o ..]} (real then dual part, 8 lane vectors),
     * normalised by the real part and applied; the normal rotated (renormalised under the exact rule).
     */
    static void dualQuaternion(float[] s, int o, float[] weights, float[] blk, int b, int width, int active,
            boolean exact, float[] outPositions, float[] outNormals) {
        dualQuaternionBlend(s, s, o, weights, b, width, active);
        dualQuaternionPositions(s, o, blk, b, outPositions);
        dualQuaternionNormals(s, o, blk, b, exact, outNormals);
    }

    /**
     * Block b's deformations ({@link org.skinlab.skinning.Skinner#skinDeformations}) on LBS: the blend
     * as in {@link #linear}, N its linear part's cofactor (unsigned, as the scalar kernel: a blend
     * of rotations turns no normal inwards unless it degenerates) or that part itself, 16 lane
     * vectors into {@code f} (128 floats), transposed into the points' records at {@code 128 b}.
     */
    static void linearDeformations(float[] s, int o, float[] weights, float[] blk, int b, int width, int active,
            boolean exact, float[] f, float[] outDeformations) {
        linearBlend(s, o, weights, b, width, active);
        linearDeformationLanes(s, o, blk, b, exact, f);
        storeDeformations(f, outDeformations, 128 * b);
    }

    /** The record's 16 fields as lane vectors, field c at {@code f[8 c ..]} (fields 3, 7, 11, 15 zero). */
    private static void linearDeformationLanes(float[] s, int o, float[] blk, int b, boolean exact, float[] f) {
        FloatVector b0 = FloatVector.fromArray(S, s, o);
        FloatVector b1 = FloatVector.fromArray(S, s, o + 8);
        FloatVector b2 = FloatVector.fromArray(S, s, o + 16);
        FloatVector b4 = FloatVector.fromArray(S, s, o + 32);
        FloatVector b5 = FloatVector.fromArray(S, s, o + 40);
        FloatVector b6 = FloatVector.fromArray(S, s, o + 48);
        FloatVector b8 = FloatVector.fromArray(S, s, o + 64);
        FloatVector b9 = FloatVector.fromArray(S, s, o + 72);
        FloatVector b10 = FloatVector.fromArray(S, s, o + 80);
        int fo = VectorStbsSkinner.BLOCK_FLOATS * b;
        FloatVector px = FloatVector.fromArray(S, blk, fo);
        FloatVector py = FloatVector.fromArray(S, blk, fo + 8);
        FloatVector pz = FloatVector.fromArray(S, blk, fo + 16);
        b0.mul(px).add(b1.mul(py)).add(b2.mul(pz)).add(FloatVector.fromArray(S, s, o + 24)).intoArray(f, 64);
        b4.mul(px).add(b5.mul(py)).add(b6.mul(pz)).add(FloatVector.fromArray(S, s, o + 56)).intoArray(f, 72);
        b8.mul(px).add(b9.mul(py)).add(b10.mul(pz)).add(FloatVector.fromArray(S, s, o + 88)).intoArray(f, 80);
        if (exact) {
            // Row-major cofactor c_rc as in ScalarStbsSkinner; the record holds N's columns.
            b5.mul(b10).sub(b9.mul(b6)).intoArray(f, 0);
            b9.mul(b2).sub(b1.mul(b10)).intoArray(f, 8);
            b1.mul(b6).sub(b5.mul(b2)).intoArray(f, 16);
            b6.mul(b8).sub(b10.mul(b4)).intoArray(f, 32);
            b10.mul(b0).sub(b2.mul(b8)).intoArray(f, 40);
            b2.mul(b4).sub(b6.mul(b0)).intoArray(f, 48);
            b4.mul(b9).sub(b8.mul(b5)).intoArray(f, 96);
            b8.mul(b1).sub(b0.mul(b9)).intoArray(f, 104);
            b0.mul(b5).sub(b4.mul(b1)).intoArray(f, 112);
        } else {
            b0.intoArray(f, 0);
            b4.intoArray(f, 8);
            b8.intoArray(f, 16);
            b1.intoArray(f, 32);
            b5.intoArray(f, 40);
            b9.intoArray(f, 48);
            b2.intoArray(f, 96);
            b6.intoArray(f, 104);
            b10.intoArray(f, 112);
        }
        FloatVector zero = FloatVector.zero(S);
        zero.intoArray(f, 24);
        zero.intoArray(f, 56);
        zero.intoArray(f, 88);
        zero.intoArray(f, 120);
    }

    /**
     * The 16 lane vectors at {@code f} transposed in place ({@link DqsLanes#transpose}: fields 0..7
     * and 8..15 of the 8 points, 8 floats each), then copied into the records at {@code out[o ..]}.
     */
    private static void storeDeformations(float[] f, float[] out, int o) {
        DqsLanes.transpose(f, f, 0, 2);
        for (int l = 0; l < 8; l++) {
            FloatVector.fromArray(S, f, 8 * l).intoArray(out, o + 16 * l);
            FloatVector.fromArray(S, f, 64 + 8 * l).intoArray(out, o + 16 * l + 8);
        }
    }

    /**
     * Block b's deformations on DQS: the blend as in {@link #dualQuaternion}, into {@code f} from 0
     * (64 floats: the layout of {@link DqsLanes}' scratch), then {@link DqsLanes#rigidDeformations}, which
     * normalises it and writes N = its rotation and p' = R p + t at {@code 128 b}.
     */
    static void dualQuaternionDeformations(float[] s, float[] weights, float[] blk, int b, int width, int active, float[] f,
            float[] outDeformations) {
        dualQuaternionBlend(s, f, 0, weights, b, width, active);
        DqsLanes.rigidDeformations(f, blk, outDeformations, b, b + 1, 0);
    }

    /** The blend of the influences in {@code s} into {@code d[o ..]}: real part, then dual part, 4 lane vectors each. */
    private static void dualQuaternionBlend(float[] s, float[] d, int o, float[] weights, int b, int width, int active) {
        FloatVector p0 = FloatVector.fromArray(S, s, 0);
        FloatVector p1 = FloatVector.fromArray(S, s, 8);
        FloatVector p2 = FloatVector.fromArray(S, s, 16);
        FloatVector p3 = FloatVector.fromArray(S, s, 24);
        FloatVector r0 = FloatVector.zero(S), r1 = r0, r2 = r0, r3 = r0, d0 = r0, d1 = r0, d2 = r0, d3 = r0;
        for (int k = 0; k < active; k++) {
            int so = StbsInfluenceLanes.INFLUENCE_FLOATS * k;
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
        r0.intoArray(d, o);
        r1.intoArray(d, o + 8);
        r2.intoArray(d, o + 16);
        r3.intoArray(d, o + 24);
        d0.intoArray(d, o + 32);
        d1.intoArray(d, o + 40);
        d2.intoArray(d, o + 48);
        d3.intoArray(d, o + 56);
    }

    /** Normalises the blend by its real part, applies it to the points, and leaves the unit real part in {@code s[o ..]}. */
    private static void dualQuaternionPositions(float[] s, int o, float[] blk, int b, float[] outPositions) {
        FloatVector r0 = FloatVector.fromArray(S, s, o);
        FloatVector r1 = FloatVector.fromArray(S, s, o + 8);
        FloatVector r2 = FloatVector.fromArray(S, s, o + 16);
        FloatVector r3 = FloatVector.fromArray(S, s, o + 24);
        FloatVector inv = FloatVector.broadcast(S, 1f).div(r0.mul(r0).add(r1.mul(r1)).add(r2.mul(r2)).add(r3.mul(r3)).sqrt());
        FloatVector rx = r0.mul(inv), ry = r1.mul(inv), rz = r2.mul(inv), rw = r3.mul(inv);
        FloatVector dx = FloatVector.fromArray(S, s, o + 32).mul(inv), dy = FloatVector.fromArray(S, s, o + 40).mul(inv);
        FloatVector dz = FloatVector.fromArray(S, s, o + 48).mul(inv), dw = FloatVector.fromArray(S, s, o + 56).mul(inv);
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
        px.add(ex.add(ex)).add(tx.add(tx)).intoArray(s, o + LANES);
        py.add(ey.add(ey)).add(ty.add(ty)).intoArray(s, o + LANES + 8);
        pz.add(ez.add(ez)).add(tz.add(tz)).intoArray(s, o + LANES + 16);
        interleave(s, o + LANES, outPositions, 24 * b);
        rx.intoArray(s, o);
        ry.intoArray(s, o + 8);
        rz.intoArray(s, o + 16);
        rw.intoArray(s, o + 24);
    }

    private static void dualQuaternionNormals(float[] s, int o, float[] blk, int b, boolean exact, float[] outNormals) {
        FloatVector rx = FloatVector.fromArray(S, s, o);
        FloatVector ry = FloatVector.fromArray(S, s, o + 8);
        FloatVector rz = FloatVector.fromArray(S, s, o + 16);
        FloatVector rw = FloatVector.fromArray(S, s, o + 24);
        int fo = VectorStbsSkinner.BLOCK_FLOATS * b;
        FloatVector nx = FloatVector.fromArray(S, blk, fo + 24);
        FloatVector ny = FloatVector.fromArray(S, blk, fo + 32);
        FloatVector nz = FloatVector.fromArray(S, blk, fo + 40);
        FloatVector cx = ry.mul(nz).sub(rz.mul(ny)).add(rw.mul(nx));
        FloatVector cy = rz.mul(nx).sub(rx.mul(nz)).add(rw.mul(ny));
        FloatVector cz = rx.mul(ny).sub(ry.mul(nx)).add(rw.mul(nz));
        FloatVector ex = ry.mul(cz).sub(rz.mul(cy));
        FloatVector ey = rz.mul(cx).sub(rx.mul(cz));
        FloatVector ez = rx.mul(cy).sub(ry.mul(cx));
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
        mx.intoArray(s, o + LANES);
        my.intoArray(s, o + LANES + 8);
        mz.intoArray(s, o + LANES + 16);
        interleave(s, o + LANES, outNormals, 24 * b);
    }

    /** The x, y, z lanes at {@code s[from ..]} (8 each) interleaved into {@code out[o .. o + 24)} (see {@link Lanes}). */
    private static void interleave(float[] s, int from, float[] out, int o) {
        FloatVector x = FloatVector.fromArray(S, s, from);
        FloatVector y = FloatVector.fromArray(S, s, from + 8);
        FloatVector z = FloatVector.fromArray(S, s, from + 16);
        x.rearrange(Lanes.X0).blend(y.rearrange(Lanes.Y0), Lanes.MY0).blend(z.rearrange(Lanes.Z0), Lanes.MZ0).intoArray(out, o);
        x.rearrange(Lanes.X1).blend(y.rearrange(Lanes.Y1), Lanes.MY1).blend(z.rearrange(Lanes.Z1), Lanes.MZ1).intoArray(out, o + 8);
        x.rearrange(Lanes.X2).blend(y.rearrange(Lanes.Y2), Lanes.MY2).blend(z.rearrange(Lanes.Z2), Lanes.MZ2).intoArray(out, o + 16);
    }
}
