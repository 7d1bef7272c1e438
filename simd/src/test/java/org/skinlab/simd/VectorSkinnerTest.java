package org.skinlab.simd;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Arrays;

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
 * The Vector API kernels against core's scalar kernels, the reference: same points, same palette,
 * outputs compared point by point.
 *
 * <p>Tolerance: |vector - scalar| <= 2e-5 * max(1, |scalar|). Both compute in float with the same
 * formulas, but the vector kernels use fused multiply-adds in the blend (one rounding instead of
 * two per term) and a float square root and division where the scalar kernels go through double;
 * each of the ~30 operations on the way to an output rounds by at most 6e-8 relative, and outputs
 * here are at most ~10 in size, so differences stay near 1e-6; 2e-5 leaves room without hiding a
 * wrong lane, sign or component (those are off by 1e-2 or more).
 */
class VectorSkinnerTest {
    /** The methods with Vector API kernels: all of them. */
    private static final SkinningMethod[] WITH_VECTOR_KERNELS = SkinningMethod.values();

    private static final float TOLERANCE = 2e-5f;

    private static Skinner vector(SkinningMethod method, SkinnedGeometry g, NormalTransform normals) {
        Skinner s = new VectorSkinnerProvider().create(method, g.boundFor(method), normals);
        assertTrue(s != null, "the test JVM has the incubator module and AVX2: the provider must offer a kernel");
        return s;
    }

    /** Skins [from, to) with both kernels into NaN-filled outputs and compares everything. */
    private static void assertAgrees(Skinner vector, JointPalette palette, int from, int to) {
        Skinner scalar = Skinners.scalar(vector.method(), vector.geometry(), vector.normalTransform());
        int n = vector.geometry().pointCount();
        float[] vp = nanFilled(3 * n);
        float[] vn = nanFilled(3 * n);
        float[] sp = nanFilled(3 * n);
        float[] sn = nanFilled(3 * n);
        vector.skin(palette, vp, vn, from, to);
        scalar.skin(palette, sp, sn, from, to);
        for (int i = 0; i < 3 * n; i++) {
            boolean inside = i >= 3 * from && i < 3 * to;
            if (!inside) {
                // Outside the range nothing may be written: the LBS kernel's wide stores spill
                // into the next points, which must stay inside the range.
                if (!Float.isNaN(vp[i]) || !Float.isNaN(vn[i])) {
                    fail("float " + i + " outside [" + from + ", " + to + ") was written");
                }
                continue;
            }
            check("position", i, vp[i], sp[i], from, to, vector);
            check("normal", i, vn[i], sn[i], from, to, vector);
        }
    }

    private static void check(String what, int i, float actual, float expected, int from, int to, Skinner k) {
        if (!(Math.abs(actual - expected) <= TOLERANCE * Math.max(1f, Math.abs(expected)))) {
            fail(k.method() + " " + k.normalTransform() + " " + what + " float " + i + " (point " + i / 3 + ") of ["
                    + from + ", " + to + "): vector " + actual + ", scalar " + expected);
        }
    }

    private static float[] nanFilled(int n) {
        float[] a = new float[n];
        Arrays.fill(a, Float.NaN);
        return a;
    }

