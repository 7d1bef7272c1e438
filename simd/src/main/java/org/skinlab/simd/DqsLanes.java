package org.skinlab.simd;

import static org.skinlab.simd.Lanes.HI;
import static org.skinlab.simd.Lanes.LEFT1;
import static org.skinlab.simd.Lanes.LEFT2;
import static org.skinlab.simd.Lanes.ODD;
import static org.skinlab.simd.Lanes.PAIRS;
import static org.skinlab.simd.Lanes.RIGHT1;
import static org.skinlab.simd.Lanes.RIGHT2;
import static org.skinlab.simd.Lanes.S;
import static org.skinlab.simd.Lanes.SWAP;

import jdk.incubator.vector.FloatVector;

/**
 * The lane passes of {@link VectorDqsSkinner} on blocks of 8 points, each a loop of its own (so
 * C2 compiles it whole: see the skinner's "Passes"), meeting in the skinner's per-thread scratch:
 * blended dual quaternions transposed into lane vectors (component c of a block's 8 points at
 * {@code 64 (block - first) + 8 c}), then either applied to the points or turned into deformations.
 * {@code blk} is the skinner's block layout of rest positions and normals (48 floats per block:
 * px py pz nx ny nz, 8 lanes each).
 */
final class DqsLanes {
    /** Points per block. */
    static final int BLOCK = 8;
    /** Floats per block of the scratch. */
    static final int SCRATCH = 64;
    /** Floats per block of the rest positions and normals. */
    static final int BLOCK_FLOATS = 48;
    /** Floats per block of the rest positions alone (positions-only skinning): px py pz, 8 lanes each. */
    static final int POSITION_BLOCK_FLOATS = 24;

    private DqsLanes() {
    }

    /**
     * Per block of {@code [b, e)}: its 8 points' rows (8 floats each, from {@code 8 (point - 8b)})
     * into 8 lane vectors of the scratch, component c at {@code 64 (block - b) + 8 c}. Stage 1
     * interleaves pairs of points, stage 2 pairs of pairs, stage 3 the halves, each a permute and a
     * blend per output.
     */
    static void transpose(float[] rows, float[] s, int b, int e) {
        for (int blk = 0; blk < e - b; blk++) {
            int ro = 64 * blk;
            FloatVector r0 = FloatVector.fromArray(S, rows, ro);
            FloatVector r1 = FloatVector.fromArray(S, rows, ro + 8);
            FloatVector r2 = FloatVector.fromArray(S, rows, ro + 16);
            FloatVector r3 = FloatVector.fromArray(S, rows, ro + 24);
            FloatVector r4 = FloatVector.fromArray(S, rows, ro + 32);
            FloatVector r5 = FloatVector.fromArray(S, rows, ro + 40);
            FloatVector r6 = FloatVector.fromArray(S, rows, ro + 48);
            FloatVector r7 = FloatVector.fromArray(S, rows, ro + 56);
            FloatVector a0 = r0.blend(r1.rearrange(RIGHT1), ODD);
            FloatVector a1 = r0.rearrange(LEFT1).blend(r1, ODD);
            FloatVector a2 = r2.blend(r3.rearrange(RIGHT1), ODD);
            FloatVector a3 = r2.rearrange(LEFT1).blend(r3, ODD);
            FloatVector a4 = r4.blend(r5.rearrange(RIGHT1), ODD);
            FloatVector a5 = r4.rearrange(LEFT1).blend(r5, ODD);
            FloatVector a6 = r6.blend(r7.rearrange(RIGHT1), ODD);
            FloatVector a7 = r6.rearrange(LEFT1).blend(r7, ODD);
            FloatVector c0 = a0.blend(a2.rearrange(RIGHT2), PAIRS);
            FloatVector c2 = a0.rearrange(LEFT2).blend(a2, PAIRS);
            FloatVector c1 = a1.blend(a3.rearrange(RIGHT2), PAIRS);
            FloatVector c3 = a1.rearrange(LEFT2).blend(a3, PAIRS);
            FloatVector c4 = a4.blend(a6.rearrange(RIGHT2), PAIRS);
            FloatVector c6 = a4.rearrange(LEFT2).blend(a6, PAIRS);
            FloatVector c5 = a5.blend(a7.rearrange(RIGHT2), PAIRS);
            FloatVector c7 = a5.rearrange(LEFT2).blend(a7, PAIRS);
            int so = SCRATCH * blk;
            c0.blend(c4.rearrange(SWAP), HI).intoArray(s, so);
            c0.rearrange(SWAP).blend(c4, HI).intoArray(s, so + 32);
            c1.blend(c5.rearrange(SWAP), HI).intoArray(s, so + 8);
            c1.rearrange(SWAP).blend(c5, HI).intoArray(s, so + 40);
            c2.blend(c6.rearrange(SWAP), HI).intoArray(s, so + 16);
            c2.rearrange(SWAP).blend(c6, HI).intoArray(s, so + 48);
            c3.blend(c7.rearrange(SWAP), HI).intoArray(s, so + 24);
            c3.rearrange(SWAP).blend(c7, HI).intoArray(s, so + 56);
        }
    }

