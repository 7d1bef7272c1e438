package org.skinlab.simd;

import static org.skinlab.simd.Lanes.HI;
import static org.skinlab.simd.Lanes.S;
import static org.skinlab.simd.Lanes.SWAP;
import static org.skinlab.simd.Lanes.YZX;
import static org.skinlab.simd.Lanes.ZXY;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorOperators;

import org.skinlab.skinning.Skinner;

/**
 * Point-by-point passes on blended 3x4 matrices, one point per iteration with the matrix spread
 * over the 8 lanes as two vectors {@code [c0 | c1]}, {@code [c2 | c3]} (columns, c3 the
 * translation, row 3 zero): the blend of any number of influences, composing with a rigid
 * matrix, and applying the result to a point (positions and normals, positions alone, or a
 * deformation of {@link Skinner#skinDeformations}). Passes meet in a small scratch of
 * {@link #CHUNK} matrices (16 floats each) that stays in L1.
 *
 * <p><b>Sign of a determinant</b> (exact normals): {@code clamp(d * 1e30, -1, 1)}, two lane-wise
 * min/max and a multiply, written out in each loop. A compare and a masked blend would say it
 * exactly, but tipped C2 over its inlining budget on JDK 17, and a call of a method of ours is not
 * inlined there either: either way every vector is then boxed (80x slower). It differs from
 * {@code Math.copySign(1, d)} only for |d| < 1e-30, where the determinant's tiny magnitude is kept
 * (the normal is renormalised afterwards; zero for a singular matrix, which has no normal
 * direction).
 *
 * <p>Why passes and not one loop: an influence loop with a variable trip count carries its
 * vectors through loop phis, which measured 1.5x slower than straight-line code on JDK 17 and 25;
 * so blends are written out for 4, 6 and 8 influences (fewer are padded with weight 0), and more
 * than 8 add their remainder in a further pass through the scratch.
 */
final class MatrixPasses {
    /** Matrices per pass (4 KB of scratch). */
    static final int CHUNK = 64;

    private MatrixPasses() {
    }

    /**
     * Influences padded to the width a blend pass takes: 4, 6 (the cap of several exporters), 8,
     * or the count itself beyond 8.
     */
    static int paddedWidth(int width) {
        return width <= 4 ? 4 : width <= 6 ? 6 : Math.max(8, width);
    }

    /**
     * Copies row-major 3x4 matrices (12 floats each) into column-major 4x4 blocks with row 3 zero
     * (16 floats each), the layout the passes load.
     */
    static void columnMajor(float[] m, int joints, float[] c) {
        for (int j = 0; j < joints; j++) {
            int s = 12 * j;
            int d = 16 * j;
            c[d] = m[s];
            c[d + 1] = m[s + 4];
            c[d + 2] = m[s + 8];
            c[d + 4] = m[s + 1];
            c[d + 5] = m[s + 5];
            c[d + 6] = m[s + 9];
            c[d + 8] = m[s + 2];
            c[d + 9] = m[s + 6];
            c[d + 10] = m[s + 10];
            c[d + 12] = m[s + 3];
            c[d + 13] = m[s + 7];
            c[d + 14] = m[s + 11];
        }
    }

    /**
     * {@code sum_k w_k C_(j_k)} for points {@code [from, to)} into {@code acc} (16 floats per
     * point from 0). {@code width} influences per point at {@code width * point} in {@code joints}
     * and {@code weights}, a {@link #paddedWidth}.
     */
    static void blend(float[] c, char[] joints, float[] weights, int width, int from, int to, float[] acc) {
        if (width == 4) {
            blend4(c, joints, weights, 0, 4, from, to, acc);
            return;
        }
        if (width == 6) {
            blend6(c, joints, weights, from, to, acc);
            return;
        }
        blend8(c, joints, weights, width, from, to, acc);
        for (int k = 8; k < width; k++) {
            for (int i = from; i < to; i++) {
                int q = width * i + k;
                int m = joints[q] << 4;
                int a = 16 * (i - from);
                FloatVector w = FloatVector.broadcast(S, weights[q]);
                FloatVector.fromArray(S, c, m).fma(w, FloatVector.fromArray(S, acc, a)).intoArray(acc, a);
                FloatVector.fromArray(S, c, m + 8).fma(w, FloatVector.fromArray(S, acc, a + 8)).intoArray(acc, a + 8);
            }
        }
    }

