package org.skinlab.simd;

import static org.skinlab.simd.Lanes.S;

import jdk.incubator.vector.FloatVector;

import org.skinlab.skinning.AbstractSkinner;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.ScalarCorSkinner;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;

/**
 * Skinning with optimized centres of rotation (Le and Hodgins 2016) on 8-lane vectors, 8 points
 * per lane group: the formula of {@link ScalarCorSkinner}, {@code p' = R (p - c) + A c}, with R
 * the rotation of the signed quaternion blend and A the LBS blend of the joints' matrices.
 *
 * <p><b>Blend.</b> Per frame a table with, per distinct (pivot, joint) pair, the joint's rotation
 * quaternion times the pair's antipodality sign and the joint's first matrix row
 * ({@link #rotationTable}), and a copy of each joint's other two matrix rows, 8 floats at a
 * 32-byte step ({@link #lowerRows}). Per point the two 8-float blends: two loads and two fused
 * multiply-adds per influence, as in LBS, written out for 4, 6 and 8 influences (an influence loop
 * for more). Eight points' blends are transposed in registers ({@link DqsLanes#transpose}) into
 * lane vectors.
 *
 * <p><b>Finish.</b> {@link #skin}: {@link CorLanes#applyAndStore} rotates and translates in lanes
 * and interleaves the results. {@link #skinDeformations} (the route of position sharing):
 * {@link CorLanes#asDualQuaternions} writes each point's motion {@code p -> R p + (A c - R c)} as
 * a dual quaternion into the DQS kernel's scratch layout, and {@link DqsLanes#rigidDeformations} turns
 * those into deformations.
 *
 * <p>Frames whose palette has a scale part ({@link JointPalette#hasScale()}) go through the scalar
 * kernel: there CoR runs DQS's scale phase first and moves the centre by the joints' rigid parts,
 * which these passes do not do. Points of a range outside whole blocks of 8 do too.
 */
final class VectorCorSkinner extends AbstractSkinner {
    private static final int BLOCK = DqsLanes.BLOCK;
    /** Blocks per pass. */
    private static final int CHUNK = SignedDqBlend.CHUNK;

