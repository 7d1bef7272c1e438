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
 * <p><b>Blend.</b> {@link SignedDqBlend}: per frame a table of each distinct (pivot, joint) pair's
 * signed dual quaternion, per point one load and one fused multiply-add per influence, then 8
 * points transposed in registers into lane vectors.
 *
 * <p><b>Passes.</b> C2 stops inlining calls of our own methods beyond a node budget (Vector API
 * methods are force-inlined), and a call that is not inlined boxes every vector; one loop doing
 * everything per block also measured 1.7x slower (register pressure). So the work for up to
 * {@link #CHUNK} blocks is cut into small loops that meet in per-thread scratch arrays that stay
 * in L1: the blend, the transpose, then one that normalises, rotates, translates and interleaves
 * the lanes back into x y z x y z ...
 *
 * <p><b>Scale.</b> When the palette has a scale part this frame ({@link JointPalette#hasScale()})
 * each point's blended dual quaternion becomes a rigid frame ({@link DqsLanes#rigidDeformations}), which is
 * composed with the point's blended scale part and applied like an LBS matrix
 * ({@link MatrixPasses}): the two-phase split of the scalar kernel, {@code D (S p)}, with normals
 * by {@code R} times S's signed cofactor. Without scale both {@link NormalTransform}s rotate the
 * normal; INVERSE_TRANSPOSE then scales it to unit length. {@link #skinDeformations} takes the matrix route always.
 *
 * <p><b>Positions only</b> ({@link NormalTransform#NONE}): blocks of positions alone
 * ({@link DqsLanes#POSITION_BLOCK_FLOATS}), {@link DqsLanes#applyPositions} instead of
 * {@link DqsLanes#applyAndStore} and {@link MatrixPasses#positions} instead of
 * {@link MatrixPasses#points}, chosen once per pass; the same operations on the positions, so
 * the same bits as with normals.
 *
 * <p><b>Influences.</b> Any number: written-out blends for up to 4, 6 and 8, then one scratch pass
 * per influence beyond the eighth.
 */
final class VectorDqsSkinner extends AbstractSkinner {
    static final int BLOCK = DqsLanes.BLOCK;
    /** Floats per block in {@link #points}: px py pz nx ny nz, 8 lanes each. */
    private static final int BLOCK_FLOATS = DqsLanes.BLOCK_FLOATS;
    /** Blocks per pass; the scratch holds the blended dual quaternions, 64 floats per block. */
    static final int CHUNK = SignedDqBlend.CHUNK;
    private static final int SCRATCH = DqsLanes.SCRATCH;

    private final ScalarDqsSkinner scalar;
    private final int blockCount;
    private final float[] restPositions;
    private final float[] restNormals;
    /** The signed blend of dual quaternions; its padded influences also drive the scale blend. */
    private final SignedDqBlend blend;
    private final ThreadLocal<float[]> scaleColumns;
    /** Rigid matrices (16 floats per point) and blended matrices of one pass of points. */
    private final ThreadLocal<float[]> rigid = ThreadLocal.withInitial(() -> new float[16 * MatrixPasses.CHUNK]);
    private final ThreadLocal<float[]> blended = ThreadLocal.withInitial(() -> new float[16 * MatrixPasses.CHUNK]);
    private final ThreadLocal<float[]> lastPoints = ThreadLocal.withInitial(() -> new float[16]);
    /** Rest positions and normals in blocks of 8 points, or positions alone under {@link NormalTransform#NONE}. */
    private final float[] points;
    /** Floats per block of {@link #points}. */
    private final int blockFloats;
    private final int jointCount;
    private final ThreadLocal<float[]> scratch = ThreadLocal.withInitial(() -> new float[CHUNK * SCRATCH]);

    VectorDqsSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.DQS, "vector-256", geometry, normals);
        this.scalar = new ScalarDqsSkinner(geometry, normals);
        this.jointCount = geometry.jointCount();
        this.restPositions = geometry.positionArray();
        this.restNormals = geometry.normalArray();
        int points = geometry.pointCount();
        blockCount = points / BLOCK;
        blockFloats = normals == NormalTransform.NONE ? DqsLanes.POSITION_BLOCK_FLOATS : BLOCK_FLOATS;
        this.points = new float[blockFloats * blockCount];
        restShapeChanged();
        blend = new SignedDqBlend(geometry);
        int size = 16 * jointCount;
        scaleColumns = ThreadLocal.withInitial(() -> new float[size]);
    }

    /**
     * Copies the rest positions and normals (unit under the exact rule; none under
     * {@link NormalTransform#NONE}) into the blocks.
     */
    @Override
    public void restShapeChanged() {
        float[] pos = restPositions;
        float[] nrm = restNormals;
        for (int i = 0, n = BLOCK * blockCount; i < n; i++) {
            int o = blockFloats * (i / BLOCK) + i % BLOCK;
            if (blockFloats == DqsLanes.POSITION_BLOCK_FLOATS) {
                for (int c = 0; c < 3; c++) {
                    points[o + BLOCK * c] = pos[3 * i + c];
                }
                continue;
            }
            // Exact normals are unit: normalised here once, a rotation keeps them so (the scalar
            // kernel, for points outside whole blocks, normalises after rotating).
            float nx = nrm[3 * i], ny = nrm[3 * i + 1], nz = nrm[3 * i + 2];
            float len2 = nx * nx + ny * ny + nz * nz;
            float scale = normals == NormalTransform.INVERSE_TRANSPOSE && len2 > 0f ? 1f / (float) Math.sqrt(len2) : 1f;
            for (int c = 0; c < 3; c++) {
                points[o + BLOCK * c] = pos[3 * i + c];
                points[o + BLOCK * (3 + c)] = nrm[3 * i + c] * scale;
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
        if (firstBlock >= endBlock) {
            scalar.skin(palette, outPositions, outNormals, from, to);
            return;
        }
        boolean positionsOnly = normals == NormalTransform.NONE;
        if (outPositions.length < 3 * BLOCK * endBlock || !positionsOnly && outNormals.length < 3 * BLOCK * endBlock) {
            throw new IndexOutOfBoundsException("output arrays shorter than " + 3 * BLOCK * endBlock);
        }
        scalar.skin(palette, outPositions, outNormals, from, BLOCK * firstBlock);
        float[] dq = palette.dualQuaternions();
        float[] tab = blend.signedPairs(dq);
        float[] s = scratch.get();
        if (palette.hasScale()) {
            // Two phases per point, as a matrix: the rigid part of the blended dual quaternion
            // times the blended scale part, then applied like an LBS matrix (see skinDeformations).
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
                blend.blend(tab, s, b, e);
                DqsLanes.rigidDeformations(s, points, blockFloats, r, b, e, p0);
                MatrixPasses.blend(cs, blend.passJoints, blend.passWeights, blend.passWidth, p0, p1, acc);
                MatrixPasses.compose(r, restPositions, p0, acc, p1 - p0);
                // Spilling past p1 is fine when points follow: the next pass or the scalar tail
                // overwrites them.
                if (positionsOnly) {
                    MatrixPasses.positions(acc, restPositions, outPositions, p0, p1, tmp, to - p1 >= 2);
                } else {
                    MatrixPasses.points(acc, restPositions, restNormals, exact, mirror, outPositions, outNormals, p0,
                            p1, tmp, to - p1 >= 2);
                }
            }
            if (exact) {
                MatrixPasses.normalise(outNormals, BLOCK * firstBlock, BLOCK * endBlock);
            }
        } else {
            for (int b = firstBlock; b < endBlock; b += CHUNK) {
                int e = Math.min(endBlock, b + CHUNK);
                blend.blend(tab, s, b, e);
                if (positionsOnly) {
                    DqsLanes.applyPositions(s, points, outPositions, b, e);
                } else {
                    DqsLanes.applyAndStore(s, points, outPositions, outNormals, b, e);
                }
            }
        }
        scalar.skin(palette, outPositions, outNormals, BLOCK * endBlock, to);
    }

    /**
     * Deformations of points {@code [from, to)}: per point the rigid matrix of its blended dual
     * quaternion ({@link DqsLanes#rigidDeformations}), composed with its blended scale part when the palette
     * has one, then applied to the rest position; N is the rotation, or the rotation times the
     * scale part's signed cofactor (exact rule) or linear part.
     */
    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        if (normals == NormalTransform.NONE) {
            throw noDeformationsWithoutNormals();
        }
        checkPalette(palette);
        int firstBlock = (from + BLOCK - 1) / BLOCK;
        int endBlock = Math.min(to / BLOCK, blockCount);
        if (firstBlock >= endBlock) {
            scalar.skinDeformations(palette, outDeformations, from, to);
            return;
        }
        scalar.skinDeformations(palette, outDeformations, from, BLOCK * firstBlock);
        float[] dq = palette.dualQuaternions();
        float[] tab = blend.signedPairs(dq);
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
            blend.blend(tab, s, b, e);
            if (scaled) {
                DqsLanes.rigidDeformations(s, points, r, b, e, p0);
                MatrixPasses.blend(cs, blend.passJoints, blend.passWeights, blend.passWidth, p0, p1, acc);
                MatrixPasses.compose(r, restPositions, p0, acc, p1 - p0);
                MatrixPasses.deformations(acc, restPositions, exact, mirror, outDeformations, p0, p1);
            } else {
                DqsLanes.rigidDeformations(s, points, outDeformations, b, e, 0);
            }
        }
        scalar.skinDeformations(palette, outDeformations, BLOCK * endBlock, to);
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
}