    /**
     * Four influences per point: joints at {@code 4 * point}, weights at {@code weightOffset +
     * weightStride * point} (so a kernel's own interleaved stream can be read in place).
     */
    static void blend4(float[] c, char[] joints, float[] weights, int weightOffset, int weightStride, int from,
            int to, float[] acc) {
        for (int i = from; i < to; i++) {
            int q = 4 * i;
            int m0 = joints[q] << 4;
            int m1 = joints[q + 1] << 4;
            int m2 = joints[q + 2] << 4;
            int m3 = joints[q + 3] << 4;
            int r = weightOffset + weightStride * i;
            FloatVector w0 = FloatVector.broadcast(S, weights[r]);
            FloatVector w1 = FloatVector.broadcast(S, weights[r + 1]);
            FloatVector w2 = FloatVector.broadcast(S, weights[r + 2]);
            FloatVector w3 = FloatVector.broadcast(S, weights[r + 3]);
            FloatVector a = FloatVector.fromArray(S, c, m0).mul(w0);
            FloatVector b = FloatVector.fromArray(S, c, m0 + 8).mul(w0);
            a = FloatVector.fromArray(S, c, m1).fma(w1, a);
            b = FloatVector.fromArray(S, c, m1 + 8).fma(w1, b);
            a = FloatVector.fromArray(S, c, m2).fma(w2, a);
            b = FloatVector.fromArray(S, c, m2 + 8).fma(w2, b);
            a = FloatVector.fromArray(S, c, m3).fma(w3, a);
            b = FloatVector.fromArray(S, c, m3 + 8).fma(w3, b);
            int o = 16 * (i - from);
            a.intoArray(acc, o);
            b.intoArray(acc, o + 8);
        }
    }

    private static void blend6(float[] c, char[] joints, float[] weights, int from, int to, float[] acc) {
        for (int i = from; i < to; i++) {
            int q = 6 * i;
            int m0 = joints[q] << 4;
            int m1 = joints[q + 1] << 4;
            int m2 = joints[q + 2] << 4;
            int m3 = joints[q + 3] << 4;
            int m4 = joints[q + 4] << 4;
            int m5 = joints[q + 5] << 4;
            FloatVector w = FloatVector.broadcast(S, weights[q]);
            FloatVector a = FloatVector.fromArray(S, c, m0).mul(w);
            FloatVector b = FloatVector.fromArray(S, c, m0 + 8).mul(w);
            w = FloatVector.broadcast(S, weights[q + 1]);
            a = FloatVector.fromArray(S, c, m1).fma(w, a);
            b = FloatVector.fromArray(S, c, m1 + 8).fma(w, b);
            w = FloatVector.broadcast(S, weights[q + 2]);
            a = FloatVector.fromArray(S, c, m2).fma(w, a);
            b = FloatVector.fromArray(S, c, m2 + 8).fma(w, b);
            w = FloatVector.broadcast(S, weights[q + 3]);
            a = FloatVector.fromArray(S, c, m3).fma(w, a);
            b = FloatVector.fromArray(S, c, m3 + 8).fma(w, b);
            w = FloatVector.broadcast(S, weights[q + 4]);
            a = FloatVector.fromArray(S, c, m4).fma(w, a);
            b = FloatVector.fromArray(S, c, m4 + 8).fma(w, b);
            w = FloatVector.broadcast(S, weights[q + 5]);
            a = FloatVector.fromArray(S, c, m5).fma(w, a);
            b = FloatVector.fromArray(S, c, m5 + 8).fma(w, b);
            int o = 16 * (i - from);
            a.intoArray(acc, o);
            b.intoArray(acc, o + 8);
        }
    }

