package org.skinlab.simd;

import static org.skinlab.simd.Lanes.S;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorOperators;

/**
 * The influence passes of {@link VectorStbsSkinner} on one block of 8 points: per influence its
 * joints' data, the endpoint weight e and half twist angle, the rotation r and the translation x
 * (core's {@code StbsInfluence}), 7 lane vectors per influence at {@code 56 k} of the scratch that
 * {@link StbsLanes} then blends.
 *
 * <p><b>No vector crosses a call of ours</b>, not even into {@link #sinCos}: see {@link StbsLanes}.
 */
final class StbsInfluenceLanes {
    /** Floats of the scratch per influence: r x, y, z, w, then x x, y, z, 8 lanes each. */
    static final int INFLUENCE_FLOATS = 56;
    /** Floats per influence of its joints' data ({@link #joints}): 24 fields, 8 lanes each. */
    static final int JOINT_FLOATS = 192;
    /** Where the dual quaternion's real part sits among a joint's fields ({@link #packJoints}). */
    private static final int DQ = 4;

    // sin and cos of |a| <= pi/2 by their Taylor series to x^11 and x^12: the first term left out
    // is below 6e-8 there (|a| <= pi/2 since the angle is -(1 - e) theta / 2 with |theta| <= pi).
    private static final float S3 = -1f / 6, S5 = 1f / 120, S7 = -1f / 5040, S9 = 1f / 362880, S11 = -1f / 39916800;
    private static final float C2 = -1f / 2, C4 = 1f / 24, C6 = -1f / 720, C8 = 1f / 40320, C10 = -1f / 3628800,
            C12 = 1f / 479001600;

    private StbsInfluenceLanes() {
    }

    /**
     * sin and cos, lane by lane, of the angles |a| <= pi/2 at {@code s[from ..]} (see the
     * constants) into {@code s[sinAt ..]} and {@code s[cosAt ..]} (either may be {@code from}).
     */
    static void sinCos(float[] s, int from, int sinAt, int cosAt) {
        FloatVector a = FloatVector.fromArray(S, s, from);
        FloatVector a2 = a.mul(a);
        FloatVector p = a2.mul(S11).add(S9);
        p = p.mul(a2).add(S7);
        p = p.mul(a2).add(S5);
        p = p.mul(a2).add(S3);
        FloatVector c = a2.mul(C12).add(C10);
        c = c.mul(a2).add(C8);
        c = c.mul(a2).add(C6);
        c = c.mul(a2).add(C4);
        c = c.mul(a2).add(C2);
        p.mul(a2).add(1f).mul(a).intoArray(s, sinAt);
        c.mul(a2).add(1f).intoArray(s, cosAt);
    }

    /**
     * Each influence of block {@code b} for its points at {@code blk[48 b ..]} (px py pz, 8 lanes
     * each): joints' data ({@link #packJoints}) through {@code rowIndex} (24 j), 8 lanes per
     * influence at {@code 8 (b width + k)}; r and x of the first {@code active} into {@code s[56 k ..]},
     * their joints' data transposed in {@code t} (192 floats per influence).
     * Four passes (see the class comment): the joints' data, the stretch e and half angle, the
     * rotation, the translation.
     */
    static void influences(float[] table, int[] rowIndex, float[] blk, int b, int width, int active, float[] s,
            float[] t) {
        joints(table, rowIndex, b, width, active, t);
        stretch(blk, b, active, s, t);
        rotation(active, s, t);
        translation(active, s, t);
    }

    /**
     * Per joint j the data the passes read, 24 floats at {@code 24 j} (so the bone-row offsets
     * index it): bone rows 0..3, the dual quaternion's real part (rows 4..7 are not read), rows 8..23.
     */
    static void packJoints(float[] rows, float[] dq, int jointCount, float[] table) {
        System.arraycopy(rows, 0, table, 0, 24 * jointCount);
        for (int j = 0; j < jointCount; j++) {
            for (int c = 0; c < 4; c++) {
                table[24 * j + DQ + c] = dq[8 * j + c];
            }
        }
    }

    /**
     * Per influence its lanes' joints' data ({@link #packJoints}) into {@code t[192 k ..]}, field f
     * at {@code 8 f} (8 lanes): each lane's 24 floats copied as three 8-float rows, then 8 lanes'
     * rows transposed ({@link DqsLanes#transpose}, in place). Not {@code fromArray} with an index
     * map: C2 intrinsifies that gather only where it inlines {@code IntVector.species} (96 bytes,
     * left out at call sites it profiles as cold), so some compilations (every one on JDK 17) run
     * its Java fallback, which allocates.
     */
    private static void joints(float[] table, int[] rowIndex, int b, int width, int active, float[] t) {
        for (int k = 0; k < active; k++) {
            int m = 8 * (b * width + k);
            int g = JOINT_FLOATS * k;
            for (int l = 0; l < 8; l++) {
                int r = rowIndex[m + l];
                FloatVector.fromArray(S, table, r).intoArray(t, g + 8 * l);
                FloatVector.fromArray(S, table, r + 8).intoArray(t, g + 64 + 8 * l);
                FloatVector.fromArray(S, table, r + 16).intoArray(t, g + 128 + 8 * l);
            }
        }
        DqsLanes.transpose(t, t, 0, 3 * active);
    }

