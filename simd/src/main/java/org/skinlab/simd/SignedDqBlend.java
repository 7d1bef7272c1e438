package org.skinlab.simd;

import static org.skinlab.simd.Lanes.S;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import jdk.incubator.vector.FloatVector;

import org.skinlab.skinning.SkinnedGeometry;

/**
 * The blend of dual quaternions with antipodality signs that DQS and CoR share: per point
 * {@code sum_k s_k w_k q_(j_k)}, {@code s_k = copySign(1, q_pivot . q_(j_k) + 0)} with the pivot
 * the point's first influence (the scalar kernels' expression in their order, so every kernel
 * flips the same terms, a dot of -0 included).
 *
 * <p>Per frame, {@link #signedPairs} multiplies each distinct (pivot, joint) pair's dual quaternion
 * by its sign into a table of 8 floats per pair (the stormtrooper has 237 pairs; the synthetic
 * benchmark's 64 joints in random order up to 4096). Per point, a signed dual quaternion is one
 * 8-lane load, so the blend is one load and one fused multiply-add per influence; then 8 points'
 * blends are transposed in registers (three stages of permute + blend, 48 operations) into lane
 * vectors: fewer operations than a transpose per influence with the sign taken by a lane compare
 * against the transposed pivot (docs/benchmarks.md times both). Gathers cost about a cycle per
 * lane on the AMD machines we measured, 7x slower.
 *
 * <p>Influences are padded to {@link MatrixPasses#paddedWidth} (weight 0 on the pivot adds +-0);
 * the padded joints and weights are public to the package so that the scale and matrix passes
 * blend the same influences.
 */
final class SignedDqBlend {
    static final int BLOCK = DqsLanes.BLOCK;
    /** Blocks per {@link #blend}; the scratch holds the blended dual quaternions, 64 floats per block. */
    static final int CHUNK = 32;

    /** Influences per point after padding ({@link MatrixPasses#paddedWidth}). */
    final int passWidth;
    /** Per point and influence, the joint (char: up to 65536 joints). */
    final char[] passJoints;
    /** Per point and influence, the weight (0 for padding). */
    final float[] passWeights;
    /** Per point and influence, the index of its (pivot, joint) pair. */
    final int[] pairOf;
    /** The distinct (pivot, other joint) pairs of the geometry. */
    final char[] pairPivot;
    final char[] pairOther;
    /** Per pair, the other joint's dual quaternion times the pair's sign ({@link #signedPairs}). */
    private final ThreadLocal<float[]> signedTable;
    /** One pass of points' blended dual quaternions, 8 floats each. */
    private final ThreadLocal<float[]> rows = ThreadLocal.withInitial(() -> new float[8 * BLOCK * CHUNK]);

    SignedDqBlend(SkinnedGeometry geometry) {
        int given = geometry.influencesPerPoint();
        int points = geometry.pointCount();
        int[] joints = geometry.jointArray();
        float[] weights = geometry.weightArray();
        passWidth = MatrixPasses.paddedWidth(given);
        passJoints = new char[passWidth * points];
        passWeights = new float[passWidth * points];
        pairOf = new int[passWidth * points];
        Map<Integer, Integer> pairs = new HashMap<>();
        List<int[]> pairList = new ArrayList<>();
        for (int i = 0; i < points; i++) {
            int pivot = joints[given * i];
            for (int k = 0; k < passWidth; k++) {
                // Padding: weight 0 on the pivot joint adds +-0.
                int j = joints[given * i + (k < given ? k : 0)];
                passWeights[passWidth * i + k] = k < given ? weights[given * i + k] : 0f;
                passJoints[passWidth * i + k] = (char) j;
                Integer key = pivot * VectorKernels.MAX_JOINTS + j;
                Integer index = pairs.get(key);
                if (index == null) {
                    index = pairList.size();
                    pairs.put(key, index);
                    pairList.add(new int[] {pivot, j});
                }
                pairOf[passWidth * i + k] = index;
            }
        }
        pairPivot = new char[pairList.size()];
        pairOther = new char[pairList.size()];
        for (int p = 0; p < pairPivot.length; p++) {
            pairPivot[p] = (char) pairList.get(p)[0];
            pairOther[p] = (char) pairList.get(p)[1];
        }
        int pairCount = pairPivot.length;
        signedTable = ThreadLocal.withInitial(() -> new float[8 * pairCount]);
    }

    /**
     * Per distinct (pivot, other) joint pair of the geometry this frame, the other joint's dual
     * quaternion times the pair's antipodality sign {@code copySign(1, q_pivot . q_other + 0)} on
     * the real parts. Flipping is exact, so {@code w (s q)} equals the scalar kernels' {@code (s w) q}.
     * The table has 8 floats per pair (the stormtrooper: 237 pairs, 7.6 KB); it is this thread's.
     */
    float[] signedPairs(float[] dq) {
        float[] tab = signedTable.get();
        for (int p = 0; p < pairPivot.length; p++) {
            int a = pairPivot[p] << 3;
            int q = pairOther[p] << 3;
            FloatVector.fromArray(S, dq, q).mul(sign(dq, a, q)).intoArray(tab, p << 3);
        }
        return tab;
    }