    /** The first 8 influences of {@code width >= 8} per point. */
    private static void blend8(float[] c, char[] joints, float[] weights, int width, int from, int to, float[] acc) {
        for (int i = from; i < to; i++) {
            int q = width * i;
            int m0 = joints[q] << 4;
            int m1 = joints[q + 1] << 4;
            int m2 = joints[q + 2] << 4;
            int m3 = joints[q + 3] << 4;
            int m4 = joints[q + 4] << 4;
            int m5 = joints[q + 5] << 4;
            int m6 = joints[q + 6] << 4;
            int m7 = joints[q + 7] << 4;
            FloatVector w = FloatVector.broadcast(S, weights[q]);
            FloatVector a = FloatVector.fromArray(S, c, m0).mul(w);
            FloatVector b = FloatVector.fromArray(S, c, m0 + 8).mul(w);
            w = FloatVector.broadcast(S, weights[q + 1]);
            a = FloatVector.fromArray(S, c, m1).fma(w, a);
            b = FloatVector.fromArray(S, c, m1 + 8).fma(w, b);
            w = FloatVector.broadcast(S, weights[q + 2]);
            a = FloatVector.fromArray(S, c, m2).fma(w, a);
            b = FloatVector.fromArray(S, c, m2 + 8).fma(w, b);
            w = FloatVector.broadcast(S, weights[q + 3]);
            a = FloatVector.fromArray(S, c, m3).fma(w, a);
            b = FloatVector.fromArray(S, c, m3 + 8).fma(w, b);
            w = FloatVector.broadcast(S, weights[q + 4]);
            a = FloatVector.fromArray(S, c, m4).fma(w, a);
            b = FloatVector.fromArray(S, c, m4 + 8).fma(w, b);
            w = FloatVector.broadcast(S, weights[q + 5]);
            a = FloatVector.fromArray(S, c, m5).fma(w, a);
            b = FloatVector.fromArray(S, c, m5 + 8).fma(w, b);
            w = FloatVector.broadcast(S, weights[q + 6]);
            a = FloatVector.fromArray(S, c, m6).fma(w, a);
            b = FloatVector.fromArray(S, c, m6 + 8).fma(w, b);
            w = FloatVector.broadcast(S, weights[q + 7]);
            a = FloatVector.fromArray(S, c, m7).fma(w, a);
            b = FloatVector.fromArray(S, c, m7 + 8).fma(w, b);
            int o = 16 * (i - from);
            a.intoArray(acc, o);
            b.intoArray(acc, o + 8);
        }
    }

