package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.Arrays;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.testing.RandomRigs;
import org.skinlab.testing.RandomRigs.Joints;
import org.skinlab.testing.TestPaths;

/**
 * {@link NormalTransform#NONE} (positions only) in the scalar kernels against the same kernels
 * with normals. Tolerance: none, positions equal bit for bit (compared as raw int bits), since a
 * positions-only loop runs the same float operations on the position as its with-normals twin and
 * only leaves the normal out; a reordered sum or a missed scale phase would change the last bits.
 * Also: nothing is written outside the range, normals are not touched (null is accepted), and the
 * methods without a positions-only kernel refuse the rule instead of writing normals.
 */
class PositionsOnlySkinningTest {
    private static final NormalTransform[] WITH_NORMALS = {NormalTransform.BLENDED_MATRIX,
        NormalTransform.INVERSE_TRANSPOSE};

    private static float[] nanFilled(int n) {
        float[] a = new float[n];
        Arrays.fill(a, Float.NaN);
        return a;
    }

    /** Raw bits equal inside [from, to), NaN (untouched) outside. */
    static void assertSameBits(float[] expected, float[] actual, int from, int to, String what) {
        for (int i = 0; i < actual.length; i++) {
            boolean inside = i >= 3 * from && i < 3 * to;
            if (!inside) {
                if (!Float.isNaN(actual[i])) {
                    fail(what + ": float " + i + " outside [" + from + ", " + to + ") was written");
                }
            } else if (Float.floatToRawIntBits(actual[i]) != Float.floatToRawIntBits(expected[i])) {
                fail(what + ": float " + i + " (point " + i / 3 + ") is " + actual[i] + ", with normals "
                        + expected[i]);
            }
        }
    }

    @ParameterizedTest(name = "{0}, {1} influences, {2} joints")
    @CsvSource({"LBS, 1, RIGID", "LBS, 2, SCALED", "LBS, 4, RIGID", "LBS, 4, SCALED", "LBS, 4, MIRRORED",
        "LBS, 8, RIGID", "LBS, 8, MIRRORED", "LBS, 2, MIRRORED", "DQS, 1, RIGID", "DQS, 1, SCALED", "DQS, 2, RIGID",
        "DQS, 4, RIGID", "DQS, 4, SCALED", "DQS, 4, MIRRORED", "DQS, 8, RIGID", "DQS, 8, SCALED", "DQS, 8, MIRRORED",
        "DQS, 2, MIRRORED"})
    void positionsOnlyAreTheWithNormalsPositionsBitForBit(SkinningMethod method, int width, Joints kind) {
        SkinnedGeometry g = RandomRigs.geometry(100 + width, 203, width, 16);
        JointPalette palette = RandomRigs.palette(g, 7 + width, kind);
        assertEquals(kind != Joints.RIGID, palette.hasScale(), "scaled and mirrored joints are DQS scale parts");
        int n = g.pointCount();
        Skinner positionsOnly = Skinners.scalar(method, g, NormalTransform.NONE);
        assertEquals(NormalTransform.NONE, positionsOnly.normalTransform());
        for (NormalTransform rule : WITH_NORMALS) {
            float[] expected = new float[3 * n];
            Skinners.scalar(method, g, rule).skinAll(palette, expected, new float[3 * n]);
            int[] edges = {0, 1, 7, 8, 9, 100, 201, 202, 203};
            for (int from : edges) {
                for (int to : edges) {
                    if (from <= to) {
                        float[] actual = nanFilled(3 * n);
                        positionsOnly.skin(palette, actual, null, from, to);
                        assertSameBits(expected, actual, from, to, method + " against " + rule);
                    }
                }
            }
        }
    }