    @ParameterizedTest(name = "{0} {1}, {2} influences")
    @CsvSource({"LBS, BLENDED_MATRIX, 4", "LBS, INVERSE_TRANSPOSE, 4", "DQS, BLENDED_MATRIX, 4",
        "DQS, INVERSE_TRANSPOSE, 4", "LBS, INVERSE_TRANSPOSE, 1", "LBS, BLENDED_MATRIX, 3", "DQS, BLENDED_MATRIX, 2",
        "DQS, INVERSE_TRANSPOSE, 3", "DQS, BLENDED_MATRIX, 1", "LBS, INVERSE_TRANSPOSE, 5", "LBS, BLENDED_MATRIX, 6",
        "LBS, INVERSE_TRANSPOSE, 7", "LBS, INVERSE_TRANSPOSE, 8", "LBS, BLENDED_MATRIX, 9", "LBS, INVERSE_TRANSPOSE, 10",
        "LBS, INVERSE_TRANSPOSE, 11", "LBS, BLENDED_MATRIX, 12", "DQS, INVERSE_TRANSPOSE, 5", "DQS, BLENDED_MATRIX, 6",
        "DQS, INVERSE_TRANSPOSE, 7", "DQS, INVERSE_TRANSPOSE, 8", "DQS, BLENDED_MATRIX, 9", "DQS, INVERSE_TRANSPOSE, 10",
        "DQS, BLENDED_MATRIX, 11", "DQS, INVERSE_TRANSPOSE, 12", "COR, BLENDED_MATRIX, 4", "COR, INVERSE_TRANSPOSE, 4",
        "COR, INVERSE_TRANSPOSE, 1", "COR, BLENDED_MATRIX, 3", "COR, INVERSE_TRANSPOSE, 6", "COR, INVERSE_TRANSPOSE, 8",
        "COR, BLENDED_MATRIX, 11"})
    void agreesWithScalarOnRandomPointsForEveryRange(SkinningMethod method, NormalTransform normals, int width) {
        // 203 points: 25 whole blocks of 8 and a tail of 3; 16 joints so 12 distinct ones fit.
        SkinnedGeometry g = RandomRigs.geometry(7 + width, 203, width, 16);
        JointPalette palette = RandomRigs.palette(g, 11, false);
        Skinner k = vector(method, g, normals);
        assertAgrees(k, palette, 0, 203);
        // Starts and ends on and off the block grid, ranges shorter than a block or the spill.
        int[] edges = {0, 1, 2, 3, 5, 7, 8, 9, 15, 16, 17, 31, 64, 100, 199, 200, 201, 202, 203};
        for (int from : edges) {
            for (int to : edges) {
                if (from <= to) {
                    assertAgrees(k, palette, from, to);
                }
            }
        }
    }

    @ParameterizedTest(name = "{0} {1}, {2} influences")
    @CsvSource({"LBS, BLENDED_MATRIX, 4", "LBS, INVERSE_TRANSPOSE, 4", "DQS, BLENDED_MATRIX, 4",
        "DQS, INVERSE_TRANSPOSE, 4", "DQS, INVERSE_TRANSPOSE, 1", "DQS, INVERSE_TRANSPOSE, 6",
        "DQS, BLENDED_MATRIX, 8", "DQS, INVERSE_TRANSPOSE, 11", "LBS, INVERSE_TRANSPOSE, 6",
        "COR, INVERSE_TRANSPOSE, 4"})
    void agreesWithScalarWhenJointsAreScaled(SkinningMethod method, NormalTransform normals, int width) {
        SkinnedGeometry g = RandomRigs.geometry(3 + width, 101, width, 16);
        JointPalette palette = RandomRigs.palette(g, 5, true);
        assertTrue(palette.hasScale(), "the pose scales every other joint");
        assertAgrees(vector(method, g, normals), palette, 0, 101);
        assertAgrees(vector(method, g, normals), palette, 9, 90);
        assertDeformationsAgree(vector(method, g, normals), palette, 0, 101);
        assertDeformationsAgree(vector(method, g, normals), palette, 3, 77);
    }