    private final ScalarCorSkinner scalar;
    /** The pairs and padded influences (its own dual-quaternion blend is DQS's, unused here). */
    private final SignedDqBlend blend;
    private final int blockCount;
    private final int jointCount;
    /** Positions and normals in blocks of 8 points ({@link DqsLanes#BLOCK_FLOATS} per block). */
    private final float[] points;
    /** Centres in blocks of 8 points (cx cy cz, 8 lanes each). */
    private final float[] centreLanes;
    /** Per pair: the signed rotation quaternion and the joint's first matrix row ({@link #rotationTable}). */
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
        float[] centres = geometry.centresOfRotation();
        blockCount = geometry.pointCount() / BLOCK;
        points = new float[DqsLanes.BLOCK_FLOATS * blockCount];
        centreLanes = new float[3 * BLOCK * blockCount];
        for (int i = 0; i < BLOCK * blockCount; i++) {
            for (int c = 0; c < 3; c++) {
                centreLanes[3 * BLOCK * (i / BLOCK) + BLOCK * c + i % BLOCK] = centres[3 * i + c];
            }
        }
        restShapeChanged();
        int pairs = blend.pairPivot.length;
        table = ThreadLocal.withInitial(() -> new float[8 * pairs]);
        int joints = jointCount;
        lower = ThreadLocal.withInitial(() -> new float[8 * joints]);
    }

    /**
     * Copies the rest positions and normals (unit under the exact rule) into the blocks; the
     * centres stay (a morphing geometry keeps its rest shape's: docs/skinning.md, "Morphs").
     */
    @Override
    public void restShapeChanged() {
        float[] positions = geometry().positionArray();
        float[] restNormals = geometry().normalArray();
        boolean exact = normalTransform() == NormalTransform.INVERSE_TRANSPOSE;
        for (int i = 0; i < BLOCK * blockCount; i++) {
            int o = DqsLanes.BLOCK_FLOATS * (i / BLOCK) + i % BLOCK;
            // Exact normals are unit: normalised here once, R keeps them so (the scalar kernel,
            // for points outside whole blocks, normalises after rotating).
            float nx = restNormals[3 * i], ny = restNormals[3 * i + 1], nz = restNormals[3 * i + 2];
            float len2 = nx * nx + ny * ny + nz * nz;
            float scale = exact && len2 > 0f ? 1f / (float) Math.sqrt(len2) : 1f;
            for (int c = 0; c < 3; c++) {
                points[o + BLOCK * c] = positions[3 * i + c];
                points[o + BLOCK * (3 + c)] = restNormals[3 * i + c] * scale;
            }
        }
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
        float[] tab = rotationTable(palette);
        float[] rows = lowerRows(palette.matrices());
        float[] lanesA = firstLanes.get();
        float[] lanesB = secondLanes.get();
        for (int b = firstBlock; b < endBlock; b += CHUNK) {
            int e = Math.min(endBlock, b + CHUNK);
            blendLanes(tab, rows, lanesA, lanesB, b, e);
            CorLanes.applyAndStore(lanesA, lanesB, points, centreLanes, outPositions, outNormals, b, e);
        }
        scalar.skin(palette, outPositions, outNormals, BLOCK * endBlock, to);
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        checkPalette(palette);
        int firstBlock = (from + BLOCK - 1) / BLOCK;
        int endBlock = Math.min(to / BLOCK, blockCount);
        if (palette.hasScale() || firstBlock >= endBlock) {
            scalar.skinDeformations(palette, outDeformations, from, to);
            return;
        }
        scalar.skinDeformations(palette, outDeformations, from, BLOCK * firstBlock);
        float[] tab = rotationTable(palette);
        float[] rows = lowerRows(palette.matrices());
        float[] lanesA = firstLanes.get();
        float[] lanesB = secondLanes.get();
        for (int b = firstBlock; b < endBlock; b += CHUNK) {
            int e = Math.min(endBlock, b + CHUNK);
            blendLanes(tab, rows, lanesA, lanesB, b, e);
            CorLanes.asDualQuaternions(lanesA, lanesB, centreLanes, b, e);
            DqsLanes.rigidDeformations(lanesA, points, outDeformations, b, e, 0);
        }
        scalar.skinDeformations(palette, outDeformations, BLOCK * endBlock, to);
    }

    /** Blocks {@code [b, e)}: the two blends of each point, transposed into lane vectors. */
    private void blendLanes(float[] tab, float[] rows, float[] lanesA, float[] lanesB, int b, int e) {
        float[] rowsA = firstRows.get();
        float[] rowsB = secondRows.get();
        int p0 = BLOCK * b;
        int p1 = BLOCK * e;
        switch (blend.passWidth) {
            case 4:
                rows4(tab, rows, p0, p1, rowsA, rowsB);
                break;
            case 6:
                rows6(tab, rows, p0, p1, rowsA, rowsB);
                break;
            case 8:
                rows8(tab, rows, p0, p1, rowsA, rowsB);
                break;
            default:
                rowsAnyWidth(tab, rows, p0, p1, rowsA, rowsB);
                break;
        }
        DqsLanes.transpose(rowsA, lanesA, b, e);
        DqsLanes.transpose(rowsB, lanesB, b, e);
    }

    /**
     * Per distinct (pivot, joint) pair: the joint's rotation quaternion times the pair's
     * antipodality sign ({@link SignedDqBlend#sign}), then the joint's first matrix row; this
     * thread's table, 8 floats per pair.
     */
    private float[] rotationTable(JointPalette palette) {
        float[] dq = palette.dualQuaternions();
        float[] mat = palette.matrices();
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

    private void rows4(float[] tab, float[] rows, int p0, int p1, float[] rowsA, float[] rowsB) {
        final float[] wt = blend.passWeights;
        final int[] pr = blend.pairOf;
        final char[] jt = blend.passJoints;
        for (int i = p0; i < p1; i++) {
            int o = 4 * i;
            FloatVector w = FloatVector.broadcast(S, wt[o]);
            FloatVector a = FloatVector.fromArray(S, tab, pr[o] << 3).mul(w);
            FloatVector b = FloatVector.fromArray(S, rows, jt[o] << 3).mul(w);
            w = FloatVector.broadcast(S, wt[o + 1]);
            a = FloatVector.fromArray(S, tab, pr[o + 1] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 1] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 2]);
            a = FloatVector.fromArray(S, tab, pr[o + 2] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 2] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 3]);
            a = FloatVector.fromArray(S, tab, pr[o + 3] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 3] << 3).fma(w, b);
            a.intoArray(rowsA, 8 * (i - p0));
            b.intoArray(rowsB, 8 * (i - p0));
        }
    }

    private void rows6(float[] tab, float[] rows, int p0, int p1, float[] rowsA, float[] rowsB) {
        final float[] wt = blend.passWeights;
        final int[] pr = blend.pairOf;
        final char[] jt = blend.passJoints;
        for (int i = p0; i < p1; i++) {
            int o = 6 * i;
            FloatVector w = FloatVector.broadcast(S, wt[o]);
            FloatVector a = FloatVector.fromArray(S, tab, pr[o] << 3).mul(w);
            FloatVector b = FloatVector.fromArray(S, rows, jt[o] << 3).mul(w);
            w = FloatVector.broadcast(S, wt[o + 1]);
            a = FloatVector.fromArray(S, tab, pr[o + 1] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 1] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 2]);
            a = FloatVector.fromArray(S, tab, pr[o + 2] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 2] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 3]);
            a = FloatVector.fromArray(S, tab, pr[o + 3] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 3] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 4]);
            a = FloatVector.fromArray(S, tab, pr[o + 4] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 4] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 5]);
            a = FloatVector.fromArray(S, tab, pr[o + 5] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 5] << 3).fma(w, b);
            a.intoArray(rowsA, 8 * (i - p0));
            b.intoArray(rowsB, 8 * (i - p0));
        }
    }

    private void rows8(float[] tab, float[] rows, int p0, int p1, float[] rowsA, float[] rowsB) {
        final float[] wt = blend.passWeights;
        final int[] pr = blend.pairOf;
        final char[] jt = blend.passJoints;
        for (int i = p0; i < p1; i++) {
            int o = 8 * i;
            FloatVector w = FloatVector.broadcast(S, wt[o]);
            FloatVector a = FloatVector.fromArray(S, tab, pr[o] << 3).mul(w);
            FloatVector b = FloatVector.fromArray(S, rows, jt[o] << 3).mul(w);
            w = FloatVector.broadcast(S, wt[o + 1]);
            a = FloatVector.fromArray(S, tab, pr[o + 1] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 1] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 2]);
            a = FloatVector.fromArray(S, tab, pr[o + 2] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 2] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 3]);
            a = FloatVector.fromArray(S, tab, pr[o + 3] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 3] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 4]);
            a = FloatVector.fromArray(S, tab, pr[o + 4] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 4] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 5]);
            a = FloatVector.fromArray(S, tab, pr[o + 5] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 5] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 6]);
            a = FloatVector.fromArray(S, tab, pr[o + 6] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 6] << 3).fma(w, b);
            w = FloatVector.broadcast(S, wt[o + 7]);
            a = FloatVector.fromArray(S, tab, pr[o + 7] << 3).fma(w, a);
            b = FloatVector.fromArray(S, rows, jt[o + 7] << 3).fma(w, b);
            a.intoArray(rowsA, 8 * (i - p0));
            b.intoArray(rowsB, 8 * (i - p0));
        }
    }

    /** More than 8 influences: a loop over them, slower than written out. */
    private void rowsAnyWidth(float[] tab, float[] rows, int p0, int p1, float[] rowsA, float[] rowsB) {
        final float[] wt = blend.passWeights;
        final int[] pr = blend.pairOf;
        final char[] jt = blend.passJoints;
        final int width = blend.passWidth;
        for (int i = p0; i < p1; i++) {
            int o = width * i;
            FloatVector w = FloatVector.broadcast(S, wt[o]);
            FloatVector a = FloatVector.fromArray(S, tab, pr[o] << 3).mul(w);
            FloatVector b = FloatVector.fromArray(S, rows, jt[o] << 3).mul(w);
            for (int k = 1; k < width; k++) {
                w = FloatVector.broadcast(S, wt[o + k]);
                a = FloatVector.fromArray(S, tab, pr[o + k] << 3).fma(w, a);
                b = FloatVector.fromArray(S, rows, jt[o + k] << 3).fma(w, b);
            }
            a.intoArray(rowsA, 8 * (i - p0));
            b.intoArray(rowsB, 8 * (i - p0));
        }
    }

    private void checkPalette(JointPalette palette) {
        if (palette.jointCount() != jointCount) {
            throw new IllegalArgumentException("palette of " + palette.jointCount() + " joints for a geometry of "
                    + jointCount);
        }
    }
}
