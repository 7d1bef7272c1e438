package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;

/**
 * Accessor decoding against values worked out by hand from the specification: every component
 * type, normalized integers ("Animations" / "Accessor Data Types": signed
 * {@code max(c / (2^(n-1)-1), -1)}, unsigned {@code c / (2^n - 1)}), interleaved views, sparse
 * substitution, padded matrix columns, and size checks that name the JSON path.
 */
class GltfAccessorTest {
    private static Accessors accessors(GltfFixture f) throws GltfException {
        byte[] json = f.gltf("").getBytes(StandardCharsets.UTF_8);
        GltfContext ctx = new GltfContext("test.gltf");
        JsonNode root = JsonTree.parse(ctx, json, 0, json.length);
        return new Accessors(ctx, root, new Buffers(ctx, root, null, new UriResolver(ctx, null)));
    }

    @Test
    void everyComponentTypeAsIs() throws Exception {
        GltfFixture f = new GltfFixture();
        int b = f.accessor(AccessorFormat.BYTE, "VEC2", false, -128, 127);
        int ub = f.accessor(AccessorFormat.UNSIGNED_BYTE, "VEC2", false, 0, 255);
        int s = f.accessor(AccessorFormat.SHORT, "VEC2", false, -32768, 32767);
        int us = f.accessor(AccessorFormat.UNSIGNED_SHORT, "VEC2", false, 0, 65535);
        int ui = f.accessor(AccessorFormat.UNSIGNED_INT, "VEC2", false, 7, 4000000000.0);
        int fl = f.floats("VEC2", -1.5, 2.25);
        Accessors a = accessors(f);
        assertArrayEquals(new float[] {-128, 127}, a.floats(b));
        assertArrayEquals(new float[] {0, 255}, a.floats(ub));
        assertArrayEquals(new float[] {-32768, 32767}, a.floats(s));
        assertArrayEquals(new float[] {0, 65535}, a.floats(us));
        assertArrayEquals(new float[] {7, 4e9f}, a.floats(ui));
        assertArrayEquals(new float[] {-1.5f, 2.25f}, a.floats(fl));
        assertArrayEquals(new int[] {0, 255}, a.ints(ub));
        assertArrayEquals(new int[] {0, 65535}, a.ints(us));
    }

    @Test
    void normalizedIntegersFollowTheSpecificationsFormulas() throws Exception {
        GltfFixture f = new GltfFixture();
        int b = f.accessor(AccessorFormat.BYTE, "VEC4", true, -128, -127, 64, 127);
        int ub = f.accessor(AccessorFormat.UNSIGNED_BYTE, "VEC4", true, 0, 1, 128, 255);
        int s = f.accessor(AccessorFormat.SHORT, "VEC4", true, -32768, -32767, 16384, 32767);
        int us = f.accessor(AccessorFormat.UNSIGNED_SHORT, "VEC4", true, 0, 1, 32768, 65535);
        Accessors a = accessors(f);
        assertArrayEquals(new float[] {-1f, -1f, 64 / 127f, 1f}, a.floats(b));
        assertArrayEquals(new float[] {0f, 1 / 255f, 128 / 255f, 1f}, a.floats(ub));
        assertArrayEquals(new float[] {-1f, -1f, 16384 / 32767f, 1f}, a.floats(s));
        assertArrayEquals(new float[] {0f, 1 / 65535f, 32768 / 65535f, 1f}, a.floats(us));
    }

    @Test
    void interleavedViewIsReadWithItsStride() throws Exception {
        GltfFixture f = new GltfFixture();
        // Two records of (VEC3 float position, VEC2 unsigned short texcoord, 4 bytes padding): 20 bytes each.
        java.nio.ByteBuffer bytes = java.nio.ByteBuffer.allocate(40).order(java.nio.ByteOrder.LITTLE_ENDIAN);
        bytes.putFloat(1).putFloat(2).putFloat(3).putShort((short) 10).putShort((short) 20).putInt(-1);
        bytes.putFloat(4).putFloat(5).putFloat(6).putShort((short) 30).putShort((short) 40).putInt(-1);
        int view = f.view(bytes.array(), 20);
        int pos = f.accessor("{\"bufferView\":" + view + ",\"componentType\":5126,\"type\":\"VEC3\",\"count\":2}");
        int uv = f.accessor("{\"bufferView\":" + view + ",\"byteOffset\":12,\"componentType\":5123,\"type\":\"VEC2\","
                + "\"count\":2}");
        Accessors a = accessors(f);
        assertArrayEquals(new float[] {1, 2, 3, 4, 5, 6}, a.floats(pos));
        assertArrayEquals(new float[] {10, 20, 30, 40}, a.floats(uv));
    }

