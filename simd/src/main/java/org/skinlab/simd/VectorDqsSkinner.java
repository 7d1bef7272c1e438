package org.skinlab.simd;

import static org.skinlab.simd.Lanes.S;

import jdk.incubator.vector.FloatVector;

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
 * both kernels flip the same terms, a dot of -0 included), times the joint's dual quaternion,
 * into a table of 8 floats per pair (the stormtrooper has 237 pairs; the synthetic benchmark's 64
 * joints in random order up to 4096). Per point, a signed dual quaternion is one 8-lane load, so
 * the blend is one load and one fused multiply-add per influence; then 8 points' blends are transposed in
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
 * each point's blended dual quaternion becomes a rigid frame ({@link DqsLanes#rigidFrames}), which is
 * composed with the point's blended scale part and applied like an LBS matrix
 * ({@link MatrixPasses}): the two-phase split of the scalar kernel, {@code D (S p)}, with normals
 * by {@code R} times S's signed cofactor. Without scale both {@link NormalTransform}s rotate the
 * normal; INVERSE_TRANSPOSE then scales it to unit length. {@link #skinFrames} takes the matrix route always.
 *
 * <p><b>Influences.</b> Any number: written-out blends for up to 4, 6 and 8, then one scratch pass
 * per influence beyond the eighth.
 */
final class VectorDqsSkinner extends AbstractSkinner {
    static final int BLOCK = DqsLanes.BLOCK;
    /** Floats per block in {@link #points}: px py pz nx ny nz, 8 lanes each. */
    private static final int BLOCK_FLOATS = DqsLanes.BLOCK_FLOATS;
    /** Blocks per pass; the scratch holds the blended dual quaternions, 64 floats per block. */
    static final int CHUNK = 32;
    private static final int SCRATCH = DqsLanes.SCRATCH;

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
    /** Per pair, the other joint's dual quaternion times the pair's sign ({@link #signedPairs}). */
    private final ThreadLocal<float[]> signedTable;
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
        signedTable = ThreadLocal.withInitial(() -> new float[8 * pairCount]);
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
        float[] tab = signedPairs(dq);
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
                blendDualQuaternions(tab, s, b, e);
                DqsLanes.rigidFrames(s, points, r, b, e, p0);
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
                blendDualQuaternions(tab, s, b, e);
                DqsLanes.applyAndStore(s, points, outPositions, outNormals, b, e);
            }
        }
        scalar.skin(palette, outPositions, outNormals, BLOCK * endBlock, to);
    }

    /**
     * Frames of points {@code [from, to)}: per point the rigid matrix of its blended dual
     * quaternion ({@link DqsLanes#rigidFrames}), composed with its blended scale part when the palette
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
        float[] tab = signedPairs(dq);
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
            blendDualQuaternions(tab, s, b, e);
            if (scaled) {
                DqsLanes.rigidFrames(s, points, r, b, e, p0);
                MatrixPasses.blend(cs, passJoints, passWeights, passWidth, p0, p1, acc);
                MatrixPasses.compose(r, restPositions, p0, acc, p1 - p0);
                MatrixPasses.frames(acc, restPositions, exact, mirror, outFrames, p0, p1);
            } else {
                DqsLanes.rigidFrames(s, points, outFrames, b, e, 0);
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
     * Per distinct (pivot, other) joint pair of the geometry this frame, the other joint's dual
     * quaternion times the pair's antipodality sign {@code copySign(1, q_pivot . q_other + 0)} on
     * the real parts (the scalar kernel's expression in its order, so both kernels flip the same
     * terms; flipping is exact, so {@code w (s q)} equals the scalar kernel's {@code (s w) q}). A
     * point's blend is then one load from this table and one fused multiply-add per influence. The
     * table has 8 floats per pair (the stormtrooper: 237 pairs, 7.6 KB).
     */
    private float[] signedPairs(float[] dq) {
        float[] tab = signedTable.get();
        for (int p = 0; p < pairPivot.length; p++) {
            int a = pairPivot[p] << 3;
            int q = pairOther[p] << 3;
            float sign = Math.copySign(1f, dq[a] * dq[q] + dq[a + 1] * dq[q + 1] + dq[a + 2] * dq[q + 2]
                    + dq[a + 3] * dq[q + 3] + 0f);
            FloatVector.fromArray(S, dq, q).mul(sign).intoArray(tab, p << 3);
        }
        return tab;
    }

    /**
     * Blocks {@code [b, e)} (at most {@link #CHUNK}): each point's blended dual quaternion, one point
     * per iteration with the 8 floats of a signed dual quaternion across the lanes (one load from
     * {@link #signedPairs}' table and one fused multiply-add per influence), then transposed
     * eight points at a time into the scratch's lane vectors (component c of the block's 8 points
     * at {@code 64 (block - b) + 8 c}) for {@link DqsLanes#applyAndStore} and {@link DqsLanes#rigidFrames}.
     */
    private void blendDualQuaternions(float[] tab, float[] s, int b, int e) {
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