    /**
     * {@code acc_l = D_l acc_l} for {@code l < count}: each scratch matrix composed with the rigid
     * motion {@code D = [R | t]} of the deformation at the same place in {@code rigid} (deformations of
     * points {@code firstPoint + l}, as {@link Skinner#skinDeformations} lays them out, N = R), t
     * recovered as {@code p' - R p} from the deformation's position and the point's rest position.
     * Column c of the product is {@code R s_c} (plus {@code t} for the translation column).
     */
    static void compose(float[] rigid, float[] positions, int firstPoint, float[] acc, int count) {
        for (int l = 0; l < count; l++) {
            int o = 16 * l;
            int v = 3 * (firstPoint + l);
            FloatVector f01 = FloatVector.fromArray(S, rigid, o);
            FloatVector fp2 = FloatVector.fromArray(S, rigid, o + 8);
            // [R0 | R0], [R1 | R1], [R2 | R2], [p' | p']
            FloatVector r0 = f01.blend(f01.rearrange(SWAP), HI);
            FloatVector r1 = f01.rearrange(SWAP).blend(f01, HI);
            FloatVector fp2Swap = fp2.rearrange(SWAP);
            FloatVector r2 = fp2Swap.blend(fp2, HI);
            FloatVector moved = fp2.blend(fp2Swap, HI);
            FloatVector t = moved.sub(r0.mul(FloatVector.broadcast(S, positions[v]))
                    .add(r1.mul(FloatVector.broadcast(S, positions[v + 1])))
                    .add(r2.mul(FloatVector.broadcast(S, positions[v + 2]))));
            t = FloatVector.zero(S).blend(t, HI);
            float[] s = acc;
            FloatVector s01 = r0.mul(FloatVector.broadcast(S, s[o]).blend(FloatVector.broadcast(S, s[o + 4]), HI))
                    .add(r1.mul(FloatVector.broadcast(S, s[o + 1]).blend(FloatVector.broadcast(S, s[o + 5]), HI)))
                    .add(r2.mul(FloatVector.broadcast(S, s[o + 2]).blend(FloatVector.broadcast(S, s[o + 6]), HI)));
            FloatVector s23 = r0.mul(FloatVector.broadcast(S, s[o + 8]).blend(FloatVector.broadcast(S, s[o + 12]), HI))
                    .add(r1.mul(FloatVector.broadcast(S, s[o + 9]).blend(FloatVector.broadcast(S, s[o + 13]), HI)))
                    .add(r2.mul(FloatVector.broadcast(S, s[o + 10]).blend(FloatVector.broadcast(S, s[o + 14]), HI)))
                    .add(t);
            s01.intoArray(acc, o);
            s23.intoArray(acc, o + 8);
        }
    }

    /**
     * Deformations ({@link Skinner#skinDeformations}) of points {@code [from, to)} from their matrices in
     * {@code acc} (from 0): the deformed position and, with {@code cofactor}, the matrix's cofactor
     * (times the sign of its determinant when {@code signed}: the palette mirrors), else its linear
     * part.
     */
    static void deformations(float[] acc, float[] positions, boolean cofactor, boolean signed, float[] out, int from,
            int to) {
        final FloatVector one = FloatVector.broadcast(S, 1f);
        final float lo = signed ? -1f : 1f; // +1: the clamp below always gives 1
        for (int i = from; i < to; i++) {
            int o = 16 * (i - from);
            FloatVector a = FloatVector.fromArray(S, acc, o);
            FloatVector b = FloatVector.fromArray(S, acc, o + 8);
            int v = 3 * i;
            FloatVector pxy = FloatVector.broadcast(S, positions[v]).blend(FloatVector.broadcast(S, positions[v + 1]), HI);
            FloatVector pz1 = FloatVector.broadcast(S, positions[v + 2]).blend(one, HI);
            FloatVector p = a.mul(pxy).add(b.mul(pz1));
            p = p.add(p.rearrange(SWAP)); // the position in both halves
            int f = Skinner.DEFORMATION_FLOATS * i;
            if (cofactor) {
                // [c1 | c2] x [c2 | c0] = [c1 x c2 | c2 x c0]; [c0 | c1] x [c1 | c0] = [c0 x c1 | ...]
                FloatVector aSwap = a.rearrange(SWAP);
                FloatVector left = aSwap.blend(b.rearrange(SWAP), HI);
                FloatVector right = b.blend(aSwap, HI);
                FloatVector k01 = left.mul(right.rearrange(YZX)).sub(left.rearrange(YZX).mul(right)).rearrange(YZX);
                FloatVector k2 = a.mul(aSwap.rearrange(YZX)).sub(a.rearrange(YZX).mul(aSwap)).rearrange(YZX);
                // det = c0 . (c1 x c2) = c1 . (c2 x c0): in lanes 0-2 and 4-6 after summing x, y, z
                FloatVector d = a.mul(k01);
                d = d.add(d.rearrange(YZX)).add(d.rearrange(ZXY));
                FloatVector sign = d.mul(1e30f).max(lo).min(1f); // sign(d), written out
                k01.mul(sign).intoArray(out, f);
                // k2's upper half is c1 x c0 = -(c0 x c1): [p | k2] without a permutation
                p.blend(k2.mul(sign).neg(), HI).intoArray(out, f + 8);
            } else {
                a.intoArray(out, f);
                p.blend(b.rearrange(SWAP), HI).intoArray(out, f + 8);
            }
        }
    }

