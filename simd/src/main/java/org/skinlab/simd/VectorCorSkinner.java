package org.skinlab.simd;

import static org.skinlab.simd.Lanes.HI;
import static org.skinlab.simd.Lanes.S;
import static org.skinlab.simd.Lanes.SWAP;

import jdk.incubator.vector.FloatVector;

import org.skinlab.skinning.AbstractSkinner;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.ScalarCorSkinner;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;

/**
 * Skinning with optimized centres of rotation (Le and Hodgins 2016) on 8-lane vectors: the
 * formula of {@link ScalarCorSkinner}, {@code p' = R (p - c) + A c}, with R the rotation of the
 * signed quaternion blend and A the LBS blend of the joints' matrices, written as one matrix per
 * point, {@code [R | A c - R c]}, and applied like an LBS matrix.
 *
 * <p><b>{@link #skin}</b>, 8 points per lane vector: per frame a table with, per distinct
 * (pivot, joint) pair, the joint's rotation quaternion times the pair's antipodality sign and the
 * joint's first matrix row ({@link #rotationTable}); per point the blend of those 8 floats and of
 * the joint's other two matrix rows (8 floats, read from the palette in place): two loads and two
 * fused multiply-adds per influence, as in LBS. Eight points' blends are transposed in registers
 * ({@link DqsLanes#transpose}) and {@link CorLanes#applyAndStore} finishes them in lanes.
 *
 * <p><b>{@link #skinFrames}</b> (rarely hot) is built from the DQS and LBS kernels' passes instead,
 * per pass of {@link MatrixPasses#CHUNK} points: the signed dual-quaternion blend
 * ({@link SignedDqBlend}) and its rotation as a frame record ({@link DqsLanes#rigidFrames}), the
 * blend of the matrices ({@link MatrixPasses#blend}), then {@link #centreMatrices} gives each
 * point its matrix {@code [R | A c - R c]} for {@link MatrixPasses#frames}.
 *
 * <p>Frames whose palette has a scale part ({@link JointPalette#hasScale()}) go through the scalar
 * kernel: there CoR runs DQS's scale phase first and moves the centre by the joints' rigid parts,
 * which these passes do not do. Points of a range outside whole blocks of 8 do too.
 */
final class VectorCorSkinner extends AbstractSkinner {
    private static final int BLOCK = DqsLanes.BLOCK;
    private static final int BLOCKS_PER_PASS = MatrixPasses.CHUNK / BLOCK;
    /** Blocks per pass of {@link #skin}. */
    private static final int CHUNK = SignedDqBlend.CHUNK;

    private final ScalarCorSkinner scalar;
    private final SignedDqBlend blend;
    private final int blockCount;
    private final int jointCount;
    private final float[] restPositions;
    private final float[] restNormals;
    private final float[] centres;
    /** Positions and normals in blocks of 8 points, as {@link DqsLanes#rigidFrames} reads them. */
    private final float[] points;
    private final ThreadLocal<float[]> columns;
    private final ThreadLocal<float[]> lanes = ThreadLocal.withInitial(() -> new float[DqsLanes.SCRATCH * BLOCKS_PER_PASS]);
    private final ThreadLocal<float[]> rotations = ThreadLocal.withInitial(() -> new float[16 * MatrixPasses.CHUNK]);
    private final ThreadLocal<float[]> matrices = ThreadLocal.withInitial(() -> new float[16 * MatrixPasses.CHUNK]);
    /** Centres in blocks of 8 points (cx cy cz, 8 lanes each) for {@link CorLanes}. */
    private final float[] centreLanes;
    /** Per pair of {@link #blend}: the signed rotation quaternion and the joint's first matrix row. */
    private final ThreadLocal<float[]> table;
    /** Per joint, its matrix's lower two rows ({@link #lowerRows}). */
    private final ThreadLocal<float[]> lower;
    private final ThreadLocal<float[]> firstRows = ThreadLocal.withInitial(() -> new float[8 * BLOCK * CHUNK]);
    private final ThreadLocal<float[]> secondRows = ThreadLocal.withInitial(() -> new float[8 * BLOCK * CHUNK]);
    private final ThreadLocal<float[]> firstLanes = ThreadLocal.withInitial(() -> new float[DqsLanes.SCRATCH * CHUNK]);
    private final ThreadLocal<float[]> secondLanes = ThreadLocal.withInitial(() -> new float[DqsLanes.SCRATCH * CHUNK]);

    VectorCorSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.COR, "vector-256", geometry, normals);
        this.scalar = new ScalarCorSkinner(geometry, normals);
        this.blend = new SignedDqBlend(geometry);
        this.jointCount = geometry.jointCount();
        this.restPositions = geometry.positionArray();
        this.restNormals = geometry.normalArray();
        this.centres = geometry.centersOfRotation();
        blockCount = geometry.pointCount() / BLOCK;
        points = new float[DqsLanes.BLOCK_FLOATS * blockCount];
        centreLanes = new float[3 * BLOCK * blockCount];
        boolean exact = normals == NormalTransform.INVERSE_TRANSPOSE;
        for (int i = 0; i < BLOCK * blockCount; i++) {
            int o = DqsLanes.BLOCK_FLOATS * (i / BLOCK) + i % BLOCK;
            // Exact normals are unit: normalised here once, R keeps them so (the scalar kernel,
            // for points outside whole blocks, normalises after rotating).
            float nx = restNormals[3 * i], ny = restNormals[3 * i + 1], nz = restNormals[3 * i + 2];
            float len2 = nx * nx + ny * ny + nz * nz;
            float scale = exact && len2 > 0f ? 1f / (float) Math.sqrt(len2) : 1f;
            for (int c = 0; c < 3; c++) {
                points[o + BLOCK * c] = restPositions[3 * i + c];
                points[o + BLOCK * (3 + c)] = restNormals[3 * i + c] * scale;
                centreLanes[3 * BLOCK * (i / BLOCK) + BLOCK * c + i % BLOCK] = centres[3 * i + c];
            }
        }
        int size = 16 * jointCount;
        columns = ThreadLocal.withInitial(() -> new float[size]);
        int pairs = blend.pairPivot.length;
        table = ThreadLocal.withInitial(() -> new float[8 * pairs]);
        int joints = jointCount;
        lower = ThreadLocal.withInitial(() -> new float[8 * joints]);
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
        if (palette.hasScale() || firstBlock >= endBlock) {
            scalar.skin(palette, outPositions, outNormals, from, to);
            return;
        }
        if (outPositions.length < 3 * BLOCK * endBlock || outNormals.length < 3 * BLOCK * endBlock) {
            throw new IndexOutOfBoundsException("output arrays shorter than " + 3 * BLOCK * endBlock);
        }
        scalar.skin(palette, outPositions, outNormals, from, BLOCK * firstBlock);
        float[] mat = lowerRows(palette.matrices());
        float[] tab = rotationTable(palette.dualQuaternions(), palette.matrices());
        float[] rowsA = firstRows.get();
        float[] rowsB = secondRows.get();
        float[] lanesA = firstLanes.get();
        float[] lanesB = secondLanes.get();
        for (int b = firstBlock; b < endBlock; b += CHUNK) {
            int e = Math.min(endBlock, b + CHUNK);
            if (blend.passWidth == 4) {
                rows4(tab, mat, BLOCK * b, BLOCK * e, rowsA, rowsB);
            } else {
                rows(tab, mat, BLOCK * b, BLOCK * e, rowsA, rowsB);
            }
            DqsLanes.transpose(rowsA, lanesA, b, e);
            DqsLanes.transpose(rowsB, lanesB, b, e);
            CorLanes.applyAndStore(lanesA, lanesB, points, centreLanes, outPositions, outNormals, b, e);
        }
        scalar.skin(palette, outPositions, outNormals, BLOCK * endBlock, to);
    }

    /**
     * Per distinct (pivot, joint) pair: the joint's rotation quaternion times the pair's
     * antipodality sign ({@link SignedDqBlend#sign}), then the joint's first matrix row; this
     * thread's table, 8 floats per pair.
     */
    private float[] rotationTable(float[] dq, float[] mat) {
        float[] tab = table.get();
        char[] pivot = blend.pairPivot;
        char[] other = blend.pairOther;
        for (int p = 0; p < pivot.length; p++) {
            int q = other[p] << 3;
            float sign = SignedDqBlend.sign(dq, pivot[p] << 3, q);
            int t = p << 3;
            int m = 12 * other[p];
            tab[t] = sign * dq[q];
            tab[t + 1] = sign * dq[q + 1];
            tab[t + 2] = sign * dq[q + 2];
            tab[t + 3] = sign * dq[q + 3];
            tab[t + 4] = mat[m];
            tab[t + 5] = mat[m + 1];
            tab[t + 6] = mat[m + 2];
            tab[t + 7] = mat[m + 3];
        }
        return tab;
    }

    /**
     * Per joint, its matrix's second and third rows, 8 floats at {@code 8 joint}: this thread's
     * copy. Read from the palette in place (12 floats per joint) every other load would straddle
     * two cache lines, which made the whole kernel about a fifth slower (docs/benchmarks.md).
     */
    private float[] lowerRows(float[] mat) {
        float[] rows = lower.get();
        for (int j = 0; j < jointCount; j++) {
            System.arraycopy(mat, 12 * j + 4, rows, 8 * j, 8);
        }
        return rows;
    }

    /** Points {@code [p0, p1)} of 4 influences: their two blended rows, written out per influence. */
    private void rows4(float[] tab, float[] mat, int p0, int p1, float[] rowsA, float[] rowsB) {
        final float[] wt = blend.passWeights;
        final int[] pr = blend.pairOf;
        final char[] jt = blend.passJoints;
        for (int i = p0; i < p1; i++) {
            int o = 4 * i;
            FloatVector w = FloatVector.broadcast(S, wt[o]);
            FloatVector a = FloatVector.fromArray(S, tab, pr[o] << 3).mul(w);
            FloatVector b = FloatVector.fromArray(S, mat, jt[o] << 3).mul(w);
            w = FloatVector.broadcast(S, wt[o + 1]);
            a = FloatVector.fromArray(S, tab, pr[o + 1] << 3).fma(w, a);
            b = FloatVector.fromArray(S, mat, jt[o + 1] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 2]);
            a = FloatVector.fromArray(S, tab, pr[o + 2] << 3).fma(w, a);
            b = FloatVector.fromArray(S, mat, jt[o + 2] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 3]);
            a = FloatVector.fromArray(S, tab, pr[o + 3] << 3).fma(w, a);
            b = FloatVector.fromArray(S, mat, jt[o + 3] << 3).fma(w, b);
            a.intoArray(rowsA, 8 * (i - p0));
            b.intoArray(rowsB, 8 * (i - p0));
        }
    }

    /** Points {@code [p0, p1)} of any padded width: an influence loop (slower than written out). */
    private void rows(float[] tab, float[] mat, int p0, int p1, float[] rowsA, float[] rowsB) {
        final float[] wt = blend.passWeights;
        final int[] pr = blend.pairOf;
        final char[] jt = blend.passJoints;
        final int width = blend.passWidth;
        for (int i = p0; i < p1; i++) {
            int o = width * i;
            FloatVector w = FloatVector.broadcast(S, wt[o]);
            FloatVector a = FloatVector.fromArray(S, tab, pr[o] << 3).mul(w);
            FloatVector b = FloatVector.fromArray(S, mat, jt[o] << 3).mul(w);
            for (int k = 1; k < width; k++) {
                w = FloatVector.broadcast(S, wt[o + k]);
                a = FloatVector.fromArray(S, tab, pr[o + k] << 3).fma(w, a);
                b = FloatVector.fromArray(S, mat, jt[o + k] << 3).fma(w, b);
            }
            a.intoArray(rowsA, 8 * (i - p0));
            b.intoArray(rowsB, 8 * (i - p0));
        }
    }

    @Override
    public void skinFrames(JointPalette palette, float[] outFrames, int from, int to) {
        checkPalette(palette);
        int firstBlock = (from + BLOCK - 1) / BLOCK;
        int endBlock = Math.min(to / BLOCK, blockCount);
        if (palette.hasScale() || firstBlock >= endBlock) {
            scalar.skinFrames(palette, outFrames, from, to);
            return;
        }
        scalar.skinFrames(palette, outFrames, from, BLOCK * firstBlock);
        boolean exact = normals == NormalTransform.INVERSE_TRANSPOSE;
        float[] tab = blend.signedPairs(palette.dualQuaternions());
        float[] cs = columnMajor(palette);
        float[] acc = matrices.get();
        for (int b = firstBlock; b < endBlock; b += BLOCKS_PER_PASS) {
            int e = Math.min(endBlock, b + BLOCKS_PER_PASS);
            pointMatrices(tab, cs, acc, b, e);
            MatrixPasses.frames(acc, restPositions, exact, false, outFrames, BLOCK * b, BLOCK * e);
        }
        scalar.skinFrames(palette, outFrames, BLOCK * endBlock, to);
    }

    /** Each point of blocks {@code [b, e)}: its matrix {@code [R | A c - R c]} into {@code acc} (from 0). */
    private void pointMatrices(float[] tab, float[] cs, float[] acc, int b, int e) {
        float[] s = lanes.get();
        float[] r = rotations.get();
        int p0 = BLOCK * b;
        int p1 = BLOCK * e;
        blend.blend(tab, s, b, e);
        DqsLanes.rigidFrames(s, points, r, b, e, p0);
        MatrixPasses.blend(cs, blend.passJoints, blend.passWeights, blend.passWidth, p0, p1, acc);
        centreMatrices(r, centres, p0, acc, p1 - p0);
    }

    /**
     * {@code acc_l = [R_l | A_l c_l - R_l c_l]} for {@code l < count}: R from the frame record at
     * {@code 16 l} in {@code rotations} (N's columns, {@link DqsLanes#rigidFrames}), A the blended
     * matrix in {@code acc} ({@code [c0 | c1], [c2 | c3]}), c the centre of point
     * {@code firstPoint + l}. Row 3 stays zero: the records' and the blends' fourth lanes are.
     */
    static void centreMatrices(float[] rotations, float[] centres, int firstPoint, float[] acc, int count) {
        final FloatVector one = FloatVector.broadcast(S, 1f);
        for (int l = 0; l < count; l++) {
            int o = 16 * l;
            int v = 3 * (firstPoint + l);
            FloatVector f01 = FloatVector.fromArray(S, rotations, o);      // [R0 | R1]
            FloatVector fp2 = FloatVector.fromArray(S, rotations, o + 8);  // [p' | R2]
            FloatVector cx = FloatVector.broadcast(S, centres[v]);
            FloatVector cy = FloatVector.broadcast(S, centres[v + 1]);
            FloatVector cz = FloatVector.broadcast(S, centres[v + 2]);
            // A c in both halves.
            FloatVector a = FloatVector.fromArray(S, acc, o);
            FloatVector b = FloatVector.fromArray(S, acc, o + 8);
            FloatVector ac = a.mul(cx.blend(cy, HI)).add(b.mul(cz.blend(one, HI)));
            ac = ac.add(ac.rearrange(SWAP));
            // R c in both halves: [R0 cx + R1 cy | R1 cy + R0 cx] + [R2 cz | R2 cz].
            FloatVector r2 = fp2.rearrange(SWAP).blend(fp2, HI);            // [R2 | R2]
            FloatVector rc = f01.mul(cx.blend(cy, HI));
            rc = rc.add(rc.rearrange(SWAP)).add(r2.mul(cz));
            f01.intoArray(acc, o);
            r2.blend(ac.sub(rc), HI).intoArray(acc, o + 8);
        }
    }

    private void checkPalette(JointPalette palette) {
        if (palette.jointCount() != jointCount) {
            throw new IllegalArgumentException("palette of " + palette.jointCount() + " joints for a geometry of "
                    + jointCount);
        }
    }

    /** This thread's copy of the palette's matrices as column-major 4x4 blocks. */
    private float[] columnMajor(JointPalette palette) {
        float[] c = columns.get();
        MatrixPasses.columnMajor(palette.matrices(), jointCount, c);
        return c;
    }
}
