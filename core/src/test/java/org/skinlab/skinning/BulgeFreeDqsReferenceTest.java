package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.skinning.reference.IndependentBulgeFreeDqs;
import org.skinlab.testing.TestPaths;
import org.skinlab.internal.metrics.ArtifactMetrics;

/**
 * The scalar bulge-free DQS kernel against {@link IndependentBulgeFreeDqs} (double, from the
 * formulas): on the bend cylinder at several angles, the humanoid and the tentacle (bone scale)
 * over their clips, within 2e-6 of the model's size (float rounding of DQS and of the pull's
 * distances; a wrong bone, sign or formula is 1e-3 and more).
 */
class BulgeFreeDqsReferenceTest {
    private static final double TOLERANCE = 2e-6;

    private static double worstRelative(String asset, float[] times) throws Exception {
        return worstRelative(asset, SkinnedModel.of(ColladaImporter.read(TestPaths.asset(asset))), times);
    }

    private static double worstRelative(String asset, SkinnedModel skinned, float[] times) {
        double worst = 0;
        double worstDqs = 0;
        for (int g = 0; g < skinned.geometries().size(); g++) {
            SkinnedGeometry geometry = skinned.geometries().get(g);
            Bones bones = geometry.bones();
            int joints = geometry.jointCount();
            float[] heads = new float[3 * joints];
            float[] tails = new float[3 * joints];
            for (int j = 0; j < joints; j++) {
                for (int a = 0; a < 3; a++) {
                    heads[3 * j + a] = bones.head(j, a);
                    tails[3 * j + a] = bones.tail(j, a);
                }
            }
            double size = ArtifactMetrics.boundsDiagonal(geometry.positionArray(), geometry.pointCount());
            float[] out = new float[3 * geometry.pointCount()];
            float[] dqs = new float[out.length];
            float[] normals = new float[out.length];
            float[] dqsNormals = new float[out.length];
            for (float time : times) {
                skinned.pose(time, RotationInterpolation.SLERP);
                skinned.skin(g, SkinningMethod.BFDQS, out, normals);
                skinned.skin(g, SkinningMethod.DQS, dqs, dqsNormals);
                assertArrayEquals(dqsNormals, normals, "the normals are DQS's");
                double[] expected = IndependentBulgeFreeDqs.skin(geometry.positionArray(), geometry.jointArray(),
                        geometry.weightArray(), geometry.influencesPerPoint(), geometry.bindMatrixArray(),
                        skinned.palette(g).matrices(), heads, tails);
                for (int i = 0; i < out.length; i++) {
                    worst = Math.max(worst, Math.abs(out[i] - expected[i]) / size);
                    worstDqs = Math.max(worstDqs, Math.abs(dqs[i] - expected[i]) / size);
                }
            }
        }
        System.out.printf("%s: largest difference from the reference %.2e of the size (DQS from it: %.2e)%n", asset,
                worst, worstDqs);
        assertTrue(worstDqs > 100 * TOLERANCE, asset + ": the pull changes something (" + worstDqs + ")");
        return worst;
    }

    @Test
    void bendCylinderAtSeveralAngles() throws Exception {
        double worst = worstRelative("cylinders/cylinder-bend.dae", new float[] {0.5f, 1f, 2f, 3f, 3.5f, 4f});
        assertTrue(worst < TOLERANCE, "cylinder-bend: " + worst);
    }

    @Test
    void humanoidWalk() throws Exception {
        double worst = worstRelative("characters/humanoid-walk.dae", new float[] {0f, 0.25f, 0.5f, 0.75f, 1f});
        assertTrue(worst < TOLERANCE, "humanoid-walk: " + worst);
    }

    @Test
    void tentacleWaveWithBoneScale() throws Exception {
        double worst = worstRelative("creatures/tentacle-wave.dae", new float[] {0f, 0.4f, 0.8f, 1.2f, 1.6f, 2f});
        assertTrue(worst < TOLERANCE, "tentacle-wave: " + worst);
    }

    /**
     * A rest shape that morphs per frame (morph-skin.gltf's "pulse"): the kernel refreshes its rest
     * distances from the morphed shape, which is what the reference computes from it.
     */
    @Test
    void morphedRestShape() throws Exception {
        org.skinlab.model.Model model = org.skinlab.gltf.GltfImporter.read(
                TestPaths.root().resolve("core/src/test/resources/gltf/morph-skin.gltf"));
        SkinnedModel skinned = new SkinnedModel(model, model.clip("pulse").orElseThrow(),
                NormalTransform.INVERSE_TRANSPOSE);
        double worst = worstRelative("morph-skin.gltf", skinned, new float[] {0.05f, 0.35f, 0.9f, 1.1f});
        assertTrue(worst < TOLERANCE, "morph-skin: " + worst);
    }
}
