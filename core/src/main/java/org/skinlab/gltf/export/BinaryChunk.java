package org.skinlab.gltf.export;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import com.fasterxml.jackson.core.JsonGenerator;

/**
 * The GLB's binary chunk and what describes it: one buffer, a buffer view per accessor (each
 * aligned to 4 bytes, so every component type is aligned), and the accessors. Vertex attribute
 * and index views carry their {@code target}; animation and inverse-bind views none, as the
 * specification asks.
 */
final class BinaryChunk {
    static final int FLOAT = 5126;
    static final int UNSIGNED_BYTE = 5121;
    static final int UNSIGNED_SHORT = 5123;
    static final int UNSIGNED_INT = 5125;
    static final int ARRAY_BUFFER = 34962;
    static final int ELEMENT_ARRAY_BUFFER = 34963;

    /** A buffer view. */
    private record View(int offset, int length, int target) {
    }

    /** An accessor of a whole view. */
    private record Accessor(int view, int componentType, int count, String type, float[] min, float[] max) {
    }

    private byte[] data = new byte[1 << 16];
    private int size;
    private final List<View> views = new ArrayList<>();
    private final List<Accessor> accessors = new ArrayList<>();

    /**
     * Adds a float accessor of {@code width} components per element ("SCALAR", "VEC2", ...); with
     * {@code bounds}, its per-component min and max (which POSITION and animation inputs require).
     */
    int floats(float[] values, String type, int width, int target, boolean bounds) {
        int count = values.length / width;
        ByteBuffer b = reserve(4 * values.length);
        for (float v : values) {
            b.putFloat(v);
        }
        float[] min = null;
        float[] max = null;
        if (bounds) {
            min = new float[width];
            max = new float[width];
            Arrays.fill(min, Float.POSITIVE_INFINITY);
            Arrays.fill(max, Float.NEGATIVE_INFINITY);
            for (int i = 0; i < values.length; i++) {
                min[i % width] = Math.min(min[i % width], values[i]);
                max[i % width] = Math.max(max[i % width], values[i]);
            }
        }
        return add(4 * values.length, target, FLOAT, count, type, min, max);
    }

    /** Adds an unsigned integer accessor ({@code componentType} UNSIGNED_BYTE, _SHORT or _INT). */
    int ints(int[] values, String type, int width, int componentType, int target) {
        int bytesPer = componentType == UNSIGNED_BYTE ? 1 : componentType == UNSIGNED_SHORT ? 2 : 4;
        ByteBuffer b = reserve(bytesPer * values.length);
        for (int v : values) {
            if (bytesPer == 1) {
                b.put((byte) v);
            } else if (bytesPer == 2) {
                b.putShort((short) v);
            } else {
                b.putInt(v);
            }
        }
        return add(bytesPer * values.length, target, componentType, values.length / width, type, null, null);
    }

    /** Adds raw bytes (an image) as a buffer view without accessor; returns the view's index. */
    int view(byte[] bytes) {
        reserve(bytes.length).put(bytes);
        return addView(bytes.length, 0);
    }

    private ByteBuffer reserve(int length) {
        int start = (size + 3) & ~3;
        if (start + length > data.length) {
            data = Arrays.copyOf(data, Math.max(start + length, 2 * data.length));
        }
        ByteBuffer b = ByteBuffer.wrap(data, start, length).order(ByteOrder.LITTLE_ENDIAN);
        size = start;
        return b;
    }

    private int add(int length, int target, int componentType, int count, String type, float[] min, float[] max) {
        int view = addView(length, target);
        accessors.add(new Accessor(view, componentType, count, type, min, max));
        return accessors.size() - 1;
    }

    private int addView(int length, int target) {
        views.add(new View(size, length, target));
        size += length;
        return views.size() - 1;
    }

    /** The chunk's length, padded to 4 bytes. */
    int paddedLength() {
        return (size + 3) & ~3;
    }

    void writeTo(OutputStream out) throws IOException {
        out.write(data, 0, size);
        for (int i = size; i < paddedLength(); i++) {
            out.write(0);
        }
    }

    /** {@code accessors}, {@code bufferViews} and {@code buffers}. */
    void writeJson(JsonGenerator g) throws IOException {
        g.writeArrayFieldStart("accessors");
        for (Accessor e : accessors) {
            g.writeStartObject();
            g.writeNumberField("bufferView", e.view);
            g.writeNumberField("componentType", e.componentType);
            g.writeNumberField("count", e.count);
            g.writeStringField("type", e.type);
            if (e.min != null) {
                writeFloats(g, "min", e.min);
                writeFloats(g, "max", e.max);
            }
            g.writeEndObject();
        }
        g.writeEndArray();
        g.writeArrayFieldStart("bufferViews");
        for (View e : views) {
            g.writeStartObject();
            g.writeNumberField("buffer", 0);
            g.writeNumberField("byteOffset", e.offset);
            g.writeNumberField("byteLength", e.length);
            if (e.target != 0) {
                g.writeNumberField("target", e.target);
            }
            g.writeEndObject();
        }
        g.writeEndArray();
        g.writeArrayFieldStart("buffers");
        g.writeStartObject();
        g.writeNumberField("byteLength", paddedLength());
        g.writeEndObject();
        g.writeEndArray();
    }

    static void writeFloats(JsonGenerator g, String name, float[] values) throws IOException {
        g.writeArrayFieldStart(name);
        for (float v : values) {
            g.writeNumber(v);
        }
        g.writeEndArray();
    }
}
