package org.skinlab.simd;

import static org.skinlab.simd.Lanes.S;

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
 * <p><b>The pull in lanes.</b> Each point reads its own bone, so the lanes' bone data is gathered
 * first: per call a table of every joint's posed head, bone vector (tail - head) and its inverse
 * squared length (0 for a point-like bone, so the projection parameter is 0); then, per pass of up
 * to {@link #PASS} points, a scalar loop copies each point's bone and DQS position into columns
 * (structure of arrays, per-thread scratch in L1), one vector loop computes the nearest point on
 * the bone, the distance, the smooth pull ({@link BulgeFreeBinding#pulledDistance}) and the new
 * position for 8 points at a time (the rest distances are loaded straight from their array), and a
 * scalar loop writes the positions back. (A Vector API gather per field was measured 7x slower
 * than scalar loads for the DQS blend, so the gather is scalar here too.)
 *
 * <p>A palette with scale takes the scalar pull (its reference distance goes through each point's
 * joint matrix; docs/skinning.md), after the vector DQS. Normals are DQS's, as in the scalar kernel.
 */
final class VectorBulgeFreeDqsSkinner extends AbstractSkinner {
    /** Points per pass of the pull: the columns' length. */
    static final int PASS = 128;
    /** Columns of one pass: hx hy hz ex ey ez inverse-length^2, qx qy qz. */
    private static final int COLUMNS = 10;

    private final VectorDqsSkinner dqs;
    private final float[] restPositions;
    private final int[] boneJoints;
    /** Rest distances, padded to whole lane groups. */
    private final float[] restDistances;
    private final BulgeFreeBinding binding;
    private final ThreadLocal<float[]> bones;
    private final ThreadLocal<float[]> columns = ThreadLocal.withInitial(() -> new float[COLUMNS * PASS]);

    VectorBulgeFreeDqsSkinner(SkinnedGeometry geometry, NormalTransform normals) {
        super(SkinningMethod.BFDQS, "vector-256", geometry, normals);
        this.dqs = new VectorDqsSkinner(geometry, normals);
        this.restPositions = geometry.positionArray();
        this.binding = BulgeFreeBinding.of(geometry);
        this.boneJoints = binding.jointArray();
        int points = geometry.pointCount();
        this.restDistances = new float[points + S.length()];
        System.arraycopy(binding.restDistanceArray(), 0, restDistances, 0, points);
        int size = 7 * geometry.jointCount();
        this.bones = ThreadLocal.withInitial(() -> new float[size]);
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
        if (palette.hasScale()) {
            float[] m = palette.matrices();
            for (int i = from; i < to; i++) {
                ScalarBulgeFreeDqsSkinner.pullPoint(rows, m, restPositions, i, boneJoints[i], restDistances[i], out,
                        stride * i + offset);
            }
            return;
        }
        float[] table = boneTable(rows, palette.jointCount());
        float[] c = columns.get();
        for (int p0 = from; p0 < to; p0 += PASS) {
            int n = Math.min(PASS, to - p0);
            gather(table, out, stride, offset, p0, n, c);
            pullLanes(c, p0, n);
            for (int k = 0; k < n; k++) {
                int o = stride * (p0 + k) + offset;
                out[o] = c[7 * PASS + k];
                out[o + 1] = c[8 * PASS + k];
                out[o + 2] = c[9 * PASS + k];
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

    /** Each point's bone and DQS position into the columns. */
    private void gather(float[] table, float[] out, int stride, int offset, int p0, int n, float[] c) {
        for (int k = 0; k < n; k++) {
            int j = 7 * boneJoints[p0 + k];
            for (int f = 0; f < 7; f++) {
                c[f * PASS + k] = table[j + f];
            }
            int o = stride * (p0 + k) + offset;
            c[7 * PASS + k] = out[o];
            c[8 * PASS + k] = out[o + 1];
            c[9 * PASS + k] = out[o + 2];
        }
    }

    /**
     * The pull of n points in lanes: columns 7..9 (the DQS positions) are overwritten with the
     * pulled ones. Lanes past n compute on stale columns and are not written back.
     */
    private void pullLanes(float[] c, int p0, int n) {
        FloatVector zero = FloatVector.zero(S);
        FloatVector one = FloatVector.broadcast(S, 1f);
        float allowance = BulgeFreeBinding.ALLOWANCE;
        for (int k = 0; k < n; k += S.length()) {
            FloatVector hx = FloatVector.fromArray(S, c, k);
            FloatVector hy = FloatVector.fromArray(S, c, PASS + k);
            FloatVector hz = FloatVector.fromArray(S, c, 2 * PASS + k);
            FloatVector ex = FloatVector.fromArray(S, c, 3 * PASS + k);
            FloatVector ey = FloatVector.fromArray(S, c, 4 * PASS + k);
            FloatVector ez = FloatVector.fromArray(S, c, 5 * PASS + k);
            FloatVector il = FloatVector.fromArray(S, c, 6 * PASS + k);
            FloatVector qx = FloatVector.fromArray(S, c, 7 * PASS + k);
            FloatVector qy = FloatVector.fromArray(S, c, 8 * PASS + k);
            FloatVector qz = FloatVector.fromArray(S, c, 9 * PASS + k);
            FloatVector r = FloatVector.fromArray(S, restDistances, p0 + k);
            FloatVector ax = qx.sub(hx), ay = qy.sub(hy), az = qz.sub(hz);
            FloatVector t = ax.mul(ex).add(ay.mul(ey)).add(az.mul(ez)).mul(il).max(zero).min(one);
            FloatVector cx = ex.fma(t, hx), cy = ey.fma(t, hy), cz = ez.fma(t, hz);
            FloatVector ux = qx.sub(cx), uy = qy.sub(cy), uz = qz.sub(cz);
            FloatVector d2 = ux.mul(ux).add(uy.mul(uy)).add(uz.mul(uz));
            VectorMask<Float> beyond = d2.compare(VectorOperators.GT, r.mul(r));
            FloatVector d = d2.sqrt();
            FloatVector a = r.mul(allowance);
            FloatVector e = d.sub(r);
            FloatVector pulled = e.mul(a).div(a.fma(a, e.mul(e)).sqrt()).add(r);
            FloatVector f = pulled.div(d);
            ux.fma(f, cx).blend(qx, beyond.not()).intoArray(c, 7 * PASS + k);
            uy.fma(f, cy).blend(qy, beyond.not()).intoArray(c, 8 * PASS + k);
            uz.fma(f, cz).blend(qz, beyond.not()).intoArray(c, 9 * PASS + k);
        }
    }
}
