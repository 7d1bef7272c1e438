package org.skinlab.simd;

import static org.skinlab.simd.Lanes.S;
import static org.skinlab.simd.Lanes.SWAP;

import jdk.incubator.vector.FloatVector;

import org.skinlab.skinning.DeformationExpansion;
import org.skinlab.skinning.Skinner;

/**
 * {@link DeformationExpansion} on 8-lane vectors, one point per iteration. The rest normals are laid out
 * once as the operands the deformation's halves {@code [N0 | N1]} and {@code [p | N2]} are multiplied by:
 * {@code [nx nx nx nx | ny ny ny ny]} and {@code [0 0 0 0 | nz nz nz nz]} (16 floats per point),
 * so a point costs four loads, a multiply, a fused multiply-add, one lane swap and an add; the
 * position is stored straight from the deformation's second half. Both stores are 8 lanes wide and spill
 * into the next points, which overwrite them; the last two points of a range are written float by
 * float with the same sums in the same order, so a range writes nothing outside itself and any
 * split gives the same bits. Exact normals are then renormalised eight at a time
 * ({@link MatrixPasses#normalise}).
 */
final class VectorDeformationExpansion implements DeformationExpansion {
    private final int[] deformationOfPoint;
    private final float[] operands;

    VectorDeformationExpansion(int[] deformationOfPoint, float[] restNormals) {
        this.deformationOfPoint = deformationOfPoint;
        int n = deformationOfPoint.length;
        operands = new float[16 * n];
        for (int i = 0; i < n; i++) {
            float nx = restNormals[3 * i], ny = restNormals[3 * i + 1], nz = restNormals[3 * i + 2];
            for (int l = 0; l < 4; l++) {
                operands[16 * i + l] = nx;
                operands[16 * i + 4 + l] = ny;
                operands[16 * i + 12 + l] = nz;
            }
        }
    }

    @Override
    public void expand(float[] deformations, float[] outPositions, float[] outNormals, int from, int to,
            boolean normalise) {
        final int[] fop = deformationOfPoint;
        final float[] ops = operands;
        int end = Math.max(from, to - 2);
        for (int i = from; i < end; i++) {
            int f = Skinner.DEFORMATION_FLOATS * fop[i];
            int v = 3 * i;
            FloatVector n01 = FloatVector.fromArray(S, deformations, f);
            FloatVector pn2 = FloatVector.fromArray(S, deformations, f + 8);
            FloatVector t = n01.mul(FloatVector.fromArray(S, ops, 16 * i))
                    .add(pn2.mul(FloatVector.fromArray(S, ops, 16 * i + 8)));
            t.add(t.rearrange(SWAP)).intoArray(outNormals, v);
            pn2.intoArray(outPositions, v);
        }
        for (int i = end; i < to; i++) {
            // The loop's sums in the loop's order: (N0 nx + 0) + (N1 ny + N2 nz).
            int f = Skinner.DEFORMATION_FLOATS * fop[i];
            int v = 3 * i;
            int o = 16 * i;
            float nx = ops[o], ny = ops[o + 4], nz = ops[o + 12];
            for (int c = 0; c < 3; c++) {
                outNormals[v + c] = (deformations[f + c] * nx + deformations[f + 8 + c] * 0f)
                        + (deformations[f + 4 + c] * ny + deformations[f + 12 + c] * nz);
                outPositions[v + c] = deformations[f + 8 + c];
            }
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
