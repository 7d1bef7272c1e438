package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;

/** .glb and .gltf containers, external buffers, and the URIs that are refused. */
class GltfContainerTest {
    private static GltfFixture triangle() {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0);
        f.accessor(AccessorFormat.UNSIGNED_SHORT, "SCALAR", false, 0, 1, 2);
        return f;
    }

    private static final String TRIANGLE_MESH = "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},"
            + "\"indices\":1}]}],\"nodes\":[{\"mesh\":0,\"translation\":[1,0,0]}],\"scenes\":[{\"nodes\":[0]}]";

    @Test
    void glbAndGltfOfTheSameContentGiveEqualModels() throws Exception {
        GltfFixture f = triangle();
        Model fromGltf = GltfFixture.read(f.gltf(TRIANGLE_MESH));
        Model fromGlb = GltfFixture.read(f.glb(TRIANGLE_MESH), "test.glb");
        Mesh a = fromGltf.meshes().get(0);
        Mesh b = fromGlb.meshes().get(0);
        assertArrayEquals(a.positions(), b.positions());
        assertArrayEquals(a.triangles(), b.triangles());
        assertEquals(a.parts(), b.parts());
        assertEquals(fromGltf.nodes().size(), fromGlb.nodes().size());
        assertTrue(fromGltf.node(0).localMatrix().equals(fromGlb.node(0).localMatrix(), 0f));
        assertEquals(fromGltf.warnings(), fromGlb.warnings());
        assertEquals("test.glb", fromGlb.source());
        assertEquals("GltfFixture", fromGlb.asset().authoringTool());
    }

    @Test
    void glbWhoseHeaderLengthDisagreesIsRefused() {
        byte[] glb = triangle().glb(TRIANGLE_MESH);
        ByteBuffer.wrap(glb).order(ByteOrder.LITTLE_ENDIAN).putInt(8, glb.length + 4);
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(glb, "x.glb"));
        assertEquals("x.glb: (GLB header): the header says " + (glb.length + 4) + " bytes but the file has "
                + glb.length, e.getMessage());
    }

    @Test
    void glbChunkLongerThanTheFileIsRefused() {
        byte[] glb = triangle().glb(TRIANGLE_MESH);
        ByteBuffer.wrap(glb).order(ByteOrder.LITTLE_ENDIAN).putInt(12, glb.length);
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(glb, "x.glb"));
        assertEquals("(GLB chunk 0)", e.path());
    }

    @Test
    void glbWithBytesAfterItsDeclaredLengthLoadsWithAWarning() throws Exception {
        byte[] glb = triangle().glb(TRIANGLE_MESH);
        byte[] longer = java.util.Arrays.copyOf(glb, glb.length + 3);
        Model model = GltfFixture.read(longer, "x.glb");
        assertEquals(3, model.meshes().get(0).positionCount());
        assertEquals("(GLB header)", model.warnings().get(0).element());
    }

    @Test
    void unusedBufferWithoutDataIsNoProblemButAUsedOneIsRefused() throws Exception {
        String json = triangle().gltf(TRIANGLE_MESH).replace("\"buffers\":[{", "\"buffers\":[{\"byteLength\":4},{")
                .replace("\"buffer\":0", "\"buffer\":1");
        assertEquals(3, GltfFixture.read(json).meshes().get(0).positionCount());
        String used = triangle().gltf(TRIANGLE_MESH).replaceAll("\"uri\":\"[^\"]*\",", "");
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(used));
        assertEquals("/buffers/0", e.path());
    }

    @Test
    void percentEncodedDataUriIsRead() throws Exception {
        GltfFixture f = new GltfFixture();
        f.accessor(AccessorFormat.UNSIGNED_BYTE, "SCALAR", false, 0, 1, 2, 65);
        String json = f.gltf("").replaceAll("data:[^\"]*", "data:application/gltf-buffer,%00%01%02A");
        byte[] bytes = json.getBytes(StandardCharsets.UTF_8);
        GltfContext ctx = new GltfContext("t.gltf");
        JsonNode root = JsonTree.parse(ctx, bytes, 0, bytes.length);
        Accessors a = new Accessors(ctx, root, new Buffers(ctx, root, null, new UriResolver(ctx, null)));
        assertArrayEquals(new int[] {0, 1, 2, 65}, a.ints(0));
    }

    @Test
    void bufferShorterThanItsByteLengthIsRefused() {
        // 36 bytes of positions and 6 of indices, padded to 44.
        String json = triangle().gltf(TRIANGLE_MESH).replace("\"byteLength\":44}]", "\"byteLength\":48}]");
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(json));
        assertEquals("test.gltf: /buffers/0/byteLength: byteLength 48 but the data has 44 bytes", e.getMessage());
    }

    @Test
    void externalBufferNextToTheFileIsRead(@TempDir Path dir) throws Exception {
        GltfFixture f = triangle();
        String embedded = f.gltf(TRIANGLE_MESH);
        String base64 = embedded.replaceAll(".*base64,([^\"]*)\".*", "$1");
        Files.createDirectories(dir.resolve("bin"));
        Files.write(dir.resolve("bin/tri angle.bin"), java.util.Base64.getDecoder().decode(base64));
        Path gltf = dir.resolve("tri.gltf");
        Files.write(gltf, embedded.replaceAll("data:[^\"]*", "bin/tri%20angle.bin").getBytes(StandardCharsets.UTF_8));
        assertEquals(3, GltfImporter.read(gltf).meshes().get(0).positionCount());
    }

    @Test
    void urisThatLeaveTheFolderOrNameASchemeAreRefused(@TempDir Path dir) throws Exception {
        String embedded = triangle().gltf(TRIANGLE_MESH);
        Files.write(dir.resolve("secret.bin"), new byte[64]);
        Path sub = Files.createDirectories(dir.resolve("sub"));
        String[][] cases = {
                {"../secret.bin", "leaves the file's folder"},
                {"a/../../secret.bin", "leaves the file's folder"},
                {"/etc/passwd", "is an absolute path"},
                {"http://example.com/x.bin", "has a scheme or drive"},
                {"file:///etc/passwd", "has a scheme or drive"},
                {"C:\\\\x.bin", "has a scheme or drive"},
                {"%2e%2e/secret.bin", "leaves the file's folder"},
        };
        for (String[] c : cases) {
            Path gltf = sub.resolve("doc.gltf");
            Files.write(gltf, embedded.replaceAll("data:[^\"]*", java.util.regex.Matcher.quoteReplacement(c[0]))
                    .getBytes(StandardCharsets.UTF_8));
            GltfException e = assertThrows(GltfException.class, () -> GltfImporter.read(gltf), c[0]);
            assertEquals("/buffers/0/uri", e.path(), c[0]);
            assertTrue(e.problem().contains(c[1]), e.getMessage());
        }
    }

    @Test
    void aLinkInsideTheFolderThatLeadsOutIsRefused(@TempDir Path dir) throws Exception {
        String embedded = triangle().gltf(TRIANGLE_MESH);
        Path outside = Files.createDirectories(dir.resolve("outside"));
        Files.write(outside.resolve("secret.bin"), new byte[64]);
        Path sub = Files.createDirectories(dir.resolve("sub"));
        try {
            Files.createSymbolicLink(sub.resolve("link.bin"), outside.resolve("secret.bin"));
        } catch (UnsupportedOperationException | java.io.IOException e) {
            org.junit.jupiter.api.Assumptions.assumeTrue(false, "symbolic links cannot be made here: " + e);
        }
        Path gltf = sub.resolve("doc.gltf");
        Files.write(gltf, embedded.replaceAll("data:[^\"]*", "link.bin").getBytes(StandardCharsets.UTF_8));
        GltfException e = assertThrows(GltfException.class, () -> GltfImporter.read(gltf));
        assertEquals("doc.gltf: /buffers/0/uri: \"link.bin\" is a link that leads out of the file's folder",
                e.getMessage());
    }

    @Test
    void fileUriWithoutALocationIsRefused() {
        String json = triangle().gltf(TRIANGLE_MESH).replaceAll("data:[^\"]*", "tri.bin");
        GltfException e = assertThrows(GltfException.class, () -> GltfImporter.read(
                new ByteArrayInputStream(json.getBytes(StandardCharsets.UTF_8)), "s.gltf", null));
        assertEquals("s.gltf: /buffers/0/uri: the URI \"tri.bin\" names a file, but the document was read from a"
                + " stream without a location", e.getMessage());
    }

    @Test
    void unsupportedRequiredExtensionsAreRefusedByName() {
        for (String ext : new String[] {"KHR_draco_mesh_compression", "EXT_meshopt_compression", "KHR_texture_basisu"}) {
            String json = triangle().gltf("\"extensionsUsed\":[\"" + ext + "\"],\"extensionsRequired\":[\"" + ext
                    + "\"]," + TRIANGLE_MESH);
            GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(json));
            assertEquals("/extensionsRequired/0", e.path());
            assertTrue(e.problem().contains(ext), e.getMessage());
        }
    }

    @Test
    void unsupportedUsedExtensionIsAWarning() throws Exception {
        Model model = GltfFixture.read(triangle().gltf("\"extensionsUsed\":[\"KHR_materials_sheen\"]," + TRIANGLE_MESH));
        assertEquals("/extensionsUsed/0", model.warnings().get(0).element());
    }

    @Test
    void versionMustBeTwo() {
        String json = triangle().gltf(TRIANGLE_MESH).replace("\"version\":\"2.0\"", "\"version\":\"1.0\"");
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(json));
        assertEquals("test.gltf: /asset/version: version \"1.0\" is not glTF 2.x", e.getMessage());
    }

    @Test
    void aByteOrderMarkIsSkippedWithAWarning() throws Exception {
        byte[] json = triangle().gltf(TRIANGLE_MESH).getBytes(StandardCharsets.UTF_8);
        byte[] withBom = new byte[json.length + 3];
        withBom[0] = (byte) 0xEF;
        withBom[1] = (byte) 0xBB;
        withBom[2] = (byte) 0xBF;
        System.arraycopy(json, 0, withBom, 3, json.length);
        Model model = GltfFixture.read(withBom, "bom.gltf");
        assertEquals(3, model.meshes().get(0).positionCount());
        assertEquals("/", model.warnings().get(0).element());
    }

    @Test
    void aDocumentThatIsNoObjectIsRefused() {
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read("[1, 2]"));
        assertEquals("test.gltf: /: the JSON document is not an object", e.getMessage());
    }

    @Test
    void malformedJsonNamesWhereItBroke() {
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(
                "{\"asset\":{\"version\":\"2.0\"},\"nodes\":[{\"name\":\"a\",}]}"));
        assertTrue(e.getMessage().startsWith("test.gltf: /nodes/0"), e.getMessage());
    }

    @Test
    void duplicateKeysAreRefused() {
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(
                "{\"asset\":{\"version\":\"2.0\",\"version\":\"2.0\"}}"));
        assertTrue(e.getMessage().contains("/asset"), e.getMessage());
    }

    @Test
    void deepNestingIsRefused() {
        StringBuilder deep = new StringBuilder("{\"asset\":{\"version\":\"2.0\"},\"extras\":");
        for (int i = 0; i < 1000; i++) {
            deep.append('[');
        }
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(deep.toString()));
        assertTrue(e.problem().contains("invalid JSON"), e.getMessage());
    }
}
