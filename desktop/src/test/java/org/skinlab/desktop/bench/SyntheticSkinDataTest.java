package org.skinlab.desktop.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.api.Test;
import org.skinlab.desktop.bench.ThesisSkinningBaseline;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.ParallelSkinner;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * The synthetic data against the C++ reference: the checksums {@code skin_ref.cpp} prints at
 * V = 10000 (copied from ../shared/perf/README.md, where the C++ computed them: LBS 971.419057,
 * DQS 1046.777414) must come out of every implementation we benchmark.
 *
 * <p>Tolerance 1e-3 on the sum: the inputs are bit-identical, but the outputs are not: our kernels
 * use fused multiply-adds (vector) or another operation order, and DQS's dual quaternions are
 * derived from the matrices by the palette rather than taken from the generator. Each of the 60000
 * summed floats (|x| <= ~3) then differs by a few float ulps, ~1e-7 each, mostly cancelling: a
 * total of 1e-4 at worst, while a wrong point alone moves the sum by ~0.1 and a wrong sign or
 * component by far more.
 */
class SyntheticSkinDataTest {
    private static final int V = 10_000;
    private static final double LBS = 971.419057;
    private static final double DQS = 1046.777414;

    @ParameterizedTest(name = "{0} {1}, {2} threads")
    @CsvSource({"LBS, scalar, 1", "LBS, auto, 1", "LBS, auto, 2", "DQS, scalar, 1", "DQS, auto, 1", "DQS, auto, 2",
        "DQS, scalar, 2"})
    void checksumMatchesTheCppReference(SkinningMethod method, String implementation, int threads) {
        SyntheticSkinData data = new SyntheticSkinData(V);
        SkinnedGeometry g = data.geometry();
        Skinner kernel = implementation.equals("scalar") ? Skinners.scalar(method, g, NormalTransform.BLENDED_MATRIX)
                : Skinners.create(method, g, NormalTransform.BLENDED_MATRIX);
        if (implementation.equals("auto")) {
            assertEquals("vector-256", kernel.implementation(), "the desktop test JVM has the Vector API kernels");
        }
        float[] p = new float[3 * V];
        float[] n = new float[3 * V];
        try (ParallelSkinner s = new ParallelSkinner(kernel, threads)) {
            s.skinAll(data.palette(), p, n);
        }
        assertEquals(method == SkinningMethod.LBS ? LBS : DQS, SyntheticSkinData.checksum(p, n), 1e-3);
    }

    @ParameterizedTest
    @CsvSource({"LBS", "DQS"})
    void thesisBaselineComputesTheSameDeformation(SkinningMethod method) {
        SyntheticSkinData data = new SyntheticSkinData(2000);
        float[] p = new float[3 * 2000];
        float[] n = new float[3 * 2000];
        new ThesisSkinningBaseline(data.geometry(), method).skinAll(data.palette(), p, n);
        float[] sp = new float[3 * 2000];
        float[] sn = new float[3 * 2000];
        Skinners.scalar(method, data.geometry(), NormalTransform.BLENDED_MATRIX).skinAll(data.palette(), sp, sn);
        for (int i = 0; i < p.length; i++) {
            // Same formulas via JOML objects; rotations from a polar decomposition in double: 1e-4.
            assertEquals(sp[i], p[i], 1e-4, "position float " + i);
            assertEquals(sn[i], n[i], 1e-4, "normal float " + i);
        }
    }

    @Test
    void paletteDualQuaternionsEqualTheGeneratorsUpToSign() {
        // The bench derives DQS's dual quaternions from the matrices, as every frame does; the C++
        // takes the generator's. Both must be the same rigid transforms: q or -q, within 1e-6.
        SyntheticSkinData data = new SyntheticSkinData(1);
        JointPalette palette = data.palette();
        assertFalse(palette.hasScale(), "the joints are rigid");
        float[] ours = palette.dualQuaternions();
        float[] ref = data.dualQuaternions();
        for (int j = 0; j < SyntheticSkinData.JOINTS; j++) {
            float sign = Math.signum(dot(ours, ref, 8 * j));
            for (int c = 0; c < 8; c++) {
                assertEquals(ref[8 * j + c], sign * ours[8 * j + c], 1e-6, "joint " + j + " component " + c);
            }
        }
    }

    @Test
    void firstJointComesFromTheFirstFourDrawsOfSplitMix64Seed42() {
        // Written out from the definition (Steele et al. 2014): the state advances by the golden
        // gamma, the output is the mixed state; floats are the top 24 bits scaled to [-1, 1).
        float[] draws = new float[4];
        long state = 42L;
        for (int i = 0; i < 4; i++) {
            long z = state += 0x9E3779B97F4A7C15L;
            z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
            z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
            z ^= z >>> 31;
            draws[i] = (float) (z >>> 40) * (1.0f / 16777216.0f) * 2.0f - 1.0f;
        }
        float n = (float) Math.sqrt(draws[0] * draws[0] + draws[1] * draws[1] + draws[2] * draws[2]
                + draws[3] * draws[3]);
        float[] q = new SyntheticSkinData(10).dualQuaternions();
        for (int c = 0; c < 4; c++) {
            assertEquals(draws[c] / n, q[c], 0f, "component " + c + " of the first joint's rotation");
        }
        assertEquals(java.util.Arrays.toString(new SyntheticSkinData(100).matrices()),
                java.util.Arrays.toString(new SyntheticSkinData(100).matrices()), "deterministic");
    }

    private static float dot(float[] a, float[] b, int o) {
        float s = 0;
        for (int c = 0; c < 4; c++) {
            s += a[o + c] * b[o + c];
        }
        return s;
    }
}
