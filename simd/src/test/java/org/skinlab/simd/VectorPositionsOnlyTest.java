package org.skinlab.simd;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Arrays;

import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.testing.RandomRigs;

/**
 * The Vector API kernels under {@link NormalTransform#NONE} (positions only) against the same
 * vector kernels with normals, on the same range. Tolerance: none, positions equal bit for bit
 * (raw int bits): the positions-only loops and passes run the same lane operations on the position
 * (the same fused multiply-adds in the same order) and leave the normal out. Ranges on and off the
 * 8-point grid (the scalar head and tail of DQS, the LBS kernel's spilling stores), nothing written
 * outside a range, normals not touched.
 */
class VectorPositionsOnlyTest {
    private static final NormalTransform[] WITH_NORMALS = {NormalTransform.BLENDED_MATRIX,
        NormalTransform.INVERSE_TRANSPOSE};

    private static Skinner vector(SkinningMethod method, SkinnedGeometry g, NormalTransform normals) {
        Skinner s = new VectorSkinnerProvider().create(method, g.boundFor(method), normals);
        assertTrue(s != null, "the test JVM has the incubator module and AVX2: the provider must offer a kernel");
        return s;
    }

    private static float[] nanFilled(int n) {
        float[] a = new float[n];
        Arrays.fill(a, Float.NaN);
        return a;
    }

    /** Palettes: random rigid joints; every other joint scaled non-uniformly; every other mirrored. */
    private static JointPalette palette(SkinnedGeometry g, long seed, String joints) {
        if (!joints.equals("mirrored")) {
            return RandomRigs.palette(g, seed, joints.equals("scaled"));
        }
        JointPalette palette = RandomRigs.palette(g, seed, false);
        Matrix4f m = new Matrix4f();
        for (int j = 0; j < palette.jointCount(); j += 2) {
            palette.setMatrix(j, palette.getMatrix(j, m).scale(-1f, 1f, 1f));
        }
        palette.prepareAll();
        return palette;
    }

    private static void assertSameBits(float[] expected, float[] actual, int from, int to, String what) {
        for (int i = 0; i < actual.length; i++) {
            boolean inside = i >= 3 * from && i < 3 * to;
            if (!inside) {
                if (!Float.isNaN(actual[i])) {
                    fail(what + ": float " + i + " outside [" + from + ", " + to + ") was written");
                }
            } else if (Float.floatToRawIntBits(actual[i]) != Float.floatToRawIntBits(expected[i])) {
                fail(what + ": float " + i + " (point " + i / 3 + ") of [" + from + ", " + to + ") is " + actual[i]
                        + ", with normals " + expected[i]);
            }
        }
    }

    @ParameterizedTest(name = "{0}, {1} influences, {2} joints")
    @CsvSource({"LBS, 1, rigid", "LBS, 2, scaled", "LBS, 3, mirrored", "LBS, 4, rigid", "LBS, 4, scaled",
        "LBS, 4, mirrored", "LBS, 6, rigid", "LBS, 8, rigid", "LBS, 8, mirrored", "LBS, 11, scaled", "DQS, 1, rigid",
        "DQS, 1, scaled", "DQS, 2, rigid", "DQS, 2, mirrored", "DQS, 4, rigid", "DQS, 4, scaled", "DQS, 4, mirrored",
        "DQS, 6, scaled", "DQS, 8, rigid", "DQS, 8, scaled", "DQS, 8, mirrored", "DQS, 11, rigid"})
    void positionsOnlyAreTheWithNormalsPositionsBitForBit(SkinningMethod method, int width, String joints) {
        // 203 points: 25 whole blocks of 8 and a tail of 3; 16 joints so 11 distinct ones fit.
        SkinnedGeometry g = RandomRigs.geometry(200 + width, 203, width, 16);
        JointPalette palette = palette(g, 31 + width, joints);
        int n = g.pointCount();
        Skinner positionsOnly = vector(method, g, NormalTransform.NONE);
        assertEquals("vector-256", positionsOnly.implementation());
        int[] edges = {0, 1, 2, 7, 8, 9, 16, 63, 64, 65, 100, 199, 200, 201, 202, 203};
        for (NormalTransform rule : WITH_NORMALS) {
            Skinner withNormals = vector(method, g, rule);
            for (int from : edges) {
                for (int to : edges) {
                    if (from <= to) {
                        // The same range with normals: DQS skins points outside whole blocks of 8
                        // with the scalar kernel, whose last bits differ from the lanes'.
                        float[] expected = new float[3 * n];
                        withNormals.skin(palette, expected, new float[3 * n], from, to);
                        float[] actual = nanFilled(3 * n);
                        positionsOnly.skin(palette, actual, null, from, to);
                        assertSameBits(expected, actual, from, to, method + " " + joints + " against " + rule);
                    }
                }
            }
        }
    }

    @Test
    void positionsOnlyOnTheDefaultCharacter() throws Exception {
        SkinnedGeometry g = Geometries.humanoid();
        int n = g.pointCount();
        for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.LBS, SkinningMethod.DQS}) {
            for (boolean scaled : new boolean[] {false, true}) {
                JointPalette palette = RandomRigs.palette(g, scaled ? 12 : 13, scaled);
                float[] expected = new float[3 * n];
                vector(m, g, NormalTransform.INVERSE_TRANSPOSE).skinAll(palette, expected, new float[3 * n]);
                float[] actual = nanFilled(3 * n);
                Skinner k = Skinners.create(m, g.boundFor(m), NormalTransform.NONE);
                assertEquals("vector-256", k.implementation(), "Skinners.create picks the vector kernel");
                k.skinAll(palette, actual, null);
                assertSameBits(expected, actual, 0, n, "humanoid " + m + (scaled ? " scaled" : ""));
            }
        }
    }

    @Test
    void theNormalsArrayIsNotTouchedAndDeformationsAreRefused() {
        SkinnedGeometry g = RandomRigs.geometry(9, 77, 4, 16);
        JointPalette palette = RandomRigs.palette(g, 10, true);
        for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.LBS, SkinningMethod.DQS}) {
            Skinner k = vector(m, g, NormalTransform.NONE);
            float[] normals = nanFilled(3 * 77);
            k.skinAll(palette, new float[3 * 77], normals);
            for (float f : normals) {
                assertTrue(Float.isNaN(f), m + " wrote a normal");
            }
            assertThrows(UnsupportedOperationException.class,
                    () -> k.skinDeformations(palette, new float[Skinner.DEFORMATION_FLOATS * 77], 0, 77));
        }
    }

    @Test
    void otherMethodsRefusePositionsOnlyInTheProviderToo() {
        SkinnedGeometry g = RandomRigs.geometry(11, 40, 2, 8);
        for (SkinningMethod m : SkinningMethod.values()) {
            if (!m.skinsPositionsOnly()) {
                IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                        () -> new VectorSkinnerProvider().create(m, g.boundFor(m), NormalTransform.NONE), m.key());
                assertTrue(e.getMessage().contains(m.key()), e.getMessage());
            }
        }
    }
}
