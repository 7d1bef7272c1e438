package org.skinlab.gltf;

import static org.skinlab.gltf.AccessorFormat.BYTE;
import static org.skinlab.gltf.AccessorFormat.FLOAT;
import static org.skinlab.gltf.AccessorFormat.SHORT;
import static org.skinlab.gltf.AccessorFormat.UNSIGNED_BYTE;
import static org.skinlab.gltf.AccessorFormat.UNSIGNED_INT;
import static org.skinlab.gltf.AccessorFormat.UNSIGNED_SHORT;

import java.nio.ByteBuffer;
import java.util.HashMap;
import java.util.Locale;
import java.util.Map;

/**
 * Decodes accessors ({@code /accessors}) into flat arrays: every component type, normalized
 * integers by the specification's formulas (signed: {@code max(c / (2^(n-1) - 1), -1)}, unsigned:
 * {@code c / (2^n - 1)}), interleaved views ({@code byteStride}), matrix columns padded to 4
 * bytes, and sparse substitution. Declared sizes are checked against the view and against
 * {@link GltfLimits#MAX_ACCESSOR_VALUES} before the result is allocated (for every accessor when
 * the document is opened, used or not); min/max are not trusted
 * (not read). Float components must be finite. Results are cached (primitives share accessors)
 * and shared: callers read them and never write them.
 */
final class Accessors {

    private final GltfContext ctx;
    private final JsonNode accessors;
    private final Buffers buffers;
    private final Map<Integer, float[]> floats = new HashMap<>();
    private final Map<Integer, int[]> ints = new HashMap<>();

    Accessors(GltfContext ctx, JsonNode root, Buffers buffers) throws GltfException {
        this.ctx = ctx;
        this.accessors = root.get("accessors").arrayOrMissing();
        this.buffers = buffers;
        for (int i = 0; i < accessors.size(); i++) {
            // Every accessor's declared layout, used or not, checked once (nothing allocated). One
            // of a type the specification does not list can only be refused where it is used.
            JsonNode a = accessors.get(i);
            if (a.get("type").string("").matches("SCALAR|VEC[234]|MAT[234]")
                    && a.get("componentType").integer(0, Integer.MAX_VALUE, 0) >= BYTE
                    && a.get("componentType").integer(0, Integer.MAX_VALUE, 0) <= FLOAT
                    && a.get("componentType").integer(0, Integer.MAX_VALUE, 0) != 5124) {
                layout(i);
            } else {
                ctx.warn(a.path(), "unknown type or component type; refused if anything uses it");
            }
        }
    }

    int count() throws GltfException {
        return accessors.size();
    }

    /** The accessor an index property (e.g. {@code attributes/POSITION}) names. */
    int resolve(JsonNode reference) throws GltfException {
        return reference.index(accessors.size(), "accessors");
    }

    JsonNode node(int accessor) throws GltfException {
        return accessors.get(accessor);
    }

    /** The accessor's element count. */
    int elementCount(int accessor) throws GltfException {
        return node(accessor).get("count").integer(1, Integer.MAX_VALUE);
    }

    /** Components per element of the accessor's type (SCALAR 1 ... MAT4 16). */
    int components(int accessor) throws GltfException {
        return components(node(accessor).get("type"));
    }

    /**
     * Checks the accessor's type and format for a use: {@code formats} lists the allowed
     * component types, a trailing "n" for normalized ones (e.g. "5121n").
     */
    void expect(int accessor, String usePath, String type, String... formats) throws GltfException {
        JsonNode a = node(accessor);
        String actualType = a.get("type").string();
        if (!actualType.equals(type)) {
            throw ctx.error(usePath, "accessor " + accessor + " is " + actualType + ", not " + type);
        }
        String format = a.get("componentType").integer(0, Integer.MAX_VALUE)
                + (a.get("normalized").bool(false) ? "n" : "");
        for (String f : formats) {
            if (f.equals(format)) {
                return;
            }
        }
        throw ctx.error(usePath, "accessor " + accessor + " has component type " + describe(format)
                + "; allowed here: " + describeAll(formats));
    }

    /** The accessor decoded to floats (normalized integers mapped, others converted). */
    float[] floats(int accessor) throws GltfException {
        float[] cached = floats.get(accessor);
        if (cached == null) {
            cached = decode(accessor);
            floats.put(accessor, cached);
        }
        return cached;
    }

