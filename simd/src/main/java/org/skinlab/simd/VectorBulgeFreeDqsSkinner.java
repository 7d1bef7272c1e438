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
 * bone, so the projection parameter is 0) in a record of 8 floats. Per {@link #CHUNK} points two
 * loops meet in per-thread scratch, as {@link VectorDqsSkinner}'s passes do: the points' records
 * are loaded (one vector load each, the offset fixed at construction) and transposed in registers
 * into lane columns ({@link #transposeBones}); then per 8 points the lanes gather their DQS positions from
 * the output (stride 3, or 16 for deformations), and the nearest point on the bone, the distance and
 * the smooth pull ({@link BulgeFreeBinding#pulledDistance}) run in lanes ({@link #pullLanes}); a
 * lane group with a pulled lane is written back through a scratch row and scalar stores (a lane
 * group with none is skipped). The last points of a range that fill no lane group take the
 * scalar pull (JDK 25 bounds-checks masked-off gather lanes).
 *
 * <p><b>Allocation-free.</b> A vector whose Vector API call C2 does not intrinsify is boxed, on
 * every call. The pull once gathered the 7 bone fields in its one loop (11 gathers in all): JDK
 * 17's C2 reached its node budget (NodeCountInliningCutoff) at the sixth gather, and the masked
 * scatter that wrote lanes back, which AVX2 lacks, JDK 17 does not emulate: about 9 kB per call
 * on 203 points, after any warm-up. On JDK 25 the loads and the transpose cost no more than the
 * gathers did.
 *
 * <p>A palette with scale takes the scalar pull (its reference distance goes through each point's
 * joint matrix; docs/skinning.md), after the vector DQS. Normals are DQS's, as in the scalar kernel.
 */
final class VectorBulgeFreeDqsSkinner extends AbstractSkinner {
    /** Lane l's offset from the first point's x: points (3 floats) and deformations (16). */
    private static final int[] POSITION_LANES = {0, 3, 6, 9, 12, 15, 18, 21};
    private static final int[] DEFORMATION_LANES = {0, 16, 32, 48, 64, 80, 96, 112};
    /** Floats per joint in the bone table: head, bone vector, 1 / |bone|^2 and one of padding (a lane vector). */
    private static final int BONE_RECORD = 8;
    /** Points per chunk of the two passes of the pull: their bone columns stay in L1. */
    private static final int CHUNK = 256;

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
    /** Per chunk of points, their bones' fields in lane columns ({@link #transposeBones}). */
    private final ThreadLocal<float[]> boneColumns = ThreadLocal.withInitial(() -> new float[BONE_RECORD * CHUNK]);
    /** One lane group's pulled x, y and z lanes on their way out ({@link #pullLanes}). */
    private final ThreadLocal<float[]> pulledLanes = ThreadLocal.withInitial(() -> new float[3 * S.length()]);

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
            boneOffsets[i] = BONE_RECORD * boneJoints[i];
        }
        this.distinctPairs = indexPairs(pairs, pairOfPoint);
        int pairCount = distinctPairs.length / 2;
        this.spreads = ThreadLocal.withInitial(() -> new float[Math.max(1, pairCount)]);
        this.restDistances = new float[points + S.length()];
        System.arraycopy(binding.restDistanceArray(), 0, restDistances, 0, points);
        int size = BONE_RECORD * geometry.jointCount();
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
    public void skinDeformations(JointPalette palette, float[] outDeformations, int from, int to) {
        dqs.skinDeformations(palette, outDeformations, from, to);
        pull(palette, outDeformations, Skinner.DEFORMATION_FLOATS, 8, from, to);
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
        float[] columns = boneColumns.get();
        float[] pulled = pulledLanes.get();
        int[] lanes = stride == 3 ? POSITION_LANES : DEFORMATION_LANES;
        int whole = from + (to - from) / S.length() * S.length();
        for (int k = from; k < whole; k += CHUNK) {
            int e = Math.min(whole, k + CHUNK);
            transposeBones(table, columns, k, e);
            pullLanes(columns, spread, pulled, lanes, out, stride, offset, k, e);
        }
        for (int k = whole; k < to; k++) {
            ScalarBulgeFreeDqsSkinner.pullPoint(rows, null, restPositions, k, boneJoints[k], restDistances[k],
                    BulgeFreeBinding.spread(dq, pairs[2 * k], pairs[2 * k + 1]), out, stride * k + offset);
        }
    }

    /**
     * Pass 1 of the pull on the lane groups of [k, e): the 8 points' bone records (head, bone
     * vector, inverse squared length, padding), one vector load each, transposed in registers into
     * lane columns, field c of lane group g at {@code 64 g + 8 c} (the padding column is not
     * stored). The network is {@link DqsLanes#transpose}'s, whose rows are contiguous; here each
     * row is a joint's record, so it is written out again rather than called (a call that C2 does
     * not inline would box its vectors).
     */
    private void transposeBones(float[] table, float[] columns, int k, int e) {
        for (int i = k, so = 0; i < e; i += S.length(), so += BONE_RECORD * S.length()) {
            FloatVector r0 = FloatVector.fromArray(S, table, boneOffsets[i]);
            FloatVector r1 = FloatVector.fromArray(S, table, boneOffsets[i + 1]);
            FloatVector r2 = FloatVector.fromArray(S, table, boneOffsets[i + 2]);
            FloatVector r3 = FloatVector.fromArray(S, table, boneOffsets[i + 3]);
            FloatVector r4 = FloatVector.fromArray(S, table, boneOffsets[i + 4]);
            FloatVector r5 = FloatVector.fromArray(S, table, boneOffsets[i + 5]);
            FloatVector r6 = FloatVector.fromArray(S, table, boneOffsets[i + 6]);
            FloatVector r7 = FloatVector.fromArray(S, table, boneOffsets[i + 7]);
            FloatVector a0 = r0.blend(r1.rearrange(Lanes.RIGHT1), Lanes.ODD);
            FloatVector a1 = r0.rearrange(Lanes.LEFT1).blend(r1, Lanes.ODD);
            FloatVector a2 = r2.blend(r3.rearrange(Lanes.RIGHT1), Lanes.ODD);
            FloatVector a3 = r2.rearrange(Lanes.LEFT1).blend(r3, Lanes.ODD);
            FloatVector a4 = r4.blend(r5.rearrange(Lanes.RIGHT1), Lanes.ODD);
            FloatVector a5 = r4.rearrange(Lanes.LEFT1).blend(r5, Lanes.ODD);
            FloatVector a6 = r6.blend(r7.rearrange(Lanes.RIGHT1), Lanes.ODD);
            FloatVector a7 = r6.rearrange(Lanes.LEFT1).blend(r7, Lanes.ODD);
            FloatVector c0 = a0.blend(a2.rearrange(Lanes.RIGHT2), Lanes.PAIRS);
            FloatVector c2 = a0.rearrange(Lanes.LEFT2).blend(a2, Lanes.PAIRS);
            FloatVector c1 = a1.blend(a3.rearrange(Lanes.RIGHT2), Lanes.PAIRS);
            FloatVector c3 = a1.rearrange(Lanes.LEFT2).blend(a3, Lanes.PAIRS);
            FloatVector c4 = a4.blend(a6.rearrange(Lanes.RIGHT2), Lanes.PAIRS);
            FloatVector c6 = a4.rearrange(Lanes.LEFT2).blend(a6, Lanes.PAIRS);
            FloatVector c5 = a5.blend(a7.rearrange(Lanes.RIGHT2), Lanes.PAIRS);
            FloatVector c7 = a5.rearrange(Lanes.LEFT2).blend(a7, Lanes.PAIRS);
            c0.blend(c4.rearrange(Lanes.SWAP), Lanes.HI).intoArray(columns, so);
            c1.blend(c5.rearrange(Lanes.SWAP), Lanes.HI).intoArray(columns, so + 8);
            c2.blend(c6.rearrange(Lanes.SWAP), Lanes.HI).intoArray(columns, so + 16);
            c3.blend(c7.rearrange(Lanes.SWAP), Lanes.HI).intoArray(columns, so + 24);
            c0.rearrange(Lanes.SWAP).blend(c4, Lanes.HI).intoArray(columns, so + 32);
            c1.rearrange(Lanes.SWAP).blend(c5, Lanes.HI).intoArray(columns, so + 40);
            c2.rearrange(Lanes.SWAP).blend(c6, Lanes.HI).intoArray(columns, so + 48);
        }
    }

    /**
     * Pass 2 on the lane groups of [k, e): the nearest point on the bone, the distance and the
     * smooth pull, for points whose DQS positions sit at {@code stride * i + offset}. A lane group
     * with a pulled lane goes out through {@code pulled} and scalar stores, every lane (the lanes
     * not pulled write back the floats they read).
     */
    private void pullLanes(float[] columns, float[] spread, float[] pulled, int[] lanes, float[] out, int stride,
            int offset, int k, int e) {
        FloatVector zero = FloatVector.zero(S);
        FloatVector one = FloatVector.broadcast(S, 1f);
        float allowance = BulgeFreeBinding.ALLOWANCE;
        for (int i = k, c = 0; i < e; i += S.length(), c += BONE_RECORD * S.length()) {
            int o = stride * i + offset;
            FloatVector hx = FloatVector.fromArray(S, columns, c);
            FloatVector hy = FloatVector.fromArray(S, columns, c + 8);
            FloatVector hz = FloatVector.fromArray(S, columns, c + 16);
            FloatVector ex = FloatVector.fromArray(S, columns, c + 24);
            FloatVector ey = FloatVector.fromArray(S, columns, c + 32);
            FloatVector ez = FloatVector.fromArray(S, columns, c + 40);
            FloatVector il = FloatVector.fromArray(S, columns, c + 48);
            FloatVector qx = FloatVector.fromArray(S, out, o, lanes, 0);
            FloatVector qy = FloatVector.fromArray(S, out, o + 1, lanes, 0);
            FloatVector qz = FloatVector.fromArray(S, out, o + 2, lanes, 0);
            FloatVector r = FloatVector.fromArray(S, restDistances, i);
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
            FloatVector a = r.mul(allowance).mul(FloatVector.fromArray(S, spread, 0, pairOfPoint, i));
            FloatVector ed = d.sub(r);
            FloatVector f = ed.mul(a).div(a.fma(a, ed.mul(ed)).max(Float.MIN_NORMAL).sqrt()).add(r).div(d);
            qx.blend(ux.fma(f, cx), beyond).intoArray(pulled, 0);
            qy.blend(uy.fma(f, cy), beyond).intoArray(pulled, 8);
            qz.blend(uz.fma(f, cz), beyond).intoArray(pulled, 16);
            for (int l = 0; l < S.length(); l++) {
                int at = o + lanes[l];
                out[at] = pulled[l];
                out[at + 1] = pulled[8 + l];
                out[at + 2] = pulled[16 + l];
            }
        }
    }

    /** Per joint: posed head, bone vector, inverse squared length (0 for a point-like bone). */
    private float[] boneTable(float[] rows, int joints) {
        float[] t = bones.get();
        for (int j = 0; j < joints; j++) {
            int b = JointPalette.BONE_FLOATS * j;
            float ex = rows[b + 4] - rows[b], ey = rows[b + 5] - rows[b + 1], ez = rows[b + 6] - rows[b + 2];
            float len2 = ex * ex + ey * ey + ez * ez;
            int o = BONE_RECORD * j;
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
