package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;
import org.skinlab.model.Model;
import org.skinlab.model.Morph;

/**
 * Morph targets (glTF 2.0, "Morph Targets": P = B + sum w_i T_i, targets are offsets): one
 * RELATIVE {@link Morph} per mesh and distinct weights, {@code node.weights} over
 * {@code mesh.weights}; instances draw the morph's result.
 */
class GltfMorphTest {
    private static String morphed(GltfFixture f, String nodes) {
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0); // 0 base
        f.floats("VEC3", 0, 0, 2, 0, 0, 2, 0, 0, 2); // 1 target 0: up by 2
        f.floats("VEC3", 1, 0, 0, 0, 0, 0, 0, 0, 0); // 2 target 1: first vertex right by 1
        return f.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"targets\":[{\"POSITION\":1},"
                + "{\"POSITION\":2}]}],\"weights\":[0.5,0]}],\"nodes\":[" + nodes + "],\"scenes\":[{\"nodes\":[0,1]}]");
    }

    @Test
    void meshWeightsAndNodeWeightsGiveTheirOwnMorphs() throws Exception {
        Model model = GltfFixture.read(morphed(new GltfFixture(), "{\"mesh\":0},{\"mesh\":0,\"weights\":[0,1]}"));
        assertEquals(2, model.morphs().size());
        Morph byMesh = model.morphs().get(0);
        assertEquals(Morph.Method.RELATIVE, byMesh.method());
        assertArrayEquals(new float[] {0, 0, 1, 1, 0, 1, 0, 1, 1}, byMesh.result().positions());
        assertArrayEquals(new float[] {1, 0, 0, 1, 0, 0, 0, 1, 0}, model.morphs().get(1).result().positions());
        assertSame(byMesh.result(), model.instances().get(0).mesh());
        assertSame(model.morphs().get(1).result(), model.instances().get(1).mesh());
        assertEquals(3, model.meshes().size(), "the base and the two results");
    }

    @Test
    void nodesWithTheSameWeightsShareAMorph() throws Exception {
        Model model = GltfFixture.read(morphed(new GltfFixture(), "{\"mesh\":0},{\"mesh\":0,\"weights\":[0.5,0]}"));
        assertEquals(1, model.morphs().size());
    }

    @Test
    void weightCountMustMatchTheTargets() {
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(
                morphed(new GltfFixture(), "{\"mesh\":0},{\"mesh\":0,\"weights\":[1]}")));
        assertEquals("/nodes/1/weights", e.path());
    }
}