    /**
     * Positions and normals of points {@code [from, to)} from their matrices in {@code acc} (from
     * 0), written at {@code 3 * point}: the normal by the cofactor (times the sign of the
     * determinant when {@code signed}) and renormalised ({@code exact}), or by the linear part. Each point's results are
     * written with 8-lane stores whose tail spills into the next points; unless {@code spillOk}
     * (more points of the same call follow and overwrite it), the last two points go through
     * {@code tmp} (16 floats), so nothing is written outside the range. Exact normals still need
     * {@link #normalise}.
     */
    static void points(float[] acc, float[] positions, float[] normals, boolean exact, boolean signed,
            float[] outPositions, float[] outNormals, int from, int to, float[] tmp, boolean spillOk) {
        int end = spillOk ? to : Math.max(from, to - 2);
        float lo = signed ? -1f : 1f; // +1: the sign clamp always gives 1
        points(acc, positions, normals, exact, lo, outPositions, outNormals, from, from, end, 0, 0);
        for (int i = end; i < to; i++) {
            int v = 3 * i;
            points(acc, positions, normals, exact, lo, tmp, tmp, from, i, i + 1, -v, 8 - v);
            System.arraycopy(tmp, 0, outPositions, v, 3);
            System.arraycopy(tmp, 8, outNormals, v, 3);
        }
    }

    private static void points(float[] acc, float[] positions, float[] normals, boolean exact, float lo,
            float[] outPositions, float[] outNormals, int base, int from, int end, int positionShift, int normalShift) {
        final FloatVector one = FloatVector.broadcast(S, 1f);
        final FloatVector zero = FloatVector.zero(S);
        for (int i = from; i < end; i++) {
            int o = 16 * (i - base);
            FloatVector a = FloatVector.fromArray(S, acc, o);
            FloatVector b = FloatVector.fromArray(S, acc, o + 8);
            int v = 3 * i;
            FloatVector pxy = FloatVector.broadcast(S, positions[v]).blend(FloatVector.broadcast(S, positions[v + 1]), HI);
            FloatVector pz1 = FloatVector.broadcast(S, positions[v + 2]).blend(one, HI);
            FloatVector p = a.mul(pxy).add(b.mul(pz1));
            p.add(p.rearrange(SWAP)).intoArray(outPositions, v + positionShift);
            FloatVector nxy = FloatVector.broadcast(S, normals[v]).blend(FloatVector.broadcast(S, normals[v + 1]), HI);
            if (exact) {
                FloatVector aSwap = a.rearrange(SWAP);
                FloatVector left = aSwap.blend(b.rearrange(SWAP), HI);
                FloatVector right = b.blend(aSwap, HI);
                FloatVector k01 = left.mul(right.rearrange(YZX)).sub(left.rearrange(YZX).mul(right)).rearrange(YZX);
                FloatVector k2 = a.mul(aSwap.rearrange(YZX)).sub(a.rearrange(YZX).mul(aSwap)).rearrange(YZX);
                FloatVector d = a.mul(k01);
                d = d.add(d.rearrange(YZX)).add(d.rearrange(ZXY));
                FloatVector sign = d.mul(1e30f).max(lo).min(1f); // sign(d), written out
                FloatVector t = k01.mul(nxy);
                t.add(t.rearrange(SWAP)).add(k2.mul(FloatVector.broadcast(S, normals[v + 2]))).mul(sign)
                        .intoArray(outNormals, v + normalShift);
            } else {
                FloatVector nz0 = FloatVector.broadcast(S, normals[v + 2]).blend(zero, HI);
                FloatVector n = a.mul(nxy).add(b.mul(nz0));
                n.add(n.rearrange(SWAP)).intoArray(outNormals, v + normalShift);
            }
        }
    }

