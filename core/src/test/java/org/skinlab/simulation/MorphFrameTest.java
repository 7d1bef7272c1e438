package org.skinlab.simulation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.gltf.GltfImporter;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.testing.TestPaths;

/**
 * A palette-only frame (what the viewer's and the phone's GPU skinning read) of a mesh whose morph
 * weights animate carries that step's morphed rest shape, and LBS from the frame alone (its
 * matrices on its rest positions, the shader's formula) gives what the CPU path skins at the same
 * clip time. Fixture {@code morph-skin.gltf}, clip "breathe": body's weights animate, body2's not.
 */
class MorphFrameTest {
    @Test
    void aPaletteOnlyFrameCarriesTheMorphedRestShapeOfItsStep() throws Exception {
        Model model = GltfImporter.read(TestPaths.root().resolve("core/src/test/resources/gltf/morph-skin.gltf"));
        AnimationClip clip = model.clip("breathe").orElseThrow();
        AnimationConfig config = new AnimationConfig();
        config.setCpuSkinning(false);
        try (SkeletalAnimatedMesh mesh = new SkeletalAnimatedMesh(model, clip, config)) {
            mesh.step(0.3);
            try (Frame f = mesh.acquire()) {
                assertNull(f.restPositions(1), "body2's weights do not animate");
                float[] rest = f.restPositions(0);
                assertNotNull(rest);
                SkinnedModel cpu = new SkinnedModel(model, clip, NormalTransform.INVERSE_TRANSPOSE);
                cpu.pose(f.clipTime(), RotationInterpolation.SLERP);
                SkinnedGeometry g = cpu.geometries().get(0);
                float[] expected = new float[3 * g.pointCount()];
                cpu.skin(0, SkinningMethod.LBS, expected, new float[expected.length]);
                float[] m = f.palette(0).matrices();
                int[] joints = g.jointArray();
                float[] weights = g.weightArray();
                int k = g.influencesPerPoint();
                for (int i = 0; i < g.pointCount(); i++) {
                    for (int r = 0; r < 3; r++) {
                        double v = 0;
                        for (int c = 0; c < k; c++) {
                            int o = 12 * joints[k * i + c] + 4 * r;
                            v += weights[k * i + c] * (m[o] * rest[3 * i] + m[o + 1] * rest[3 * i + 1]
                                    + m[o + 2] * rest[3 * i + 2] + m[o + 3]);
                        }
                        assertEquals(expected[3 * i + r], v, 1e-5, "point " + i);
                    }
                }
            }
        }
    }
}
