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
 * <p>Built from the DQS and LBS kernels' passes, per pass of {@link MatrixPasses#CHUNK} points:
 * the signed dual-quaternion blend ({@link SignedDqBlend}) and its rotation as a frame record
 * ({@link DqsLanes#rigidFrames}; the record's position, which CoR does not need, comes along),
 * the blend of the matrices ({@link MatrixPasses#blend}), {@link #centreMatrices} and
 * {@link MatrixPasses#points}. Normals turn by R (R is its own cofactor).
 *
 * <p>Frames whose palette has a scale part ({@link JointPalette#hasScale()}) go through the scalar
 * kernel: there CoR runs DQS's scale phase first and moves the centre by the joints' rigid parts,
 * which these passes do not do. Points of a range outside whole blocks of 8 do too.
 */
final class VectorCorSkinner extends AbstractSkinner {
    private static final int BLOCK = DqsLanes.BLOCK;
    private static final int BLOCKS_PER_PASS = MatrixPasses.CHUNK / BLOCK;

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
    private final ThreadLocal<float[]> lastPoints = ThreadLocal.withInitial(() -> new float[16]);

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
        for (int i = 0; i < BLOCK * blockCount; i++) {
            int o = DqsLanes.BLOCK_FLOATS * (i / BLOCK) + i % BLOCK;
            for (int c = 0; c < 3; c++) {
                points[o + BLOCK * c] = restPositions[3 * i + c];
                points[o + BLOCK * (3 + c)] = restNormals[3 * i + c];
            }
        }
        int size = 16 * jointCount;
        columns = ThreadLocal.withInitial(() -> new float[size]);
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
        boolean exact = normals == NormalTransform.INVERSE_TRANSPOSE;
        float[] tab = blend.signedPairs(palette.dualQuaternions());
        float[] cs = columnMajor(palette);
        float[] acc = matrices.get();
        float[] tmp = lastPoints.get();
        for (int b = firstBlock; b < endBlock; b += BLOCKS_PER_PASS) {
            int e = Math.min(endBlock, b + BLOCKS_PER_PASS);
            int p0 = BLOCK * b;
            int p1 = BLOCK * e;
            pointMatrices(tab, cs, acc, b, e);
            // Spilling past p1 is fine when points follow: the next pass or the scalar tail
            // overwrites them.
            MatrixPasses.points(acc, restPositions, restNormals, exact, false, outPositions, outNormals, p0, p1, tmp,
                    to - p1 >= 2);
        }
        if (exact) {
            MatrixPasses.normalise(outNormals, BLOCK * firstBlock, BLOCK * endBlock);
        }
        scalar.skin(palette, outPositions, outNormals, BLOCK * endBlock, to);
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