    /**
     * {@link #points} without normals ({@link org.skinlab.skinning.NormalTransform#NONE}): the
     * positions of points {@code [from, to)}, the same operations, the same spill rule.
     */
    static void positions(float[] acc, float[] positions, float[] outPositions, int from, int to, float[] tmp,
            boolean spillOk) {
        int end = spillOk ? to : Math.max(from, to - 2);
        positions(acc, positions, outPositions, from, from, end, 0);
        for (int i = end; i < to; i++) {
            int v = 3 * i;
            positions(acc, positions, tmp, from, i, i + 1, -v);
            System.arraycopy(tmp, 0, outPositions, v, 3);
        }
    }

    private static void positions(float[] acc, float[] positions, float[] outPositions, int base, int from, int end,
            int positionShift) {
        final FloatVector one = FloatVector.broadcast(S, 1f);
        for (int i = from; i < end; i++) {
            int o = 16 * (i - base);
            FloatVector a = FloatVector.fromArray(S, acc, o);
            FloatVector b = FloatVector.fromArray(S, acc, o + 8);
            int v = 3 * i;
            FloatVector pxy = FloatVector.broadcast(S, positions[v]).blend(FloatVector.broadcast(S, positions[v + 1]), HI);
            FloatVector pz1 = FloatVector.broadcast(S, positions[v + 2]).blend(one, HI);
            FloatVector p = a.mul(pxy).add(b.mul(pz1));
            p.add(p.rearrange(SWAP)).intoArray(outPositions, v + positionShift);
        }
    }

    /**
     * Scales the normals of points {@code [from, to)} (interleaved, at {@code 3 * point}) to unit
     * length, zero ones staying zero: eight points per step, de-interleaved into x, y, z lanes, so
     * that a square root and a division serve eight normals. Points past the last whole group of
     * eight take the same float operations one by one, so results do not depend on where groups
     * start.
     */
    static void normalise(float[] normals, int from, int to) {
        final FloatVector zero = FloatVector.zero(S);
        final FloatVector one = FloatVector.broadcast(S, 1f);
        int i = from;
        for (; i + 8 <= to; i += 8) {
            int o = 3 * i;
            FloatVector v0 = FloatVector.fromArray(S, normals, o);
            FloatVector v1 = FloatVector.fromArray(S, normals, o + 8);
            FloatVector v2 = FloatVector.fromArray(S, normals, o + 16);
            FloatVector x = v0.rearrange(Lanes.GX0).blend(v1.rearrange(Lanes.GX1), Lanes.MGX1)
                    .blend(v2.rearrange(Lanes.GX2), Lanes.MGX2);
            FloatVector y = v0.rearrange(Lanes.GY0).blend(v1.rearrange(Lanes.GY1), Lanes.MGY1)
                    .blend(v2.rearrange(Lanes.GY2), Lanes.MGY2);
            FloatVector z = v0.rearrange(Lanes.GZ0).blend(v1.rearrange(Lanes.GZ1), Lanes.MGZ1)
                    .blend(v2.rearrange(Lanes.GZ2), Lanes.MGZ2);
            FloatVector len2 = x.mul(x).add(y.mul(y)).add(z.mul(z));
            FloatVector scale = zero.blend(one.div(len2.sqrt()), len2.compare(VectorOperators.GT, 0f));
            v0.mul(scale.rearrange(Lanes.TRIPLE0)).intoArray(normals, o);
            v1.mul(scale.rearrange(Lanes.TRIPLE1)).intoArray(normals, o + 8);
            v2.mul(scale.rearrange(Lanes.TRIPLE2)).intoArray(normals, o + 16);
        }
        for (; i < to; i++) {
            int o = 3 * i;
            float x = normals[o];
            float y = normals[o + 1];
            float z = normals[o + 2];
            float len2 = x * x + y * y + z * z;
            float scale = len2 > 0f ? 1f / (float) Math.sqrt(len2) : 0f;
            normals[o] = x * scale;
            normals[o + 1] = y * scale;
            normals[o + 2] = z * scale;
        }
    }
}
