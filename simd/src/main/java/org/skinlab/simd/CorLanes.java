package org.skinlab.simd;

import static org.skinlab.simd.Lanes.S;

import jdk.incubator.vector.FloatVector;

/**
 * The per-block pass of {@link VectorCorSkinner}: 8 points per lane vector. From the scratch
 * (component c of a block's 8 points at {@code 64 (block - b) + 8 c}, after
 * {@link DqsLanes#transpose}) it reads the blended quaternion and the blended matrix's first row
 * ({@code qx qy qz qw a00 a01 a02 a03}) and the other two rows ({@code a10 .. a13 a20 .. a23}),
 * then computes {@code p' = R (p - c) + A c} with R the normalised quaternion's rotation, applied
 * as {@code e + 2 r x (r x e + w e)}, and the normal turned by R; the x, y, z lanes are
 * interleaved into the outputs (x y z x y z ..., see {@link Lanes}) with the store written out
 * here, not called, to stay inlined.
 */
final class CorLanes {
    private CorLanes() {
    }

    /**
     * Blocks {@code [firstBlock, endBlock)}; {@code blk} holds the rest positions and normals
     * ({@link DqsLanes#BLOCK_FLOATS} per block), {@code centres} the centres (24 floats per block:
     * cx cy cz, 8 lanes each).
     */
    static void applyAndStore(float[] first, float[] second, float[] blk, float[] centres, float[] outPositions,
            float[] outNormals, int firstBlock, int endBlock) {
        final FloatVector one = FloatVector.broadcast(S, 1f);
        for (int b = firstBlock; b < endBlock; b++) {
            int so = DqsLanes.SCRATCH * (b - firstBlock);
            int fo = DqsLanes.BLOCK_FLOATS * b;
            int co = 3 * DqsLanes.BLOCK * b;
            FloatVector x0 = FloatVector.fromArray(S, first, so);
            FloatVector x1 = FloatVector.fromArray(S, first, so + 8);
            FloatVector x2 = FloatVector.fromArray(S, first, so + 16);
            FloatVector x3 = FloatVector.fromArray(S, first, so + 24);
            FloatVector inv = one.div(x0.mul(x0).add(x1.mul(x1)).add(x2.mul(x2)).add(x3.mul(x3)).sqrt());
            FloatVector rx = x0.mul(inv);
            FloatVector ry = x1.mul(inv);
            FloatVector rz = x2.mul(inv);
            FloatVector rw = x3.mul(inv);
            FloatVector cx = FloatVector.fromArray(S, centres, co);
            FloatVector cy = FloatVector.fromArray(S, centres, co + 8);
            FloatVector cz = FloatVector.fromArray(S, centres, co + 16);
            // A c, row by row.
            FloatVector tx = FloatVector.fromArray(S, first, so + 32).mul(cx)
                    .add(FloatVector.fromArray(S, first, so + 40).mul(cy))
                    .add(FloatVector.fromArray(S, first, so + 48).mul(cz))
                    .add(FloatVector.fromArray(S, first, so + 56));
            FloatVector ty = FloatVector.fromArray(S, second, so).mul(cx)
                    .add(FloatVector.fromArray(S, second, so + 8).mul(cy))
                    .add(FloatVector.fromArray(S, second, so + 16).mul(cz))
                    .add(FloatVector.fromArray(S, second, so + 24));
            FloatVector tz = FloatVector.fromArray(S, second, so + 32).mul(cx)
                    .add(FloatVector.fromArray(S, second, so + 40).mul(cy))
                    .add(FloatVector.fromArray(S, second, so + 48).mul(cz))
                    .add(FloatVector.fromArray(S, second, so + 56));
            FloatVector px = FloatVector.fromArray(S, blk, fo).sub(cx);
            FloatVector py = FloatVector.fromArray(S, blk, fo + 8).sub(cy);
            FloatVector pz = FloatVector.fromArray(S, blk, fo + 16).sub(cz);
            FloatVector ux = ry.mul(pz).sub(rz.mul(py)).add(rw.mul(px));
            FloatVector uy = rz.mul(px).sub(rx.mul(pz)).add(rw.mul(py));
            FloatVector uz = rx.mul(py).sub(ry.mul(px)).add(rw.mul(pz));
            FloatVector ex = ry.mul(uz).sub(rz.mul(uy));
            FloatVector ey = rz.mul(ux).sub(rx.mul(uz));
            FloatVector ez = rx.mul(uy).sub(ry.mul(ux));
            FloatVector ox = px.add(ex.add(ex)).add(tx);
            FloatVector oy = py.add(ey.add(ey)).add(ty);
            FloatVector oz = pz.add(ez.add(ez)).add(tz);
            int out = 3 * DqsLanes.BLOCK * b;
            ox.rearrange(Lanes.X0).blend(oy.rearrange(Lanes.Y0), Lanes.MY0).blend(oz.rearrange(Lanes.Z0), Lanes.MZ0).intoArray(outPositions, out);
            ox.rearrange(Lanes.X1).blend(oy.rearrange(Lanes.Y1), Lanes.MY1).blend(oz.rearrange(Lanes.Z1), Lanes.MZ1).intoArray(outPositions, out + 8);
            ox.rearrange(Lanes.X2).blend(oy.rearrange(Lanes.Y2), Lanes.MY2).blend(oz.rearrange(Lanes.Z2), Lanes.MZ2).intoArray(outPositions, out + 16);
            FloatVector nx = FloatVector.fromArray(S, blk, fo + 24);
            FloatVector ny = FloatVector.fromArray(S, blk, fo + 32);
            FloatVector nz = FloatVector.fromArray(S, blk, fo + 40);
            ux = ry.mul(nz).sub(rz.mul(ny)).add(rw.mul(nx));
            uy = rz.mul(nx).sub(rx.mul(nz)).add(rw.mul(ny));
            uz = rx.mul(ny).sub(ry.mul(nx)).add(rw.mul(nz));
            ex = ry.mul(uz).sub(rz.mul(uy));
            ey = rz.mul(ux).sub(rx.mul(uz));
            ez = rx.mul(uy).sub(ry.mul(ux));
            ox = nx.add(ex.add(ex));
            oy = ny.add(ey.add(ey));
            oz = nz.add(ez.add(ez));
            ox.rearrange(Lanes.X0).blend(oy.rearrange(Lanes.Y0), Lanes.MY0).blend(oz.rearrange(Lanes.Z0), Lanes.MZ0).intoArray(outNormals, out);
            ox.rearrange(Lanes.X1).blend(oy.rearrange(Lanes.Y1), Lanes.MY1).blend(oz.rearrange(Lanes.Z1), Lanes.MZ1).intoArray(outNormals, out + 8);
            ox.rearrange(Lanes.X2).blend(oy.rearrange(Lanes.Y2), Lanes.MY2).blend(oz.rearrange(Lanes.Z2), Lanes.MZ2).intoArray(outNormals, out + 16);
        }
    }

