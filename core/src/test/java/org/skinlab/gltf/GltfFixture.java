package org.skinlab.gltf;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.Locale;

import org.skinlab.model.Model;

/**
 * Writes small glTF documents for tests: binary data goes into one buffer (a base64 data URI in
 * .gltf, the BIN chunk in .glb), views and accessors are listed as they are added, and the test
 * writes the rest of the JSON (meshes, nodes, ...) by hand.
 */
final class GltfFixture {
    private final ByteArrayOutputStream bin = new ByteArrayOutputStream();
    private final List<String> views = new ArrayList<>();
    private final List<String> accessors = new ArrayList<>();

    /** A view over the given bytes (4-byte aligned), with a byteStride when stride > 0. */
    int view(byte[] data, int stride) {
        while (bin.size() % 4 != 0) {
            bin.write(0);
        }
        views.add("{\"buffer\":0,\"byteOffset\":" + bin.size() + ",\"byteLength\":" + data.length
                + (stride > 0 ? ",\"byteStride\":" + stride : "") + "}");
        bin.write(data, 0, data.length);
        return views.size() - 1;
    }

    /** An accessor written as given (JSON object text). */
    int accessor(String json) {
        accessors.add(json);
        return accessors.size() - 1;
    }

    /**
     * Values encoded in a component type, in their own view, and an accessor over them, with the
     * min and max of the stored values that valid glTF requires of positions and key times.
     */
    int accessor(int componentType, String type, boolean normalized, double... values) {
        byte[] data = encode(componentType, values);
        int view = view(data, 0);
        int components = AccessorFormat.components(type);
        return accessor("{\"bufferView\":" + view + ",\"componentType\":" + componentType + ",\"type\":\"" + type
                + "\",\"count\":" + values.length / components + (normalized ? ",\"normalized\":true" : "")
                + bounds(componentType, components, data) + "}");
    }

    /** ",\"min\":[...],\"max\":[...]" of the stored values, or nothing when one is not finite. */
    private static String bounds(int componentType, int components, byte[] data) {
        ByteBuffer b = ByteBuffer.wrap(data).order(ByteOrder.LITTLE_ENDIAN);
        int n = componentType == AccessorFormat.FLOAT || componentType == AccessorFormat.UNSIGNED_INT ? data.length / 4
                : componentType == AccessorFormat.SHORT || componentType == AccessorFormat.UNSIGNED_SHORT ? data.length / 2
                : data.length;
        if (n == 0) {
            return "";
        }
        double[] min = new double[components];
        double[] max = new double[components];
        java.util.Arrays.fill(min, Double.POSITIVE_INFINITY);
        java.util.Arrays.fill(max, Double.NEGATIVE_INFINITY);
        for (int i = 0; i < n; i++) {
            double v;
            switch (componentType) {
                case AccessorFormat.FLOAT:
                    v = b.getFloat(4 * i);
                    break;
                case AccessorFormat.UNSIGNED_INT:
                    v = Integer.toUnsignedLong(b.getInt(4 * i));
                    break;
                case AccessorFormat.SHORT:
                    v = b.getShort(2 * i);
                    break;
                case AccessorFormat.UNSIGNED_SHORT:
                    v = b.getShort(2 * i) & 0xffff;
                    break;
                case AccessorFormat.BYTE:
                    v = b.get(i);
                    break;
                default:
                    v = b.get(i) & 0xff;
            }
            if (!Double.isFinite(v)) {
                return "";
            }
            min[i % components] = Math.min(min[i % components], v);
            max[i % components] = Math.max(max[i % components], v);
        }
        return ",\"min\":" + json(min) + ",\"max\":" + json(max);
    }

    private static String json(double[] values) {
        StringBuilder sb = new StringBuilder("[");
        for (double v : values) {
            sb.append(sb.length() == 1 ? "" : ",").append(v == Math.rint(v) ? Long.toString((long) v)
                    : Float.toString((float) v));
        }
        return sb.append(']').toString();
    }

    int floats(String type, double... values) {
        return accessor(AccessorFormat.FLOAT, type, false, values);
    }

    static byte[] encode(int componentType, double... values) {
        int size = AccessorFormat.componentSize(componentType);
        ByteBuffer b = ByteBuffer.allocate(values.length * size).order(ByteOrder.LITTLE_ENDIAN);
        for (double v : values) {
            switch (componentType) {
                case AccessorFormat.FLOAT:
                    b.putFloat((float) v);
                    break;
                case AccessorFormat.UNSIGNED_INT:
                    b.putInt((int) (long) v);
                    break;
                case AccessorFormat.SHORT:
                case AccessorFormat.UNSIGNED_SHORT:
                    b.putShort((short) (long) v);
                    break;
                default:
                    b.put((byte) (long) v);
            }
        }
        return b.array();
    }

    /** The whole .gltf text: asset, buffer (data URI), views, accessors, then {@code rest}. */
    String gltf(String rest) {
        return document(rest, "\"uri\":\"data:application/octet-stream;base64,"
                + Base64.getEncoder().encodeToString(paddedBin()) + "\",");
    }

    private String document(String rest, String uri) {
        StringBuilder sb = new StringBuilder("{\"asset\":{\"version\":\"2.0\",\"generator\":\"GltfFixture\"}");
        if (bin.size() > 0) {
            sb.append(",\"buffers\":[{").append(uri).append("\"byteLength\":").append(paddedBin().length).append("}]");
            sb.append(",\"bufferViews\":[").append(String.join(",", views)).append(']');
        }
        if (!accessors.isEmpty()) {
            sb.append(",\"accessors\":[").append(String.join(",", accessors)).append(']');
        }
        if (!rest.isEmpty()) {
            sb.append(',').append(rest);
        }
        return sb.append('}').toString();
    }

    private byte[] paddedBin() {
        byte[] data = bin.toByteArray();
        return java.util.Arrays.copyOf(data, (data.length + 3) / 4 * 4);
    }

    /** The same content as a .glb: the JSON chunk (space-padded) and the BIN chunk. */
    byte[] glb(String rest) {
        byte[] json = document(rest, "").getBytes(StandardCharsets.UTF_8);
        int jsonLength = (json.length + 3) / 4 * 4;
        byte[] data = paddedBin();
        int total = 12 + 8 + jsonLength + (data.length > 0 ? 8 + data.length : 0);
        ByteBuffer b = ByteBuffer.allocate(total).order(ByteOrder.LITTLE_ENDIAN);
        b.putInt(0x46546C67).putInt(2).putInt(total);
        b.putInt(jsonLength).putInt(0x4E4F534A).put(json);
        for (int i = json.length; i < jsonLength; i++) {
            b.put((byte) ' ');
        }
        if (data.length > 0) {
            b.putInt(data.length).putInt(0x004E4942).put(data);
        }
        return b.array();
    }

    static Model read(String json) throws Exception {
        return GltfImporter.read(new ByteArrayInputStream(json.getBytes(StandardCharsets.UTF_8)), "test.gltf", null);
    }

    static Model read(byte[] bytes, String name) throws Exception {
        return GltfImporter.read(new ByteArrayInputStream(bytes), name, null);
    }

    /** A one-mesh document: the mesh's primitives JSON, one node drawing it, one scene. */
    String singleMesh(String primitives) {
        return gltf(String.format(Locale.ROOT, "\"meshes\":[{\"primitives\":[%s]}],\"nodes\":[{\"mesh\":0}],"
                + "\"scenes\":[{\"nodes\":[0]}],\"scene\":0", primitives));
    }
}
