package org.skinlab.gltf;

import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Arrays;

/**
 * The bytes of a document, told apart by content: a binary glTF (GLB: 12-byte header with the
 * magic {@code glTF}, a JSON chunk, an optional BIN chunk) or a JSON text. Every GLB length is
 * checked against the bytes there are before anything is sliced.
 */
final class GlbContainer {
    static final int MAGIC = 0x46546C67; // "glTF" little-endian
    private static final int CHUNK_JSON = 0x4E4F534A;
    private static final int CHUNK_BIN = 0x004E4942;
    private static final String HEADER = "(GLB header)";

    final byte[] bytes;
    final int jsonOffset;
    final int jsonLength;
    /** The BIN chunk's offset in {@link #bytes}, or -1 when there is none. */
    final int binOffset;
    final int binLength;
    final boolean glb;

    private GlbContainer(boolean glb, byte[] bytes, int jsonOffset, int jsonLength, int binOffset, int binLength) {
        this.glb = glb;
        this.bytes = bytes;
        this.jsonOffset = jsonOffset;
        this.jsonLength = jsonLength;
        this.binOffset = binOffset;
        this.binLength = binLength;
    }

    /** Reads the whole stream (at most {@link GltfLimits#MAX_FILE_BYTES}) and splits it. */
    static GlbContainer read(GltfContext ctx, InputStream in) throws IOException, GltfException {
        byte[] bytes = readAll(ctx, in);
        if (bytes.length >= 4 && ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN).getInt(0) == MAGIC) {
            return glb(ctx, bytes);
        }
        int start = byteOrderMark(ctx, bytes, 0, bytes.length);
        return new GlbContainer(false, bytes, start, bytes.length - start, -1, 0);
    }

    /**
     * 3 when the JSON at {@code offset} starts with a UTF-8 byte order mark, which JSON forbids but
     * editors write (skipped with a warning), else 0.
     */
    private static int byteOrderMark(GltfContext ctx, byte[] bytes, int offset, long length) {
        if (length >= 3 && (bytes[offset] & 0xff) == 0xEF && (bytes[offset + 1] & 0xff) == 0xBB
                && (bytes[offset + 2] & 0xff) == 0xBF) {
            ctx.warn("", "the JSON starts with a UTF-8 byte order mark; skipped");
            return 3;
        }
        return 0;
    }

    /**
     * The stream's bytes. The buffer starts at the size the stream says it has left (exact for
     * in-memory and file streams), so a document is read without growing or trimming copies.
     */
    private static byte[] readAll(GltfContext ctx, InputStream in) throws IOException, GltfException {
        byte[] buf = new byte[Math.max(1 << 16, Math.min(in.available(), GltfLimits.MAX_FILE_BYTES))];
        int n = 0;
        for (int r; (r = in.read(buf, n, buf.length - n)) != -1;) {
            n += r;
            if (n == buf.length) {
                int next = in.read();
                if (next < 0) {
                    return buf;
                }
                if (buf.length >= GltfLimits.MAX_FILE_BYTES) {
                    throw ctx.error("", "the file is larger than " + GltfLimits.MAX_FILE_BYTES + " bytes");
                }
                buf = Arrays.copyOf(buf, (int) Math.min((long) buf.length * 2, GltfLimits.MAX_FILE_BYTES));
                buf[n++] = (byte) next;
            }
        }
        return n == buf.length ? buf : Arrays.copyOf(buf, n);
    }

    private static GlbContainer glb(GltfContext ctx, byte[] bytes) throws GltfException {
        ByteBuffer b = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
        if (bytes.length < 12) {
            throw ctx.error(HEADER, "the GLB file has " + bytes.length + " bytes, fewer than its 12-byte header");
        }
        int version = b.getInt(4);
        if (version != 2) {
            throw ctx.error(HEADER, "GLB version " + Integer.toUnsignedString(version) + " is not 2");
        }
        if (bytes.length < 20) {
            throw ctx.error(HEADER, "the GLB file has " + bytes.length + " bytes, fewer than a header and a chunk header");
        }
        long length = Integer.toUnsignedLong(b.getInt(8));
        if (length > bytes.length || length < 20) {
            throw ctx.error(HEADER, "the header says " + length + " bytes but the file has " + bytes.length);
        }
        if (length < bytes.length) {
            ctx.warn(HEADER, (bytes.length - length) + " bytes after the " + length + " the header declares; ignored");
            bytes = Arrays.copyOf(bytes, (int) length);
            b = ByteBuffer.wrap(bytes).order(ByteOrder.LITTLE_ENDIAN);
        }
        long jsonLength = Integer.toUnsignedLong(b.getInt(12));
        if (b.getInt(16) != CHUNK_JSON) {
            throw ctx.error("(GLB chunk 0)", "the first chunk is not JSON (type 0x"
                    + Integer.toHexString(b.getInt(16)) + ")");
        }
        if (jsonLength > bytes.length - 20L) {
            throw ctx.error("(GLB chunk 0)", "the JSON chunk claims " + jsonLength + " bytes but "
                    + (bytes.length - 20) + " follow");
        }
        warnIfUnaligned(ctx, "(GLB chunk 0)", jsonLength);
        int binOffset = -1;
        int binLength = 0;
        long at = 20 + jsonLength;
        for (int chunk = 1; at < bytes.length; chunk++) {
            String where = "(GLB chunk " + chunk + ")";
            if (bytes.length - at < 8) {
                throw ctx.error(where, (bytes.length - at) + " bytes left, fewer than a chunk header");
            }
            long chunkLength = Integer.toUnsignedLong(b.getInt((int) at));
            int type = b.getInt((int) at + 4);
            if (chunkLength > bytes.length - at - 8) {
                throw ctx.error(where, "the chunk claims " + chunkLength + " bytes but " + (bytes.length - at - 8)
                        + " follow");
            }
            warnIfUnaligned(ctx, where, chunkLength);
            if (type == CHUNK_BIN && chunk == 1) {
                binOffset = (int) at + 8;
                binLength = (int) chunkLength;
            } else if (type == CHUNK_BIN || type == CHUNK_JSON) {
                throw ctx.error(where, "a second " + (type == CHUNK_BIN ? "BIN" : "JSON")
                        + " chunk, or a BIN chunk not right after the JSON one");
            } else {
                ctx.warn(where, "unknown chunk type 0x" + Integer.toHexString(type) + "; skipped");
            }
            at += 8 + chunkLength;
        }
        int start = byteOrderMark(ctx, bytes, 20, jsonLength);
        return new GlbContainer(true, bytes, 20 + start, (int) jsonLength - start, binOffset, binLength);
    }

    /** The specification pads every chunk to 4 bytes; readers cope without, so only a warning. */
    private static void warnIfUnaligned(GltfContext ctx, String where, long chunkLength) {
        if (chunkLength % 4 != 0) {
            ctx.warn(where, "the chunk's length " + chunkLength + " is not a multiple of 4 (chunks are padded)");
        }
    }
}
