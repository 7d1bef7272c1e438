package org.skinlab.simd;

import static org.skinlab.simd.Lanes.S;

import java.util.Arrays;
import java.util.HashMap;
import java.util.Map;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;

import org.skinlab.skinning.AbstractSkinner;
import org.skinlab.skinning.BulgeFreeBinding;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.ScalarBulgeFreeDqsSkinner;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.SkinningMethod;

/**
 * Bulge-free DQS on 8-lane vectors: {@link VectorDqsSkinner} (the DQS lanes, unchanged), then the
 * pull of {@link ScalarBulgeFreeDqsSkinner} over the same range, 8 points per lane group.
 *
 * <p><b>The pull in lanes.</b> Each point reads its own bone, so per call a table holds every
 * joint's posed head, bone vector (tail - head) and inverse squared length (0 for a point-like
 * bone, so the projection parameter is 0), and per 8 points the lanes gather their bone's fields
 * from it (a per-point offset fixed at construction) and their DQS positions from the output
 * (stride 3, or 16 for frames); the nearest point on the bone, the distance and the smooth pull
 * ({@link BulgeFreeBinding#pulledDistance}) run in lanes, and only lanes that are pulled are
 * scattered back (a lane group with none is skipped). Measured on JDK 25 against a scalar gather
 * into columns: 1.66-1.73x vector DQS's time instead of 1.7-2.3x (on JDK 17, whose gathers are
 * slower, 2.0-2.4x against 1.3-1.9x; the start scripts run the newest JDK). The last points of a
 * range that fill no lane group take the scalar pull (JDK 25 bounds-checks masked-off gather lanes).
 *
 * <p>A palette with scale takes the scalar pull (its reference distance goes through each point's
 * joint matrix; docs/skinning.md), after the vector DQS. Normals are DQS's, as in the scalar kernel.
 */
final class VectorBulgeFreeDqsSkinner extends AbstractSkinner {
    /** Lane l's offset from the first point's x: points (3 floats) and frames (16). */
    private static final int[] POSITION_LANES = {0, 3, 6, 9, 12, 15, 18, 21};
    private static final int[] FRAME_LANES = {0, 16, 32, 48, 64, 80, 96, 112};

    private final VectorDqsSkinner dqs;
    private final float[] restPositions;
    private final int[] boneJoints;
    /** Per point, padded to whole lane groups: its bone's offset in the per-call bone table. */
    private final int[] boneOffsets;
    /** Per point its two heaviest influences' joints. */
    private final int[] pairs;
    /**
     * The distinct pairs of two heaviest influences (joints a, b per pair) and per point (padded)
     * the index of its pair: the spread is computed once per pair and call, and gathered per lane.
     */
    private final int[] distinctPairs;
    private final int[] pairOfPoint;
    private final ThreadLocal<float[]> spreads;
    /** Rest distances, padded to whole lane groups. */
    private final float[] restDistances;
    private final BulgeFreeBinding binding;
    private final ThreadLocal<float[]> bones;

    VectorBulgeFreeDqsSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.BFDQS, "vector-256", geometry, normals);
        this.dqs = new VectorDqsSkinner(geometry, normals);
        this.restPositions = geometry.positionArray();
        this.binding = BulgeFreeBinding.of(geometry);
        this.boneJoints = binding.jointArray();
        int points = geometry.pointCount();
        this.boneOffsets = new int[points + S.length()];
        this.pairs = binding.pairArray();
        this.pairOfPoint = new int[points + S.length()];
        for (int i = 0; i < points; i++) {
            boneOffsets[i] = 7 * boneJoints[i];
        }
        this.distinctPairs = indexPairs(pairs, pairOfPoint);
        int pairCount = distinctPairs.length / 2;
        this.spreads = ThreadLocal.withInitial(() -> new float[Math.max(1, pairCount)]);
        this.restDistances = new float[points + S.length()];
        System.arraycopy(binding.restDistanceArray(), 0, restDistances, 0, points);
        int size = 7 * geometry.jointCount();
        this.bones = ThreadLocal.withInitial(() -> new float[size]);
    }

    /** The distinct pairs (a, b) of {@code pairs}, each point's index among them into {@code pairOfPoint}. */
    private static int[] indexPairs(int[] pairs, int[] pairOfPoint) {
        Map<Long, Integer> index = new HashMap<>();
        int[] found = new int[pairs.length];
        for (int i = 0; i < pairs.length / 2; i++) {
            long key = (long) pairs[2 * i] << 32 | pairs[2 * i + 1];
            Integer known = index.get(key);
            if (known == null) {
                known = index.size();
                index.put(key, known);
                found[2 * known] = pairs[2 * i];
                found[2 * known + 1] = pairs[2 * i + 1];
            }
            pairOfPoint[i] = known;
        }
        return Arrays.copyOf(found, 2 * index.size());
    }

    @Override
    public int rangeAlignment() {
        return dqs.rangeAlignment();
    }

    @Override
    public void restShapeChanged() {
        dqs.restShapeChanged();
        binding.restDistances(geometry.bones(), restPositions, restDistances);
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        dqs.skin(palette, outPositions, outNormals, from, to);
        pull(palette, outPositions, 3, 0, from, to);
    }

    @Override
    public void skinFrames(JointPalette palette, float[] outFrames, int from, int to) {
        dqs.skinFrames(palette, outFrames, from, to);
        pull(palette, outFrames, Skinner.FRAME_FLOATS, 8, from, to);
    }

    /** Pulls points [from, to) whose DQS positions sit at {@code stride * i + offset}. */
    private void pull(JointPalette palette, float[] out, int stride, int offset, int from, int to) {
        float[] rows = palette.boneRows();
        float[] dq = palette.dualQuaternions();
        if (palette.hasScale()) {
            float[] m = palette.matrices();
            for (int i = from; i < to; i++) {
                ScalarBulgeFreeDqsSkinner.pullPoint(rows, m, restPositions, i, boneJoints[i], restDistances[i],
                        BulgeFreeBinding.spread(dq, pairs[2 * i], pairs[2 * i + 1]), out, stride * i + offset);
            }
            return;
        }
        float[] table = boneTable(rows, palette.jointCount());
        float[] spread = spreads.get();
        for (int p = 0; 2 * p < distinctPairs.length; p++) {
            spread[p] = BulgeFreeBinding.spread(dq, distinctPairs[2 * p], distinctPairs[2 * p + 1]);
        }
        int[] lanes = stride == 3 ? POSITION_LANES : FRAME_LANES;
        FloatVector zero = FloatVector.zero(S);
        FloatVector one = FloatVector.broadcast(S, 1f);
        float allowance = BulgeFreeBinding.ALLOWANCE;
        int k = from;
        for (; k + S.length() <= to; k += S.length()) {
            int o = stride * k + offset;
            FloatVector hx = FloatVector.fromArray(S, table, 0, boneOffsets, k);
            FloatVector hy = FloatVector.fromArray(S, table, 1, boneOffsets, k);
            FloatVector hz = FloatVector.fromArray(S, table, 2, boneOffsets, k);
            FloatVector ex = FloatVector.fromArray(S, table, 3, boneOffsets, k);
            FloatVector ey = FloatVector.fromArray(S, table, 4, boneOffsets, k);
            FloatVector ez = FloatVector.fromArray(S, table, 5, boneOffsets, k);
            FloatVector il = FloatVector.fromArray(S, table, 6, boneOffsets, k);
            FloatVector qx = FloatVector.fromArray(S, out, o, lanes, 0);
            FloatVector qy = FloatVector.fromArray(S, out, o + 1, lanes, 0);
            FloatVector qz = FloatVector.fromArray(S, out, o + 2, lanes, 0);
            FloatVector r = FloatVector.fromArray(S, restDistances, k);
            FloatVector ax = qx.sub(hx), ay = qy.sub(hy), az = qz.sub(hz);
            FloatVector t = ax.mul(ex).add(ay.mul(ey)).add(az.mul(ez)).mul(il).max(zero).min(one);
            FloatVector cx = ex.fma(t, hx), cy = ey.fma(t, hy), cz = ez.fma(t, hz);
            FloatVector ux = qx.sub(cx), uy = qy.sub(cy), uz = qz.sub(cz);
            FloatVector d2 = ux.mul(ux).add(uy.mul(uy)).add(uz.mul(uz));
            VectorMask<Float> beyond = d2.compare(VectorOperators.GT, r.mul(r));
            if (!beyond.anyTrue()) {
                continue;
            }
            FloatVector d = d2.sqrt();
            FloatVector a = r.mul(allowance).mul(FloatVector.fromArray(S, spread, 0, pairOfPoint, k));
            FloatVector e = d.sub(r);
            FloatVector f = e.mul(a).div(a.fma(a, e.mul(e)).max(Float.MIN_NORMAL).sqrt()).add(r).div(d);
            ux.fma(f, cx).intoArray(out, o, lanes, 0, beyond);
            uy.fma(f, cy).intoArray(out, o + 1, lanes, 0, beyond);
            uz.fma(f, cz).intoArray(out, o + 2, lanes, 0, beyond);
        }
        for (; k < to; k++) {
            ScalarBulgeFreeDqsSkinner.pullPoint(rows, null, restPositions, k, boneJoints[k], restDistances[k],
                    BulgeFreeBinding.spread(dq, pairs[2 * k], pairs[2 * k + 1]), out, stride * k + offset);
        }
    }

    /** Per joint: posed head, bone vector, inverse squared length (0 for a point-like bone). */
    private float[] boneTable(float[] rows, int joints) {
        float[] t = bones.get();
        for (int j = 0; j < joints; j++) {
            int b = JointPalette.BONE_FLOATS * j;
            float ex = rows[b + 4] - rows[b], ey = rows[b + 5] - rows[b + 1], ez = rows[b + 6] - rows[b + 2];
            float len2 = ex * ex + ey * ey + ez * ez;
            int o = 7 * j;
            t[o] = rows[b];
            t[o + 1] = rows[b + 1];
            t[o + 2] = rows[b + 2];
            t[o + 3] = ex;
            t[o + 4] = ey;
            t[o + 5] = ez;
            t[o + 6] = len2 > 0f ? 1f / len2 : 0f;
        }
        return t;
    }
}
