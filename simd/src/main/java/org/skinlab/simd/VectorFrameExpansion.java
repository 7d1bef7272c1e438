package org.skinlab.simd;

import static org.skinlab.simd.Lanes.HI;
import static org.skinlab.simd.Lanes.S;
import static org.skinlab.simd.Lanes.SWAP;

import jdk.incubator.vector.FloatVector;

import org.skinlab.skinning.FrameExpansion;
import org.skinlab.skinning.Skinner;

/**
 * {@link FrameExpansion} on 8-lane vectors, one point per iteration: the frame's two halves
 * {@code [N0 | N1]}, {@code [N2 | p]} are two loads, {@code N n} is two multiplies and a lane swap,
 * and both results go out with 8-lane stores whose tails spill into the next points (the last two
 * points of a range are written float by float with the same sums, so a range writes nothing
 * outside itself). Exact
 * normals are then renormalised eight at a time ({@link MatrixPasses#normalise}).
 */
final class VectorFrameExpansion implements FrameExpansion {
    static final VectorFrameExpansion INSTANCE = new VectorFrameExpansion();

    private VectorFrameExpansion() {
    }

    @Override
    public void expand(float[] frames, int[] frameOfPoint, float[] restNormals, float[] outPositions,
            float[] outNormals, int from, int to, boolean normalise) {
        int end = Math.max(from, to - 2);
        final FloatVector zero = FloatVector.zero(S);
        for (int i = from; i < end; i++) {
            int f = Skinner.FRAME_FLOATS * frameOfPoint[i];
            int v = 3 * i;
            FloatVector n01 = FloatVector.fromArray(S, frames, f);
            FloatVector n2p = FloatVector.fromArray(S, frames, f + 8);
            FloatVector nxy = FloatVector.broadcast(S, restNormals[v]).blend(FloatVector.broadcast(S, restNormals[v + 1]), HI);
            FloatVector nz0 = FloatVector.broadcast(S, restNormals[v + 2]).blend(zero, HI);
            FloatVector t = n01.mul(nxy).add(n2p.mul(nz0));
            t.add(t.rearrange(SWAP)).intoArray(outNormals, v);
            n2p.rearrange(SWAP).intoArray(outPositions, v);
        }
        for (int i = end; i < to; i++) {
            // The loop's sums in the loop's order, so results do not depend on where a range ends.
            int f = Skinner.FRAME_FLOATS * frameOfPoint[i];
            int v = 3 * i;
            float nx = restNormals[v], ny = restNormals[v + 1], nz = restNormals[v + 2];
            outNormals[v] = frames[f] * nx + frames[f + 8] * nz + frames[f + 4] * ny;
            outNormals[v + 1] = frames[f + 1] * nx + frames[f + 9] * nz + frames[f + 5] * ny;
            outNormals[v + 2] = frames[f + 2] * nx + frames[f + 10] * nz + frames[f + 6] * ny;
            outPositions[v] = frames[f + 12];
            outPositions[v + 1] = frames[f + 13];
            outPositions[v + 2] = frames[f + 14];
        }
        if (normalise) {
            MatrixPasses.normalise(outNormals, from, to);
        }
    }

    @Override
    public String implementation() {
        return "vector-256";
    }
}
