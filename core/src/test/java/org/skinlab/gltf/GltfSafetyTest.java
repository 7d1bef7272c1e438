package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.lang.management.ManagementFactory;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Base64;
import java.util.Locale;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.ValueSource;
import org.skinlab.model.Model;

/**
 * Hostile files: sizes are checked before anything is allocated, indices and accessor ranges
 * before they are used, URIs stay inside the document's folder, the JSON's nesting and numbers
 * are bounded, and images are never decoded. Each refusal names the JSON path of the culprit.
 *
 * <p>Memory is measured as the bytes the importing thread allocates (HotSpot's per-thread
 * counter, after a first import has loaded the classes): a file of a few hundred bytes that
 * declares gigabytes must be refused having allocated at most {@link #SMALL} bytes, which is
 * what reading it and its JSON tree cost, not what it declares.
 */
class GltfSafetyTest {
    private static final long SMALL = 4L << 20;

    @TempDir
    Path dir;

    /** The first import of a JVM loads and initialises the importer's classes: not the file's cost. */
    @BeforeAll
    static void warmUp() throws Exception {
        GltfImporter.read(new ByteArrayInputStream(triangle(new int[] {0, 1, 2}, "", "")
                .getBytes(StandardCharsets.UTF_8)), "warm-up.gltf", null);
    }

    /** A document with one buffer of {@code bufferJson} and the given accessors/bufferViews JSON. */
    private static String doc(String buffer, String rest) {
        return "{\"asset\":{\"version\":\"2.0\"},\"buffers\":[" + buffer + "]" + (rest.isEmpty() ? "" : "," + rest) + "}";
    }

    private static String dataUri(int bytes) {
        return "data:application/octet-stream;base64," + Base64.getEncoder().encodeToString(new byte[bytes]);
    }

    /** A GLB of the JSON and a BIN chunk of {@code bin} zero bytes. */
    private static byte[] glb(String json, int bin) {
        byte[] js = json.getBytes(StandardCharsets.UTF_8);
        int jsonLength = (js.length + 3) / 4 * 4;
        int binLength = (bin + 3) / 4 * 4;
        ByteBuffer b = ByteBuffer.allocate(12 + 8 + jsonLength + (bin > 0 ? 8 + binLength : 0))
                .order(ByteOrder.LITTLE_ENDIAN);
        b.putInt(GlbContainer.MAGIC).putInt(2).putInt(b.capacity());
        b.putInt(jsonLength).putInt(0x4E4F534A).put(js);
        while (b.position() % 4 != 0) {
            b.put((byte) ' ');
        }
        if (bin > 0) {
            b.putInt(binLength).putInt(0x004E4942);
        }
        return b.array();
    }

    /** The refusal of importing {@code bytes} as {@code name} located in {@link #dir}, with its allocation checked. */
    private GltfException refused(byte[] bytes, String name) {
        long before = allocatedBytes();
        GltfException e = assertThrows(GltfException.class,
                () -> GltfImporter.read(new ByteArrayInputStream(bytes), name, dir.resolve(name)));
        long allocated = allocatedBytes() - before;
        assertTrue(allocated < SMALL, () -> String.format(Locale.ROOT, "allocated %,d bytes to refuse %d bytes: %s",
                allocated, bytes.length, e.getMessage()));
        assertTrue(e.getMessage().startsWith(name + ": "), e::getMessage);
        return e;
    }

    private GltfException refused(String json) {
        return refused(json.getBytes(StandardCharsets.UTF_8), "attack.gltf");
    }

    private static long allocatedBytes() {
        return ((com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean())
                .getThreadAllocatedBytes(Thread.currentThread().getId());
    }

    // ------------------------------------------------------------------------------------ sizes

    @Test
    void aGlbDeclaringAFourGigabyteBufferIsRefusedBeforeAllocating() {
        GltfException e = refused(glb(doc("{\"byteLength\":4294967296}", ""), 16), "huge.glb");
        assertEquals("/buffers/0/byteLength", e.location(), e::getMessage);
    }

    @Test
    void aGlbHeaderClaimingTwoGigabytesIsRefusedWithoutReadingThem() {
        byte[] bytes = glb(doc("{\"byteLength\":4}", ""), 4);
        ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN).putInt(8, Integer.MAX_VALUE);
        GltfException e = refused(bytes, "header.glb");
        assertTrue(e.location().startsWith("(GLB"), e::getMessage);
    }