    /**
     * Per influence the endpoint weight e of the block's points along the bone (1 for a bone
     * without length) into {@code s[56 k + 32 ..]} and the half twist angle (e - 1) theta / 2 into
     * {@code s[56 k + 40 ..]}, where {@link #translation} later writes x.
     */
    private static void stretch(float[] blk, int b, int active, float[] s, float[] t) {
        final FloatVector one = FloatVector.broadcast(S, 1f);
        final FloatVector zero = FloatVector.zero(S);
        int fo = VectorStbsSkinner.BLOCK_FLOATS * b;
        FloatVector px = FloatVector.fromArray(S, blk, fo);
        FloatVector py = FloatVector.fromArray(S, blk, fo + 8);
        FloatVector pz = FloatVector.fromArray(S, blk, fo + 16);
        for (int k = 0; k < active; k++) {
            int g = JOINT_FLOATS * k;
            FloatVector hx = FloatVector.fromArray(S, t, g + 8 * 16);
            FloatVector hy = FloatVector.fromArray(S, t, g + 8 * 17);
            FloatVector hz = FloatVector.fromArray(S, t, g + 8 * 18);
            FloatVector length = FloatVector.fromArray(S, t, g + 8 * 19);
            FloatVector along = px.sub(hx).mul(FloatVector.fromArray(S, t, g + 8 * 20).sub(hx))
                    .add(py.sub(hy).mul(FloatVector.fromArray(S, t, g + 8 * 21).sub(hy)))
                    .add(pz.sub(hz).mul(FloatVector.fromArray(S, t, g + 8 * 22).sub(hz)));
            VectorMask<Float> point = length.compare(VectorOperators.GT, 0f);
            FloatVector e = one.blend(along.div(length.mul(length)).max(zero).min(one), point);
            int so = INFLUENCE_FLOATS * k;
            e.intoArray(s, so + 32);
            e.sub(one).mul(FloatVector.fromArray(S, t, g + 8 * 3)).mul(0.5f).intoArray(s, so + 40);
        }
    }

    /** Per influence the rotation r = u q, u the twist by the half angle about the bone, into {@code s[56 k ..]}. */
    private static void rotation(int active, float[] s, float[] t) {
        for (int k = 0; k < active; k++) {
            int g = JOINT_FLOATS * k;
            int so = INFLUENCE_FLOATS * k;
            sinCos(s, so + 40, so + 40, so + 48);
            FloatVector sin = FloatVector.fromArray(S, s, so + 40);
            FloatVector uw = FloatVector.fromArray(S, s, so + 48);
            FloatVector ux = FloatVector.fromArray(S, t, g + 8 * 12).mul(sin);
            FloatVector uy = FloatVector.fromArray(S, t, g + 8 * 13).mul(sin);
            FloatVector uz = FloatVector.fromArray(S, t, g + 8 * 14).mul(sin);
            FloatVector qx = FloatVector.fromArray(S, t, g + 8 * (DQ + 0));
            FloatVector qy = FloatVector.fromArray(S, t, g + 8 * (DQ + 1));
            FloatVector qz = FloatVector.fromArray(S, t, g + 8 * (DQ + 2));
            FloatVector qw = FloatVector.fromArray(S, t, g + 8 * (DQ + 3));
            uw.mul(qx).add(ux.mul(qw)).add(uy.mul(qz).sub(uz.mul(qy))).intoArray(s, so);
            uw.mul(qy).add(uy.mul(qw)).add(uz.mul(qx).sub(ux.mul(qz))).intoArray(s, so + 8);
            uw.mul(qz).add(uz.mul(qw)).add(ux.mul(qy).sub(uy.mul(qx))).intoArray(s, so + 16);
            uw.mul(qw).sub(ux.mul(qx).add(uy.mul(qy)).add(uz.mul(qz))).intoArray(s, so + 24);
        }
    }

    /**
     * Per influence the translation x = o + e t - R(r) h (o, t: bone rows 0..2 and 8..10, h the
     * head; R(r) h = h + 2 r x (r x h + w h)) into {@code s[56 k + 32 ..]}, over e and the half angle.
     */
    private static void translation(int active, float[] s, float[] t) {
        for (int k = 0; k < active; k++) {
            int g = JOINT_FLOATS * k;
            int so = INFLUENCE_FLOATS * k;
            FloatVector rx = FloatVector.fromArray(S, s, so);
            FloatVector ry = FloatVector.fromArray(S, s, so + 8);
            FloatVector rz = FloatVector.fromArray(S, s, so + 16);
            FloatVector rw = FloatVector.fromArray(S, s, so + 24);
            FloatVector e = FloatVector.fromArray(S, s, so + 32);
            FloatVector hx = FloatVector.fromArray(S, t, g + 8 * 16);
            FloatVector hy = FloatVector.fromArray(S, t, g + 8 * 17);
            FloatVector hz = FloatVector.fromArray(S, t, g + 8 * 18);
            FloatVector cx = ry.mul(hz).sub(rz.mul(hy)).add(rw.mul(hx));
            FloatVector cy = rz.mul(hx).sub(rx.mul(hz)).add(rw.mul(hy));
            FloatVector cz = rx.mul(hy).sub(ry.mul(hx)).add(rw.mul(hz));
            FloatVector gx = ry.mul(cz).sub(rz.mul(cy));
            FloatVector gy = rz.mul(cx).sub(rx.mul(cz));
            FloatVector gz = rx.mul(cy).sub(ry.mul(cx));
            e.fma(FloatVector.fromArray(S, t, g + 8 * 8), FloatVector.fromArray(S, t, g + 8 * 0))
                    .sub(hx.add(gx.add(gx))).intoArray(s, so + 32);
            e.fma(FloatVector.fromArray(S, t, g + 8 * 9), FloatVector.fromArray(S, t, g + 8 * 1))
                    .sub(hy.add(gy.add(gy))).intoArray(s, so + 40);
            e.fma(FloatVector.fromArray(S, t, g + 8 * 10), FloatVector.fromArray(S, t, g + 8 * 2))
                    .sub(hz.add(gz.add(gz))).intoArray(s, so + 48);
        }
    }
}