    @Test
    void sparseValuesReplaceTheBaseOrZeros() throws Exception {
        GltfFixture f = new GltfFixture();
        int base = f.floats("SCALAR", 1, 2, 3, 4, 5);
        int indices = f.view(GltfFixture.encode(AccessorFormat.UNSIGNED_SHORT, 1, 3), 0);
        int values = f.view(GltfFixture.encode(AccessorFormat.FLOAT, 20, 40), 0);
        String sparse = ",\"sparse\":{\"count\":2,\"indices\":{\"bufferView\":" + indices
                + ",\"componentType\":5123},\"values\":{\"bufferView\":" + values + "}}}";
        int onBase = f.accessor("{\"bufferView\":0,\"componentType\":5126,\"type\":\"SCALAR\",\"count\":5" + sparse);
        int onZeros = f.accessor("{\"componentType\":5126,\"type\":\"SCALAR\",\"count\":5" + sparse);
        Accessors a = accessors(f);
        assertArrayEquals(new float[] {1, 2, 3, 4, 5}, a.floats(base), "the base accessor is untouched");
        assertArrayEquals(new float[] {1, 20, 3, 40, 5}, a.floats(onBase));
        assertArrayEquals(new float[] {0, 20, 0, 40, 0}, a.floats(onZeros));
    }

    @Test
    void sparseIndicesMustIncrease() throws Exception {
        GltfFixture f = new GltfFixture();
        int indices = f.view(GltfFixture.encode(AccessorFormat.UNSIGNED_BYTE, 3, 1), 0);
        int values = f.view(GltfFixture.encode(AccessorFormat.FLOAT, 20, 40), 0);
        int acc = f.accessor("{\"componentType\":5126,\"type\":\"SCALAR\",\"count\":5,\"sparse\":{\"count\":2,"
                + "\"indices\":{\"bufferView\":" + indices + ",\"componentType\":5121},\"values\":{\"bufferView\":"
                + values + "}}}");
        GltfException e = assertThrows(GltfException.class, () -> accessors(f).floats(acc));
        assertEquals("/accessors/" + acc + "/sparse/indices", e.path());
    }

    @Test
    void matrixColumnsOfBytesArePaddedToFourBytes() throws Exception {
        GltfFixture f = new GltfFixture();
        // MAT2 of signed bytes: columns (1, 2) and (3, 4), each padded to 4 bytes.
        int view = f.view(new byte[] {1, 2, 0, 0, 3, 4, 0, 0}, 0);
        int acc = f.accessor("{\"bufferView\":" + view + ",\"componentType\":5120,\"type\":\"MAT2\",\"count\":1}");
        assertArrayEquals(new float[] {1, 2, 3, 4}, accessors(f).floats(acc));
    }

    @Test
    void theLastMatrixNeedsNoPaddingAfterItsLastColumn() throws Exception {
        GltfFixture f = new GltfFixture();
        // Two MAT3 of unsigned bytes: 12 bytes each with column padding, the last one 11 (23 in all).
        byte[] data = new byte[23];
        for (int e = 0; e < 2; e++) {
            for (int c = 0; c < 9; c++) {
                data[12 * e + 4 * (c / 3) + c % 3] = (byte) (10 * e + c);
            }
        }
        int view = f.view(data, 0);
        int acc = f.accessor("{\"bufferView\":" + view + ",\"componentType\":5121,\"type\":\"MAT3\",\"count\":2}");
        assertArrayEquals(new float[] {0, 1, 2, 3, 4, 5, 6, 7, 8, 10, 11, 12, 13, 14, 15, 16, 17, 18},
                accessors(f).floats(acc));
    }

    @Test
    void countBeyondTheViewIsRefusedBeforeReading() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 1, 1, 1);
        int acc = f.accessor("{\"bufferView\":0,\"componentType\":5126,\"type\":\"VEC3\",\"count\":3}");
        GltfException e = assertThrows(GltfException.class, () -> accessors(f).floats(acc));
        assertEquals("/accessors/1/count", e.path());
        assertEquals("test.gltf: /accessors/1/count: 3 elements of 12 bytes (stride 12) from offset 0 need 36 bytes"
                + " but buffer view 0 has 24", e.getMessage());
    }

    @Test
    void hugeCountWithoutDataIsRefusedBeforeAllocating() throws Exception {
        GltfFixture f = new GltfFixture();
        int acc = f.accessor("{\"componentType\":5126,\"type\":\"MAT4\",\"count\":2000000000}");
        GltfException e = assertThrows(GltfException.class, () -> accessors(f).floats(acc));
        assertEquals("/accessors/0/count", e.path());
    }

    @Test
    void nonFiniteFloatsAreRefused() throws Exception {
        GltfFixture f = new GltfFixture();
        int acc = f.floats("VEC2", 1, Double.NaN);
        GltfException e = assertThrows(GltfException.class, () -> accessors(f).floats(acc));
        assertEquals("test.gltf: /accessors/0: element 0 component 1 is NaN", e.getMessage());
    }
}
