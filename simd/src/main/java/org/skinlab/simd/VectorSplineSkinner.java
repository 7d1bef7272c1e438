package org.skinlab.simd;

import org.skinlab.skinning.AbstractSkinner;
import org.skinlab.skinning.Bones;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.ScalarSplineSkinner;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.skinning.SplineBinding;

/**
 * Spline-based skinning on 8-lane vectors, one point per lane: the formulas of
 * {@link ScalarSplineSkinner} in the passes of {@link SplineLanes}. Per call a table of one
 * record per curve (its control points, posed and rest, its two rotations and the angle between
 * them: the per-curve part of the slerp, so no lane computes an arccos); per block of 8 points and
 * column, the lanes' records are copied in, then the curve, the slerp, the frame and the sums run
 * on lanes. Each point's slots on one curve are merged (one entry with their summed weight), and
 * its rigid influences and distinct curves are moved to the front of their columns, so a block
 * near one joint evaluates one curve, not one per slot.
 *
 * <p>With joint scale, a second per-call table holds each curve's two scale parts, blended along
 * the curve per lane as in the scalar kernel. {@link #skinDeformations} (the route of position sharing)
 * writes the same sums as deformations. Frames with a mirroring joint under exact normals go
 * through the scalar kernel, as do points of a range outside whole blocks of 8.
 */
final class VectorSplineSkinner extends AbstractSkinner {
    private static final int BLOCK = 8;

    private final ScalarSplineSkinner scalar;
    private final int width;
    private final int blockCount;
    /** Per joint its parent when a curve crosses it, else -1 (the table's rows to fill). */
    private final int[] curveParents;
    /** Per block: rest x, y, z, normal x, y, z, 8 lanes each. */
    private final float[] points;
    /** Per (block, column) 8 lanes: the rigid weight and 12 j. */
    private final float[] rigidWeights;
    private final int[] rigidIndex;
    /** Per (block, column) 8 lanes: the merged curve weight and the curve's record offset. */
    private final float[] curveWeights;
    private final int[] curveIndex;
    /** Per (block, column): x, b1, b2, d1, d2, 8 lanes each. */
    private final float[] parameters;
    private final boolean[] anyRigid;
    private final boolean[] anyCurve;
    /** Whether any point follows a curve (else the palette's bone rows are not read, as in the scalar kernel). */
    private final boolean hasCurves;
    private final ThreadLocal<float[]> table;
    /** Per thread: with joint scale, per curve its two joints' scale parts ({@link SplineLanes#scaleTable}). */
    private final ThreadLocal<float[]> scaleTable;
    /** Per thread: the passes' rows ({@link SplineLanes#ROWS}). */
    private final ThreadLocal<float[]> scratch = ThreadLocal.withInitial(() -> new float[SplineLanes.ROWS * BLOCK]);

    VectorSplineSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.SPLINE, "vector-256", geometry, normals);
        SplineBinding binding = SplineBinding.of(geometry);
        this.scalar = new ScalarSplineSkinner(geometry, normals, binding);
        this.width = geometry.influencesPerPoint();
        this.blockCount = geometry.pointCount() / BLOCK;
        int joints = geometry.jointCount();
        Bones bones = geometry.bones();
        curveParents = new int[joints];
        for (int j = 0; j < joints; j++) {
            curveParents[j] = SplineBinding.hasCurve(bones, j) ? bones.parent(j) : -1;
        }
        int slots = BLOCK * width * blockCount;
        points = new float[6 * BLOCK * blockCount];
        rigidWeights = new float[slots];
        rigidIndex = new int[slots];
        curveWeights = new float[slots];
        curveIndex = new int[slots];
        java.util.Arrays.fill(curveIndex, SplineLanes.RECORD * joints);
        parameters = new float[5 * slots];
        anyRigid = new boolean[width * blockCount];
        anyCurve = new boolean[width * blockCount];
        table = ThreadLocal.withInitial(() -> new float[SplineLanes.RECORD * (joints + 1)]);
        scaleTable = ThreadLocal.withInitial(() -> new float[SplineLanes.RECORD * (joints + 1)]);
        layOut(geometry, binding);
        boolean curved = false;
        for (boolean c : anyCurve) {
            curved |= c;
        }
        hasCurves = curved;
        restShapeChanged();
    }

    /**
     * Fills the lanes from the geometry's influences and the binding, each point's rigid
     * influences and its distinct curves moved to the front of their columns.
     */
    private void layOut(SkinnedGeometry geometry, SplineBinding binding) {
        int[] joints = geometry.jointArray();
        float[] weights = geometry.weightArray();
        double a = binding.stiffness();
        for (int i = 0; i < BLOCK * blockCount; i++) {
            int rigidColumn = 0;
            int curveColumn = 0;
            for (int k = 0; k < width; k++) {
                float w = weights[width * i + k];
                int c = binding.curve(i, k);
                if (w == 0f) {
                    continue;
                }
                if (c < 0) {
                    int group = width * (i / BLOCK) + rigidColumn++;
                    rigidWeights[BLOCK * group + i % BLOCK] = w;
                    rigidIndex[BLOCK * group + i % BLOCK] = 12 * joints[width * i + k];
                    anyRigid[group] = true;
                    continue;
                }
                float merged = 0f;
                boolean first = true;
                for (int m = 0; m < width; m++) {
                    if (binding.curve(i, m) == c) {
                        first &= m >= k || weights[width * i + m] == 0f;
                        merged += m >= k ? weights[width * i + m] : 0f;
                    }
                }
                if (!first) {
                    continue;
                }
                int group = width * (i / BLOCK) + curveColumn++;
                curveWeights[BLOCK * group + i % BLOCK] = merged;
                curveIndex[BLOCK * group + i % BLOCK] = SplineLanes.RECORD * c;
                float x = binding.x(i, k);
                int o = 5 * BLOCK * group + i % BLOCK;
                parameters[o] = x;
                parameters[o + BLOCK] = (float) (1 - Math.pow(1 - x, a));
                parameters[o + 2 * BLOCK] = (float) Math.pow(x, a);
                parameters[o + 3 * BLOCK] = (float) (a * Math.pow(1 - x, a - 1));
                parameters[o + 4 * BLOCK] = (float) (a * Math.pow(x, a - 1));
                anyCurve[group] = true;
            }
        }
    }

    @Override
    public void restShapeChanged() {
        float[] positions = geometry().positionArray();
        float[] restNormals = geometry().normalArray();
        for (int i = 0; i < BLOCK * blockCount; i++) {
            int o = 6 * BLOCK * (i / BLOCK) + i % BLOCK;
            for (int c = 0; c < 3; c++) {
                points[o + BLOCK * c] = positions[3 * i + c];
                points[o + BLOCK * (3 + c)] = restNormals[3 * i + c];
            }
        }
        scalar.restShapeChanged();
    }

    @Override
    public int rangeAlignment() {
        return BLOCK;
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        boolean exact = normalTransform() == NormalTransform.INVERSE_TRANSPOSE;
        int firstBlock = (from + BLOCK - 1) / BLOCK;
        int endBlock = Math.min(to / BLOCK, blockCount);
        if ((exact && palette.mirrorsMatrices()) || firstBlock >= endBlock) {
            scalar.skin(palette, outPositions, outNormals, from, to);
            return;
        }
        if (outPositions.length < 3 * BLOCK * endBlock || outNormals.length < 3 * BLOCK * endBlock) {
            throw new IndexOutOfBoundsException("output arrays shorter than " + 3 * BLOCK * endBlock);
        }
        scalar.skin(palette, outPositions, outNormals, from, BLOCK * firstBlock);
        float[] records = prepareTable(palette);
        float[] acc = scratch.get();
        for (int b = firstBlock; b < endBlock; b++) {
            sums(palette, records, b, exact, acc);
            SplineLanes.store(points, 6 * BLOCK * b, exact, acc, outPositions, outNormals, 3 * BLOCK * b);
        }
        scalar.skin(palette, outPositions, outNormals, BLOCK * endBlock, to);
    }

    /**
     * This call's curve table, and with joint scale its scale table (neither filled for a geometry
     * without curves, whose palette may lack bone rows).
     */
    private float[] prepareTable(JointPalette palette) {
        float[] records = table.get();
        if (hasCurves) {
            SplineLanes.curveTable(palette.boneRows(), palette.dualQuaternions(), curveParents, records);
            if (palette.hasScale()) {
                SplineLanes.scaleTable(palette.scales(), curveParents, scaleTable.get());
            }
        }
        return records;
    }

    /** Block b's sums of all its columns into {@code acc}: positions, then the normal matrix. */
    private void sums(JointPalette palette, float[] records, int b, boolean exact, float[] acc) {
        java.util.Arrays.fill(acc, 0, 12 * BLOCK, 0f);
        int pb = 6 * BLOCK * b;
        float[] matrices = palette.matrices();
        for (int k = 0; k < width; k++) {
            int group = width * b + k;
            int lanes = BLOCK * group;
            if (anyRigid[group]) {
                SplineLanes.load(matrices, rigidIndex, lanes, 12, acc);
                SplineLanes.addRigid(rigidWeights, lanes, points, pb, exact, acc);
            }
            if (anyCurve[group]) {
                SplineLanes.load(records, curveIndex, lanes, SplineLanes.RECORD, acc);
                SplineLanes.curve(parameters, 5 * lanes, points, pb, acc);
                SplineLanes.slerp(parameters, 5 * lanes, acc);
                SplineLanes.frame(acc);
                if (palette.hasScale()) {
                    SplineLanes.loadScales(scaleTable.get(), curveIndex, lanes, acc);
                    SplineLanes.scale(parameters, 5 * lanes, exact, acc);
                    SplineLanes.accumulateScaled(curveWeights, lanes, acc);
                } else {
                    SplineLanes.accumulate(curveWeights, lanes, acc);
                }
            }
        }
    }

    @Override
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        boolean exact = normalTransform() == NormalTransform.INVERSE_TRANSPOSE;
        int firstBlock = (from + BLOCK - 1) / BLOCK;
        int endBlock = Math.min(to / BLOCK, blockCount);
        if ((exact && palette.mirrorsMatrices()) || firstBlock >= endBlock) {
            scalar.skinDeformations(palette, outDeformations, from, to);
            return;
        }
        if (outDeformations.length < DEFORMATION_FLOATS * BLOCK * endBlock) {
            throw new IndexOutOfBoundsException("output array shorter than " + DEFORMATION_FLOATS * BLOCK * endBlock);
        }
        scalar.skinDeformations(palette, outDeformations, from, BLOCK * firstBlock);
        float[] records = prepareTable(palette);
        float[] acc = scratch.get();
        for (int b = firstBlock; b < endBlock; b++) {
            sums(palette, records, b, exact, acc);
            SplineLanes.storeDeformations(acc, outDeformations, DEFORMATION_FLOATS * BLOCK * b);
        }
        scalar.skinDeformations(palette, outDeformations, BLOCK * endBlock, to);
    }
}