    /**
     * The antipodality sign of the rotation quaternions at {@code dq[a]} and {@code dq[q]}:
     * {@code copySign(1, q_a . q_q + 0)}, in the scalar kernels' order of operations.
     */
    static float sign(float[] dq, int a, int q) {
        return Math.copySign(1f, dq[a] * dq[q] + dq[a + 1] * dq[q + 1] + dq[a + 2] * dq[q + 2]
                + dq[a + 3] * dq[q + 3] + 0f);
    }

    /**
     * Blocks {@code [b, e)} (at most {@link #CHUNK}): each point's blended dual quaternion, one point
     * per iteration with the 8 floats of a signed dual quaternion across the lanes (one load from
     * {@link #signedPairs}' table and one fused multiply-add per influence), then transposed
     * eight points at a time into the scratch's lane vectors (component c of the block's 8 points
     * at {@code 64 (block - b) + 8 c}) for {@link DqsLanes#applyAndStore} and {@link DqsLanes#rigidDeformations}.
     */
    void blend(float[] tab, float[] s, int b, int e) {
        float[] rows = this.rows.get();
        int p0 = BLOCK * b;
        int p1 = BLOCK * e;
        switch (passWidth) {
            case 4:
                rows4(tab, p0, p1, rows);
                break;
            case 6:
                rows6(tab, p0, p1, rows);
                break;
            default:
                rows8(tab, p0, p1, rows);
                for (int k = 8; k < passWidth; k++) {
                    for (int i = p0; i < p1; i++) {
                        int q = passWidth * i + k;
                        int r = 8 * (i - p0);
                        FloatVector.fromArray(S, tab, pairOf[q] << 3)
                                .fma(FloatVector.broadcast(S, passWeights[q]), FloatVector.fromArray(S, rows, r))
                                .intoArray(rows, r);
                    }
                }
                break;
        }
        DqsLanes.transpose(rows, s, b, e);
    }
    private void rows4(float[] tab, int p0, int p1, float[] rows) {
        final float[] wt = passWeights;
        final int[] pr = pairOf;
        for (int i = p0; i < p1; i++) {
            int o = 4 * i;
            FloatVector x = FloatVector.fromArray(S, tab, pr[o] << 3).mul(FloatVector.broadcast(S, wt[o]));
            x = FloatVector.fromArray(S, tab, pr[o + 1] << 3).fma(FloatVector.broadcast(S, wt[o + 1]), x);
            x = FloatVector.fromArray(S, tab, pr[o + 2] << 3).fma(FloatVector.broadcast(S, wt[o + 2]), x);
            x = FloatVector.fromArray(S, tab, pr[o + 3] << 3).fma(FloatVector.broadcast(S, wt[o + 3]), x);
            x.intoArray(rows, 8 * (i - p0));
        }
    }

    private void rows6(float[] tab, int p0, int p1, float[] rows) {
        final float[] wt = passWeights;
        final int[] pr = pairOf;
        for (int i = p0; i < p1; i++) {
            int o = 6 * i;
            FloatVector x = FloatVector.fromArray(S, tab, pr[o] << 3).mul(FloatVector.broadcast(S, wt[o]));
            x = FloatVector.fromArray(S, tab, pr[o + 1] << 3).fma(FloatVector.broadcast(S, wt[o + 1]), x);
            x = FloatVector.fromArray(S, tab, pr[o + 2] << 3).fma(FloatVector.broadcast(S, wt[o + 2]), x);
            x = FloatVector.fromArray(S, tab, pr[o + 3] << 3).fma(FloatVector.broadcast(S, wt[o + 3]), x);
            x = FloatVector.fromArray(S, tab, pr[o + 4] << 3).fma(FloatVector.broadcast(S, wt[o + 4]), x);
            x = FloatVector.fromArray(S, tab, pr[o + 5] << 3).fma(FloatVector.broadcast(S, wt[o + 5]), x);
            x.intoArray(rows, 8 * (i - p0));
        }
    }

    /** The first 8 influences of {@code passWidth >= 8} per point. */
    private void rows8(float[] tab, int p0, int p1, float[] rows) {
        final float[] wt = passWeights;
        final int[] pr = pairOf;
        final int w = passWidth;
        for (int i = p0; i < p1; i++) {
            int o = w * i;
            FloatVector x = FloatVector.fromArray(S, tab, pr[o] << 3).mul(FloatVector.broadcast(S, wt[o]));
            x = FloatVector.fromArray(S, tab, pr[o + 1] << 3).fma(FloatVector.broadcast(S, wt[o + 1]), x);
            x = FloatVector.fromArray(S, tab, pr[o + 2] << 3).fma(FloatVector.broadcast(S, wt[o + 2]), x);
            x = FloatVector.fromArray(S, tab, pr[o + 3] << 3).fma(FloatVector.broadcast(S, wt[o + 3]), x);
            x = FloatVector.fromArray(S, tab, pr[o + 4] << 3).fma(FloatVector.broadcast(S, wt[o + 4]), x);
            x = FloatVector.fromArray(S, tab, pr[o + 5] << 3).fma(FloatVector.broadcast(S, wt[o + 5]), x);
            x = FloatVector.fromArray(S, tab, pr[o + 6] << 3).fma(FloatVector.broadcast(S, wt[o + 6]), x);
            x = FloatVector.fromArray(S, tab, pr[o + 7] << 3).fma(FloatVector.broadcast(S, wt[o + 7]), x);
            x.intoArray(rows, 8 * (i - p0));
        }
    }
}
