package org.skinlab.importer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.skinlab.collada.ColladaException;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.gltf.GltfException;
import org.skinlab.model.ImportException;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;

/** The format is told by content; the name decides only when the content does not. */
class ModelImporterTest {
    private static final String GLTF = "  \n{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"name\":\"only\"}],"
            + "\"scenes\":[{\"nodes\":[0]}]}";

    private static Model read(String text, String name) throws Exception {
        return ModelImporter.read(new ByteArrayInputStream(text.getBytes(StandardCharsets.UTF_8)), name, null);
    }

    @Test
    void gltfJsonIsReadWhateverItsName() throws Exception {
        assertEquals("only", read(GLTF, "misnamed.dae").node(0).name());
    }

    @Test
    void glbIsToldByItsMagic() throws Exception {
        byte[] glb = {'g', 'l', 'T', 'F', 1, 0, 0, 0, 12, 0, 0, 0};
        ImportException e = assertThrows(GltfException.class, () -> ModelImporter.read(
                new ByteArrayInputStream(glb), "x.bin", null));
        assertTrue(e.getMessage().contains("version 1 is not 2"), e.getMessage());
    }

    @Test
    void xmlGoesToColladaWhateverItsName() {
        assertThrows(ColladaException.class, () -> read("<?xml version=\"1.0\"?><notcollada/>", "x.gltf"));
    }

    @Test
    void ourColladaAssetStillLoads() throws Exception {
        Path dae = TestPaths.asset("cylinders/cylinder-bend.dae");
        assertEquals(ColladaImporter.read(dae).meshes().get(0).positionCount(), ModelImporter.read(dae).meshes().get(0).positionCount());
    }

    @Test
    void modelFileNames() {
        assertTrue(ModelImporter.isModelFile("a.DAE"));
        assertTrue(ModelImporter.isModelFile("b.gltf"));
        assertTrue(ModelImporter.isModelFile("c.GLB"));
        assertFalse(ModelImporter.isModelFile("d.obj"));
        assertFalse(ModelImporter.isModelFile("glb"));
    }
}