    /**
     * Blocks {@code [firstBlock, endBlock)}, in place in {@code first}: each point's motion
     * {@code p -> R p + T}, {@code T = A c - R c}, as the dual quaternion that
     * {@link DqsLanes#rigidDeformations} reads (component c at {@code 8 c}: the blended rotation
     * quaternion as it is, then the dual part). For the unit quaternion r the dual part is
     * {@code d = T r / 2} (T as a pure quaternion), {@code d_v = (r_w T + T x r) / 2},
     * {@code d_w = -(T . r) / 2}; it is stored times |blend| because rigidDeformations divides both
     * parts by it.
     */
    static void asDualQuaternions(float[] first, float[] second, float[] centres, int firstBlock, int endBlock) {
        final FloatVector one = FloatVector.broadcast(S, 1f);
        for (int b = firstBlock; b < endBlock; b++) {
            int so = DqsLanes.SCRATCH * (b - firstBlock);
            int co = 3 * DqsLanes.BLOCK * b;
            FloatVector x0 = FloatVector.fromArray(S, first, so);
            FloatVector x1 = FloatVector.fromArray(S, first, so + 8);
            FloatVector x2 = FloatVector.fromArray(S, first, so + 16);
            FloatVector x3 = FloatVector.fromArray(S, first, so + 24);
            FloatVector norm = x0.mul(x0).add(x1.mul(x1)).add(x2.mul(x2)).add(x3.mul(x3)).sqrt();
            FloatVector inv = one.div(norm);
            FloatVector rx = x0.mul(inv);
            FloatVector ry = x1.mul(inv);
            FloatVector rz = x2.mul(inv);
            FloatVector rw = x3.mul(inv);
            FloatVector cx = FloatVector.fromArray(S, centres, co);
            FloatVector cy = FloatVector.fromArray(S, centres, co + 8);
            FloatVector cz = FloatVector.fromArray(S, centres, co + 16);
            FloatVector tx = FloatVector.fromArray(S, first, so + 32).mul(cx)
                    .add(FloatVector.fromArray(S, first, so + 40).mul(cy))
                    .add(FloatVector.fromArray(S, first, so + 48).mul(cz))
                    .add(FloatVector.fromArray(S, first, so + 56));
            FloatVector ty = FloatVector.fromArray(S, second, so).mul(cx)
                    .add(FloatVector.fromArray(S, second, so + 8).mul(cy))
                    .add(FloatVector.fromArray(S, second, so + 16).mul(cz))
                    .add(FloatVector.fromArray(S, second, so + 24));
            FloatVector tz = FloatVector.fromArray(S, second, so + 32).mul(cx)
                    .add(FloatVector.fromArray(S, second, so + 40).mul(cy))
                    .add(FloatVector.fromArray(S, second, so + 48).mul(cz))
                    .add(FloatVector.fromArray(S, second, so + 56));
            // T = A c - R c, R c = c + 2 r x (r x c + w c).
            FloatVector ux = ry.mul(cz).sub(rz.mul(cy)).add(rw.mul(cx));
            FloatVector uy = rz.mul(cx).sub(rx.mul(cz)).add(rw.mul(cy));
            FloatVector uz = rx.mul(cy).sub(ry.mul(cx)).add(rw.mul(cz));
            FloatVector ex = ry.mul(uz).sub(rz.mul(uy));
            FloatVector ey = rz.mul(ux).sub(rx.mul(uz));
            FloatVector ez = rx.mul(uy).sub(ry.mul(ux));
            tx = tx.sub(cx.add(ex.add(ex)));
            ty = ty.sub(cy.add(ey.add(ey)));
            tz = tz.sub(cz.add(ez.add(ez)));
            FloatVector half = norm.mul(0.5f);
            rw.mul(tx).add(ty.mul(rz).sub(tz.mul(ry))).mul(half).intoArray(first, so + 32);
            rw.mul(ty).add(tz.mul(rx).sub(tx.mul(rz))).mul(half).intoArray(first, so + 40);
            rw.mul(tz).add(tx.mul(ry).sub(ty.mul(rx))).mul(half).intoArray(first, so + 48);
            tx.mul(rx).add(ty.mul(ry)).add(tz.mul(rz)).mul(half).neg().intoArray(first, so + 56);
        }
    }
}