    @Test
    void aJsonChunkClaimingMoreThanTheFileIsRefused() {
        byte[] bytes = glb(doc("{\"byteLength\":4}", ""), 4);
        ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN).putInt(12, 0x7ffffff0);
        refused(bytes, "chunk.glb");
    }

    @Test
    void anAccessorCountNearTheIntegerLimitIsRefusedBeforeAllocating() {
        String rest = "\"bufferViews\":[{\"buffer\":0,\"byteLength\":12}],\"accessors\":[{\"bufferView\":0,"
                + "\"componentType\":5126,\"count\":2147483647,\"type\":\"VEC3\",\"min\":[0,0,0],\"max\":[0,0,0]}],"
                + "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}]";
        GltfException e = refused(glb(doc("{\"byteLength\":12}", rest), 12), "count.glb");
        assertTrue(e.location().startsWith("/accessors/0"), e::getMessage);
    }

    @Test
    void anAccessorWithoutDataDeclaringAHugeCountIsRefusedBeforeAllocating() {
        // No bufferView: the values are zeros, which a reader must not materialise blindly.
        String json = doc("{\"byteLength\":4,\"uri\":\"" + dataUri(4) + "\"}", "\"accessors\":[{\"componentType\":5126,"
                + "\"count\":2000000000,\"type\":\"VEC3\",\"min\":[0,0,0],\"max\":[0,0,0]}],"
                + "\"meshes\":[{\"primitives\":[{\"attributes\":"
                + "{\"POSITION\":0}}]}]");
        GltfException e = refused(json);
        assertTrue(e.location().startsWith("/accessors/0") || e.location().startsWith("/meshes/0"), e::getMessage);
    }

    @Test
    void aBufferViewOutsideItsBufferIsRefused() {
        GltfException e = refused(doc("{\"byteLength\":8,\"uri\":\"" + dataUri(8) + "\"}",
                "\"bufferViews\":[{\"buffer\":0,\"byteOffset\":4,\"byteLength\":8}]"));
        assertEquals("/bufferViews/0/byteLength", e.location(), e::getMessage);
    }

    @Test
    void aBufferShorterThanItsByteLengthIsRefused() {
        GltfException e = refused(doc("{\"byteLength\":64,\"uri\":\"" + dataUri(8) + "\"}", ""));
        assertTrue(e.location().startsWith("/buffers/0"), e::getMessage);
    }

    // ---------------------------------------------------------------------- indices and ranges

    /** A triangle (3 positions) with its indices' values given; joints and skin optional. */
    private static String triangle(int[] indices, String extraAttributes, String extra) {
        ByteBuffer b = ByteBuffer.allocate(36 + 12 + 12 + 16).order(ByteOrder.LITTLE_ENDIAN);
        b.putFloat(0).putFloat(0).putFloat(0).putFloat(1).putFloat(0).putFloat(0).putFloat(0).putFloat(1).putFloat(0);
        for (int i : indices) {
            b.putInt(i);
        }
        b.position(48);
        for (int v = 0; v < 3; v++) {
            b.put((byte) (v == 2 ? 5 : 0)).put((byte) 0).put((byte) 0).put((byte) 0); // joints: vertex 2 names joint 5
        }
        b.position(60);
        for (int v = 0; v < 3; v++) {
            b.put((byte) 255).put((byte) 0).put((byte) 0).put((byte) 0);
        }
        String uri = "data:application/octet-stream;base64," + Base64.getEncoder().encodeToString(b.array());
        return doc("{\"byteLength\":76,\"uri\":\"" + uri + "\"}",
                "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36},{\"buffer\":0,\"byteOffset\":36,\"byteLength\":12},"
                + "{\"buffer\":0,\"byteOffset\":48,\"byteLength\":12},{\"buffer\":0,\"byteOffset\":60,\"byteLength\":12}],"
                + "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\","
                + "\"min\":[0,0,0],\"max\":[1,1,0]},{\"bufferView\":1,\"componentType\":5125,\"count\":3,"
                + "\"type\":\"SCALAR\"},{\"bufferView\":2,\"componentType\":5121,\"count\":3,\"type\":\"VEC4\"},"
                + "{\"bufferView\":3,\"componentType\":5121,\"normalized\":true,\"count\":3,\"type\":\"VEC4\"}],"
                + "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0" + extraAttributes + "},"
                + "\"indices\":1}]}]" + extra);
    }

    @Test
    void theTriangleOfTheseTestsLoads() throws Exception {
        Model m = GltfImporter.read(new ByteArrayInputStream(triangle(new int[] {0, 1, 2}, "", "")
                .getBytes(StandardCharsets.UTF_8)), "ok.gltf", dir.resolve("ok.gltf"));
        assertEquals(1, m.meshes().size());
        assertEquals(1, m.meshes().get(0).triangleCount());
    }

    @Test
    void anIndexBeyondTheVerticesIsRefused() {
        GltfException e = refused(triangle(new int[] {0, 1, 3}, "", ""));
        assertEquals("/meshes/0/primitives/0/indices", e.location(), e::getMessage);
    }

    @Test
    void anIndexOfMinusOneAsUnsignedIntIsRefused() {
        GltfException e = refused(triangle(new int[] {0, 1, -1}, "", ""));
        assertEquals("/meshes/0/primitives/0/indices", e.location(), e::getMessage);
    }

    @Test
    void aJointBeyondTheSkinIsRefused() {
        String skinned = triangle(new int[] {0, 1, 2}, ",\"JOINTS_0\":2,\"WEIGHTS_0\":3",
                ",\"nodes\":[{\"mesh\":0,\"skin\":0},{}],\"skins\":[{\"joints\":[1]}],\"scenes\":[{\"nodes\":[0,1]}]");
        GltfException e = refused(skinned);
        assertEquals("/meshes/0/primitives/0/attributes/JOINTS_0", e.location(), e::getMessage);
    }

    @Test
    void aDanglingIndexIsRefusedWithItsPath() {
        GltfException e = refused(triangle(new int[] {0, 1, 2}, "", ",\"nodes\":[{\"mesh\":7}]"));
        assertEquals("/nodes/0/mesh", e.location(), e::getMessage);
    }

    @Test
    void anAccessorReachingPastItsViewIsRefused() {
        String json = triangle(new int[] {0, 1, 2}, "", "").replace("\"count\":3,\"type\":\"VEC3\"",
                "\"count\":4,\"type\":\"VEC3\"");
        GltfException e = refused(json);
        assertTrue(e.location().startsWith("/accessors/0"), e::getMessage);
    }

    // -------------------------------------------------------------------------------------- URIs

    /** URIs that name something outside the document's folder, or not a file at all. */
    @ParameterizedTest
    @ValueSource(strings = {"../secret.bin", "sub/../../secret.bin", "..%2Fsecret.bin", "%2e%2e/secret.bin",
        "..\\\\secret.bin", "/etc/passwd", "\\\\\\\\server\\\\share\\\\x.bin", "file:///etc/passwd",
        "http://example.com/x.bin", "https://example.com/x.bin", "C:\\\\secret.bin", "C:/secret.bin", "c:secret.bin",
        "ftp://example.com/x.bin", "."})
    void aBufferUriOutsideTheFolderIsRefused(String uri) throws Exception {
        Path inner = Files.createDirectories(dir.resolve("inner"));
        Files.write(dir.resolve("secret.bin"), new byte[16]);
        Files.createDirectories(inner.resolve("sub"));
        String json = doc("{\"byteLength\":16,\"uri\":\"" + uri + "\"}", "");
        GltfException e = assertThrows(GltfException.class, () -> GltfImporter.read(
                new ByteArrayInputStream(json.getBytes(StandardCharsets.UTF_8)), "doc.gltf", inner.resolve("doc.gltf")));
        assertEquals("/buffers/0/uri", e.location(), e::getMessage);
    }

    @Test
    void aBufferUriInsideTheFolderIsRead() throws Exception {
        Files.createDirectories(dir.resolve("data"));
        Files.write(dir.resolve("data/x y.bin"), new byte[16]);
        String json = doc("{\"byteLength\":16,\"uri\":\"data/x%20y.bin\"}", "");
        GltfImporter.read(new ByteArrayInputStream(json.getBytes(StandardCharsets.UTF_8)), "doc.gltf",
                dir.resolve("doc.gltf"));
    }

    @Test
    void aLinkLeadingOutOfTheFolderIsRefused() throws Exception {
        Path inner = Files.createDirectories(dir.resolve("inner"));
        Files.write(dir.resolve("secret.bin"), new byte[16]);
        Files.createSymbolicLink(inner.resolve("link.bin"), dir.resolve("secret.bin"));
        String json = doc("{\"byteLength\":16,\"uri\":\"link.bin\"}", "");
        GltfException e = assertThrows(GltfException.class, () -> GltfImporter.read(
                new ByteArrayInputStream(json.getBytes(StandardCharsets.UTF_8)), "doc.gltf", inner.resolve("doc.gltf")));
        assertEquals("/buffers/0/uri", e.location(), e::getMessage);
    }

    @Test
    void withoutALocationNoFileIsRead() {
        String json = doc("{\"byteLength\":16,\"uri\":\"x.bin\"}", "");
        GltfException e = assertThrows(GltfException.class, () -> GltfImporter.read(
                new ByteArrayInputStream(json.getBytes(StandardCharsets.UTF_8)), "doc.gltf", null));
        assertEquals("/buffers/0/uri", e.location(), e::getMessage);
    }

    // -------------------------------------------------------------------------------------- JSON

    @Test
    void deepNestingIsRefusedWithoutOverflowingTheStack() {
        int depth = 100_000;
        String json = "{\"asset\":{\"version\":\"2.0\"},\"extras\":" + "[".repeat(depth) + "]".repeat(depth) + "}";
        GltfException e = refused(json);
        assertTrue(e.problem().contains("nesting") || e.problem().contains("depth"), e::getMessage);
    }

    @Test
    void aNumberOfThousandsOfDigitsIsRefused() {
        refused("{\"asset\":{\"version\":\"2.0\"},\"scene\":" + "9".repeat(5000) + "}");
    }

    @Test
    void aDuplicateKeyIsRefused() {
        GltfException e = refused("{\"asset\":{\"version\":\"2.0\"},\"scene\":0,\"scene\":1}");
        assertTrue(e.problem().contains("scene"), e::getMessage);
    }

    // ------------------------------------------------------------------------------------ images

    @Test
    void imagesAreNeverDecoded() throws Exception {
        // A PNG header claiming 65535 x 65535 pixels (16 GB of RGBA): decoding it would show.
        ByteBuffer png = ByteBuffer.allocate(33);
        png.put(new byte[] {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'}).putInt(13).put("IHDR".getBytes(
                StandardCharsets.US_ASCII)).putInt(65535).putInt(65535).put((byte) 8).put((byte) 6);
        String uri = "data:image/png;base64," + Base64.getEncoder().encodeToString(png.array());
        String json = "{\"asset\":{\"version\":\"2.0\"},\"images\":[{\"uri\":\"" + uri + "\"}],"
                + "\"textures\":[{\"source\":0}],\"materials\":[{\"pbrMetallicRoughness\":{\"baseColorTexture\":"
                + "{\"index\":0}}}]}";
        long before = allocatedBytes();
        GltfImporter.read(new ByteArrayInputStream(json.getBytes(StandardCharsets.UTF_8)), "image.gltf",
                dir.resolve("image.gltf"));
        assertTrue(allocatedBytes() - before < SMALL, "the importer decoded the image");
    }
}
