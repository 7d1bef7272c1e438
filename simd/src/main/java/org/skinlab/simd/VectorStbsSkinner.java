package org.skinlab.simd;

import org.skinlab.skinning.AbstractSkinner;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.ScalarStbsSkinner;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;

/**
 * Stretchable and twistable bones on LBS or DQS on 8-lane vectors, 8 points per block: the
 * arithmetic of {@link ScalarStbsSkinner} written once per lane, in small passes per block
 * ({@link StbsLanes}): every influence's rigid transformation (its joint's bone rows and dual
 * quaternion copied per lane from a per-call joint table and transposed; sin and cos by
 * polynomials), then the blend and its application.
 *
 * <p><b>Layout.</b> The constructor repacks the geometry into blocks of 8 points: px py pz nx ny
 * nz, 8 lanes each, and per influence k of block b at {@code 8 (b width + k)} the weights and the
 * offsets of the joints' data (24 j, in the bone rows and in {@link StbsLanes#packJoints}'s table). Points of a range
 * outside whole blocks ({@link #rangeAlignment()}) go through the scalar kernel.
 *
 * <p>{@link #skinDeformations} (the route of position sharing) runs the same influence pass and blend,
 * then writes 8 points' deformations from lanes: on LBS the blend's position and its linear
 * part's cofactor (or that part), transposed ({@link StbsLanes#linearDeformations}); on DQS through
 * the DQS kernel's {@link DqsLanes#rigidDeformations}.
 */
final class VectorStbsSkinner extends AbstractSkinner {
    static final int BLOCK = 8;
    static final int BLOCK_FLOATS = 48;

    private final ScalarStbsSkinner scalar;
    private final boolean dualQuaternions;
    private final int width;
    private final int blockCount;
    private final int jointCount;
    private final float[] restPositions;
    private final float[] restNormals;
    private final float[] points;
    private final float[] weights;
    private final int[] rowIndex;
    /** Per block the influences that matter: 1 + the last slot with a weight above 0 in any lane. */
    private final int[] activeWidth;
    private final ThreadLocal<float[]> scratch;
    private final ThreadLocal<float[]> jointScratch;
    /** Per thread the joints' data of the palette being applied ({@link StbsLanes#packJoints}). */
    private final ThreadLocal<float[]> jointTable;
    /** Per thread one block's deformations in lanes ({@link #skinDeformations}): 16 fields, 8 lanes each. */
    private final ThreadLocal<float[]> deformationScratch = ThreadLocal.withInitial(() -> new float[DEFORMATION_FLOATS * BLOCK]);

    VectorStbsSkinner(SkinningMethod method, SkinnedGeometry geometry, NormalTransform normals) {
        super(method, "vector-256", geometry, normals);
        this.scalar = new ScalarStbsSkinner(method, geometry, normals);
        this.dualQuaternions = method == SkinningMethod.STBS_DQS;
        this.width = geometry.influencesPerPoint();
        this.jointCount = geometry.jointCount();
        this.restPositions = geometry.positionArray();
        this.restNormals = geometry.normalArray();
        blockCount = geometry.pointCount() / BLOCK;
        points = new float[BLOCK_FLOATS * blockCount];
        restShapeChanged();
        int n = BLOCK * blockCount * width;
        weights = new float[n];
        rowIndex = new int[n];
        int[] js = geometry.jointArray();
        float[] ws = geometry.weightArray();
        for (int i = 0; i < BLOCK * blockCount; i++) {
            for (int k = 0; k < width; k++) {
                int o = BLOCK * ((i / BLOCK) * width + k) + i % BLOCK;
                weights[o] = ws[width * i + k];
                rowIndex[o] = JointPalette.BONE_FLOATS * js[width * i + k];
            }
        }
        activeWidth = new int[blockCount];
        for (int i = 0; i < BLOCK * blockCount; i++) {
            for (int k = 0; k < width; k++) {
                if (ws[width * i + k] != 0f) {
                    activeWidth[i / BLOCK] = Math.max(activeWidth[i / BLOCK], k + 1);
                }
            }
        }
        int size = StbsInfluenceLanes.INFLUENCE_FLOATS * width + StbsLanes.BLEND_FLOATS;
        scratch = ThreadLocal.withInitial(() -> new float[size]);
        jointScratch = ThreadLocal.withInitial(() -> new float[StbsInfluenceLanes.JOINT_FLOATS * width]);
        int tableSize = JointPalette.BONE_FLOATS * jointCount;
        jointTable = ThreadLocal.withInitial(() -> new float[tableSize]);
    }