    /**
     * The accessor's integer values (indices, joints), which must be unsigned and not normalized;
     * unsigned ints of 2^31 - 1 and more read as {@code Integer.MAX_VALUE} (beyond any count).
     */
    int[] ints(int accessor) throws GltfException {
        int[] cached = ints.get(accessor);
        if (cached == null) {
            JsonNode a = node(accessor);
            int type = a.get("componentType").integer(0, Integer.MAX_VALUE);
            if (type != UNSIGNED_BYTE && type != UNSIGNED_SHORT && type != UNSIGNED_INT || a.get("normalized").bool(false)) {
                throw a.get("componentType").error("integer data must be unsigned byte, short or int, not normalized");
            }
            Layout layout = layout(accessor);
            ctx.charge(layout.values(), a.path());
            cached = new int[layout.values()];
            if (layout.view >= 0) {
                readInts(buffers.view(layout.view), layout, type, cached);
                for (int i = 0; type == UNSIGNED_INT && i < cached.length; i++) {
                    cached[i] = cached[i] < 0 ? Integer.MAX_VALUE : cached[i];
                }
            }
            Sparse sparse = sparse(accessor, layout);
            for (int s = 0; sparse != null && s < sparse.indices.length; s++) {
                for (int c = 0; c < layout.components; c++) {
                    cached[sparse.indices[s] * layout.components + c] = (int) Math.min(Integer.MAX_VALUE,
                            integer(sparse.values, (s * layout.components + c) * layout.componentSize, type));
                }
            }
            ints.put(accessor, cached);
        }
        return cached;
    }

    private float[] decode(int accessor) throws GltfException {
        JsonNode a = node(accessor);
        int type = a.get("componentType").integer(0, Integer.MAX_VALUE);
        boolean normalized = a.get("normalized").bool(false);
        if (normalized && (type == FLOAT || type == UNSIGNED_INT)) {
            throw a.get("normalized").error("only byte and short components can be normalized");
        }
        Layout layout = layout(accessor);
        ctx.charge(layout.values(), a.path());
        float[] out = new float[layout.values()];
        if (layout.view >= 0 && type == FLOAT && layout.isPacked()) {
            // Tightly packed floats (most files' positions, normals, texture coordinates): one bulk copy.
            ByteBuffer b = buffers.view(layout.view);
            b.position(layout.offset);
            b.asFloatBuffer().get(out);
        } else if (layout.view >= 0 && !normalized && type != FLOAT) {
            // Integers (joints, indices, key frames read as numbers).
            int[] values = new int[out.length];
            readInts(buffers.view(layout.view), layout, type, values);
            for (int i = 0; i < out.length; i++) {
                out[i] = type == UNSIGNED_INT ? Integer.toUnsignedLong(values[i]) : values[i];
            }
        } else if (layout.view >= 0) {
            ByteBuffer b = buffers.view(layout.view);
            for (int e = 0; e < layout.count; e++) {
                for (int c = 0; c < layout.components; c++) {
                    out[e * layout.components + c] = component(b, layout.byteOf(e, c), type, normalized);
                }
            }
        }
        Sparse sparse = sparse(accessor, layout);
        for (int s = 0; sparse != null && s < sparse.indices.length; s++) {
            for (int c = 0; c < layout.components; c++) {
                out[sparse.indices[s] * layout.components + c] = component(sparse.values,
                        (s * layout.components + c) * layout.componentSize, type, normalized);
            }
        }
        if (type == FLOAT) {
            for (int i = 0; i < out.length; i++) {
                if (!Float.isFinite(out[i])) {
                    throw a.error("element " + i / layout.components + " component " + i % layout.components + " is "
                            + out[i]);
                }
            }
        }
        return out;
    }

    private static float component(ByteBuffer b, int at, int type, boolean normalized) {
        switch (type) {
            case BYTE:
                return normalized ? Math.max(b.get(at) / 127f, -1f) : b.get(at);
            case UNSIGNED_BYTE:
                return normalized ? (b.get(at) & 0xff) / 255f : b.get(at) & 0xff;
            case SHORT:
                return normalized ? Math.max(b.getShort(at) / 32767f, -1f) : b.getShort(at);
            case UNSIGNED_SHORT:
                return normalized ? (b.getShort(at) & 0xffff) / 65535f : b.getShort(at) & 0xffff;
            case UNSIGNED_INT:
                return Integer.toUnsignedLong(b.getInt(at));
            default:
                return b.getFloat(at);
        }
    }