    @ParameterizedTest(name = "{0} {1}, {2} influences, scaled {3}")
    @CsvSource({"LBS, BLENDED_MATRIX, 4, false", "LBS, INVERSE_TRANSPOSE, 3, false", "LBS, INVERSE_TRANSPOSE, 7, false",
        "LBS, INVERSE_TRANSPOSE, 12, true", "DQS, BLENDED_MATRIX, 2, false", "DQS, INVERSE_TRANSPOSE, 4, false",
        "DQS, INVERSE_TRANSPOSE, 6, false", "DQS, INVERSE_TRANSPOSE, 6, true", "DQS, BLENDED_MATRIX, 9, true",
        "COR, INVERSE_TRANSPOSE, 4, false", "COR, BLENDED_MATRIX, 6, false", "COR, INVERSE_TRANSPOSE, 9, false"})
    void deformationsAgreeWithScalar(SkinningMethod method, NormalTransform normals, int width, boolean scaled) {
        SkinnedGeometry g = RandomRigs.geometry(40 + width, 203, width, 16);
        JointPalette palette = RandomRigs.palette(g, 41, scaled);
        Skinner k = vector(method, g, normals);
        int[] edges = {0, 1, 7, 8, 9, 63, 64, 65, 130, 200, 203};
        for (int from : edges) {
            for (int to : edges) {
                if (from <= to) {
                    assertDeformationsAgree(k, palette, from, to);
                }
            }
        }
    }

    @ParameterizedTest(name = "{0} {1}, {2} influences")
    @CsvSource({"LBS, INVERSE_TRANSPOSE, 4", "LBS, INVERSE_TRANSPOSE, 6", "DQS, INVERSE_TRANSPOSE, 4",
        "DQS, INVERSE_TRANSPOSE, 6"})
    void mirroringPalettesAgreeWithScalar(SkinningMethod method, NormalTransform normals, int width) {
        // Every other joint mirrored (a negative scale): LBS blends of mixed signs, DQS scale parts
        // with negative determinants; the scalar kernel turns such normals outwards.
        SkinnedGeometry g = RandomRigs.geometry(60 + width, 203, width, 16);
        JointPalette palette = RandomRigs.palette(g, 61, false);
        org.joml.Matrix4f m = new org.joml.Matrix4f();
        for (int j = 0; j < palette.jointCount(); j += 2) {
            palette.setMatrix(j, palette.getMatrix(j, m).scale(-1f, 1f, 1f));
        }
        palette.prepareAll();
        assertTrue(palette.hasScale(), "a mirrored joint is a scale part for DQS");
        assertAgrees(vector(method, g, normals), palette, 0, 203);
        assertDeformationsAgree(vector(method, g, normals), palette, 0, 203);
    }

    @ParameterizedTest(name = "{0} influences")
    @CsvSource({"2", "4", "6", "9"})
    void geometriesWithManyJointPairsAgreeWithScalar(int width) {
        // 64 joints in random order over 2003 points: thousands of distinct (pivot, joint) pairs,
        // so the blend's signed pair table is large and indexed all over.
        SkinnedGeometry g = RandomRigs.geometry(80 + width, 2003, width, 64);
        JointPalette palette = RandomRigs.palette(g, 81, false);
        Skinner k = vector(SkinningMethod.DQS, g, NormalTransform.INVERSE_TRANSPOSE);
        assertAgrees(k, palette, 0, 2003);
        assertAgrees(k, palette, 5, 1999);
        assertDeformationsAgree(k, palette, 0, 2003);
        JointPalette scaled = RandomRigs.palette(g, 82, true);
        assertAgrees(k, scaled, 0, 2003);
    }

    /** skinDeformations of both kernels on [from, to), outputs compared (nothing written outside). */
    private static void assertDeformationsAgree(Skinner vector, JointPalette palette, int from, int to) {
        SkinnedGeometry g = vector.geometry();
        Skinner scalar = Skinners.scalar(vector.method(), g, vector.normalTransform());
        int n = g.pointCount();
        float[] vf = nanFilled(Skinner.DEFORMATION_FLOATS * n);
        float[] sf = nanFilled(Skinner.DEFORMATION_FLOATS * n);
        vector.skinDeformations(palette, vf, from, to);
        scalar.skinDeformations(palette, sf, from, to);
        for (int i = 0; i < vf.length; i++) {
            int point = i / Skinner.DEFORMATION_FLOATS;
            if (point < from || point >= to) {
                if (!Float.isNaN(vf[i])) {
                    fail("deformation float " + i + " outside [" + from + ", " + to + ") was written");
                }
                continue;
            }
            check("deformation", i, vf[i], sf[i], from, to, vector);
        }
    }

