package org.skinlab.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;


import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.gltf.GltfImporter;
import org.skinlab.model.Model;
import org.skinlab.model.UpAxis;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.testing.TestPaths;

/** Every file stands upright, on the floor, at its size in metres. */
class ModelFramingTest {
    private static ModelFraming framing(String asset) throws Exception {
        Model model = ColladaImporter.read(TestPaths.asset(asset));
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(model)) {
            mesh.step(0);
            try (Frame f = mesh.acquire()) {
                return ModelFraming.of(model.asset(), mesh.geometries(), f);
            }
        }
    }

    @Test
    void theHumanoidStandsUprightOnTheFloor() throws Exception {
        // A Z-up Blender file (assets/README.md: about 1.81 m tall, feet on z = 0).
        Model model = ColladaImporter.read(TestPaths.asset("characters/humanoid-walk.dae"));
        assertEquals(UpAxis.Z_UP, model.asset().upAxis());
        ModelFraming f = framing("characters/humanoid-walk.dae");
        assertEquals(1.81, f.height(), 0.1);
        assertEquals(f.height() / 2, f.centre().y, 0.05);
        // Its head is up: the top of the bounds is the head's height, and the radius covers it.
        Vector3f head = f.upright().transformPosition(new Vector3f(0, 0, 1.75f), new Vector3f());
        assertEquals(1.75, head.y, 0.1);
        assertTrue(f.radius() >= f.height() / 2);
    }

    @Test
    void theCylinderIsTwoMetresTall() throws Exception {
        ModelFraming f = framing("cylinders/cylinder-twist-high.dae");
        assertEquals(2.0, f.height(), 0.02);
        assertEquals(0.0, f.centre().x, 1e-5);
        assertEquals(0.0, f.centre().z, 1e-5);
    }

    @Test
    void aMorphingMeshIsFramedAsTheFrameHoldsIt() throws Exception {
        // The morph's rest shape of the held frame, not the one the simulation has moved on to:
        // the framing's bounds are those of the frame's own CPU-skinned positions (glTF: Y-up
        // metres already), to float rounding.
        Model model = GltfImporter.read(TestPaths.root().resolve("core/src/test/resources/gltf/morph-skin.gltf"));
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(model, "pulse", new AnimationConfig())) {
            mesh.step(0.25);
            try (Frame held = mesh.acquire()) {
                for (int i = 0; i < 3; i++) {
                    mesh.step(0.3);
                }
                ModelFraming f = ModelFraming.of(model.asset(), mesh.geometries(), held);
                float min = Float.POSITIVE_INFINITY;
                float max = Float.NEGATIVE_INFINITY;
                for (int g = 0; g < held.geometryCount(); g++) {
                    float[] p = held.positions(g);
                    for (int i = 1; i < p.length; i += 3) {
                        min = Math.min(min, p[i]);
                        max = Math.max(max, p[i]);
                    }
                }
                assertEquals(max - min, f.height(), 1e-5);
            }
        }
    }
}