    /**
     * The integers as stored: signed types sign-extended, unsigned bytes and shorts zero-extended,
     * unsigned ints as their bits (the caller maps those of 2^31 and more).
     */
    private static void readInts(ByteBuffer b, Layout layout, int type, int[] out) {
        int n = layout.components;
        if (layout.rows != n) {
            for (int e = 0; e < layout.count; e++) {
                for (int c = 0; c < n; c++) {
                    out[e * n + c] = stored(b, layout.byteOf(e, c), type);
                }
            }
        } else if (type == UNSIGNED_INT && layout.stride == 4 * n) {
            b.position(layout.offset);
            b.asIntBuffer().get(out);
        } else {
            for (int e = 0, i = 0; e < layout.count; e++, i += n) {
                int at = layout.offset + e * layout.stride;
                for (int c = 0; c < n; c++) {
                    out[i + c] = stored(b, at + c * layout.componentSize, type);
                }
            }
        }
    }

    /** One integer component as stored (unsigned ints as their bits). */
    private static int stored(ByteBuffer b, int at, int type) {
        switch (type) {
            case BYTE:
                return b.get(at);
            case UNSIGNED_BYTE:
                return b.get(at) & 0xff;
            case SHORT:
                return b.getShort(at);
            case UNSIGNED_SHORT:
                return b.getShort(at) & 0xffff;
            default:
                return b.getInt(at);
        }
    }

    /** The largest value of an unsigned index type: the primitive restart value glTF forbids in indices. */
    static long restartValue(int componentType) {
        return componentType == UNSIGNED_BYTE ? 0xffL : componentType == UNSIGNED_SHORT ? 0xffffL : 0xffffffffL;
    }

    private static long integer(ByteBuffer b, int at, int type) {
        switch (type) {
            case UNSIGNED_BYTE:
                return b.get(at) & 0xff;
            case UNSIGNED_SHORT:
                return b.getShort(at) & 0xffff;
            default:
                return Integer.toUnsignedLong(b.getInt(at));
        }
    }

    /** Where each element's components lie, checked against the view. */
    private Layout layout(int accessor) throws GltfException {
        JsonNode a = node(accessor);
        JsonNode typeNode = a.get("componentType");
        int componentSize = componentSize(typeNode);
        int components = components(a.get("type"));
        int count = elementCount(accessor);
        if ((long) count * components > GltfLimits.MAX_ACCESSOR_VALUES) {
            throw a.get("count").error(count + " elements of " + components + " components exceed the limit of "
                    + GltfLimits.MAX_ACCESSOR_VALUES + " values");
        }
        // Matrix columns start on 4-byte boundaries (glTF 2.0, "Data Alignment"); a vector is one column.
        String type = a.get("type").string();
        int componentType = typeNode.integer(0, Integer.MAX_VALUE);
        int rows = AccessorFormat.rows(type);
        int columnStride = AccessorFormat.columnStride(type, componentType);
        int elementSize = AccessorFormat.elementSize(type, componentType);
        JsonNode viewNode = a.get("bufferView");
        if (viewNode.isMissing()) {
            if (a.has("byteOffset")) {
                throw a.get("byteOffset").error("byteOffset without a bufferView");
            }
            return new Layout(-1, 0, 0, count, components, rows, columnStride, componentSize);
        }
        int view = viewNode.index(buffers.viewCount(), "bufferViews");
        long offset = a.get("byteOffset").integer(0, Integer.MAX_VALUE, 0);
        int stride = buffers.stride(view) == 0 ? elementSize : buffers.stride(view);
        if (stride < elementSize) {
            throw ctx.error(buffers.viewPath(view) + "/byteStride", "byteStride " + stride + " is smaller than the "
                    + elementSize + "-byte elements of accessor " + accessor);
        }
        if (offset % componentSize != 0) {
            throw a.get("byteOffset").error("byteOffset " + offset + " is not a multiple of the component size "
                    + componentSize);
        }
        // The last column's padding need not be there: it is never read (as the validator reads it).
        long end = offset + (long) stride * (count - 1) + elementSize - AccessorFormat.trailingPadding(type, componentType);
        int viewLength = buffers.viewLength(view);
        if (end > viewLength) {
            throw a.get("count").error(count + " elements of " + elementSize + " bytes (stride " + stride + ") from offset "
                    + offset + " need " + end + " bytes but buffer view " + view + " has " + viewLength);
        }
        return new Layout(view, (int) offset, stride, count, components, rows, columnStride, componentSize);
    }

