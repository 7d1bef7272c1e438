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
import jdk.incubator.vector.VectorOperators;

import org.skinlab.skinning.AbstractSkinner;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.ScalarDqsSkinner;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;

/**
 * Dual Quaternion Skinning (Kavan et al. 2008) on 8-lane vectors, 8 points per lane group: the
 * same arithmetic as {@link ScalarDqsSkinner} written once per lane.
 *
 * <p><b>Layout.</b> The constructor repacks the geometry into blocks of 8 points (AoSoA): px[8]
 * py[8] pz[8] nx[8] ny[8] nz[8] (48 floats), and per block and influence 8 weights and 8 joints
 * (char) in one stream each. A block starts at a point index that is a multiple of 8
 * ({@link #rangeAlignment()}); points of a range outside whole blocks go through the scalar kernel.
 * (One stream per influence measured 3-7% slower: more streams in flight at 1M points.)
 *
 * <p><b>No gathers.</b> Per block and influence the 8 joints' dual quaternions are loaded as 8 rows
 * of 8 floats and transposed in registers (three stages of permute + blend, 48 operations), which
 * is cheaper than 8 gathers on the AMD machines we measured.
 *
 * <p><b>Passes.</b> C2 stops inlining calls of our own methods beyond a node budget (Vector API
 * methods are force-inlined), and a call that is not inlined boxes every vector; one loop doing
 * everything per block also measured 1.7x slower (register pressure). So the work for up to
 * {@link #CHUNK} blocks is cut into small loops that meet in a per-thread scratch array that stays
 * in L1: one for the first two influences, one per further influence (transpose, antipodality
 * sign, weighted sum), then one that normalises, rotates, translates and interleaves the lanes
 * back into x y z x y z ... (a loop with three transposes measured slower, these a little faster
 * than one loop per step).
 *
 * <p><b>Sign.</b> {@code copySign(w_k, q_0 . q_k + 0)} as a lane compare and blend: branch-free
 * like the scalar kernel and identical to it, a dot of -0 included.
 *
 * <p><b>Scale.</b> When the palette has a scale part this frame ({@link JointPalette#hasScale()})
 * each point's blended dual quaternion becomes a rigid matrix ({@link #rigidMatrices}), which is
 * composed with the point's blended scale part and applied like an LBS matrix
 * ({@link MatrixPasses}): the two-phase split of the scalar kernel, {@code D (S p)}, with normals
 * by {@code R} times S's signed cofactor. Without scale both {@link NormalTransform}s rotate the
 * normal; INVERSE_TRANSPOSE then scales it to unit length. {@link #skinFrames} takes the matrix route always.
 *
 * <p><b>Influences.</b> Any number: one scratch pass per influence beyond the second.
 */
final class VectorDqsSkinner extends AbstractSkinner {
    static final int BLOCK = 8;
    /** Floats per block in {@link #points}: px py pz nx ny nz, 8 lanes each. */
    private static final int BLOCK_FLOATS = 48;
    /** Blocks per pass; the scratch holds 96 floats per block (blended dq, pivot real part / results). */
    static final int CHUNK = 32;
    private static final int SCRATCH = 96;

    private final ScalarDqsSkinner scalar;
    /** Influences per point in the block layout: the geometry's, at least 2 (padded with weight 0). */
    private final int width;
    private final int blockCount;
    private final float[] restPositions;
    private final float[] restNormals;
    /** The scale blend's influences, per point ({@link MatrixPasses#paddedWidth}). */
    private final int passWidth;
    private final char[] passJoints;
    private final float[] passWeights;
    private final ThreadLocal<float[]> scaleColumns;
    /** Rigid matrices (16 floats per point) and blended matrices of one pass of points. */
    private final ThreadLocal<float[]> rigid = ThreadLocal.withInitial(() -> new float[16 * MatrixPasses.CHUNK]);
    private final ThreadLocal<float[]> blended = ThreadLocal.withInitial(() -> new float[16 * MatrixPasses.CHUNK]);
    private final ThreadLocal<float[]> lastPoints = ThreadLocal.withInitial(() -> new float[16]);
    private final float[] points;
    /** Per block, per influence k: 8 weights and 8 joints at {@code 8 width b + 8 k}. */
    private final float[] blockWeights;
    private final char[] blockJoints;
    private final int jointCount;
    private final ThreadLocal<float[]> scratch = ThreadLocal.withInitial(() -> new float[CHUNK * SCRATCH]);

    VectorDqsSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.DQS, "vector-256", geometry, normals);
        int given = geometry.influencesPerPoint();
        this.width = Math.max(2, given);
        this.scalar = new ScalarDqsSkinner(geometry, normals);
        this.jointCount = geometry.jointCount();
        this.restPositions = geometry.positionArray();
        this.restNormals = geometry.normalArray();
        int points = geometry.pointCount();
        blockCount = points / BLOCK;
        float[] pos = restPositions;
        float[] nrm = restNormals;
        int[] joints = geometry.jointArray();
        float[] weights = geometry.weightArray();
        int n = BLOCK * blockCount;
        this.points = new float[BLOCK_FLOATS * blockCount];
        blockWeights = new float[width * n];
        blockJoints = new char[width * n];
        for (int i = 0; i < n; i++) {
            int o = BLOCK_FLOATS * (i / BLOCK) + i % BLOCK;
            // Exact normals are unit: normalised here once, a rotation keeps them so (the scalar
            // kernel, for points outside whole blocks, normalises after rotating).
            float nx = nrm[3 * i], ny = nrm[3 * i + 1], nz = nrm[3 * i + 2];
            float len2 = nx * nx + ny * ny + nz * nz;
            float scale = normals == NormalTransform.INVERSE_TRANSPOSE && len2 > 0f ? 1f / (float) Math.sqrt(len2) : 1f;
            for (int c = 0; c < 3; c++) {
                this.points[o + BLOCK * c] = pos[3 * i + c];
                this.points[o + BLOCK * (3 + c)] = nrm[3 * i + c] * scale;
            }
            for (int k = 0; k < width; k++) {
                // Padding: weight 0 on the pivot joint adds +-0.
                int q = width * BLOCK * (i / BLOCK) + BLOCK * k + i % BLOCK;
                blockWeights[q] = k < given ? weights[given * i + k] : 0f;
                blockJoints[q] = (char) joints[given * i + (k < given ? k : 0)];
            }
        }
        passWidth = MatrixPasses.paddedWidth(given);
        passJoints = new char[passWidth * points];
        passWeights = new float[passWidth * points];
        for (int i = 0; i < points; i++) {
            for (int k = 0; k < passWidth; k++) {
                passWeights[passWidth * i + k] = k < given ? weights[given * i + k] : 0f;
                passJoints[passWidth * i + k] = (char) joints[given * i + (k < given ? k : 0)];
            }
        }
        int size = 16 * jointCount;
        scaleColumns = ThreadLocal.withInitial(() -> new float[size]);
    }

    @Override
    public int rangeAlignment() {
        return BLOCK;
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        checkPalette(palette);
        int firstBlock = (from + BLOCK - 1) / BLOCK;
        int endBlock = Math.min(to / BLOCK, blockCount);
        if (firstBlock >= endBlock) {
            scalar.skin(palette, outPositions, outNormals, from, to);
            return;
        }
        if (outPositions.length < 3 * BLOCK * endBlock || outNormals.length < 3 * BLOCK * endBlock) {
            throw new IndexOutOfBoundsException("output arrays shorter than " + 3 * BLOCK * endBlock);
        }
        scalar.skin(palette, outPositions, outNormals, from, BLOCK * firstBlock);
        float[] dq = palette.dualQuaternions();
        float[] s = scratch.get();
        if (palette.hasScale()) {
            // Two phases per point, as a matrix: the rigid part of the blended dual quaternion
            // times the blended scale part, then applied like an LBS matrix (see skinFrames).
            float[] cs = scaleColumns(palette);
            float[] r = rigid.get();
            float[] acc = blended.get();
            float[] tmp = lastPoints.get();
            boolean exact = normals == NormalTransform.INVERSE_TRANSPOSE;
            int blocksPerPass = MatrixPasses.CHUNK / BLOCK;
            for (int b = firstBlock; b < endBlock; b += blocksPerPass) {
                int e = Math.min(endBlock, b + blocksPerPass);
                int p0 = BLOCK * b;
                int p1 = BLOCK * e;
                blendDualQuaternions(dq, s, b, e);
                rigidMatrices(s, r, b, e);
                MatrixPasses.blend(cs, passJoints, passWeights, passWidth, p0, p1, acc);
                MatrixPasses.compose(r, acc, p1 - p0);
                // Spilling past p1 is fine when points follow: the next pass or the scalar tail
                // overwrites them.
                MatrixPasses.points(acc, restPositions, restNormals, exact, outPositions, outNormals, p0, p1, tmp,
                        to - p1 >= 2);
            }
            if (exact) {
                MatrixPasses.normalise(outNormals, BLOCK * firstBlock, BLOCK * endBlock);
            }
        } else {
            for (int b = firstBlock; b < endBlock; b += CHUNK) {
                int e = Math.min(endBlock, b + CHUNK);
                blendDualQuaternions(dq, s, b, e);
                applyAndStore(s, outPositions, outNormals, b, e);
            }
        }
        scalar.skin(palette, outPositions, outNormals, BLOCK * endBlock, to);
    }

    /**
     * Frames of points {@code [from, to)}: per point the rigid matrix of its blended dual
     * quaternion ({@link #rigidMatrices}), composed with its blended scale part when the palette
     * has one, then applied to the rest position; N is the rotation, or the rotation times the
     * scale part's signed cofactor (exact rule) or linear part.
     */
    @Override
    public void skinFrames(JointPalette palette, float[] outFrames, int from, int to) {
        checkPalette(palette);
        int firstBlock = (from + BLOCK - 1) / BLOCK;
        int endBlock = Math.min(to / BLOCK, blockCount);
        if (firstBlock >= endBlock) {
            scalar.skinFrames(palette, outFrames, from, to);
            return;
        }
        scalar.skinFrames(palette, outFrames, from, BLOCK * firstBlock);
        float[] dq = palette.dualQuaternions();
        float[] s = scratch.get();
        float[] r = rigid.get();
        boolean scaled = palette.hasScale();
        float[] cs = scaled ? scaleColumns(palette) : null;
        float[] acc = blended.get();
        int blocksPerPass = MatrixPasses.CHUNK / BLOCK;
        for (int b = firstBlock; b < endBlock; b += blocksPerPass) {
            int e = Math.min(endBlock, b + blocksPerPass);
            int p0 = BLOCK * b;
            int p1 = BLOCK * e;
            blendDualQuaternions(dq, s, b, e);
            rigidMatrices(s, r, b, e);
            if (scaled) {
                MatrixPasses.blend(cs, passJoints, passWeights, passWidth, p0, p1, acc);
                MatrixPasses.compose(r, acc, p1 - p0);
                MatrixPasses.frames(acc, restPositions, normals == NormalTransform.INVERSE_TRANSPOSE, outFrames, p0, p1);
            } else {
                MatrixPasses.frames(r, restPositions, false, outFrames, p0, p1);
            }
        }
        scalar.skinFrames(palette, outFrames, BLOCK * endBlock, to);
    }

    private void checkPalette(JointPalette palette) {
        if (palette.jointCount() != jointCount) {
            throw new IllegalArgumentException("palette of " + palette.jointCount() + " joints for a geometry of "
                    + jointCount);
        }
    }

    /** This thread's copy of the palette's scale parts as column-major 4x4 blocks. */
    private float[] scaleColumns(JointPalette palette) {
        float[] c = scaleColumns.get();
        MatrixPasses.columnMajor(palette.scales(), jointCount, c);
        return c;
    }

    /** Every influence of blocks {@code [b, e)} (at most {@link #CHUNK}) into the scratch. */
    private void blendDualQuaternions(float[] dq, float[] s, int b, int e) {
        pivotAndFirst(dq, s, b, e);
        for (int k = 2; k < width; k++) {
            accumulate(dq, s, b, e, k);
        }
    }

    /**
     * Influence {@code k >= 2} of each block: {@code b += copySign(w_k, q_0 . q_k + 0) q_k}, in the
     * scratch. Two transposes per method at most: with three, register pressure made it slower.
     */
    /**
     * Influences 0 (the pivot) and 1 of each block, into the scratch: {@code w_0 q_0 + copySign(w_1,
     * q_0 . q_1 + 0) q_1} as 8 lane vectors (floats 0..63) and the pivot's real part (64..95).
     * Per influence the 8 joints' dual quaternions are loaded as rows and transposed: stage 1
     * interleaves pairs of points, stage 2 pairs of pairs, stage 3 the halves, each a permute and a
     * blend per output.
     */
    private void pivotAndFirst(float[] dq, float[] s, int firstBlock, int endBlock) {
        final float[] wl0 = blockWeights;
        final float[] wl1 = blockWeights;
        final char[] row0 = blockJoints;
        final char[] row1 = blockJoints;
        for (int b = firstBlock; b < endBlock; b++) {
            int so = SCRATCH * (b - firstBlock);
            int o = width * BLOCK * b;
            int o1 = o + BLOCK;
            FloatVector r0_0 = FloatVector.fromArray(S, dq, row0[o] << 3);
            FloatVector r1_0 = FloatVector.fromArray(S, dq, row0[o + 1] << 3);
            FloatVector r2_0 = FloatVector.fromArray(S, dq, row0[o + 2] << 3);
            FloatVector r3_0 = FloatVector.fromArray(S, dq, row0[o + 3] << 3);
            FloatVector r4_0 = FloatVector.fromArray(S, dq, row0[o + 4] << 3);
            FloatVector r5_0 = FloatVector.fromArray(S, dq, row0[o + 5] << 3);
            FloatVector r6_0 = FloatVector.fromArray(S, dq, row0[o + 6] << 3);
            FloatVector r7_0 = FloatVector.fromArray(S, dq, row0[o + 7] << 3);
            // a_i: components (0 2 4 6) or (1 3 5 7) of two points, interleaved
            FloatVector a0_0 = r0_0.blend(r1_0.rearrange(RIGHT1), ODD);
            FloatVector a1_0 = r0_0.rearrange(LEFT1).blend(r1_0, ODD);
            FloatVector a2_0 = r2_0.blend(r3_0.rearrange(RIGHT1), ODD);
            FloatVector a3_0 = r2_0.rearrange(LEFT1).blend(r3_0, ODD);
            FloatVector a4_0 = r4_0.blend(r5_0.rearrange(RIGHT1), ODD);
            FloatVector a5_0 = r4_0.rearrange(LEFT1).blend(r5_0, ODD);
            FloatVector a6_0 = r6_0.blend(r7_0.rearrange(RIGHT1), ODD);
            FloatVector a7_0 = r6_0.rearrange(LEFT1).blend(r7_0, ODD);
            // c_i: components (0 4), (1 5), (2 6), (3 7) of four points
            FloatVector c0_0 = a0_0.blend(a2_0.rearrange(RIGHT2), PAIRS);
            FloatVector c2_0 = a0_0.rearrange(LEFT2).blend(a2_0, PAIRS);
            FloatVector c1_0 = a1_0.blend(a3_0.rearrange(RIGHT2), PAIRS);
            FloatVector c3_0 = a1_0.rearrange(LEFT2).blend(a3_0, PAIRS);
            FloatVector c4_0 = a4_0.blend(a6_0.rearrange(RIGHT2), PAIRS);
            FloatVector c6_0 = a4_0.rearrange(LEFT2).blend(a6_0, PAIRS);
            FloatVector c5_0 = a5_0.blend(a7_0.rearrange(RIGHT2), PAIRS);
            FloatVector c7_0 = a5_0.rearrange(LEFT2).blend(a7_0, PAIRS);
            // t_c: component c of all eight points
            FloatVector t0_0 = c0_0.blend(c4_0.rearrange(SWAP), HI);
            FloatVector t4_0 = c0_0.rearrange(SWAP).blend(c4_0, HI);
            FloatVector t1_0 = c1_0.blend(c5_0.rearrange(SWAP), HI);
            FloatVector t5_0 = c1_0.rearrange(SWAP).blend(c5_0, HI);
            FloatVector t2_0 = c2_0.blend(c6_0.rearrange(SWAP), HI);
            FloatVector t6_0 = c2_0.rearrange(SWAP).blend(c6_0, HI);
            FloatVector t3_0 = c3_0.blend(c7_0.rearrange(SWAP), HI);
            FloatVector t7_0 = c3_0.rearrange(SWAP).blend(c7_0, HI);
            FloatVector r0_1 = FloatVector.fromArray(S, dq, row1[o1] << 3);
            FloatVector r1_1 = FloatVector.fromArray(S, dq, row1[o1 + 1] << 3);
            FloatVector r2_1 = FloatVector.fromArray(S, dq, row1[o1 + 2] << 3);
            FloatVector r3_1 = FloatVector.fromArray(S, dq, row1[o1 + 3] << 3);
            FloatVector r4_1 = FloatVector.fromArray(S, dq, row1[o1 + 4] << 3);
            FloatVector r5_1 = FloatVector.fromArray(S, dq, row1[o1 + 5] << 3);
            FloatVector r6_1 = FloatVector.fromArray(S, dq, row1[o1 + 6] << 3);
            FloatVector r7_1 = FloatVector.fromArray(S, dq, row1[o1 + 7] << 3);
            // a_i: components (0 2 4 6) or (1 3 5 7) of two points, interleaved
            FloatVector a0_1 = r0_1.blend(r1_1.rearrange(RIGHT1), ODD);
            FloatVector a1_1 = r0_1.rearrange(LEFT1).blend(r1_1, ODD);
            FloatVector a2_1 = r2_1.blend(r3_1.rearrange(RIGHT1), ODD);
            FloatVector a3_1 = r2_1.rearrange(LEFT1).blend(r3_1, ODD);
            FloatVector a4_1 = r4_1.blend(r5_1.rearrange(RIGHT1), ODD);
            FloatVector a5_1 = r4_1.rearrange(LEFT1).blend(r5_1, ODD);
            FloatVector a6_1 = r6_1.blend(r7_1.rearrange(RIGHT1), ODD);
            FloatVector a7_1 = r6_1.rearrange(LEFT1).blend(r7_1, ODD);
            // c_i: components (0 4), (1 5), (2 6), (3 7) of four points
            FloatVector c0_1 = a0_1.blend(a2_1.rearrange(RIGHT2), PAIRS);
            FloatVector c2_1 = a0_1.rearrange(LEFT2).blend(a2_1, PAIRS);
            FloatVector c1_1 = a1_1.blend(a3_1.rearrange(RIGHT2), PAIRS);
            FloatVector c3_1 = a1_1.rearrange(LEFT2).blend(a3_1, PAIRS);
            FloatVector c4_1 = a4_1.blend(a6_1.rearrange(RIGHT2), PAIRS);
            FloatVector c6_1 = a4_1.rearrange(LEFT2).blend(a6_1, PAIRS);
            FloatVector c5_1 = a5_1.blend(a7_1.rearrange(RIGHT2), PAIRS);
            FloatVector c7_1 = a5_1.rearrange(LEFT2).blend(a7_1, PAIRS);
            // t_c: component c of all eight points
            FloatVector t0_1 = c0_1.blend(c4_1.rearrange(SWAP), HI);
            FloatVector t4_1 = c0_1.rearrange(SWAP).blend(c4_1, HI);
            FloatVector t1_1 = c1_1.blend(c5_1.rearrange(SWAP), HI);
            FloatVector t5_1 = c1_1.rearrange(SWAP).blend(c5_1, HI);
            FloatVector t2_1 = c2_1.blend(c6_1.rearrange(SWAP), HI);
            FloatVector t6_1 = c2_1.rearrange(SWAP).blend(c6_1, HI);
            FloatVector t3_1 = c3_1.blend(c7_1.rearrange(SWAP), HI);
            FloatVector t7_1 = c3_1.rearrange(SWAP).blend(c7_1, HI);
            t0_0.intoArray(s, so + 64);
            t1_0.intoArray(s, so + 72);
            t2_0.intoArray(s, so + 80);
            t3_0.intoArray(s, so + 88);
            FloatVector w0 = FloatVector.fromArray(S, wl0, o);
            FloatVector w1 = FloatVector.fromArray(S, wl1, o1).abs();
            FloatVector dot = t0_0.mul(t0_1).add(t1_0.mul(t1_1)).add(t2_0.mul(t2_1)).add(t3_0.mul(t3_1));
            w1 = w1.blend(w1.neg(), dot.compare(VectorOperators.LT, 0f));
            t0_1.fma(w1, t0_0.mul(w0)).intoArray(s, so);
            t1_1.fma(w1, t1_0.mul(w0)).intoArray(s, so + 8);
            t2_1.fma(w1, t2_0.mul(w0)).intoArray(s, so + 16);
            t3_1.fma(w1, t3_0.mul(w0)).intoArray(s, so + 24);
            t4_1.fma(w1, t4_0.mul(w0)).intoArray(s, so + 32);
            t5_1.fma(w1, t5_0.mul(w0)).intoArray(s, so + 40);
            t6_1.fma(w1, t6_0.mul(w0)).intoArray(s, so + 48);
            t7_1.fma(w1, t7_0.mul(w0)).intoArray(s, so + 56);
        }
    }

    private void accumulate(float[] dq, float[] s, int firstBlock, int endBlock, int k) {
        final float[] wk = blockWeights;
        final char[] row = blockJoints;
        for (int b = firstBlock; b < endBlock; b++) {
            int so = SCRATCH * (b - firstBlock);
            int o = width * BLOCK * b + BLOCK * k;
            FloatVector r0 = FloatVector.fromArray(S, dq, row[o] << 3);
            FloatVector r1 = FloatVector.fromArray(S, dq, row[o + 1] << 3);
            FloatVector r2 = FloatVector.fromArray(S, dq, row[o + 2] << 3);
            FloatVector r3 = FloatVector.fromArray(S, dq, row[o + 3] << 3);
            FloatVector r4 = FloatVector.fromArray(S, dq, row[o + 4] << 3);
            FloatVector r5 = FloatVector.fromArray(S, dq, row[o + 5] << 3);
            FloatVector r6 = FloatVector.fromArray(S, dq, row[o + 6] << 3);
            FloatVector r7 = FloatVector.fromArray(S, dq, row[o + 7] << 3);
            // a_i: components (0 2 4 6) or (1 3 5 7) of two points, interleaved
            FloatVector a0 = r0.blend(r1.rearrange(RIGHT1), ODD);
            FloatVector a1 = r0.rearrange(LEFT1).blend(r1, ODD);
            FloatVector a2 = r2.blend(r3.rearrange(RIGHT1), ODD);
            FloatVector a3 = r2.rearrange(LEFT1).blend(r3, ODD);
            FloatVector a4 = r4.blend(r5.rearrange(RIGHT1), ODD);
            FloatVector a5 = r4.rearrange(LEFT1).blend(r5, ODD);
            FloatVector a6 = r6.blend(r7.rearrange(RIGHT1), ODD);
            FloatVector a7 = r6.rearrange(LEFT1).blend(r7, ODD);
            // c_i: components (0 4), (1 5), (2 6), (3 7) of four points
            FloatVector c0 = a0.blend(a2.rearrange(RIGHT2), PAIRS);
            FloatVector c2 = a0.rearrange(LEFT2).blend(a2, PAIRS);
            FloatVector c1 = a1.blend(a3.rearrange(RIGHT2), PAIRS);
            FloatVector c3 = a1.rearrange(LEFT2).blend(a3, PAIRS);
            FloatVector c4 = a4.blend(a6.rearrange(RIGHT2), PAIRS);
            FloatVector c6 = a4.rearrange(LEFT2).blend(a6, PAIRS);
            FloatVector c5 = a5.blend(a7.rearrange(RIGHT2), PAIRS);
            FloatVector c7 = a5.rearrange(LEFT2).blend(a7, PAIRS);
            // t_c: component c of all eight points
            FloatVector t0 = c0.blend(c4.rearrange(SWAP), HI);
            FloatVector t4 = c0.rearrange(SWAP).blend(c4, HI);
            FloatVector t1 = c1.blend(c5.rearrange(SWAP), HI);
            FloatVector t5 = c1.rearrange(SWAP).blend(c5, HI);
            FloatVector t2 = c2.blend(c6.rearrange(SWAP), HI);
            FloatVector t6 = c2.rearrange(SWAP).blend(c6, HI);
            FloatVector t3 = c3.blend(c7.rearrange(SWAP), HI);
            FloatVector t7 = c3.rearrange(SWAP).blend(c7, HI);
            FloatVector w = FloatVector.fromArray(S, wk, o);
            FloatVector dot = FloatVector.fromArray(S, s, so + 64).mul(t0)
                    .add(FloatVector.fromArray(S, s, so + 72).mul(t1))
                    .add(FloatVector.fromArray(S, s, so + 80).mul(t2))
                    .add(FloatVector.fromArray(S, s, so + 88).mul(t3));
            // copySign(w, dot + 0), the scalar kernel's rule (-0 counts as +0), as a compare and a
            // blend: C2 does not intrinsify the float/int reinterpretation a bitwise copySign needs.
            // Written out here: Vector API methods are force-inlined, a helper of ours would not be
            // once the method passes C2's node budget, and would then box every vector.
            w = w.abs();
            w = w.blend(w.neg(), dot.compare(VectorOperators.LT, 0f));
            t0.fma(w, FloatVector.fromArray(S, s, so)).intoArray(s, so);
            t1.fma(w, FloatVector.fromArray(S, s, so + 8)).intoArray(s, so + 8);
            t2.fma(w, FloatVector.fromArray(S, s, so + 16)).intoArray(s, so + 16);
            t3.fma(w, FloatVector.fromArray(S, s, so + 24)).intoArray(s, so + 24);
            t4.fma(w, FloatVector.fromArray(S, s, so + 32)).intoArray(s, so + 32);
            t5.fma(w, FloatVector.fromArray(S, s, so + 40)).intoArray(s, so + 40);
            t6.fma(w, FloatVector.fromArray(S, s, so + 48)).intoArray(s, so + 48);
            t7.fma(w, FloatVector.fromArray(S, s, so + 56)).intoArray(s, so + 56);
        }
    }

    /**
     * Per block: normalise the blended dual quaternion by its real part, then
     * {@code p' = p + 2 r x (r x p + w p) + t} with {@code t = 2 (w d - d_w r + r x d)}, and the
     * normal rotated the same way; the x, y, z lanes are interleaved into the outputs (x y z x y z
     * ..., see {@link Lanes}) with the store written out here, not called, to stay inlined.
     */
    private void applyAndStore(float[] s, float[] outPositions, float[] outNormals, int firstBlock, int endBlock) {
        final float[] blk = points;
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
     * Per point of blocks {@code [firstBlock, endBlock)}: the blended dual quaternion of the
     * scratch, normalised, as a rigid matrix {@code [R | t]} in {@link MatrixPasses}' layout (16
     * floats per point from 0 in {@code out}): R from the rotation quaternion, t = 2 (w d - d_w r +
     * r x d). The eight lane vectors of each half of the record are transposed into eight points'
     * rows by the network {@link #pivotAndFirst} uses (a transpose is its own inverse).
     */
    private void rigidMatrices(float[] s, float[] out, int firstBlock, int endBlock) {
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
            tx = tx.add(tx);
            ty = ty.add(ty);
            tz = tz.add(tz);
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
            int base = 16 * BLOCK * (b - firstBlock);
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
            // Second halves: [R2 0 | t 0].
            a0 = r02.blend(r12.rearrange(RIGHT1), ODD);
            a1 = r02.rearrange(LEFT1).blend(r12, ODD);
            a2 = r22.blend(zero, ODD);
            a3 = r22.rearrange(LEFT1).blend(zero, ODD);
            a4 = tx.blend(ty.rearrange(RIGHT1), ODD);
            a5 = tx.rearrange(LEFT1).blend(ty, ODD);
            a6 = tz.blend(zero, ODD);
            a7 = tz.rearrange(LEFT1).blend(zero, ODD);
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
