package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.skinlab.model.Model;

/**
 * Documents that are small but ask for much: the allocation budget (a few bytes of JSON must not
 * make the importer allocate gigabytes) and graphs whose checks must stay linear.
 */
class GltfHostileSizeTest {
    @Test
    void manyDatalessAccessorsExhaustTheBudgetNotTheHeap() {
        // Each accessor is 2^26 - 1 values of zeros: within the per-accessor limit, 256 MB each.
        StringBuilder accessors = new StringBuilder();
        StringBuilder attributes = new StringBuilder("\"POSITION\":0");
        for (int i = 0; i < 40; i++) {
            accessors.append(i == 0 ? "{\"componentType\":5126,\"type\":\"VEC3\",\"count\":22369621,"
                    + "\"min\":[0,0,0],\"max\":[0,0,0]}" : ",{\"componentType\":5126,\"type\":\"VEC2\",\"count\":22369621}");
            if (i > 0) {
                attributes.append(",\"TEXCOORD_").append(i - 1).append("\":").append(i);
            }
        }
        String json = "{\"asset\":{\"version\":\"2.0\"},\"accessors\":[" + accessors + "],\"meshes\":[{\"primitives\":"
                + "[{\"attributes\":{" + attributes + "}}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]}";
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(json));
        assertTrue(e.problem().contains("more than the"), e.getMessage());
        assertTrue(e.path().startsWith("/meshes/0") || e.path().startsWith("/accessors/"), e.getMessage());
    }

    @Test
    void manyEmptyMorphTargetsExhaustTheBudget() {
        GltfFixture f = new GltfFixture();
        double[] positions = new double[3 * 3000];
        f.floats("VEC3", positions);
        StringBuilder targets = new StringBuilder();
        for (int i = 0; i < 20000; i++) {
            targets.append(i == 0 ? "{}" : ",{}");
        }
        String json = f.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"targets\":[" + targets
                + "]}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]");
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(json));
        assertEquals("/meshes/0/primitives", e.path());
    }

    @Test
    void warningsAreCapped() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0);
        StringBuilder primitives = new StringBuilder("{\"attributes\":{\"POSITION\":0}}");
        for (int i = 0; i < 1000; i++) {
            primitives.append(",{\"attributes\":{\"POSITION\":0},\"mode\":0}");
        }
        Model model = GltfFixture.read(f.singleMesh(primitives.toString()));
        assertEquals(GltfContext.MAX_WARNINGS + 1, model.warnings().size());
        assertEquals("800 more warnings not shown", model.warnings().get(GltfContext.MAX_WARNINGS).message());
    }

    @Test
    void aLongChainOfNodesIsCheckedInLinearTime() throws Exception {
        int n = 100_000;
        StringBuilder nodes = new StringBuilder();
        for (int i = 0; i < n; i++) {
            nodes.append(i == 0 ? "" : ",").append(i + 1 < n ? "{\"children\":[" + (i + 1) + "]}" : "{}");
        }
        Model model = GltfFixture.read("{\"asset\":{\"version\":\"2.0\"},\"nodes\":[" + nodes
                + "],\"scenes\":[{\"nodes\":[0]}]}");
        assertEquals(n, model.nodes().size());
        assertEquals(n - 2, model.node(n - 1).parent());
    }
}
