package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.junit.jupiter.params.provider.ValueSource;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.model.Skin;
import org.skinlab.model.UpAxis;
import org.skinlab.testing.TestPaths;

/** Our own assets import with the counts assets/README.md states and without warnings. */
class OwnAssetsImportTest {
    private static Model read(String asset) throws Exception {
        Path file = TestPaths.asset(asset);
        return ColladaImporter.read(file);
    }

    @Test
    void defaultHumanoidHasNineteenJointsFourInfluencesAndALoopingWalk() throws Exception {
        Model m = read("characters/humanoid-walk.dae");
        assertEquals(UpAxis.Z_UP, m.asset().upAxis());
        assertEquals(1, m.meshes().size());
        Mesh mesh = m.meshes().get(0);
        assertEquals(951, mesh.positionCount());
        assertEquals(1896, mesh.triangleCount());
        Skin skin = m.skins().get(0);
        assertEquals(19, skin.jointCount());
        assertEquals(4, skin.maxInfluences());
        assertEquals(1, m.clips().size());
        AnimationClip walk = m.clips().get(0);
        assertEquals(1.0f, walk.duration(), 1e-6f);
        assertTrue(walk.channels().stream().allMatch(c -> c.track().keyCount() == 9));
        assertEquals(0, m.warnings().size(), () -> m.warnings().toString());
    }

    @Test
    void thesisCylindersHaveTheThesisTriangleCounts() throws Exception {
        assertEquals(1148, read("cylinders/cylinder-twist-low.dae").meshes().get(0).triangleCount());
        assertEquals(2044, read("cylinders/cylinder-twist-high.dae").meshes().get(0).triangleCount());
        assertEquals(2044, read("cylinders/cylinder-bend.dae").meshes().get(0).triangleCount());
    }

    @ParameterizedTest(name = "{0}")
    @ValueSource(strings = {"cylinders/cylinder-twist-full.dae", "cylinders/cylinder-bend-full.dae"})
    void wholeTurnCylindersHaveTheTwistHighMeshAndTwentyFiveKeysOverSixSeconds(String asset) throws Exception {
        Model m = read(asset);
        Mesh mesh = m.meshes().get(0);
        assertEquals(1024, mesh.positionCount());
        assertEquals(2044, mesh.triangleCount());
        Skin skin = m.skins().get(0);
        assertEquals(2, skin.jointCount());
        assertEquals(2, skin.maxInfluences());
        AnimationClip clip = m.clips().get(0);
        assertEquals(6.0f, clip.duration(), 1e-6f);
        assertTrue(clip.channels().stream().allMatch(c -> c.track().keyCount() == 25));
        assertEquals(0, m.warnings().size(), () -> m.warnings().toString());
    }

    @ParameterizedTest(name = "{0}")
    @CsvSource({"stretch/limb-stretch.dae, 9", "twist/arm-twist.dae, 17"})
    void stretchAndTwistLimbsHaveThreeJointsTwoInfluencesAndATwoSecondLoop(String asset, int keys) throws Exception {
        Model m = read(asset);
        Mesh mesh = m.meshes().get(0);
        assertEquals(1568, mesh.positionCount());
        assertEquals(3132, mesh.triangleCount());
        Skin skin = m.skins().get(0);
        assertEquals(3, skin.jointCount());
        assertEquals(2, skin.maxInfluences());
        AnimationClip clip = m.clips().get(0);
        assertEquals(2.0f, clip.duration(), 1e-6f);
        assertTrue(clip.channels().stream().allMatch(c -> c.track().keyCount() == keys));
        assertEquals(0, m.warnings().size(), () -> m.warnings().toString());
    }
}