    /**
     * Per block: normalise the blended dual quaternion by its real part, then
     * {@code p' = p + 2 r x (r x p + w p) + t} with {@code t = 2 (w d - d_w r + r x d)}, and the
     * normal rotated the same way; the x, y, z lanes are interleaved into the outputs (x y z x y z
     * ..., see {@link Lanes}) with the store written out here, not called, to stay inlined.
     */
    static void applyAndStore(float[] s, float[] blk, float[] outPositions, float[] outNormals, int firstBlock,
            int endBlock) {
        final FloatVector one = FloatVector.broadcast(S, 1f);
        for (int b = firstBlock; b < endBlock; b++) {
            int so = SCRATCH * (b - firstBlock);
            int fo = BLOCK_FLOATS * b;
            FloatVector x0 = FloatVector.fromArray(S, s, so);
            FloatVector x1 = FloatVector.fromArray(S, s, so + 8);
            FloatVector x2 = FloatVector.fromArray(S, s, so + 16);
            FloatVector x3 = FloatVector.fromArray(S, s, so + 24);
            FloatVector inv = one.div(x0.mul(x0).add(x1.mul(x1)).add(x2.mul(x2)).add(x3.mul(x3)).sqrt());
            FloatVector rx = x0.mul(inv);
            FloatVector ry = x1.mul(inv);
            FloatVector rz = x2.mul(inv);
            FloatVector rw = x3.mul(inv);
            FloatVector dx = FloatVector.fromArray(S, s, so + 32).mul(inv);
            FloatVector dy = FloatVector.fromArray(S, s, so + 40).mul(inv);
            FloatVector dz = FloatVector.fromArray(S, s, so + 48).mul(inv);
            FloatVector dw = FloatVector.fromArray(S, s, so + 56).mul(inv);
            FloatVector tx = rw.mul(dx).sub(dw.mul(rx)).add(ry.mul(dz).sub(rz.mul(dy)));
            FloatVector ty = rw.mul(dy).sub(dw.mul(ry)).add(rz.mul(dx).sub(rx.mul(dz)));
            FloatVector tz = rw.mul(dz).sub(dw.mul(rz)).add(rx.mul(dy).sub(ry.mul(dx)));
            FloatVector px = FloatVector.fromArray(S, blk, fo);
            FloatVector py = FloatVector.fromArray(S, blk, fo + 8);
            FloatVector pz = FloatVector.fromArray(S, blk, fo + 16);
            FloatVector cx = ry.mul(pz).sub(rz.mul(py)).add(rw.mul(px));
            FloatVector cy = rz.mul(px).sub(rx.mul(pz)).add(rw.mul(py));
            FloatVector cz = rx.mul(py).sub(ry.mul(px)).add(rw.mul(pz));
            FloatVector ex = ry.mul(cz).sub(rz.mul(cy));
            FloatVector ey = rz.mul(cx).sub(rx.mul(cz));
            FloatVector ez = rx.mul(cy).sub(ry.mul(cx));
            FloatVector ox = px.add(ex.add(ex)).add(tx.add(tx));
            FloatVector oy = py.add(ey.add(ey)).add(ty.add(ty));
            FloatVector oz = pz.add(ez.add(ez)).add(tz.add(tz));
            int out = 3 * BLOCK * b;
            ox.rearrange(Lanes.X0).blend(oy.rearrange(Lanes.Y0), Lanes.MY0).blend(oz.rearrange(Lanes.Z0), Lanes.MZ0).intoArray(outPositions, out);
            ox.rearrange(Lanes.X1).blend(oy.rearrange(Lanes.Y1), Lanes.MY1).blend(oz.rearrange(Lanes.Z1), Lanes.MZ1).intoArray(outPositions, out + 8);
            ox.rearrange(Lanes.X2).blend(oy.rearrange(Lanes.Y2), Lanes.MY2).blend(oz.rearrange(Lanes.Z2), Lanes.MZ2).intoArray(outPositions, out + 16);
            FloatVector nx = FloatVector.fromArray(S, blk, fo + 24);
            FloatVector ny = FloatVector.fromArray(S, blk, fo + 32);
            FloatVector nz = FloatVector.fromArray(S, blk, fo + 40);
            cx = ry.mul(nz).sub(rz.mul(ny)).add(rw.mul(nx));
            cy = rz.mul(nx).sub(rx.mul(nz)).add(rw.mul(ny));
            cz = rx.mul(ny).sub(ry.mul(nx)).add(rw.mul(nz));
            ex = ry.mul(cz).sub(rz.mul(cy));
            ey = rz.mul(cx).sub(rx.mul(cz));
            ez = rx.mul(cy).sub(ry.mul(cx));
            ox = nx.add(ex.add(ex));
            oy = ny.add(ey.add(ey));
            oz = nz.add(ez.add(ez));
            ox.rearrange(Lanes.X0).blend(oy.rearrange(Lanes.Y0), Lanes.MY0).blend(oz.rearrange(Lanes.Z0), Lanes.MZ0).intoArray(outNormals, out);
            ox.rearrange(Lanes.X1).blend(oy.rearrange(Lanes.Y1), Lanes.MY1).blend(oz.rearrange(Lanes.Z1), Lanes.MZ1).intoArray(outNormals, out + 8);
            ox.rearrange(Lanes.X2).blend(oy.rearrange(Lanes.Y2), Lanes.MY2).blend(oz.rearrange(Lanes.Z2), Lanes.MZ2).intoArray(outNormals, out + 16);
        }
    }

