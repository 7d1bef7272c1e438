package org.skinlab.simd;

import static org.skinlab.simd.Lanes.HI;
import static org.skinlab.simd.Lanes.S;
import static org.skinlab.simd.Lanes.SWAP;
import static org.skinlab.simd.Lanes.YZX;

import jdk.incubator.vector.FloatVector;

import org.skinlab.skinning.AbstractSkinner;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;

/**
 * Linear Blend Skinning on 8-lane vectors, one point at a time with the matrix spread over the
 * lanes (the layout of ozz-animation's SSE skinning job, at twice the width):
 *
 * <ul>
 * <li>per call, the palette's row-major 3x4 matrices are copied into column-major 4x4 blocks
 *     {@code [c0 | c1]}, {@code [c2 | c3]} (c3 the translation, row 3 zero): two vector loads per
 *     joint, no gather (gathers are slow on the machines we measured: about 1 cycle per lane);</li>
 * <li>per point, {@code [c0 | c1] = sum_k w_k [c0 | c1]_(j_k)} and the same for {@code [c2 | c3]}
 *     (two fused multiply-adds per influence), then {@code p' = c0 px + c1 py + c2 pz + c3} as
 *     {@code [c0|c1] * [px px px px | py py py py] + [c2|c3] * [pz.. | 1..]} and the sum of the two
 *     halves;</li>
 * <li>the geometry is repacked once, in the constructor, into one stream of 10 floats per point
 *     ({@code px py pz nx ny nz w0 w1 w2 w3}) plus one of joint indices (char); a point's
 *     operands {@code [px.. | py..]} etc. are two broadcasts and a blend (JDK 17 checks a
 *     shuffle's indexes at every lane permutation, which measured 10-15% slower).</li>
 * </ul>
 *
 * <p>Each point's result is written with one 8-lane store at {@code 3 * point}, whose last five
 * lanes spill into the next points and are overwritten when those are done; the last two points
 * of a range therefore go through a scratch array, so a range never writes outside itself (and
 * the results do not depend on how a mesh is split into ranges).
 *
 * <p>Geometries with up to 4 influences per point are padded to 4 with weight 0 and take the
 * fused loops below; more influences, and {@link #skinDeformations}, go through {@link MatrixPasses}
 * (a blend pass written out for 4 or 8 influences, then the application to the points).
 *
 * <p>Positions only ({@link NormalTransform#NONE}): the stream holds 7 floats per point
 * ({@code px py pz w0 w1 w2 w3}) and {@link #positions} is the fused loop without the normal, or
 * the passes end in {@link MatrixPasses#positions}; the same blend and position operations, so the
 * same bits as with normals.
 *
 * <p>When the palette mirrors ({@link JointPalette#mirrorsMatrices()}), exact normals carry the sign
 * of the blended matrix's determinant (a mirroring blend would otherwise turn them inwards), as in
 * the scalar kernel; such palettes take the passes, whose loops have that sign, and the fused
 * loops stay without its cost.
 */
final class VectorLbsSkinner extends AbstractSkinner {
    static final int INFLUENCES = 4;
    /** Floats per point in {@link #points}. */
    private static final int STRIDE = 10;
    /** Floats per point in {@link #points} under {@link NormalTransform#NONE}: px py pz w0 w1 w2 w3. */
    private static final int POSITION_STRIDE = 7;


    /** Up to 4 influences: the fused loops' stream (null otherwise). */
    private final float[] points;
    /** Palette joint per influence (4 or {@link #passWidth} per point; char: joint counts up to 65536). */
    private final char[] joints;
    /** The weights the blend pass reads: {@link #points} (fused) or {@link #passWidth} per point. */
    private final float[] passWeights;
    private final boolean fused;
    /** The stream's floats per point and where in them the weights start. */
    private final int stride;
    private final int weightOffset;
    private final int passWidth;
    private final float[] restPositions;
    private final float[] restNormals;
    private final int jointCount;
    private final ThreadLocal<float[]> columns;
    private final ThreadLocal<float[]> scratch = ThreadLocal.withInitial(() -> new float[16 * MatrixPasses.CHUNK]);
    private final ThreadLocal<float[]> lastPointScratch = ThreadLocal.withInitial(() -> new float[16]);

    VectorLbsSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.LBS, "vector-256", geometry, normals);
        int width = geometry.influencesPerPoint();
        this.jointCount = geometry.jointCount();
        this.restPositions = geometry.positionArray();
        this.restNormals = geometry.normalArray();
        int n = geometry.pointCount();
        int[] joints = geometry.jointArray();
        float[] weights = geometry.weightArray();
        this.fused = width <= INFLUENCES;
        this.passWidth = MatrixPasses.paddedWidth(width);
        this.stride = normals == NormalTransform.NONE ? POSITION_STRIDE : STRIDE;
        this.weightOffset = stride - INFLUENCES;
        if (fused) {
            points = new float[stride * n];
            this.joints = new char[INFLUENCES * n];
            passWeights = points;
            restShapeChanged();
            for (int i = 0; i < n; i++) {
                int o = stride * i;
                for (int k = 0; k < INFLUENCES; k++) {
                    // Padding: weight 0 on the first joint adds exactly nothing.
                    points[o + weightOffset + k] = k < width ? weights[width * i + k] : 0f;
                    this.joints[INFLUENCES * i + k] = (char) joints[width * i + (k < width ? k : 0)];
                }
            }
        } else {
            points = null;
            this.joints = new char[passWidth * n];
            passWeights = new float[passWidth * n];
            for (int i = 0; i < n; i++) {
                for (int k = 0; k < passWidth; k++) {
                    passWeights[passWidth * i + k] = k < width ? weights[width * i + k] : 0f;
                    this.joints[passWidth * i + k] = (char) joints[width * i + (k < width ? k : 0)];
                }
            }
        }
        int size = 16 * jointCount;
        columns = ThreadLocal.withInitial(() -> new float[size]);
    }

    /**
     * Copies the rest positions and normals (positions only under {@link NormalTransform#NONE})
     * into the fused layout (the unfused one reads them in place).
     */
    @Override
    public void restShapeChanged() {
        if (!fused) {
            return;
        }
        float[] pos = restPositions;
        float[] nrm = restNormals;
        for (int i = 0, n = pos.length / 3; i < n; i++) {
            int o = stride * i;
            points[o] = pos[3 * i];
            points[o + 1] = pos[3 * i + 1];
            points[o + 2] = pos[3 * i + 2];
            if (stride == POSITION_STRIDE) {
                continue;
            }
            points[o + 3] = nrm[3 * i];
            points[o + 4] = nrm[3 * i + 1];
            points[o + 5] = nrm[3 * i + 2];
        }
    }

    /** Blends points [from, to) into the scratch (16 floats per point from 0). */
    private void blend(float[] c, int from, int to, float[] acc) {
        if (fused) {
            MatrixPasses.blend4(c, joints, passWeights, weightOffset, stride, from, to, acc);
        } else {
            MatrixPasses.blend(c, joints, passWeights, passWidth, from, to, acc);
        }
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        if (normals == NormalTransform.NONE) {
            throw noDeformationsWithoutNormals();
        }
        float[] c = columnMajor(palette);
        float[] acc = scratch.get();
        boolean cofactor = normals == NormalTransform.INVERSE_TRANSPOSE;
        boolean mirror = cofactor && palette.mirrorsMatrices();
        for (int s = from; s < to; s += MatrixPasses.CHUNK) {
            int e = Math.min(to, s + MatrixPasses.CHUNK);
            blend(c, s, e, acc);
            MatrixPasses.deformations(acc, restPositions, cofactor, mirror, outDeformations, s, e);
        }
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        float[] c = columnMajor(palette);
        if (normals == NormalTransform.NONE) {
            skinPositions(c, outPositions, from, to);
            return;
        }
        boolean exact = normals == NormalTransform.INVERSE_TRANSPOSE;
        boolean mirror = exact && palette.mirrorsMatrices();
        // The fused loops leave out the determinant's sign, which only a mirroring palette needs.
        if (!fused || mirror) {
            float[] acc = scratch.get();
            float[] tmp = lastPointScratch.get();
            for (int s = from; s < to; s += MatrixPasses.CHUNK) {
                int e = Math.min(to, s + MatrixPasses.CHUNK);
                blend(c, s, e, acc);
                MatrixPasses.points(acc, restPositions, restNormals, exact, mirror, outPositions, outNormals, s, e,
                        tmp, to - e >= 2);
            }
            if (exact) {
                MatrixPasses.normalise(outNormals, from, to);
            }
            return;
        }
        int end = Math.max(from, to - 2);
        if (normals == NormalTransform.BLENDED_MATRIX) {
            blendedNormals(c, outPositions, outNormals, from, end);
        } else {
            exactNormals(c, outPositions, outNormals, from, end);
        }
        for (int i = end; i < to; i++) {
            lastPoint(c, outPositions, outNormals, i);
        }
        if (normals == NormalTransform.INVERSE_TRANSPOSE) {
            MatrixPasses.normalise(outNormals, from, to);
        }
    }

    /** {@link #skin} under {@link NormalTransform#NONE}: the fused loop or the passes, positions only. */
    private void skinPositions(float[] c, float[] outPositions, int from, int to) {
        if (!fused) {
            float[] acc = scratch.get();
            float[] tmp = lastPointScratch.get();
            for (int s = from; s < to; s += MatrixPasses.CHUNK) {
                int e = Math.min(to, s + MatrixPasses.CHUNK);
                blend(c, s, e, acc);
                MatrixPasses.positions(acc, restPositions, outPositions, s, e, tmp, to - e >= 2);
            }
            return;
        }
        int end = Math.max(from, to - 2);
        positions(c, outPositions, from, end, 0);
        float[] tmp = lastPointScratch.get();
        for (int i = end; i < to; i++) {
            // As lastPoint: the loop's store into a scratch copy, so nothing spills past the range.
            int v = 3 * i;
            positions(c, tmp, i, i + 1, -v);
            System.arraycopy(tmp, 0, outPositions, v, 3);
        }
    }

    /**
     * One point with the loops' arithmetic, written lane by lane (no spill past the point): so a
     * range's last points, and therefore any split of a mesh into ranges, give the same bits as
     * one range. Slow (lane extraction, boxed vectors when not inlined), used for two points per
     * range.
     */
    private void lastPoint(float[] c, float[] outPositions, float[] outNormals, int i) {
        float[] tmp = lastPointScratch.get();
        int v = 3 * i;
        if (normals == NormalTransform.BLENDED_MATRIX) {
            // The loop writes [v, v + 8) of both arrays; here it writes a scratch copy instead.
            blendedNormals(c, tmp, tmp, i, i + 1, -v, 8 - v);
        } else {
            exactNormals(c, tmp, tmp, i, i + 1, -v, 8 - v);
        }
        System.arraycopy(tmp, 0, outPositions, v, 3);
        System.arraycopy(tmp, 8, outNormals, v, 3);
    }

    /** This thread's copy of the palette as column-major 4x4 blocks (row 3 zero). */
    private float[] columnMajor(JointPalette palette) {
        if (palette.jointCount() != jointCount) {
            throw new IllegalArgumentException("palette of " + palette.jointCount() + " joints for a geometry of "
                    + jointCount);
        }
        float[] c = columns.get();
        MatrixPasses.columnMajor(palette.matrices(), jointCount, c);
        return c;
    }

    private void blendedNormals(float[] c, float[] outPositions, float[] outNormals, int from, int end) {
        blendedNormals(c, outPositions, outNormals, from, end, 0, 0);
    }

    /** The loop; point i's results go to {@code 3 i + positionShift} and {@code 3 i + normalShift}. */
    private void blendedNormals(float[] c, float[] outPositions, float[] outNormals, int from, int end,
            int positionShift, int normalShift) {
        final float[] pts = points;
        final char[] off = joints;
        final FloatVector one = FloatVector.broadcast(S, 1f);
        final FloatVector zero = FloatVector.zero(S);
        for (int i = from; i < end; i++) {
            int o = STRIDE * i;
            int q = INFLUENCES * i;
            int m0 = off[q] << 4;
            int m1 = off[q + 1] << 4;
            int m2 = off[q + 2] << 4;
            int m3 = off[q + 3] << 4;
            FloatVector w0 = FloatVector.broadcast(S, pts[o + 6]);
            FloatVector w1 = FloatVector.broadcast(S, pts[o + 7]);
            FloatVector w2 = FloatVector.broadcast(S, pts[o + 8]);
            FloatVector w3 = FloatVector.broadcast(S, pts[o + 9]);
            FloatVector a = FloatVector.fromArray(S, c, m0).mul(w0);
            FloatVector b = FloatVector.fromArray(S, c, m0 + 8).mul(w0);
            a = FloatVector.fromArray(S, c, m1).fma(w1, a);
            b = FloatVector.fromArray(S, c, m1 + 8).fma(w1, b);
            a = FloatVector.fromArray(S, c, m2).fma(w2, a);
            b = FloatVector.fromArray(S, c, m2 + 8).fma(w2, b);
            a = FloatVector.fromArray(S, c, m3).fma(w3, a);
            b = FloatVector.fromArray(S, c, m3 + 8).fma(w3, b);
            // Broadcasts and blends, not lane permutations of one load: JDK 17 checks a shuffle's
            // indexes at every rearrange, a constant mask costs nothing.
            FloatVector pxy = FloatVector.broadcast(S, pts[o]).blend(FloatVector.broadcast(S, pts[o + 1]), HI);
            FloatVector pz1 = FloatVector.broadcast(S, pts[o + 2]).blend(one, HI);
            FloatVector nxy = FloatVector.broadcast(S, pts[o + 3]).blend(FloatVector.broadcast(S, pts[o + 4]), HI);
            FloatVector nz0 = FloatVector.broadcast(S, pts[o + 5]).blend(zero, HI);
            FloatVector p = a.mul(pxy).add(b.mul(pz1));
            FloatVector n = a.mul(nxy).add(b.mul(nz0));
            p.add(p.rearrange(SWAP)).intoArray(outPositions, 3 * i + positionShift);
            n.add(n.rearrange(SWAP)).intoArray(outNormals, 3 * i + normalShift);
        }
    }

    /**
     * {@link #blendedNormals} without the normal, on the positions-only stream; point i's position
     * goes to {@code 3 i + positionShift}.
     */
    private void positions(float[] c, float[] outPositions, int from, int end, int positionShift) {
        final float[] pts = points;
        final char[] off = joints;
        final FloatVector one = FloatVector.broadcast(S, 1f);
        for (int i = from; i < end; i++) {
            int o = POSITION_STRIDE * i;
            int q = INFLUENCES * i;
            int m0 = off[q] << 4;
            int m1 = off[q + 1] << 4;
            int m2 = off[q + 2] << 4;
            int m3 = off[q + 3] << 4;
            FloatVector w0 = FloatVector.broadcast(S, pts[o + 3]);
            FloatVector w1 = FloatVector.broadcast(S, pts[o + 4]);
            FloatVector w2 = FloatVector.broadcast(S, pts[o + 5]);
            FloatVector w3 = FloatVector.broadcast(S, pts[o + 6]);
            FloatVector a = FloatVector.fromArray(S, c, m0).mul(w0);
            FloatVector b = FloatVector.fromArray(S, c, m0 + 8).mul(w0);
            a = FloatVector.fromArray(S, c, m1).fma(w1, a);
            b = FloatVector.fromArray(S, c, m1 + 8).fma(w1, b);
            a = FloatVector.fromArray(S, c, m2).fma(w2, a);
            b = FloatVector.fromArray(S, c, m2 + 8).fma(w2, b);
            a = FloatVector.fromArray(S, c, m3).fma(w3, a);
            b = FloatVector.fromArray(S, c, m3 + 8).fma(w3, b);
            FloatVector pxy = FloatVector.broadcast(S, pts[o]).blend(FloatVector.broadcast(S, pts[o + 1]), HI);
            FloatVector pz1 = FloatVector.broadcast(S, pts[o + 2]).blend(one, HI);
            FloatVector p = a.mul(pxy).add(b.mul(pz1));
            p.add(p.rearrange(SWAP)).intoArray(outPositions, 3 * i + positionShift);
        }
    }

    /**
     * As {@link #blendedNormals}, but the normal goes through the cofactor matrix of the blended
     * linear part, whose columns are c1 x c2, c2 x c0, c0 x c1 (the inverse-transpose times det);
     * {@link #normalise} then scales it to unit length (a zero result stays zero, as in the scalar
     * kernel).
     */
    private void exactNormals(float[] c, float[] outPositions, float[] outNormals, int from, int end) {
        exactNormals(c, outPositions, outNormals, from, end, 0, 0);
    }

    private void exactNormals(float[] c, float[] outPositions, float[] outNormals, int from, int end,
            int positionShift, int normalShift) {
        final float[] pts = points;
        final char[] off = joints;
        final FloatVector one = FloatVector.broadcast(S, 1f);
        for (int i = from; i < end; i++) {
            int o = STRIDE * i;
            int q = INFLUENCES * i;
            int m0 = off[q] << 4;
            int m1 = off[q + 1] << 4;
            int m2 = off[q + 2] << 4;
            int m3 = off[q + 3] << 4;
            FloatVector w0 = FloatVector.broadcast(S, pts[o + 6]);
            FloatVector w1 = FloatVector.broadcast(S, pts[o + 7]);
            FloatVector w2 = FloatVector.broadcast(S, pts[o + 8]);
            FloatVector w3 = FloatVector.broadcast(S, pts[o + 9]);
            FloatVector a = FloatVector.fromArray(S, c, m0).mul(w0);
            FloatVector b = FloatVector.fromArray(S, c, m0 + 8).mul(w0);
            a = FloatVector.fromArray(S, c, m1).fma(w1, a);
            b = FloatVector.fromArray(S, c, m1 + 8).fma(w1, b);
            a = FloatVector.fromArray(S, c, m2).fma(w2, a);
            b = FloatVector.fromArray(S, c, m2 + 8).fma(w2, b);
            a = FloatVector.fromArray(S, c, m3).fma(w3, a);
            b = FloatVector.fromArray(S, c, m3 + 8).fma(w3, b);
            FloatVector pxy = FloatVector.broadcast(S, pts[o]).blend(FloatVector.broadcast(S, pts[o + 1]), HI);
            FloatVector pz1 = FloatVector.broadcast(S, pts[o + 2]).blend(one, HI);
            FloatVector p = a.mul(pxy).add(b.mul(pz1));
            p.add(p.rearrange(SWAP)).intoArray(outPositions, 3 * i + positionShift);
            // [c1 | c2] x [c2 | c0] = [c1 x c2 | c2 x c0]; [c0 | c1] x [c1 | c0] = [c0 x c1 | ...]
            FloatVector aSwap = a.rearrange(SWAP);
            FloatVector left = aSwap.blend(b.rearrange(SWAP), HI);
            FloatVector right = b.blend(aSwap, HI);
            // u x v = (u v.yzx - u.yzx v).yzx: three permutations per cross product instead of four
            FloatVector k01 = left.mul(right.rearrange(YZX)).sub(left.rearrange(YZX).mul(right)).rearrange(YZX);
            FloatVector k2 = a.mul(aSwap.rearrange(YZX)).sub(a.rearrange(YZX).mul(aSwap)).rearrange(YZX);
            FloatVector nxy = FloatVector.broadcast(S, pts[o + 3]).blend(FloatVector.broadcast(S, pts[o + 4]), HI);
            FloatVector t = k01.mul(nxy);
            // Unnormalised here; normalise() does 8 points per square root and division.
            t.add(t.rearrange(SWAP)).add(k2.mul(FloatVector.broadcast(S, pts[o + 5])))
                    .intoArray(outNormals, 3 * i + normalShift);
        }
    }
}
