package org.skinlab.simd;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.gltf.GltfImporter;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.PositionSharing;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * A mesh whose morph weights animate, skinned per frame by the Vector API kernels (which copy
 * rest positions and normals into their own layout and re-pack them when told,
 * {@code Skinner.restShapeChanged}) against core's scalar kernels on the same morphed arrays, at
 * times between keys of the fixture {@code morph-skin.gltf}'s clip "pulse" (CUBICSPLINE and STEP
 * weights, normals morphing too). Tolerance as {@link CorpusVectorSkinningTest}: 2e-5 of the size.
 */
class MorphVectorSkinningTest {
    @Test
    void vectorKernelsFollowTheMorphEveryFrame() throws Exception {
        Path root = Path.of(System.getProperty("skinlab.root", "..")).toAbsolutePath().normalize();
        Model model = GltfImporter.read(root.resolve("core/src/test/resources/gltf/morph-skin.gltf"));
        SkinnedModel skinned = new SkinnedModel(model, model.clip("pulse").orElseThrow(),
                NormalTransform.INVERSE_TRANSPOSE);
        for (SkinningMethod method : SkinningMethod.values()) {
            assertEquals("vector-256", skinned.skinner(0, method).implementation(), method.toString());
        }
        SkinnedGeometry g = skinned.geometries().get(0);
        int n = 3 * g.pointCount();
        for (float t : new float[] {0.05f, 0.35f, 0.9f, 1.1f}) {
            skinned.pose(t, RotationInterpolation.SLERP);
            for (SkinningMethod method : SkinningMethod.values()) {
                float[] p = new float[n];
                float[] nn = new float[n];
                skinned.skin(0, method, p, nn);
                float[] sp = new float[n];
                float[] sn = new float[n];
                Skinners.scalar(method, g.boundFor(method), NormalTransform.INVERSE_TRANSPOSE, PositionSharing.NEVER)
                        .skinAll(skinned.palette(0).prepareAll(), sp, sn);
                for (int i = 0; i < n; i++) {
                    assertTrue(Math.abs(p[i] - sp[i]) <= 2e-5f * 2.3f, method + " t=" + t + " position " + i);
                    assertTrue(Math.abs(nn[i] - sn[i]) <= 2e-5f, method + " t=" + t + " normal " + i);
                }
            }
        }
    }
}