    /**
     * {@link #applyAndStore} without the normal (positions-only skinning): the same operations on
     * the position, from blocks of {@link #POSITION_BLOCK_FLOATS}. Written out again rather than
     * shared through a method, which C2 would not inline into both loops (see the skinner's
     * "Passes").
     */
    static void applyPositions(float[] s, float[] blk, float[] outPositions, int firstBlock, int endBlock) {
        final FloatVector one = FloatVector.broadcast(S, 1f);
        for (int b = firstBlock; b < endBlock; b++) {
            int so = SCRATCH * (b - firstBlock);
            int fo = POSITION_BLOCK_FLOATS * b;
            FloatVector x0 = FloatVector.fromArray(S, s, so);
            FloatVector x1 = FloatVector.fromArray(S, s, so + 8);
            FloatVector x2 = FloatVector.fromArray(S, s, so + 16);
            FloatVector x3 = FloatVector.fromArray(S, s, so + 24);
            FloatVector inv = one.div(x0.mul(x0).add(x1.mul(x1)).add(x2.mul(x2)).add(x3.mul(x3)).sqrt());
            FloatVector rx = x0.mul(inv);
            FloatVector ry = x1.mul(inv);
            FloatVector rz = x2.mul(inv);
            FloatVector rw = x3.mul(inv);
            FloatVector dx = FloatVector.fromArray(S, s, so + 32).mul(inv);
            FloatVector dy = FloatVector.fromArray(S, s, so + 40).mul(inv);
            FloatVector dz = FloatVector.fromArray(S, s, so + 48).mul(inv);
            FloatVector dw = FloatVector.fromArray(S, s, so + 56).mul(inv);
            FloatVector tx = rw.mul(dx).sub(dw.mul(rx)).add(ry.mul(dz).sub(rz.mul(dy)));
            FloatVector ty = rw.mul(dy).sub(dw.mul(ry)).add(rz.mul(dx).sub(rx.mul(dz)));
            FloatVector tz = rw.mul(dz).sub(dw.mul(rz)).add(rx.mul(dy).sub(ry.mul(dx)));
            FloatVector px = FloatVector.fromArray(S, blk, fo);
            FloatVector py = FloatVector.fromArray(S, blk, fo + 8);
            FloatVector pz = FloatVector.fromArray(S, blk, fo + 16);
            FloatVector cx = ry.mul(pz).sub(rz.mul(py)).add(rw.mul(px));
            FloatVector cy = rz.mul(px).sub(rx.mul(pz)).add(rw.mul(py));
            FloatVector cz = rx.mul(py).sub(ry.mul(px)).add(rw.mul(pz));
            FloatVector ex = ry.mul(cz).sub(rz.mul(cy));
            FloatVector ey = rz.mul(cx).sub(rx.mul(cz));
            FloatVector ez = rx.mul(cy).sub(ry.mul(cx));
            FloatVector ox = px.add(ex.add(ex)).add(tx.add(tx));
            FloatVector oy = py.add(ey.add(ey)).add(ty.add(ty));
            FloatVector oz = pz.add(ez.add(ez)).add(tz.add(tz));
            int out = 3 * BLOCK * b;
            ox.rearrange(Lanes.X0).blend(oy.rearrange(Lanes.Y0), Lanes.MY0).blend(oz.rearrange(Lanes.Z0), Lanes.MZ0).intoArray(outPositions, out);
            ox.rearrange(Lanes.X1).blend(oy.rearrange(Lanes.Y1), Lanes.MY1).blend(oz.rearrange(Lanes.Z1), Lanes.MZ1).intoArray(outPositions, out + 8);
            ox.rearrange(Lanes.X2).blend(oy.rearrange(Lanes.Y2), Lanes.MY2).blend(oz.rearrange(Lanes.Z2), Lanes.MZ2).intoArray(outPositions, out + 16);
        }
    }

