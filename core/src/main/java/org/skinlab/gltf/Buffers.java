package org.skinlab.gltf;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;

/**
 * The document's buffers ({@code /buffers}) and buffer views ({@code /bufferViews}), each checked
 * once: a buffer's data (GLB BIN chunk, data URI or file) must hold its declared
 * {@code byteLength}, at most {@link GltfLimits#MAX_FILE_BYTES}; a view's range must lie inside
 * its buffer. Views are little-endian {@link ByteBuffer}s over the shared bytes (no copies).
 *
 * <p>A placeholder buffer (no uri, and not a .glb's first buffer) refuses the file only when
 * something reads it: an unused placeholder is valid glTF. A buffer whose uri is refused (it
 * leaves the document's folder, has a scheme, is a broken data URI) or names no file, or whose
 * data are shorter than its byteLength, refuses the file whether used or not, as the
 * glTF-Validator reports it. Nothing is ever fetched from outside the document's folder.
 */
final class Buffers {
    private final GltfContext ctx;
    private final JsonNode views;
    private final ByteBuffer[] buffers;
    private final GltfException[] bufferErrors;
    private final int[] viewStrides;
    private final ByteBuffer[] viewData;
    private final GltfException[] viewErrors;

    Buffers(GltfContext ctx, JsonNode root, GlbContainer container, UriResolver uris) throws GltfException {
        this.ctx = ctx;
        JsonNode list = root.get("buffers").arrayOrMissing();
        buffers = new ByteBuffer[list.size()];
        bufferErrors = new GltfException[buffers.length];
        int[] declared = new int[buffers.length];
        for (int i = 0; i < buffers.length; i++) {
            declared[i] = list.get(i).get("byteLength").integer(1, GltfLimits.MAX_FILE_BYTES);
            if (isPlaceholder(list.get(i), i, container)) {
                bufferErrors[i] = list.get(i).error("a buffer without uri must be the first buffer of a .glb with a"
                        + " BIN chunk");
            } else {
                buffers[i] = load(list.get(i), i, container, uris);
            }
        }
        views = root.get("bufferViews").arrayOrMissing();
        viewStrides = new int[views.size()];
        viewData = new ByteBuffer[views.size()];
        viewErrors = new GltfException[views.size()];
        for (int i = 0; i < viewData.length; i++) {
            viewData[i] = view(views.get(i), i, declared);
        }
    }

    /** A buffer without uri that is not the first of a .glb (whose data would be the BIN chunk). */
    private static boolean isPlaceholder(JsonNode buffer, int index, GlbContainer container) throws GltfException {
        return !buffer.has("uri") && !(container.glb && index == 0);
    }

    private ByteBuffer load(JsonNode buffer, int index, GlbContainer container, UriResolver uris)
            throws GltfException {
        JsonNode lengthNode = buffer.get("byteLength");
        int length = lengthNode.integer(1, GltfLimits.MAX_FILE_BYTES);
        String uri = buffer.get("uri").string(null);
        JsonNode uriNode = buffer.get("uri");
        ByteBuffer data;
        if (uri == null) {
            if (!container.glb || index != 0 || container.binOffset < 0) {
                throw buffer.error("a buffer without uri must be the first buffer of a .glb with a BIN chunk");
            }
            data = ByteBuffer.wrap(container.bytes, container.binOffset, container.binLength).slice();
            if (container.binLength > length + 3L) {
                ctx.warn(lengthNode.path(), "the BIN chunk has " + container.binLength + " bytes, more than "
                        + length + " and its padding");
            }
        } else if (UriResolver.isDataUri(uri)) {
            data = ByteBuffer.wrap(uris.decodeData(uri, uriNode.path(), GltfLimits.MAX_FILE_BYTES));
        } else {
            data = ByteBuffer.wrap(uris.readFile(uri, uriNode.path(), GltfLimits.MAX_FILE_BYTES));
            ctx.addDocumentBytes(data.capacity());
        }
        if (data.remaining() < length) {
            throw ctx.error(lengthNode.path(), "byteLength " + length + " but the data has " + data.remaining()
                    + " bytes");
        }
        data.limit(data.position() + length);
        return data.slice().order(ByteOrder.LITTLE_ENDIAN);
    }

    private ByteBuffer view(JsonNode view, int index, int[] declared) throws GltfException {
        int buffer = view.get("buffer").index(buffers.length, "buffers");
        long offset = view.get("byteOffset").integer(0, Integer.MAX_VALUE, 0);
        long length = view.get("byteLength").integer(1, Integer.MAX_VALUE);
        JsonNode stride = view.get("byteStride");
        viewStrides[index] = stride.integer(4, 252, 0);
        if (viewStrides[index] % 4 != 0) {
            throw stride.error("byteStride " + viewStrides[index] + " is not a multiple of 4");
        }
        int bufferLength = declared[buffer];
        if (offset + length > bufferLength) {
            throw view.error("bytes [" + offset + ", " + (offset + length) + ") lie outside buffer " + buffer + " of "
                    + bufferLength + " bytes");
        }
        if (buffers[buffer] == null) {
            viewErrors[index] = bufferErrors[buffer];
            return null;
        }
        ByteBuffer b = buffers[buffer].duplicate();
        b.position((int) offset).limit((int) (offset + length));
        return b.slice().order(ByteOrder.LITTLE_ENDIAN);
    }

    int viewCount() {
        return viewData.length;
    }

    /** Whether the view's buffer has data (it is not an unused placeholder's). */
    boolean hasData(int index) {
        return viewErrors[index] == null;
    }

    /** A view's bytes (a duplicate; absolute gets only); refused when its buffer's data could not be had. */
    ByteBuffer view(int index) throws GltfException {
        if (viewErrors[index] != null) {
            throw viewErrors[index];
        }
        return viewData[index].duplicate().order(ByteOrder.LITTLE_ENDIAN);
    }

    /** A view's declared byteLength. */
    int viewLength(int index) throws GltfException {
        return views.get(index).get("byteLength").integer(1, Integer.MAX_VALUE);
    }

    /** The view's byteStride, or 0 when it declares none. */
    int stride(int index) {
        return viewStrides[index];
    }

    /** The JSON path of a view, for messages. */
    String viewPath(int index) {
        return views.path() + "/" + index;
    }

    /** A copy of a view's bytes (embedded images). */
    byte[] copy(int index) throws GltfException {
        ByteBuffer b = view(index);
        byte[] out = new byte[b.remaining()];
        b.get(out);
        return out;
    }
}
