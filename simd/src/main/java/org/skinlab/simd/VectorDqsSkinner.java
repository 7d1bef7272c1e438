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
 * py[8] pz[8] nx[8] ny[8] nz[8] (48 floats), and per point its influences padded to 4, 6, 8 or
 * more ({@link MatrixPasses#paddedWidth}): joints (char), weights, and the index of each
 * influence's (pivot, joint) pair among the geometry's distinct pairs. A block starts at a point
 * index that is a multiple of 8 ({@link #rangeAlignment()}); points of a range outside whole
 * blocks go through the scalar kernel.
 *
 * <p><b>Blend.</b> Per frame, the antipodality sign of every distinct pair,
 * {@code copySign(1, q_pivot . q_joint + 0)}, the scalar kernel's expression in its order (so
 * both kernels flip the same terms, a dot of -0 included), into a small table. Per point, one
 * joint's dual quaternion is one 8-lane load, so the blend is one load and one fused multiply-add
 * per influence with the weight times its pair's sign; then 8 points' blends are transposed in
 * registers (three stages of permute + blend, 48 operations) into lane vectors. This replaced a
 * transpose per influence, with the sign taken by a lane compare against the transposed pivot
 * (docs/benchmarks.md has both). Gathers cost about a cycle per lane on the AMD machines we
 * measured and were 7x slower.
 *
 * <p><b>Passes.</b> C2 stops inlining calls of our own methods beyond a node budget (Vector API
 * methods are force-inlined), and a call that is not inlined boxes every vector; one loop doing
 * everything per block also measured 1.7x slower (register pressure). So the work for up to
 * {@link #CHUNK} blocks is cut into small loops that meet in per-thread scratch arrays that stay
 * in L1: the blend, the transpose, then one that normalises, rotates, translates and interleaves
 * the lanes back into x y z x y z ...
 *
 * <p><b>Scale.</b> When the palette has a scale part this frame ({@link JointPalette#hasScale()})
 * each point's blended dual quaternion becomes a rigid frame ({@link #rigidFrames}), which is
 * composed with the point's blended scale part and applied like an LBS matrix
 * ({@link MatrixPasses}): the two-phase split of the scalar kernel, {@code D (S p)}, with normals
 * by {@code R} times S's signed cofactor. Without scale both {@link NormalTransform}s rotate the
 * normal; INVERSE_TRANSPOSE then scales it to unit length. {@link #skinFrames} takes the matrix route always.
 *
 * <p><b>Influences.</b> Any number: written-out blends for up to 4, 6 and 8, then one scratch pass
 * per influence beyond the eighth.
 */
final class VectorDqsSkinner extends AbstractSkinner {
    static final int BLOCK = 8;
    /** Floats per block in {@link #points}: px py pz nx ny nz, 8 lanes each. */
    private static final int BLOCK_FLOATS = 48;
    /** Blocks per pass; the scratch holds the blended dual quaternions, 64 floats per block. */
    static final int CHUNK = 32;
    private static final int SCRATCH = 64;

    private final ScalarDqsSkinner scalar;
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
    /** Per point and influence ({@link #passWidth}), the index of its (pivot, joint) pair. */
    private final int[] pairOf;
    /** The distinct (pivot, other joint) pairs of the geometry. */
    private final char[] pairPivot;
    private final char[] pairOther;
    private final ThreadLocal<float[]> signs;
    /** One pass of points' blended dual quaternions, 8 floats each. */
    private final ThreadLocal<float[]> rows = ThreadLocal.withInitial(() -> new float[8 * BLOCK * CHUNK]);
    private final int jointCount;
    private final ThreadLocal<float[]> scratch = ThreadLocal.withInitial(() -> new float[CHUNK * SCRATCH]);

    VectorDqsSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.DQS, "vector-256", geometry, normals);
        int given = geometry.influencesPerPoint();
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
        }
        passWidth = MatrixPasses.paddedWidth(given);
        passJoints = new char[passWidth * points];
        passWeights = new float[passWidth * points];
        pairOf = new int[passWidth * points];
        java.util.Map<Integer, Integer> pairs = new java.util.HashMap<>();
        java.util.List<int[]> pairList = new java.util.ArrayList<>();
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
        signs = ThreadLocal.withInitial(() -> new float[pairCount]);
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
        float[] sg = pairSigns(dq);
        float[] s = scratch.get();
        if (palette.hasScale()) {
            // Two phases per point, as a matrix: the rigid part of the blended dual quaternion
            // times the blended scale part, then applied like an LBS matrix (see skinFrames).
            float[] cs = scaleColumns(palette);
            float[] r = rigid.get();
            float[] acc = blended.get();
            float[] tmp = lastPoints.get();
            boolean exact = normals == NormalTransform.INVERSE_TRANSPOSE;
            boolean mirror = exact && palette.mirrorsScales();
            int blocksPerPass = MatrixPasses.CHUNK / BLOCK;
            for (int b = firstBlock; b < endBlock; b += blocksPerPass) {
                int e = Math.min(endBlock, b + blocksPerPass);
                int p0 = BLOCK * b;
                int p1 = BLOCK * e;
                blendDualQuaternions(dq, sg, s, b, e);
                rigidFrames(s, r, b, e, p0);
                MatrixPasses.blend(cs, passJoints, passWeights, passWidth, p0, p1, acc);
                MatrixPasses.compose(r, restPositions, p0, acc, p1 - p0);
                // Spilling past p1 is fine when points follow: the next pass or the scalar tail
                // overwrites them.
                MatrixPasses.points(acc, restPositions, restNormals, exact, mirror, outPositions, outNormals, p0, p1,
                        tmp, to - p1 >= 2);
            }
            if (exact) {
                MatrixPasses.normalise(outNormals, BLOCK * firstBlock, BLOCK * endBlock);
            }
        } else {
            for (int b = firstBlock; b < endBlock; b += CHUNK) {
                int e = Math.min(endBlock, b + CHUNK);
                blendDualQuaternions(dq, sg, s, b, e);
                applyAndStore(s, outPositions, outNormals, b, e);
            }
        }
        scalar.skin(palette, outPositions, outNormals, BLOCK * endBlock, to);
    }

    /**
     * Frames of points {@code [from, to)}: per point the rigid matrix of its blended dual
     * quaternion ({@link #rigidFrames}), composed with its blended scale part when the palette
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
        float[] sg = pairSigns(dq);
        float[] s = scratch.get();
        float[] r = rigid.get();
        boolean scaled = palette.hasScale();
        boolean exact = normals == NormalTransform.INVERSE_TRANSPOSE;
        boolean mirror = exact && palette.mirrorsScales();
        float[] cs = scaled ? scaleColumns(palette) : null;
        float[] acc = blended.get();
        int blocksPerPass = MatrixPasses.CHUNK / BLOCK;
        for (int b = firstBlock; b < endBlock; b += blocksPerPass) {
            int e = Math.min(endBlock, b + blocksPerPass);
            int p0 = BLOCK * b;
            int p1 = BLOCK * e;
            blendDualQuaternions(dq, sg, s, b, e);
            if (scaled) {
                rigidFrames(s, r, b, e, p0);
                MatrixPasses.blend(cs, passJoints, passWeights, passWidth, p0, p1, acc);
                MatrixPasses.compose(r, restPositions, p0, acc, p1 - p0);
                MatrixPasses.frames(acc, restPositions, exact, mirror, outFrames, p0, p1);
            } else {
                rigidFrames(s, outFrames, b, e, 0);
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

    /**
     * The antipodality sign of every distinct (pivot, other) joint pair of the geometry this frame:
     * {@code copySign(1, q_pivot . q_other + 0)} on the real parts, the scalar kernel's expression
     * in its order, so both kernels flip the same terms. A point's sign for influence k is then a
     * table lookup, and its blend one load and one fused multiply-add per influence.
     */
    private float[] pairSigns(float[] dq) {
        float[] sg = signs.get();
        for (int p = 0; p < pairPivot.length; p++) {
            int a = pairPivot[p] << 3;
            int q = pairOther[p] << 3;
            sg[p] = Math.copySign(1f, dq[a] * dq[q] + dq[a + 1] * dq[q + 1] + dq[a + 2] * dq[q + 2]
                    + dq[a + 3] * dq[q + 3] + 0f);
        }
        return sg;
    }

    /**
     * Blocks {@code [b, e)} (at most {@link #CHUNK}): each point's blended dual quaternion, one point
     * per iteration with the 8 floats of a joint's dual quaternion across the lanes (one load and
     * one fused multiply-add per influence, the weight times its pair's sign), then transposed
     * eight points at a time into the scratch's lane vectors (component c of the block's 8 points
     * at {@code 64 (block - b) + 8 c}) for {@link #applyAndStore} and {@link #rigidFrames}.
     */
    private void blendDualQuaternions(float[] dq, float[] sg, float[] s, int b, int e) {
        float[] rows = this.rows.get();
        int p0 = BLOCK * b;
        int p1 = BLOCK * e;
        switch (passWidth) {
            case 4:
                rows4(dq, sg, p0, p1, rows);
                break;
            case 6:
                rows6(dq, sg, p0, p1, rows);
                break;
            default:
                rows8(dq, sg, p0, p1, rows);
                for (int k = 8; k < passWidth; k++) {
                    for (int i = p0; i < p1; i++) {
                        int q = passWidth * i + k;
                        int r = 8 * (i - p0);
                        FloatVector.fromArray(S, dq, passJoints[q] << 3)
                                .fma(FloatVector.broadcast(S, passWeights[q] * sg[pairOf[q]]), FloatVector.fromArray(S, rows, r))
                                .intoArray(rows, r);
                    }
                }
                break;
        }
        transpose(rows, s, b, e);
    }

    private void rows4(float[] dq, float[] sg, int p0, int p1, float[] rows) {
        final char[] jn = passJoints;
        final float[] wt = passWeights;
        final int[] pr = pairOf;
        for (int i = p0; i < p1; i++) {
            int o = 4 * i;
            FloatVector x = FloatVector.fromArray(S, dq, jn[o] << 3).mul(FloatVector.broadcast(S, wt[o]));
            x = FloatVector.fromArray(S, dq, jn[o + 1] << 3).fma(FloatVector.broadcast(S, wt[o + 1] * sg[pr[o + 1]]), x);
            x = FloatVector.fromArray(S, dq, jn[o + 2] << 3).fma(FloatVector.broadcast(S, wt[o + 2] * sg[pr[o + 2]]), x);
            x = FloatVector.fromArray(S, dq, jn[o + 3] << 3).fma(FloatVector.broadcast(S, wt[o + 3] * sg[pr[o + 3]]), x);
            x.intoArray(rows, 8 * (i - p0));
        }
    }

    private void rows6(float[] dq, float[] sg, int p0, int p1, float[] rows) {
        final char[] jn = passJoints;
        final float[] wt = passWeights;
        final int[] pr = pairOf;
        for (int i = p0; i < p1; i++) {
            int o = 6 * i;
            FloatVector x = FloatVector.fromArray(S, dq, jn[o] << 3).mul(FloatVector.broadcast(S, wt[o]));
            x = FloatVector.fromArray(S, dq, jn[o + 1] << 3).fma(FloatVector.broadcast(S, wt[o + 1] * sg[pr[o + 1]]), x);
            x = FloatVector.fromArray(S, dq, jn[o + 2] << 3).fma(FloatVector.broadcast(S, wt[o + 2] * sg[pr[o + 2]]), x);
            x = FloatVector.fromArray(S, dq, jn[o + 3] << 3).fma(FloatVector.broadcast(S, wt[o + 3] * sg[pr[o + 3]]), x);
            x = FloatVector.fromArray(S, dq, jn[o + 4] << 3).fma(FloatVector.broadcast(S, wt[o + 4] * sg[pr[o + 4]]), x);
            x = FloatVector.fromArray(S, dq, jn[o + 5] << 3).fma(FloatVector.broadcast(S, wt[o + 5] * sg[pr[o + 5]]), x);
            x.intoArray(rows, 8 * (i - p0));
        }
    }

    /** The first 8 influences of {@code passWidth >= 8} per point. */
    private void rows8(float[] dq, float[] sg, int p0, int p1, float[] rows) {
        final char[] jn = passJoints;
        final float[] wt = passWeights;
        final int[] pr = pairOf;
        final int w = passWidth;
        for (int i = p0; i < p1; i++) {
            int o = w * i;
            FloatVector x = FloatVector.fromArray(S, dq, jn[o] << 3).mul(FloatVector.broadcast(S, wt[o]));
            x = FloatVector.fromArray(S, dq, jn[o + 1] << 3).fma(FloatVector.broadcast(S, wt[o + 1] * sg[pr[o + 1]]), x);
            x = FloatVector.fromArray(S, dq, jn[o + 2] << 3).fma(FloatVector.broadcast(S, wt[o + 2] * sg[pr[o + 2]]), x);
            x = FloatVector.fromArray(S, dq, jn[o + 3] << 3).fma(FloatVector.broadcast(S, wt[o + 3] * sg[pr[o + 3]]), x);
            x = FloatVector.fromArray(S, dq, jn[o + 4] << 3).fma(FloatVector.broadcast(S, wt[o + 4] * sg[pr[o + 4]]), x);
            x = FloatVector.fromArray(S, dq, jn[o + 5] << 3).fma(FloatVector.broadcast(S, wt[o + 5] * sg[pr[o + 5]]), x);
            x = FloatVector.fromArray(S, dq, jn[o + 6] << 3).fma(FloatVector.broadcast(S, wt[o + 6] * sg[pr[o + 6]]), x);
            x = FloatVector.fromArray(S, dq, jn[o + 7] << 3).fma(FloatVector.broadcast(S, wt[o + 7] * sg[pr[o + 7]]), x);
            x.intoArray(rows, 8 * (i - p0));
        }
    }

    /**
     * Per block of {@code [b, e)}: its 8 points' rows (8 floats each, from {@code 8 (point - 8b)})
     * into 8 lane vectors of the scratch, component c at {@code 64 (block - b) + 8 c}. Stage 1
     * interleaves pairs of points, stage 2 pairs of pairs, stage 3 the halves, each a permute and a
     * blend per output.
     */
    private static void transpose(float[] rows, float[] s, int b, int e) {
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
     * scratch, normalised, as the point's frame ({@link org.skinlab.skinning.Skinner#skinFrames}):
     * the rotation R as N's columns and the deformed position {@code p' = R p + t}, with R from the
     * rotation quaternion and t = 2 (w d - d_w r + r x d), into {@code out} at
     * {@code 16 (point - outFirstPoint)}. The eight lane vectors of each half of the record are
     * transposed into eight points' rows by the network {@link #transpose} uses (a transpose is
     * its own inverse). The scale phase recovers t from p' ({@link MatrixPasses#compose}).
     */
    private void rigidFrames(float[] s, float[] out, int firstBlock, int endBlock, int outFirstPoint) {
        final float[] blk = points;
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
            int fo = BLOCK_FLOATS * b;
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