    private Sparse sparse(int accessor, Layout layout) throws GltfException {
        JsonNode sparse = node(accessor).get("sparse");
        if (sparse.isMissing()) {
            return null;
        }
        int n = sparse.get("count").integer(1, layout.count);
        JsonNode indices = sparse.get("indices");
        int indexType = indices.get("componentType").integer(0, Integer.MAX_VALUE);
        if (indexType != UNSIGNED_BYTE && indexType != UNSIGNED_SHORT && indexType != UNSIGNED_INT) {
            throw indices.get("componentType").error("sparse indices must be unsigned byte, short or int");
        }
        int indexSize = componentSize(indices.get("componentType"));
        ByteBuffer indexData = sparseData(indices, (long) n * indexSize);
        int[] at = new int[n];
        for (int s = 0; s < n; s++) {
            long i = integer(indexData, s * indexSize, indexType);
            if (i >= layout.count || s > 0 && i <= at[s - 1]) {
                throw indices.error("sparse index " + s + " is " + i + ": indices must increase and stay below "
                        + layout.count);
            }
            at[s] = (int) i;
        }
        if (layout.rows != layout.components) {
            throw sparse.error("sparse matrix accessors are not supported");
        }
        ByteBuffer values = sparseData(sparse.get("values"), (long) n * layout.components * layout.componentSize);
        return new Sparse(at, values);
    }

    private ByteBuffer sparseData(JsonNode part, long bytes) throws GltfException {
        int view = part.get("bufferView").index(buffers.viewCount(), "bufferViews");
        long offset = part.get("byteOffset").integer(0, Integer.MAX_VALUE, 0);
        ByteBuffer b = buffers.view(view);
        if (offset + bytes > b.capacity()) {
            throw part.error("needs " + bytes + " bytes from offset " + offset + " but buffer view " + view + " has "
                    + b.capacity());
        }
        b.position((int) offset);
        return b.slice().order(java.nio.ByteOrder.LITTLE_ENDIAN);
    }

    private static int componentSize(JsonNode typeNode) throws GltfException {
        int size = AccessorFormat.componentSize(typeNode.integer(0, Integer.MAX_VALUE));
        if (size == 0) {
            throw typeNode.error("unknown component type " + typeNode.integer(0, Integer.MAX_VALUE));
        }
        return size;
    }

    private static int components(JsonNode typeNode) throws GltfException {
        int components = AccessorFormat.components(typeNode.string());
        if (components == 0) {
            throw typeNode.error("unknown accessor type \"" + typeNode.string() + "\"");
        }
        return components;
    }

    private static String describe(String format) {
        boolean normalized = format.endsWith("n");
        int type = Integer.parseInt(normalized ? format.substring(0, format.length() - 1) : format);
        String[] names = {"byte", "unsigned byte", "short", "unsigned short", "?", "unsigned int", "float"};
        String name = type >= BYTE && type <= FLOAT ? names[type - BYTE] : Integer.toString(type);
        return (normalized ? "normalized " : "") + name;
    }

    private static String describeAll(String[] formats) {
        StringBuilder sb = new StringBuilder();
        for (String f : formats) {
            sb.append(sb.length() == 0 ? "" : ", ").append(describe(f));
        }
        return sb.toString().toLowerCase(Locale.ROOT);
    }

    /** Byte positions of an accessor's elements in its view. */
    private static final class Layout {
        final int view;
        final int offset;
        final int stride;
        final int count;
        final int components;
        final int rows;
        final int columnStride;
        final int componentSize;

        Layout(int view, int offset, int stride, int count, int components, int rows, int columnStride,
                int componentSize) {
            this.view = view;
            this.offset = offset;
            this.stride = stride;
            this.count = count;
            this.components = components;
            this.rows = rows;
            this.columnStride = columnStride;
            this.componentSize = componentSize;
        }

        int values() {
            return count * components;
        }

        /** True when the components follow one another without gaps (no stride padding, no column padding). */
        boolean isPacked() {
            return rows == components ? stride == components * componentSize
                    : columnStride == rows * componentSize && stride == components * componentSize;
        }

        /** Byte of component {@code c} (column-major for matrices) of element {@code e}. */
        int byteOf(int e, int c) {
            return offset + e * stride + (c / rows) * columnStride + (c % rows) * componentSize;
        }
    }

    private static final class Sparse {
        final int[] indices;
        final ByteBuffer values;

        Sparse(int[] indices, ByteBuffer values) {
            this.indices = indices;
            this.values = values;
        }
    }
}