    /** Copies the rest positions and normals (unit under the exact rule) into the blocks. */
    @Override
    public void restShapeChanged() {
        for (int i = 0, n = BLOCK * blockCount; i < n; i++) {
            int o = BLOCK_FLOATS * (i / BLOCK) + i % BLOCK;
            float nx = restNormals[3 * i], ny = restNormals[3 * i + 1], nz = restNormals[3 * i + 2];
            float len2 = nx * nx + ny * ny + nz * nz;
            boolean unit = normals == NormalTransform.INVERSE_TRANSPOSE && dualQuaternions && len2 > 0f;
            float scale = unit ? 1f / (float) Math.sqrt(len2) : 1f;
            for (int c = 0; c < 3; c++) {
                points[o + BLOCK * c] = restPositions[3 * i + c];
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
        if (palette.jointCount() != jointCount) {
            throw new IllegalArgumentException("palette of " + palette.jointCount() + " joints for a geometry of "
                    + jointCount);
        }
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
        float[] rows = palette.boneRows();
        float[] dq = palette.dualQuaternions();
        float[] s = scratch.get();
        float[] t = jointScratch.get();
        float[] table = jointTable.get();
        StbsInfluenceLanes.packJoints(rows, dq, jointCount, table);
        boolean exact = normals == NormalTransform.INVERSE_TRANSPOSE;
        int blend = StbsInfluenceLanes.INFLUENCE_FLOATS * width;
        for (int b = firstBlock; b < endBlock; b++) {
            // Trailing slots without weight in the whole block (padding) are left out: each costs
            // 24 copied and transposed floats per lane and a sin and a cos.
            int active = Math.max(1, activeWidth[b]);
            StbsInfluenceLanes.influences(table, rowIndex, points, b, width, active, s, t);
            if (dualQuaternions) {
                StbsLanes.dualQuaternion(s, blend, weights, points, b, width, active, exact, outPositions, outNormals);
            } else {
                StbsLanes.linear(s, blend, weights, points, b, width, active, exact, outPositions, outNormals);
            }
        }
        scalar.skin(palette, outPositions, outNormals, BLOCK * endBlock, to);
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        if (palette.jointCount() != jointCount) {
            throw new IllegalArgumentException("palette of " + palette.jointCount() + " joints for a geometry of "
                    + jointCount);
        }
        int firstBlock = (from + BLOCK - 1) / BLOCK;
        int endBlock = Math.min(to / BLOCK, blockCount);
        if (firstBlock >= endBlock) {
            scalar.skinDeformations(palette, outDeformations, from, to);
            return;
        }
        if (outDeformations.length < DEFORMATION_FLOATS * BLOCK * endBlock) {
            throw new IndexOutOfBoundsException("output array shorter than " + DEFORMATION_FLOATS * BLOCK * endBlock);
        }
        scalar.skinDeformations(palette, outDeformations, from, BLOCK * firstBlock);
        float[] s = scratch.get();
        float[] t = jointScratch.get();
        float[] table = jointTable.get();
        float[] f = deformationScratch.get();
        StbsInfluenceLanes.packJoints(palette.boneRows(), palette.dualQuaternions(), jointCount, table);
        boolean exact = normals == NormalTransform.INVERSE_TRANSPOSE;
        int blend = StbsInfluenceLanes.INFLUENCE_FLOATS * width;
        for (int b = firstBlock; b < endBlock; b++) {
            int active = Math.max(1, activeWidth[b]);
            StbsInfluenceLanes.influences(table, rowIndex, points, b, width, active, s, t);
            if (dualQuaternions) {
                StbsLanes.dualQuaternionDeformations(s, weights, points, b, width, active, f, outDeformations);
            } else {
                StbsLanes.linearDeformations(s, blend, weights, points, b, width, active, exact, f, outDeformations);
            }
        }
        scalar.skinDeformations(palette, outDeformations, BLOCK * endBlock, to);
    }
}
