package org.skinlab.simd;

import static org.skinlab.simd.Lanes.HI;
import static org.skinlab.simd.Lanes.S;
import static org.skinlab.simd.Lanes.SWAP;
import static org.skinlab.simd.Lanes.YZX;
import static org.skinlab.simd.Lanes.ZXY;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorOperators;

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
 * Geometries with up to 4 influences per point are padded to 4 with weight 0.
 */
final class VectorLbsSkinner extends AbstractSkinner {
    static final int INFLUENCES = 4;
    /** Floats per point in {@link #points}. */
    private static final int STRIDE = 10;


    private final float[] points;
    /** Palette joint per influence (4 per point; char: joint counts up to 65536). */
    private final char[] joints;
    private final int jointCount;
    private final ThreadLocal<float[]> columns;
    private final ThreadLocal<float[]> lastPointScratch = ThreadLocal.withInitial(() -> new float[16]);

    VectorLbsSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.LBS, "vector-256", geometry, normals);
        int width = geometry.influencesPerPoint();
        if (width > INFLUENCES) {
            throw new IllegalArgumentException(width + " influences per point; this kernel takes up to " + INFLUENCES);
        }
        this.jointCount = geometry.jointCount();
        int n = geometry.pointCount();
        float[] pos = geometry.positionArray();
        float[] nrm = geometry.normalArray();
        int[] joints = geometry.jointArray();
        float[] weights = geometry.weightArray();
        points = new float[STRIDE * n];
        this.joints = new char[INFLUENCES * n];
        for (int i = 0; i < n; i++) {
            int o = STRIDE * i;
            points[o] = pos[3 * i];
            points[o + 1] = pos[3 * i + 1];
            points[o + 2] = pos[3 * i + 2];
            points[o + 3] = nrm[3 * i];
            points[o + 4] = nrm[3 * i + 1];
            points[o + 5] = nrm[3 * i + 2];
            for (int k = 0; k < INFLUENCES; k++) {
                // Padding: weight 0 on the first joint adds exactly nothing.
                points[o + 6 + k] = k < width ? weights[width * i + k] : 0f;
                this.joints[INFLUENCES * i + k] = (char) joints[width * i + (k < width ? k : 0)];
            }
        }
        int size = 16 * jointCount;
        columns = ThreadLocal.withInitial(() -> new float[size]);
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        float[] c = columnMajor(palette);
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
            normalise(outNormals, from, to);
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
        float[] m = palette.matrices();
        float[] c = columns.get();
        for (int j = 0; j < jointCount; j++) {
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

    /**
     * Scales the normals of points {@code [from, to)} (interleaved, at {@code 3 * point}) to unit
     * length, zero ones staying zero: eight points per step, de-interleaved into x, y, z lanes, so
     * that a square root and a division serve eight normals. Points past the last whole group of
     * eight take the same float operations one by one, so results do not depend on where groups
     * start.
     */
    private static void normalise(float[] normals, int from, int to) {
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
