package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.EnumSet;

import org.joml.Matrix4f;
import org.junit.jupiter.api.Test;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.testing.RandomRigs;
import org.skinlab.testing.TestPaths;

/**
 * Bind time apart from frame time: a {@link SkinnedModel} skins with the methods it was bound
 * for and with nothing else, CoR's centres exist only where the model was bound for CoR (and are
 * then the paper's, computed once for a crowd), and a {@link JointPalette} derives what a method
 * reads once per set of matrices, again after every write.
 */
class BindTimeTest {
    private static Model humanoid() throws Exception {
        return ColladaImporter.read(TestPaths.asset("characters/humanoid-walk.dae"));
    }

    @Test
    void aModelSkinsWithTheMethodsItWasBoundForAndRefusesTheOthers() throws Exception {
        Model model = humanoid();
        SkinnedModel skinned = new SkinnedModel(model, model.clips().get(0), NormalTransform.INVERSE_TRANSPOSE,
                EnumSet.of(SkinningMethod.LBS, SkinningMethod.DQS));
        assertEquals(EnumSet.of(SkinningMethod.LBS, SkinningMethod.DQS), skinned.methods());
        int n = 3 * skinned.geometries().get(0).pointCount();
        skinned.skin(0, SkinningMethod.DQS, new float[n], new float[n]);
        IllegalArgumentException refused = assertThrows(IllegalArgumentException.class,
                () -> skinned.skin(0, SkinningMethod.COR, new float[n], new float[n]));
        assertTrue(refused.getMessage().contains("COR was not bound"), refused.getMessage());
        SkinnedGeometry geometry = skinned.geometries().get(0);
        assertFalse(geometry.hasCentresOfRotation(), "no CoR, no centres");
        assertThrows(IllegalStateException.class, geometry::centresOfRotation);
        assertThrows(IllegalArgumentException.class, () -> new SkinnedModel(model, null,
                NormalTransform.INVERSE_TRANSPOSE, EnumSet.noneOf(SkinningMethod.class)));
    }

    @Test
    void boundForCorEveryGeometryCarriesThePapersCentresOnceForACrowd() throws Exception {
        Model model = humanoid();
        SkinnedModel skinned = new SkinnedModel(model, model.clips().get(0), NormalTransform.INVERSE_TRANSPOSE,
                EnumSet.of(SkinningMethod.COR));
        for (int g = 0; g < skinned.geometries().size(); g++) {
            SkinnedGeometry bound = skinned.geometries().get(g);
            assertTrue(bound.hasCentresOfRotation(), "geometry " + g);
            float[] expected = CentresOfRotation.compute(SkinnedGeometry.of(model.instances().get(g), model.nodes()),
                    CentresOfRotation.Parameters.DEFAULT, CentresOfRotation.Progress.NONE);
            assertArrayEquals(expected, bound.centresOfRotation(), 0f, "geometry " + g);
            assertSame(bound.centresOfRotation(), skinned.newCharacter().geometries().get(g).centresOfRotation(),
                    "a crowd shares its centres");
        }
        SkinnedGeometry unbound = SkinnedGeometry.of(model.instances().get(0), model.nodes());
        assertSame(unbound, unbound.boundFor(SkinningMethod.DQS), "only CoR has bind-time data of its own");
        assertTrue(unbound.boundFor(SkinningMethod.COR).hasCentresOfRotation());
        assertThrows(IllegalArgumentException.class, () -> unbound.withCentresOfRotation(new float[3]),
                "one centre per point, or none");
    }

    @Test
    void thePaletteDerivesOncePerSetOfMatricesAndAgainAfterEveryWrite() {
        SkinnedGeometry geometry = RandomRigs.geometry(3, 10, 2, 4);
        JointPalette palette = RandomRigs.palette(geometry, 5, RandomRigs.Joints.SCALED);
        float[] first = palette.dualQuaternions().clone();
        assertSame(palette, palette.prepare(SkinningMethod.DQS));
        assertArrayEquals(first, palette.dualQuaternions(), 0f, "prepared twice: the same");

        // A write through the array: LBS reads the matrices alone and derives nothing; DQS derives again.
        JointPalette other = RandomRigs.palette(geometry, 6, RandomRigs.Joints.SCALED);
        System.arraycopy(other.matrices(), 0, palette.writableMatrices(), 0, other.matrices().length);
        palette.prepare(SkinningMethod.LBS);
        assertArrayEquals(first, palette.dualQuaternions(), 0f, "LBS derives nothing");
        palette.prepare(SkinningMethod.STBS_DQS);
        assertArrayEquals(other.dualQuaternions(), palette.dualQuaternions(), 0f, "derived again after the write");
        assertArrayEquals(other.scales(), palette.scales(), 0f);
        assertArrayEquals(other.boneRows(), palette.boneRows(), 0f, "a bone method derives the bone rows too");

        // A write of one joint: that joint's parts follow, the copy carries what was derived.
        palette.setMatrix(1, new Matrix4f().rotationY(1f));
        palette.prepareAll();
        assertArrayEquals(new float[] {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0},
                java.util.Arrays.copyOfRange(palette.scales(), 12, 24), 1e-6f, "joint 1 is rigid now: S = I");
        JointPalette copy = geometry.newPalette();
        copy.set(palette);
        assertArrayEquals(palette.dualQuaternions(), copy.dualQuaternions(), 0f);
        assertArrayEquals(palette.scales(), copy.scales(), 0f);
        assertArrayEquals(palette.boneRows(), copy.boneRows(), 0f);
        assertEquals(palette.hasScale(), copy.hasScale());
    }
}