    @ParameterizedTest(name = "{0} {1}")
    @CsvSource({"LBS, BLENDED_MATRIX", "LBS, INVERSE_TRANSPOSE", "DQS, BLENDED_MATRIX", "DQS, INVERSE_TRANSPOSE",
        "COR, BLENDED_MATRIX", "COR, INVERSE_TRANSPOSE"})
    void agreesWithScalarOnTheDefaultCharacter(SkinningMethod method, NormalTransform normals) throws Exception {
        SkinnedGeometry g = Geometries.humanoid();
        assertTrue(g.influencesPerPoint() <= 4, "the humanoid has at most 4 influences per point");
        JointPalette palette = RandomRigs.palette(g, 23, false);
        if (method == SkinningMethod.COR) {
            // Random geometries have no triangles, so their centres are the points themselves
            // (p' = A p); the character's mesh gives real centres, which this case must exercise.
            float[] c = g.centresOfRotation();
            float[] p = g.positionArray();
            int away = 0;
            for (int i = 0; i < g.pointCount(); i++) {
                double dx = c[3 * i] - p[3 * i], dy = c[3 * i + 1] - p[3 * i + 1], dz = c[3 * i + 2] - p[3 * i + 2];
                away += dx * dx + dy * dy + dz * dz > 1e-6 ? 1 : 0;
            }
            assertTrue(away > g.pointCount() / 4, "centres away from their points: " + away + " of " + g.pointCount());
        }
        Skinner k = vector(method, g, normals);
        assertAgrees(k, palette, 0, g.pointCount());
        assertAgrees(k, palette, 13, g.pointCount() - 5);
    }

    @Test
    void exactNormalsAreUnitAndBlendedOnesAreNotRenormalised() {
        // Independent of the scalar kernel: with LBS between two joints rotated apart, the blended
        // matrix shrinks normals (|n'| < 1), while the inverse-transpose rule gives unit normals.
        SkinnedGeometry g = RandomRigs.geometry(19, 64, 4, 8);
        JointPalette palette = RandomRigs.palette(g, 29, false);
        float[] p = new float[3 * 64];
        float[] exact = new float[3 * 64];
        float[] blended = new float[3 * 64];
        vector(SkinningMethod.LBS, g, NormalTransform.INVERSE_TRANSPOSE).skinAll(palette, p, exact);
        vector(SkinningMethod.LBS, g, NormalTransform.BLENDED_MATRIX).skinAll(palette, p, blended);
        int shrunk = 0;
        for (int i = 0; i < 64; i++) {
            double e = Math.sqrt(sq(exact, i));
            if (i % 5 == 4) {
                assertEquals(0.0, e, 0.0, "a zero normal stays zero");
            } else {
                assertEquals(1.0, e, 1e-5, "unit normal at point " + i);
                shrunk += Math.sqrt(sq(blended, i)) < 0.999 ? 1 : 0;
            }
        }
        assertTrue(shrunk > 10, "blended normals are not renormalised: " + shrunk + " of 51 shorter");
    }

    @Test
    void identityPoseGivesTheBindShape() {
        // Independent check: identity palette, so every kernel must return its input.
        SkinnedGeometry g = RandomRigs.geometry(31, 37, 4, 5);
        JointPalette palette = g.newPalette(); // identity skinning matrices until set
        palette.prepareAll();
        for (SkinningMethod m : WITH_VECTOR_KERNELS) {
            float[] p = new float[3 * 37];
            float[] n = new float[3 * 37];
            vector(m, g, NormalTransform.BLENDED_MATRIX).skinAll(palette, p, n);
            assertArrayEquals(g.positionArray(), p, 1e-6f, m.key());
            assertArrayEquals(g.normalArray(), n, 1e-6f, m.key());
        }
    }

    private static double sq(float[] a, int i) {
        return a[3 * i] * a[3 * i] + a[3 * i + 1] * a[3 * i + 1] + a[3 * i + 2] * a[3 * i + 2];
    }
}
