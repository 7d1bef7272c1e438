package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;

/**
 * The stormtrooper's skin, the case the bind-space rules exist for: its bind shape matrix mirrors
 * and scales by 1.662 and every inverse bind matrix mirrors back. Held in bind space with the
 * common mirror moved into the points, its skinning matrices are rigid (no joint mirrors, DQS
 * needs no scale phase) and its points are not mirrored against the file's mesh (the two mirrors
 * cancel). That LBS is unchanged by these rules is {@link CorpusLbsConformanceTest}'s job (an
 * independent evaluator of {@code world * INV_BIND * BSM} on the file's positions).
 */
class BindSpaceTest {
    @Test
    void theStormtroopersSkinningMatricesAreRigid() throws Exception {
        Model model = ColladaImporter.read(TestPaths.corpusFileOrSkip("S03_stormtrooper.dae"));
        SkinnedModel skinned = SkinnedModel.of(model);
        SkinnedGeometry geometry = skinned.geometries().get(0);
        assertTrue(model.instances().get(0).skin().bindShapeMatrix().determinant3x3() < 0f,
                "the file's bind shape matrix mirrors");
        assertFalse(geometry.windingMirrored(), "the bind shape's mirror and the bind frames' cancel");
        float start = skinned.sampler().start();
        float end = skinned.sampler().end();
        for (int t = 0; t < 5; t++) {
            skinned.pose(start + (end - start) * t / 4f, RotationInterpolation.SLERP);
            JointPalette palette = skinned.palette(0).prepareAll();
            assertFalse(palette.mirrorsMatrices(), "no joint mirrors at step " + t);
            assertFalse(palette.hasScale(), "DQS needs no scale phase at step " + t);
        }
    }
}
