package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.model.TransformElement;

/** Nodes: TRS and matrix transforms, the chosen scene, and node graphs that are not trees. */
class GltfSceneTest {
    private static Model read(String rest) throws Exception {
        return GltfFixture.read(new GltfFixture().gltf(rest));
    }

    @Test
    void trsBecomesTranslateRotationScaleWithSidsTheChannelsTarget() throws Exception {
        double h = Math.sqrt(0.5);
        Node n = read("\"nodes\":[{\"translation\":[1,2,3],\"rotation\":[0,0," + h + "," + h + "],\"scale\":[2,2,2]}],"
                + "\"scenes\":[{\"nodes\":[0]}]").node(0);
        assertEquals(3, n.transforms().size());
        assertEquals(TransformElement.Kind.TRANSLATE, n.transforms().get(0).kind());
        assertEquals(TransformElement.Kind.QUATERNION, n.transforms().get(1).kind());
        assertEquals(TransformElement.Kind.SCALE, n.transforms().get(2).kind());
        assertEquals(1, n.transformIndex("rotation"));
        // T * R * S applied to (1,0,0): scaled to (2,0,0), turned to (0,2,0), moved to (1,4,3).
        Vector3f p = n.localMatrix().transformPosition(new Vector3f(1, 0, 0));
        assertArrayEquals(new float[] {1, 4, 3}, new float[] {p.x, p.y, p.z}, 1e-6f);
    }

    @Test
    void aRotationThatIsNotUnitIsNormalisedWithAWarning() throws Exception {
        Model model = read("\"nodes\":[{\"rotation\":[0,0,0,2]}],\"scenes\":[{\"nodes\":[0]}]");
        assertArrayEquals(new float[] {0, 0, 0, 1}, model.node(0).transforms().get(1).values());
        assertTrue(model.node(0).localMatrix().equals(new Matrix4f(), 0f), "no scaling by |q|^2");
        assertEquals("/nodes/0/rotation", model.warnings().get(0).element());
    }

    @Test
    void columnMajorMatrixIsStoredRowMajor() throws Exception {
        // Column-major: the translation (5, 6, 7) is in elements 12..14.
        Node n = read("\"nodes\":[{\"matrix\":[1,0,0,0, 0,1,0,0, 0,0,1,0, 5,6,7,1]}],\"scenes\":[{\"nodes\":[0]}]")
                .node(0);
        TransformElement m = n.transforms().get(0);
        assertEquals(TransformElement.Kind.MATRIX, m.kind());
        assertEquals(5f, m.value(3));
        assertEquals(6f, m.value(7));
        assertEquals(7f, m.value(11));
        assertTrue(n.localMatrix().equals(new Matrix4f().translation(5, 6, 7), 0f));
    }

    @Test
    void nodesAreDepthFirstAndOnlyThoseOfTheChosenScene() throws Exception {
        Model model = read("\"nodes\":[{\"name\":\"a\",\"children\":[2]},{\"name\":\"b\"},{\"name\":\"c\"},"
                + "{\"name\":\"d\"}],\"scenes\":[{\"nodes\":[3]},{\"nodes\":[1,0]}],\"scene\":1");
        assertEquals(3, model.nodes().size());
        assertEquals("b", model.node(0).name());
        assertEquals("a", model.node(1).name());
        assertEquals("c", model.node(2).name());
        assertEquals(1, model.node(2).parent());
        assertTrue(model.warnings().stream().anyMatch(w -> w.message().contains("1 of 4 nodes are not in the scene")));
    }

    @Test
    void aSecondParentIsRefused() {
        GltfException e = assertThrows(GltfException.class, () -> read("\"nodes\":[{\"children\":[2]},"
                + "{\"children\":[2]},{}],\"scenes\":[{\"nodes\":[0,1]}]"));
        assertEquals("test.gltf: /nodes/1/children/0: node 2 is already a child of node 0 (the node graph must be a"
                + " tree)", e.getMessage());
    }

    @Test
    void aCycleIsRefused() {
        GltfException e = assertThrows(GltfException.class, () -> read("\"nodes\":[{\"children\":[1]},"
                + "{\"children\":[2]},{\"children\":[0]}],\"scenes\":[{\"nodes\":[0]}]"));
        assertEquals("/nodes/0/children", e.path());
    }

    @Test
    void matrixAndTrsTogetherAreRefused() {
        GltfException e = assertThrows(GltfException.class, () -> read("\"nodes\":[{\"matrix\":"
                + "[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1],\"scale\":[1,1,1]}],\"scenes\":[{\"nodes\":[0]}]"));
        assertEquals("/nodes/0/scale", e.path());
    }

    @Test
    void aDanglingChildIndexNamesItsPath() {
        GltfException e = assertThrows(GltfException.class, () -> read("\"nodes\":[{\"children\":[7]}],"
                + "\"scenes\":[{\"nodes\":[0]}]"));
        assertEquals("test.gltf: /nodes/0/children/0: index 7 does not name one of the 1 nodes", e.getMessage());
    }
}