    @Test
    void theNormalsArrayIsNotTouched() {
        SkinnedGeometry g = RandomRigs.geometry(5, 50, 4, 8);
        JointPalette palette = RandomRigs.palette(g, 6, Joints.SCALED);
        for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.LBS, SkinningMethod.DQS}) {
            float[] normals = nanFilled(3 * 50);
            Skinners.scalar(m, g, NormalTransform.NONE).skinAll(palette, new float[3 * 50], normals);
            for (float f : normals) {
                assertTrue(Float.isNaN(f), m + " wrote a normal");
            }
        }
    }

    @Test
    void positionsOnlyFollowTheAssetsClips() throws Exception {
        // The humanoid (4 influences, rigid joints) and the tentacle (scaled joints: DQS's scale
        // phase) through SkinnedModel, the path a caller takes, at several times of their clips.
        for (String asset : new String[] {"characters/humanoid-walk.dae", "creatures/tentacle-wave.dae"}) {
            Model model = ColladaImporter.read(TestPaths.asset(asset));
            SkinnedModel withNormals = SkinnedModel.of(model);
            SkinnedModel positionsOnly = new SkinnedModel(model, model.clips().get(0), NormalTransform.NONE);
            float end = model.clips().get(0).duration();
            for (float t : new float[] {0f, 0.31f * end, 0.5f * end, 0.77f * end, end}) {
                withNormals.pose(t, RotationInterpolation.SLERP);
                positionsOnly.pose(t, RotationInterpolation.SLERP);
                for (int g = 0; g < withNormals.geometries().size(); g++) {
                    int n = withNormals.geometries().get(g).pointCount();
                    for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.LBS, SkinningMethod.DQS}) {
                        float[] expected = new float[3 * n];
                        withNormals.skin(g, m, expected, new float[3 * n]);
                        float[] actual = nanFilled(3 * n);
                        positionsOnly.skin(g, m, actual, null);
                        assertSameBits(expected, actual, 0, n, asset + " " + m + " at " + t);
                    }
                }
            }
        }
    }

    @Test
    void sharedPositionsAreCopiedToTheirPoints() throws Exception {
        // The bend cylinder's render vertices share positions (1118 points on 1024 positions); with
        // sharing forced, each position is skinned once and copied to its points: the same bits as
        // skinning every point with normals.
        Model model = ColladaImporter.read(TestPaths.asset("cylinders/cylinder-bend.dae"));
        SkinnedModel skinned = SkinnedModel.of(model);
        skinned.pose(0.8f * model.clips().get(0).duration(), RotationInterpolation.SLERP);
        SkinnedGeometry g = skinned.geometries().get(0);
        assertTrue(g.sharedPositions() != null && g.sharedPositions().pointCount() < g.pointCount(),
                "the cylinder's points share positions");
        int n = g.pointCount();
        for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.LBS, SkinningMethod.DQS}) {
            JointPalette palette = skinned.palette(0).prepare(m);
            float[] expected = new float[3 * n];
            Skinners.scalar(m, g, NormalTransform.INVERSE_TRANSPOSE, PositionSharing.NEVER).skinAll(palette, expected,
                    new float[3 * n]);
            Skinner shared = Skinners.scalar(m, g, NormalTransform.NONE, PositionSharing.ALWAYS);
            assertTrue(Skinners.sharesPositions(shared), shared.implementation());
            assertTrue(shared.implementation().contains("positions copied"), shared.implementation());
            for (int[] range : new int[][] {{0, n}, {5, 700}}) {
                float[] actual = nanFilled(3 * n);
                shared.skin(palette, actual, null, range[0], range[1]);
                assertSameBits(expected, actual, range[0], range[1], m + " shared");
            }
        }
    }

    @Test
    void positionsOnlySharingPaysFromAboutOneAndAThirdPointsPerPosition() {
        for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.LBS, SkinningMethod.DQS}) {
            assertTrue(SharedPositionSkinner.pays(m, NormalTransform.NONE, 4252, 740, 6), m + ": the cowboy");
            assertTrue(SharedPositionSkinner.pays(m, NormalTransform.NONE, 5174, 3275, 6), m + ": the stormtrooper");
            assertFalse(SharedPositionSkinner.pays(m, NormalTransform.NONE, 1118, 1024, 2), m + ": the bend cylinder");
            assertFalse(SharedPositionSkinner.pays(m, NormalTransform.NONE, 951, 951, 4), m + ": the humanoid");
        }
    }

    @Test
    void methodsWithoutAPositionsOnlyKernelRefuseIt() {
        SkinnedGeometry g = RandomRigs.geometry(3, 20, 2, 4);
        for (SkinningMethod m : SkinningMethod.values()) {
            if (m.skinsPositionsOnly()) {
                continue;
            }
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> Skinners.scalar(m, g, NormalTransform.NONE), m.key());
            assertTrue(e.getMessage().startsWith(m.key() + " skinning has no positions-only kernel"), e.getMessage());
            assertThrows(IllegalArgumentException.class, () -> Skinners.create(m, g, NormalTransform.NONE), m.key());
        }
        assertTrue(SkinningMethod.LBS.skinsPositionsOnly() && SkinningMethod.DQS.skinsPositionsOnly());
    }

    @Test
    void deformationsNeedANormalRule() {
        SkinnedGeometry g = RandomRigs.geometry(4, 20, 3, 4);
        JointPalette palette = RandomRigs.palette(g, 5, Joints.RIGID);
        for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.LBS, SkinningMethod.DQS}) {
            Skinner s = Skinners.scalar(m, g, NormalTransform.NONE);
            UnsupportedOperationException e = assertThrows(UnsupportedOperationException.class,
                    () -> s.skinDeformations(palette, new float[Skinner.DEFORMATION_FLOATS * 20], 0, 20));
            assertTrue(e.getMessage().contains(m.key()) && e.getMessage().contains("NONE"), e.getMessage());
        }
    }
}
