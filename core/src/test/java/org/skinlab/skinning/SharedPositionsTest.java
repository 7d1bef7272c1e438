package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;

/**
 * Skinning each position once ({@link SkinnedGeometry#sharedPositions()}, {@link Skinner#skinDeformations},
 * {@link DeformationExpansion}) against skinning every point on its own with the same scalar kernel, on
 * the thesis' cowboy (740 positions in 4252 render vertices, 6 influences, flat-shaded) at five
 * times of its clip. Tolerance 1e-5 of the model's extent on positions and 1e-5 on unit normals:
 * the same float operations, except that a normal goes through a stored matrix (one more rounding
 * per term).
 */
class SharedPositionsTest {

    @Test
    void theRuleSharesWhereItSaves() {
        NormalTransform exact = NormalTransform.INVERSE_TRANSPOSE;
        for (SkinningMethod m : SkinningMethod.values()) {
            assertTrue(SharedPositionSkinner.pays(m, exact, 4252, 740, 6), m + ": the cowboy, 5.7 points per position");
            assertFalse(SharedPositionSkinner.pays(m, exact, 951, 951, 4), m + ": one point per position");
            assertTrue(SharedPositionSkinner.pays(m, exact, 10710, 1856, 3), m + ": Suzanne, 5.8 points per position");
        }
        // The stormtrooper, 1.58 points per position: both share, DQS narrowly; at 1.25 points per
        // position DQS's cheap direct kernel wins, LBS still shares.
        assertTrue(SharedPositionSkinner.pays(SkinningMethod.LBS, exact, 5174, 3275, 6));
        assertTrue(SharedPositionSkinner.pays(SkinningMethod.DQS, exact, 5174, 3275, 6));
        assertFalse(SharedPositionSkinner.pays(SkinningMethod.DQS, exact, 5000, 4000, 6));
        assertTrue(SharedPositionSkinner.pays(SkinningMethod.LBS, exact, 5000, 4000, 6));
        // CoR: the stormtrooper shares (both ways measured alike); at 1.25 points per position the
        // direct kernel wins.
        assertTrue(SharedPositionSkinner.pays(SkinningMethod.COR, exact, 5174, 3275, 6));
        assertFalse(SharedPositionSkinner.pays(SkinningMethod.COR, exact, 5000, 4000, 6));
    }

    @Test
    void theSharedPositionsCarryTheCentresOfTheirPoints() throws Exception {
        // CoR's centres come from the render vertices' triangles; the positions' twin must take
        // them from there (its mesh's triangles index the render vertices, not the positions).
        Path file = TestPaths.corpusFileOrSkip("S01_cowboy.dae");
        SkinnedGeometry g = SkinnedModel.of(ColladaImporter.read(file)).geometries().get(0);
        SkinnedGeometry shared = g.sharedPositions();
        float[] perPosition = shared.centresOfRotation();
        float[] perPoint = g.centresOfRotation();
        int moved = 0;
        for (int i = 0; i < g.pointCount(); i++) {
            int f = g.deformationOfPointArray()[i];
            for (int c = 0; c < 3; c++) {
                assertEquals(perPoint[3 * i + c], perPosition[3 * f + c], 0f, "point " + i);
            }
            moved += perPoint[3 * i] != g.positionArray()[3 * i] ? 1 : 0;
        }
        assertTrue(moved > g.pointCount() / 4, "centres away from their points: " + moved);
    }

    @Test
    void aGeometryWithOnePointPerPositionHasNoSharedTwin() throws Exception {
        // The humanoid: smooth, one render vertex per position (and one unused position).
        Model model = ColladaImporter.read(TestPaths.asset("characters/humanoid-walk.dae"));
        SkinnedGeometry g = SkinnedModel.of(model).geometries().get(0);
        assertEquals(g.positionCount(), g.pointCount());
        assertNull(g.sharedPositions());
        assertFalse(Skinners.scalar(SkinningMethod.LBS, g, NormalTransform.INVERSE_TRANSPOSE).implementation()
                .contains("each position once"));
    }

    @Test
    void geometriesFromArraysNeverShare() {
        SkinnedGeometry g = SkinnedGeometry.fromArrays(new float[6], new float[6], 1, new int[2], new float[] {1, 1},
                new float[16]);
        assertNull(g.sharedPositions());
        assertNull(g.deformationOfPointArray());
    }

    @Test
    void negativeWeightsAreRefusedInArrays() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> SkinnedGeometry.fromArrays(
                new float[3], new float[3], 2, new int[2], new float[] {1.5f, -0.5f}, new float[32]));
        assertTrue(e.getMessage().contains("-0.5"), e.getMessage());
    }

    @Test
    void theCowboySkinnedOncePerPositionEqualsEveryPointSkinned() throws Exception {
        Path file = TestPaths.corpusFileOrSkip("S01_cowboy.dae");
        Model model = ColladaImporter.read(file);
        SkinnedModel skinned = SkinnedModel.of(model);
        SkinnedGeometry g = skinned.geometries().get(0);
        SkinnedGeometry shared = g.sharedPositions();
        assertNotNull(shared, "the cowboy's render vertices share positions");
        assertEquals(g.positionCount(), shared.pointCount());
        assertEquals(4252, g.pointCount());
        assertEquals(740, shared.pointCount());
        for (int i = 0; i < g.pointCount(); i++) {
            int f = g.deformationOfPointArray()[i];
            for (int c = 0; c < 3; c++) {
                assertEquals(g.positionArray()[3 * i + c], shared.positionArray()[3 * f + c], "point " + i);
            }
        }
        float start = skinned.sampler().start();
        float end = skinned.sampler().end();
        for (SkinningMethod method : SkinningMethod.values()) {
            for (NormalTransform rule : NormalTransform.values()) {
                if (rule == NormalTransform.NONE && !method.skinsPositionsOnly()) {
                    continue; // refused (PositionsOnlySkinningTest)
                }
                Skinner once = Skinners.scalar(method, g, rule);
                assertTrue(once.implementation().contains("each position once"), once.implementation());
                Skinner everyPoint = Skinners.create(method, g, rule, PositionSharing.NEVER);
                for (int t = 0; t < 5; t++) {
                    skinned.pose(start + (end - start) * t / 4f, RotationInterpolation.SLERP);
                    JointPalette palette = skinned.palette(0).prepare(method);
                    int n = 3 * g.pointCount();
                    float[] p1 = new float[n], n1 = new float[n], p2 = new float[n], n2 = new float[n];
                    once.skinAll(palette, p1, n1);
                    everyPoint.skinAll(palette, p2, n2);
                    float extent = 0;
                    for (float v : p2) {
                        extent = Math.max(extent, Math.abs(v));
                    }
                    for (int i = 0; i < n; i++) {
                        if (!(Math.abs(p1[i] - p2[i]) <= 1e-5f * extent)
                                || !(Math.abs(n1[i] - n2[i]) <= 1e-5f * Math.max(1f, Math.abs(n2[i])))) {
                            fail(method + " " + rule + " t" + t + " point " + i / 3 + ": " + p1[i] + " vs " + p2[i]
                                    + ", normal " + n1[i] + " vs " + n2[i]);
                        }
                    }
                }
            }
        }
    }
}
