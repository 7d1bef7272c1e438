package org.skinlab.simd;

import jdk.incubator.vector.FloatVector;
import jdk.incubator.vector.VectorMask;
import jdk.incubator.vector.VectorShuffle;
import jdk.incubator.vector.VectorSpecies;

/**
 * The 8-lane (256-bit) species the kernels use, and the constant lane permutations they share.
 * Everything here is a compile-time constant for C2, which turns each {@code rearrange} into one
 * {@code vpermps} and each {@code blend} into one {@code vblendps}.
 */
final class Lanes {
    static final VectorSpecies<Float> S = FloatVector.SPECIES_256;

    /** Swaps the two 4-lane halves. */
    static final VectorShuffle<Float> SWAP = shuffle(4, 5, 6, 7, 0, 1, 2, 3);
    /** Lanes 4..7. */
    static final VectorMask<Float> HI = mask(4, 5, 6, 7);
    /** Per half, (x y z w) -> (y z x w) and (z x y w): the operands of a cross product. */
    static final VectorShuffle<Float> YZX = shuffle(1, 2, 0, 3, 5, 6, 4, 7);
    static final VectorShuffle<Float> ZXY = shuffle(2, 0, 1, 3, 6, 4, 5, 7);

    // 8x8 transpose in three stages of blend(shifted): 1-lane, 2-lane, then 4-lane granules.
    static final VectorShuffle<Float> RIGHT1 = shuffle(0, 0, 1, 2, 3, 4, 5, 6);
    static final VectorShuffle<Float> LEFT1 = shuffle(1, 2, 3, 4, 5, 6, 7, 7);
    static final VectorShuffle<Float> RIGHT2 = shuffle(0, 1, 0, 1, 2, 3, 4, 5);
    static final VectorShuffle<Float> LEFT2 = shuffle(2, 3, 4, 5, 6, 7, 6, 7);
    static final VectorMask<Float> ODD = mask(1, 3, 5, 7);
    static final VectorMask<Float> PAIRS = mask(2, 3, 6, 7);

    // Interleaving three 8-lane vectors x, y, z into x0 y0 z0 x1 ... z7 (three output vectors):
    // output vector o, lane l holds element IL[o][l] of the 24 (x = 0..7, y = 8..15, z = 16..23);
    // output o = x.rearrange(Xo).blend(y.rearrange(Yo), MYo).blend(z.rearrange(Zo), MZo).
    private static final int[][] IL = {{0, 8, 16, 1, 9, 17, 2, 10}, {18, 3, 11, 19, 4, 12, 20, 5},
        {13, 21, 6, 14, 22, 7, 15, 23}};
    static final VectorShuffle<Float> X0 = interleave(0, 0), Y0 = interleave(0, 1), Z0 = interleave(0, 2);
    static final VectorShuffle<Float> X1 = interleave(1, 0), Y1 = interleave(1, 1), Z1 = interleave(1, 2);
    static final VectorShuffle<Float> X2 = interleave(2, 0), Y2 = interleave(2, 1), Z2 = interleave(2, 2);
    static final VectorMask<Float> MY0 = from(0, 1), MZ0 = from(0, 2);
    static final VectorMask<Float> MY1 = from(1, 1), MZ1 = from(1, 2);
    static final VectorMask<Float> MY2 = from(2, 1), MZ2 = from(2, 2);

    // The inverse: lane l of component c (x = 0, y = 1, z = 2) is element 3 l + c of the 24, taken
    // from v0, v1 or v2 (element / 8): c = v0.rearrange(Gc0).blend(v1.rearrange(Gc1), MGc1)
    // .blend(v2.rearrange(Gc2), MGc2).
    static final VectorShuffle<Float> GX0 = gather(0, 0), GX1 = gather(0, 1), GX2 = gather(0, 2);
    static final VectorShuffle<Float> GY0 = gather(1, 0), GY1 = gather(1, 1), GY2 = gather(1, 2);
    static final VectorShuffle<Float> GZ0 = gather(2, 0), GZ1 = gather(2, 1), GZ2 = gather(2, 2);
    static final VectorMask<Float> MGX1 = gatherMask(0, 1), MGX2 = gatherMask(0, 2);
    static final VectorMask<Float> MGY1 = gatherMask(1, 1), MGY2 = gatherMask(1, 2);
    static final VectorMask<Float> MGZ1 = gatherMask(2, 1), MGZ2 = gatherMask(2, 2);
    /** One value per point spread over that point's three floats, for output vectors 0, 1, 2. */
    static final VectorShuffle<Float> TRIPLE0 = shuffle(0, 0, 0, 1, 1, 1, 2, 2);
    static final VectorShuffle<Float> TRIPLE1 = shuffle(2, 3, 3, 3, 4, 4, 4, 5);
    static final VectorShuffle<Float> TRIPLE2 = shuffle(5, 5, 6, 6, 6, 7, 7, 7);

    private Lanes() {
    }

    private static VectorShuffle<Float> gather(int component, int source) {
        int[] lanes = new int[8];
        for (int l = 0; l < 8; l++) {
            int e = 3 * l + component;
            lanes[l] = e / 8 == source ? e % 8 : 0;
        }
        return shuffle(lanes);
    }

    private static VectorMask<Float> gatherMask(int component, int source) {
        boolean[] set = new boolean[8];
        for (int l = 0; l < 8; l++) {
            set[l] = (3 * l + component) / 8 == source;
        }
        return VectorMask.fromArray(S, set, 0);
    }


    private static VectorShuffle<Float> shuffle(int... lanes) {
        return VectorShuffle.fromArray(S, lanes, 0);
    }

    private static VectorMask<Float> mask(int... lanes) {
        boolean[] set = new boolean[S.length()];
        for (int l : lanes) {
            set[l] = true;
        }
        return VectorMask.fromArray(S, set, 0);
    }

    private static VectorShuffle<Float> interleave(int output, int source) {
        int[] lanes = new int[8];
        for (int l = 0; l < 8; l++) {
            lanes[l] = IL[output][l] / 8 == source ? IL[output][l] % 8 : 0;
        }
        return shuffle(lanes);
    }

    private static VectorMask<Float> from(int output, int source) {
        boolean[] set = new boolean[8];
        for (int l = 0; l < 8; l++) {
            set[l] = IL[output][l] / 8 == source;
        }
        return VectorMask.fromArray(S, set, 0);
    }
}
