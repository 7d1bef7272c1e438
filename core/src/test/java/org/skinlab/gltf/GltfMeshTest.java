package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshPart;
import org.skinlab.model.Model;

/** Primitives to triangles: modes and their winding (glTF 2.0, "Meshes": topology), attributes, parts. */
class GltfMeshTest {
    private static final double[] FIVE_POINTS = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0, 0, 2, 0};

    @Test
    void nonIndexedStripAlternatesItsWinding() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", FIVE_POINTS);
        Mesh mesh = GltfFixture.read(f.singleMesh("{\"attributes\":{\"POSITION\":0},\"mode\":5}")).meshes().get(0);
        // Strip triangle i is (v_i, v_(i+1+i%2), v_(i+2-i%2)).
        assertArrayEquals(new int[] {0, 1, 2, 1, 3, 2, 2, 3, 4}, mesh.triangles());
        assertEquals("triangle_strip", mesh.parts().get(0).primitive());
        assertFalse(mesh.hasNormals(), "no NORMAL: no normals, as for COLLADA (renderers use face normals)");
    }

    @Test
    void indexedFanTurnsAroundItsFirstVertex() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", FIVE_POINTS);
        f.accessor(AccessorFormat.UNSIGNED_BYTE, "SCALAR", false, 4, 0, 1, 3);
        Mesh mesh = GltfFixture.read(f.singleMesh("{\"attributes\":{\"POSITION\":0},\"indices\":1,\"mode\":6}"))
                .meshes().get(0);
        // Fan triangle i is (v_(i+1), v_(i+2), v_0) with v = indices.
        assertArrayEquals(new int[] {0, 1, 4, 1, 3, 4}, mesh.triangles());
    }

    @Test
    void primitivesBecomePartsAndShareVerticesOnlyWhenTheirAttributesAreTheSame() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", FIVE_POINTS); // 0
        f.accessor(AccessorFormat.UNSIGNED_SHORT, "SCALAR", false, 0, 1, 2); // 1
        f.accessor(AccessorFormat.UNSIGNED_INT, "SCALAR", false, 2, 1, 3); // 2
        f.floats("VEC3", 0, 0, 5, 1, 0, 5, 0, 1, 5); // 3
        String json = f.gltf("\"materials\":[{\"name\":\"red\"},{\"name\":\"blue\"}],"
                + "\"meshes\":[{\"name\":\"m\",\"primitives\":["
                + "{\"attributes\":{\"POSITION\":0},\"indices\":1,\"material\":1},"
                + "{\"attributes\":{\"POSITION\":0},\"indices\":2,\"material\":0},"
                + "{\"attributes\":{\"POSITION\":3}},"
                + "{\"attributes\":{\"POSITION\":3},\"mode\":1}]}],"
                + "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]");
        Model model = GltfFixture.read(json);
        Mesh mesh = model.meshes().get(0);
        assertEquals(8, mesh.positionCount(), "5 shared by the first two primitives, 3 of the third");
        assertArrayEquals(new int[] {0, 1, 2, 2, 1, 3, 5, 6, 7}, mesh.triangles());
        assertEquals(3, mesh.parts().size(), "the LINES primitive is skipped");
        assertEquals(new MeshPart("triangles", "/materials/1", 0, 1), mesh.parts().get(0));
        assertEquals(new MeshPart("triangles", "/materials/0", 1, 1), mesh.parts().get(1));
        assertEquals(new MeshPart("triangles", null, 2, 1), mesh.parts().get(2));
        assertEquals(5f, mesh.position(7, 2));
        assertEquals("blue", model.instances().get(0).material("/materials/1").material().name());
        assertTrue(model.warnings().stream().anyMatch(w -> w.element().equals("/meshes/0/primitives/3")
                && w.message().contains("mode 1 (lines)")), model.warnings().toString());
    }

    @Test
    void verticesSplitAtAHardEdgeShareTheirPositions() throws Exception {
        GltfFixture f = new GltfFixture();
        // Two triangles folded along the edge (0,0,0)-(1,0,0); the edge's vertices are written
        // twice, with each face's normal, as exporters do at a hard edge.
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1);
        f.floats("VEC3", 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, -1, 0, 0, -1, 0, 0, -1, 0);
        Mesh mesh = GltfFixture.read(f.singleMesh("{\"attributes\":{\"POSITION\":0,\"NORMAL\":1}}")).meshes().get(0);
        assertEquals(6, mesh.vertexCount());
        assertEquals(4, mesh.positionCount());
        assertArrayEquals(new int[] {0, 1, 2, 0, 1, 3}, mesh.vertexPositions());
        assertArrayEquals(new int[] {0, 3}, mesh.verticesOfPosition(0));
        assertArrayEquals(new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}, mesh.positions());
        assertArrayEquals(new int[] {0, 1, 2, 3, 4, 5}, mesh.triangles(), "triangles index vertices");
    }

    @Test
    void verticesSplitAtAUvSeamShareTheirPositionAndKeepTheirTexCoords() throws Exception {
        GltfFixture f = new GltfFixture();
        // A quad whose diagonal (1,0,0)-(0,1,0) is a texture seam: both triangles write the
        // diagonal's corners with their own u.
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0);
        f.floats("VEC2", 0, 0, 1, 0, 0, 1, 0.25f, 0, 0.5f, 0.5f, 0.75f, 1);
        Mesh mesh = GltfFixture.read(f.singleMesh("{\"attributes\":{\"POSITION\":0,\"TEXCOORD_0\":1}}"))
                .meshes().get(0);
        assertEquals(6, mesh.vertexCount());
        assertArrayEquals(new int[] {0, 1, 2, 1, 3, 2}, mesh.vertexPositions());
        assertArrayEquals(new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, mesh.positions());
        assertArrayEquals(new float[] {0, 1, 1, 1, 0, 0, 0.25f, 1, 0.5f, 0.5f, 0.75f, 0}, mesh.texCoords(0),
                "per vertex, v flipped");
    }

    @Test
    void normalsColoursAndTexCoordSetsAreCarriedPerVertex() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0); // 0
        f.floats("VEC3", 0, 0, 1, 0, 0, 1, 0, 0, 1); // 1
        f.accessor(AccessorFormat.UNSIGNED_BYTE, "VEC3", true, 255, 0, 0, 0, 255, 0, 0, 0, 51); // 2
        f.floats("VEC2", 0, 0, 1, 0, 0, 1); // 3
        f.accessor(AccessorFormat.UNSIGNED_SHORT, "VEC2", true, 0, 65535, 65535, 65535, 0, 0); // 4
        Mesh mesh = GltfFixture.read(f.singleMesh("{\"attributes\":{\"POSITION\":0,\"NORMAL\":1,\"COLOR_0\":2,"
                + "\"TEXCOORD_1\":4,\"TEXCOORD_0\":3}}")).meshes().get(0);
        assertArrayEquals(new float[] {0, 0, 1, 0, 0, 1, 0, 0, 1}, mesh.normals());
        assertArrayEquals(new float[] {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 0.2f, 1}, mesh.colors(), 1e-7f);
        assertEquals(2, mesh.texCoordSetCount());
        assertEquals(1, mesh.texCoordSetNumber(1));
        // (0,1) (1,1) (0,0) in glTF's v-down convention are (0,0) (1,0) (0,1) in the model's v-up one.
        assertArrayEquals(new float[] {0, 0, 1, 0, 0, 1}, mesh.texCoords(1));
    }

    @Test
    void aPrimitiveWithoutNormalsBesideOneWithThemGetsZerosAndAWarning() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0);
        f.floats("VEC3", 0, 0, 1, 0, 0, 1, 0, 0, 1);
        f.floats("VEC3", 0, 0, 2, 1, 0, 2, 0, 1, 2);
        Model model = GltfFixture.read(f.singleMesh("{\"attributes\":{\"POSITION\":0,\"NORMAL\":1}},"
                + "{\"attributes\":{\"POSITION\":2}}"));
        float[] normals = model.meshes().get(0).normals();
        assertArrayEquals(new float[] {0, 0, 1, 0, 0, 0}, new float[] {normals[6], normals[7], normals[8],
                normals[9], normals[10], normals[11]});
        assertEquals("/meshes/0/primitives/1/attributes", model.warnings().get(0).element());
    }

    @Test
    void indexOutOfRangeNamesTheIndicesPath() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0);
        f.accessor(AccessorFormat.UNSIGNED_BYTE, "SCALAR", false, 0, 1, 3);
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(
                f.singleMesh("{\"attributes\":{\"POSITION\":0},\"indices\":1}")));
        assertEquals("test.gltf: /meshes/0/primitives/0/indices: index 2 is 3 but the primitive has 3 vertices",
                e.getMessage());
    }

    @Test
    void anUnknownAttributeIsRefusedButAnApplicationsIsNot() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0);
        assertEquals(3, GltfFixture.read(f.singleMesh("{\"attributes\":{\"POSITION\":0,\"_TEMPERATURE\":0}}"))
                .meshes().get(0).positionCount());
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(
                f.singleMesh("{\"attributes\":{\"POSITION\":0,\"TEXCOORD_01\":0}}")));
        assertEquals("/meshes/0/primitives/0/attributes/TEXCOORD_01", e.path());
    }

    @Test
    void thePrimitiveRestartValueIsRefused() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0);
        f.accessor(AccessorFormat.UNSIGNED_BYTE, "SCALAR", false, 0, 1, 255);
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(
                f.singleMesh("{\"attributes\":{\"POSITION\":0},\"indices\":1}")));
        assertEquals("test.gltf: /meshes/0/primitives/0/indices: index 2 is the primitive restart value 255, which glTF"
                + " does not allow", e.getMessage());
    }

    @Test
    void attributeOfTheWrongFormatIsRefused() throws Exception {
        GltfFixture f = new GltfFixture();
        f.accessor(AccessorFormat.SHORT, "VEC3", false, 0, 0, 0, 1, 0, 0, 0, 1, 0);
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(
                f.singleMesh("{\"attributes\":{\"POSITION\":0}}")));
        assertEquals("/meshes/0/primitives/0/attributes/POSITION", e.path());
    }

    @Test
    void quantizedPositionsAreReadWithKhrMeshQuantization() throws Exception {
        GltfFixture f = new GltfFixture();
        f.accessor(AccessorFormat.SHORT, "VEC3", false, 0, 0, 0, 100, 0, 0, 0, -100, 0);
        String json = f.gltf("\"extensionsUsed\":[\"KHR_mesh_quantization\"],\"extensionsRequired\":"
                + "[\"KHR_mesh_quantization\"],\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
                + "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]");
        assertArrayEquals(new float[] {0, 0, 0, 100, 0, 0, 0, -100, 0}, GltfFixture.read(json).meshes().get(0)
                .positions());
    }
}
