package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.Arrays;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;

/**
 * {@link SkinnedModel#newCharacter()}: a copy that shares the geometries deforms exactly as a model
 * built on its own does at the same clip time (the same kernels on the same data: equal floats),
 * and posing one copy leaves the other's output as it was (each owns its pose and palettes).
 */
class SkinnedModelCharacterTest {
    @Test
    void aCharacterSkinsAsItsOwnModelAndApartFromItsTemplate() throws Exception {
        Model model = ColladaImporter.read(TestPaths.asset("characters/humanoid-walk.dae"));
        SkinnedModel template = SkinnedModel.of(model);
        SkinnedModel copy = template.newCharacter();
        SkinnedModel alone = SkinnedModel.of(model);
        assertSame(template.geometries(), copy.geometries());
        float end = template.sampler().end();
        for (SkinningMethod m : SkinningMethod.values()) {
            template.pose(0.2f * end, RotationInterpolation.SLERP);
            copy.pose(0.7f * end, RotationInterpolation.SLERP);
            alone.pose(0.7f * end, RotationInterpolation.SLERP);
            for (int g = 0; g < copy.geometries().size(); g++) {
                int floats = 3 * copy.geometries().get(g).pointCount();
                float[][] c = skin(copy, g, m, floats);
                float[][] a = skin(alone, g, m, floats);
                assertArrayEquals(a[0], c[0], m + ": positions");
                assertArrayEquals(a[1], c[1], m + ": normals");
                float[][] t = skin(template, g, m, floats);
                assertFalse(Arrays.equals(t[0], c[0]), m + ": the template poses at its own time");
                template.pose(0.9f * end, RotationInterpolation.SLERP);
                assertArrayEquals(c[0], skin(copy, g, m, floats)[0], m + ": posing the template left the copy as it was");
            }
        }
    }

    private static float[][] skin(SkinnedModel s, int g, SkinningMethod m, int floats) {
        float[] p = new float[floats];
        float[] n = new float[floats];
        s.skin(g, m, p, n);
        return new float[][] {p, n};
    }
}