    /**
     * Per point of blocks {@code [firstBlock, endBlock)}: the blended dual quaternion of the
     * scratch, normalised, as the point's deformation ({@link org.skinlab.skinning.Skinner#skinDeformations}):
     * the rotation R as N's columns and the deformed position {@code p' = R p + t}, with R from the
     * rotation quaternion and t = 2 (w d - d_w r + r x d), into {@code out} at
     * {@code 16 (point - outFirstPoint)}. The eight lane vectors of each half of the record are
     * transposed into eight points' rows by the network {@link #transpose} uses (a transpose is
     * its own inverse). The scale phase recovers t from p' ({@link MatrixPasses#compose}).
     */
    static void rigidDeformations(float[] s, float[] blk, float[] out, int firstBlock, int endBlock, int outFirstPoint) {
        rigidDeformations(s, blk, BLOCK_FLOATS, out, firstBlock, endBlock, outFirstPoint);
    }

    /** As above, the rest positions in blocks of {@code blockFloats} (48, or 24 for positions only). */
    static void rigidDeformations(float[] s, float[] blk, int blockFloats, float[] out, int firstBlock, int endBlock,
            int outFirstPoint) {
        final FloatVector one = FloatVector.broadcast(S, 1f);
        final FloatVector zero = FloatVector.zero(S);
        for (int b = firstBlock; b < endBlock; b++) {
            int so = SCRATCH * (b - firstBlock);
            FloatVector x0 = FloatVector.fromArray(S, s, so);
            FloatVector x1 = FloatVector.fromArray(S, s, so + 8);
            FloatVector x2 = FloatVector.fromArray(S, s, so + 16);
            FloatVector x3 = FloatVector.fromArray(S, s, so + 24);
            FloatVector inv = one.div(x0.mul(x0).add(x1.mul(x1)).add(x2.mul(x2)).add(x3.mul(x3)).sqrt());
            FloatVector rx = x0.mul(inv);
            FloatVector ry = x1.mul(inv);
            FloatVector rz = x2.mul(inv);
            FloatVector rw = x3.mul(inv);
            FloatVector dx = FloatVector.fromArray(S, s, so + 32).mul(inv);
            FloatVector dy = FloatVector.fromArray(S, s, so + 40).mul(inv);
            FloatVector dz = FloatVector.fromArray(S, s, so + 48).mul(inv);
            FloatVector dw = FloatVector.fromArray(S, s, so + 56).mul(inv);
            FloatVector tx = rw.mul(dx).sub(dw.mul(rx)).add(ry.mul(dz).sub(rz.mul(dy)));
            FloatVector ty = rw.mul(dy).sub(dw.mul(ry)).add(rz.mul(dx).sub(rx.mul(dz)));
            FloatVector tz = rw.mul(dz).sub(dw.mul(rz)).add(rx.mul(dy).sub(ry.mul(dx)));
            FloatVector xx = rx.mul(rx), yy = ry.mul(ry), zz = rz.mul(rz);
            FloatVector xy = rx.mul(ry), xz = rx.mul(rz), yz = ry.mul(rz);
            FloatVector xw = rx.mul(rw), yw = ry.mul(rw), zw = rz.mul(rw);
            FloatVector r00 = one.sub(yy.add(zz).mul(2f));
            FloatVector r10 = xy.add(zw).mul(2f);
            FloatVector r20 = xz.sub(yw).mul(2f);
            FloatVector r01 = xy.sub(zw).mul(2f);
            FloatVector r11 = one.sub(xx.add(zz).mul(2f));
            FloatVector r21 = yz.add(xw).mul(2f);
            FloatVector r02 = xz.add(yw).mul(2f);
            FloatVector r12 = yz.sub(xw).mul(2f);
            FloatVector r22 = one.sub(xx.add(yy).mul(2f));
            int fo = blockFloats * b;
            FloatVector px = FloatVector.fromArray(S, blk, fo);
            FloatVector py = FloatVector.fromArray(S, blk, fo + 8);
            FloatVector pz = FloatVector.fromArray(S, blk, fo + 16);
            FloatVector qx = r00.mul(px).add(r01.mul(py)).add(r02.mul(pz)).add(tx.add(tx));
            FloatVector qy = r10.mul(px).add(r11.mul(py)).add(r12.mul(pz)).add(ty.add(ty));
            FloatVector qz = r20.mul(px).add(r21.mul(py)).add(r22.mul(pz)).add(tz.add(tz));
            int base = 16 * (BLOCK * b - outFirstPoint);
            // First halves of the records: [R0 0 | R1 0]; lanes are points, vectors components.
            FloatVector a0 = r00.blend(r10.rearrange(RIGHT1), ODD);
            FloatVector a1 = r00.rearrange(LEFT1).blend(r10, ODD);
            FloatVector a2 = r20.blend(zero, ODD);
            FloatVector a3 = r20.rearrange(LEFT1).blend(zero, ODD);
            FloatVector a4 = r01.blend(r11.rearrange(RIGHT1), ODD);
            FloatVector a5 = r01.rearrange(LEFT1).blend(r11, ODD);
            FloatVector a6 = r21.blend(zero, ODD);
            FloatVector a7 = r21.rearrange(LEFT1).blend(zero, ODD);
            FloatVector c0 = a0.blend(a2.rearrange(RIGHT2), PAIRS);
            FloatVector c2 = a0.rearrange(LEFT2).blend(a2, PAIRS);
            FloatVector c1 = a1.blend(a3.rearrange(RIGHT2), PAIRS);
            FloatVector c3 = a1.rearrange(LEFT2).blend(a3, PAIRS);
            FloatVector c4 = a4.blend(a6.rearrange(RIGHT2), PAIRS);
            FloatVector c6 = a4.rearrange(LEFT2).blend(a6, PAIRS);
            FloatVector c5 = a5.blend(a7.rearrange(RIGHT2), PAIRS);
            FloatVector c7 = a5.rearrange(LEFT2).blend(a7, PAIRS);
            c0.blend(c4.rearrange(SWAP), HI).intoArray(out, base);
            c0.rearrange(SWAP).blend(c4, HI).intoArray(out, base + 64);
            c1.blend(c5.rearrange(SWAP), HI).intoArray(out, base + 16);
            c1.rearrange(SWAP).blend(c5, HI).intoArray(out, base + 80);
            c2.blend(c6.rearrange(SWAP), HI).intoArray(out, base + 32);
            c2.rearrange(SWAP).blend(c6, HI).intoArray(out, base + 96);
            c3.blend(c7.rearrange(SWAP), HI).intoArray(out, base + 48);
            c3.rearrange(SWAP).blend(c7, HI).intoArray(out, base + 112);
            // Second halves: [p' 0 | R2 0].
            a0 = qx.blend(qy.rearrange(RIGHT1), ODD);
            a1 = qx.rearrange(LEFT1).blend(qy, ODD);
            a2 = qz.blend(zero, ODD);
            a3 = qz.rearrange(LEFT1).blend(zero, ODD);
            a4 = r02.blend(r12.rearrange(RIGHT1), ODD);
            a5 = r02.rearrange(LEFT1).blend(r12, ODD);
            a6 = r22.blend(zero, ODD);
            a7 = r22.rearrange(LEFT1).blend(zero, ODD);
            c0 = a0.blend(a2.rearrange(RIGHT2), PAIRS);
            c2 = a0.rearrange(LEFT2).blend(a2, PAIRS);
            c1 = a1.blend(a3.rearrange(RIGHT2), PAIRS);
            c3 = a1.rearrange(LEFT2).blend(a3, PAIRS);
            c4 = a4.blend(a6.rearrange(RIGHT2), PAIRS);
            c6 = a4.rearrange(LEFT2).blend(a6, PAIRS);
            c5 = a5.blend(a7.rearrange(RIGHT2), PAIRS);
            c7 = a5.rearrange(LEFT2).blend(a7, PAIRS);
            c0.blend(c4.rearrange(SWAP), HI).intoArray(out, base + 8);
            c0.rearrange(SWAP).blend(c4, HI).intoArray(out, base + 72);
            c1.blend(c5.rearrange(SWAP), HI).intoArray(out, base + 24);
            c1.rearrange(SWAP).blend(c5, HI).intoArray(out, base + 88);
            c2.blend(c6.rearrange(SWAP), HI).intoArray(out, base + 40);
            c2.rearrange(SWAP).blend(c6, HI).intoArray(out, base + 104);
            c3.blend(c7.rearrange(SWAP), HI).intoArray(out, base + 56);
            c3.rearrange(SWAP).blend(c7, HI).intoArray(out, base + 120);
        }
    }
}
