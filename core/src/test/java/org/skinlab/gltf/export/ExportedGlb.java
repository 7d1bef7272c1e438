package org.skinlab.gltf.export;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

/**
 * A GLB read back for tests, apart from the importer (which ignores what the export adds): its
 * JSON as a databind tree and float accessors out of its binary chunk.
 */
final class ExportedGlb {
    final JsonNode json;
    private final ByteBuffer bin;

    ExportedGlb(byte[] glb) throws IOException {
        ByteBuffer b = ByteBuffer.wrap(glb).order(ByteOrder.LITTLE_ENDIAN);
        if (b.getInt(0) != 0x46546C67 || b.getInt(4) != 2 || b.getInt(8) != glb.length) {
            throw new IOException("not a GLB 2 of " + glb.length + " bytes");
        }
        int jsonLength = b.getInt(12);
        if (b.getInt(16) != 0x4E4F534A) {
            throw new IOException("first chunk is not JSON");
        }
        json = new ObjectMapper().readTree(new String(glb, 20, jsonLength, StandardCharsets.UTF_8));
        int binStart = 20 + jsonLength;
        int binLength = b.getInt(binStart);
        if (b.getInt(binStart + 4) != 0x004E4942) {
            throw new IOException("second chunk is not BIN");
        }
        bin = ByteBuffer.wrap(glb, binStart + 8, binLength).slice().order(ByteOrder.LITTLE_ENDIAN);
    }

    /** A FLOAT accessor's values, tightly packed ({@code width} per element). */
    float[] floats(int accessor, int width) {
        JsonNode a = json.get("accessors").get(accessor);
        if (a.get("componentType").asInt() != 5126) {
            throw new IllegalArgumentException("accessor " + accessor + " is not FLOAT");
        }
        JsonNode view = json.get("bufferViews").get(a.get("bufferView").asInt());
        int offset = view.path("byteOffset").asInt(0) + a.path("byteOffset").asInt(0);
        float[] out = new float[a.get("count").asInt() * width];
        for (int i = 0; i < out.length; i++) {
            out[i] = bin.getFloat(offset + 4 * i);
        }
        return out;
    }
}
