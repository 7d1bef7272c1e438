package org.skinlab.simd;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;

import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.ParallelSkinner;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.testing.RandomRigs;

/**
 * The vector kernels split over threads give the same bits as one call: LBS computes a range's
 * last points with the same vector arithmetic (through a scratch array), and the parallel split
 * keeps DQS's and CoR's blocks whole (their range alignment is 8).
 */
class ParallelVectorSkinnerTest {
    @ParameterizedTest(name = "{0} {1}")
    @CsvSource({"LBS, BLENDED_MATRIX", "LBS, INVERSE_TRANSPOSE", "DQS, BLENDED_MATRIX", "DQS, INVERSE_TRANSPOSE",
        "COR, BLENDED_MATRIX", "COR, INVERSE_TRANSPOSE"})
    void splitOverThreadsIsBitIdenticalToOneCall(SkinningMethod method, NormalTransform normals) {
        for (int points : new int[] {1, 2, 3, 17, 64, 1003}) {
            SkinnedGeometry g = RandomRigs.geometry(points, points, 4, 10);
            JointPalette palette = RandomRigs.palette(g, 3, false);
            Skinner kernel = new VectorSkinnerProvider().create(method, g.boundFor(method), normals);
            float[] p1 = new float[3 * points];
            float[] n1 = new float[3 * points];
            kernel.skinAll(palette, p1, n1);
            for (int threads = 2; threads <= 3; threads++) {
                try (ParallelSkinner parallel = new ParallelSkinner(kernel, threads)) {
                    float[] p = new float[3 * points];
                    float[] n = new float[3 * points];
                    parallel.skinAll(palette, p, n);
                    assertArrayEquals(p1, p, points + " points, " + threads + " threads");
                    assertArrayEquals(n1, n, points + " points, " + threads + " threads");
                }
            }
            // Any split into two ranges, too (what a caller's own scheduling might do).
            for (int cut = 0; cut <= points; cut += Math.max(1, points / 7)) {
                float[] p = new float[3 * points];
                float[] n = new float[3 * points];
                kernel.skin(palette, p, n, 0, cut);
                kernel.skin(palette, p, n, cut, points);
                if (method == SkinningMethod.LBS || cut % 8 == 0) { // DQS, CoR: partial blocks go scalar
                    assertArrayEquals(p1, p, "cut at " + cut);
                    assertArrayEquals(n1, n, "cut at " + cut);
                }
            }
        }
    }
}
