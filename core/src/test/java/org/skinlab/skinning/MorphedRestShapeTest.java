package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.gltf.GltfImporter;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;
import org.skinlab.internal.metrics.ArtifactMetrics;

/**
 * The per-frame morph ahead of skinning on the fixture {@code morph-skin.gltf} (clip "breathe":
 * node body's weights animate, body2's do not): characters of one model morph apart, and what
 * keeping CoR's centres of the rest shape costs against recomputing them on the morphed shape.
 */
class MorphedRestShapeTest {
    private static Model fixture() throws Exception {
        return GltfImporter.read(TestPaths.root().resolve("core/src/test/resources/gltf/morph-skin.gltf"));
    }

    private static AnimationClip breathe(Model m) {
        return m.clip("breathe").orElseThrow();
    }

    @Test
    void onlyTheMeshWhoseWeightsAnimateMorphsAndEachCharacterMorphsAtItsOwnTime() throws Exception {
        Model m = fixture();
        SkinnedModel a = new SkinnedModel(m, breathe(m), NormalTransform.INVERSE_TRANSPOSE);
        assertTrue(a.morphs(0));
        assertFalse(a.morphs(1));
        SkinnedModel b = a.newCharacter();
        assertNotSame(a.geometries().get(0), b.geometries().get(0), "a morphing geometry is per character");
        assertSame(a.geometries().get(1), b.geometries().get(1), "the others are shared");
        a.pose(0.5f, RotationInterpolation.SLERP);
        b.pose(0f, RotationInterpolation.SLERP);
        float[] pa = new float[3 * a.geometries().get(0).pointCount()];
        float[] pb = new float[pa.length];
        a.skin(0, SkinningMethod.DQS, pa, new float[pa.length]);
        b.skin(0, SkinningMethod.DQS, pb, new float[pb.length]);
        b.pose(0.5f, RotationInterpolation.SLERP);
        float[] pb2 = new float[pa.length];
        b.skin(0, SkinningMethod.DQS, pb2, new float[pb2.length]);
        assertArrayEquals(pa, pb2, 0f, "the same time gives the same shape");
        assertFalse(java.util.Arrays.equals(pa, pb), "different times morph differently");
    }

    /**
     * CoR with the rest shape's centres (what the per-frame path does) against CoR with centres
     * recomputed on each frame's morphed shape, over the clip's keys and midpoints; printed, and
     * bounded by 1e-3 of the model's size (measured 3.8e-4, against 2.1e-3 between CoR and LBS; docs/skinning.md, "Morphs").
     */
    @Test
    void restCentresAgainstCentresOfTheMorphedShape() throws Exception {
        Model m = fixture();
        SkinnedModel skinned = new SkinnedModel(m, breathe(m), NormalTransform.INVERSE_TRANSPOSE);
        SkinnedGeometry geometry = skinned.geometries().get(0);
        int n = 3 * geometry.pointCount();
        double size = ArtifactMetrics.boundsDiagonal(geometry.positionArray(), geometry.vertexCount());
        double worst = 0;
        double moved = 0;
        for (float t = 0f; t <= 1.0001f; t += 0.125f) {
            skinned.pose(t, RotationInterpolation.SLERP);
            float[] ours = new float[n];
            skinned.skin(0, SkinningMethod.COR, ours, new float[n]);
            // The same mesh with this frame's morphed rest positions, its centres computed on them.
            SkinnedGeometry morphed = SkinnedGeometry.of(geometry.instance());
            System.arraycopy(geometry.positionArray(), 0, morphed.positionArray(), 0, n);
            float[] recomputed = new float[n];
            new ScalarCorSkinner(morphed.withCentresOfRotation(), NormalTransform.INVERSE_TRANSPOSE).skinAll(skinned.palette(0).prepareAll(),
                    recomputed, new float[n]);
            float[] lbs = new float[n];
            skinned.skin(0, SkinningMethod.LBS, lbs, new float[n]);
            for (int i = 0; i < n; i += 3) {
                worst = Math.max(worst, distance(ours, recomputed, i));
                moved = Math.max(moved, distance(ours, lbs, i));
            }
        }
        System.out.printf("morph-skin.gltf breathe: CoR rest centres vs recomputed: %.3e of the size %.4g"
                + " (CoR vs LBS: %.3e)%n", worst / size, size, moved / size);
        assertTrue(worst <= 1e-3 * size, worst / size + " of the size");
        assertTrue(worst < moved, "the approximation is smaller than the methods' own difference");
    }

    private static double distance(float[] a, float[] b, int i) {
        double dx = a[i] - b[i];
        double dy = a[i + 1] - b[i + 1];
        double dz = a[i + 2] - b[i + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
