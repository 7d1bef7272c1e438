package org.skinlab.desktop.bench;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * Writes {@link SyntheticCollada}'s character as a binary glTF 2.0 file ({@code .glb}) for parse
 * benchmarks: the same wavy grid, the same chain of {@value SyntheticCollada#JOINTS} joints with
 * the same four weights per position, the same keys. glTF has one index per vertex, so every quad
 * corner is its own vertex (the COLLADA file's corners differ in their per-quad normal too, and
 * its importer makes the same vertices). The COLLADA file is Z-up and glTF is Y-up, so every
 * point, normal, bind matrix and key is turned by (x, y, z) to (x, z, -y): both files give the
 * same character once each is brought to Y-up. Deterministic: the same arguments give the same
 * bytes.
 */
public final class SyntheticGltf {
    private static final int FLOAT = 5126;
    private static final int UNSIGNED_BYTE = 5121;
    private static final int UNSIGNED_INT = 5125;
    private static final int ARRAY_BUFFER = 34962;
    private static final int ELEMENT_ARRAY_BUFFER = 34963;

    private SyntheticGltf() {
    }

    /** {@code SyntheticGltf FILE TRIANGLES}: writes the file, prints the triangle count. */
    public static void main(String[] args) throws IOException {
        if (args.length != 2) {
            System.err.println("usage: SyntheticGltf FILE TRIANGLES");
            System.exit(2);
        }
        System.out.println(write(Path.of(args[0]), Long.parseLong(args[1])));
    }

    /** The triangles a file needs to be about {@code bytes} long (232 bytes per quad of two triangles). */
    public static long trianglesForBytes(long bytes) {
        return Math.max(2, bytes / 232 * 2);
    }

    /** Writes the file and returns the number of triangles it holds (2 per grid cell). */
    public static long write(Path file, long minTriangles) throws IOException {
        int n = Math.max(1, SyntheticCollada.cellsPerSide(minTriangles));
        long quads = (long) n * n;
        long vertices = 4 * quads;
        if (vertices * 52 + quads * 24 > Integer.MAX_VALUE - (1 << 20)) {
            throw new IllegalArgumentException(minTriangles + " triangles do not fit in one glTF buffer");
        }
        Layout layout = new Layout((int) vertices, (int) quads);
        ByteBuffer bin = ByteBuffer.allocate(layout.total).order(ByteOrder.LITTLE_ENDIAN);
        float[] bounds = writeVertices(bin, layout, n);
        writeIndices(bin, layout, (int) quads);
        writeBindMatrices(bin, layout);
        writeKeys(bin, layout);
        byte[] json = json(layout, bounds).getBytes(StandardCharsets.UTF_8);
        writeGlb(file, json, bin.array());
        return 2 * quads;
    }

    /** Byte offsets of the buffer views, each 4-byte aligned (all sizes are multiples of 4). */
    private static final class Layout {
        final int vertices;
        final int quads;
        final int positions;
        final int normals;
        final int uvs;
        final int joints;
        final int weights;
        final int indices;
        final int bind;
        final int times;
        final int rotations;
        final int total;

        Layout(int vertices, int quads) {
            this.vertices = vertices;
            this.quads = quads;
            positions = 0;
            normals = positions + 12 * vertices;
            uvs = normals + 12 * vertices;
            joints = uvs + 8 * vertices;
            weights = joints + 4 * vertices;
            indices = weights + 16 * vertices;
            bind = indices + 24 * quads;
            times = bind + 64 * SyntheticCollada.JOINTS;
            rotations = times + 4 * SyntheticCollada.KEYS;
            total = rotations + 16 * SyntheticCollada.KEYS * SyntheticCollada.JOINTS;
        }
    }

    /**
     * The four corners of every quad, as the COLLADA file's polylist lists them; returns the
     * positions' bounds (min xyz, max xyz), which glTF requires in the accessor.
     */
    private static float[] writeVertices(ByteBuffer bin, Layout l, int n) {
        float[] bounds = {Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE,
            -Float.MAX_VALUE};
        int side = n + 1;
        float segment = 4f / SyntheticCollada.JOINTS;
        int[] nearest = new int[4];
        float[] weights = new float[4];
        int v = 0;
        long q = 0;
        for (int y = 0; y < n; y++) {
            for (int x = 0; x < n; x++, q++) {
                float a = (q % 7) * 0.01f;
                float len = (float) Math.sqrt(1 + a * a);
                int first = y * side + x;
                int[] corners = {first, first + 1, first + 1 + side, first + side};
                for (int c : corners) {
                    int cx = c % side;
                    int cy = c / side;
                    float px = cx / (float) n * 4f;
                    float py = cy / (float) n * 4f;
                    float pz = 0.1f * (float) Math.sin(px * 3.1) * (float) Math.cos(py * 2.3);
                    putYUp(bin, l.positions + 12 * v, px, py, pz);
                    for (int i = 0; i < 3; i++) {
                        float value = bin.getFloat(l.positions + 12 * v + 4 * i);
                        bounds[i] = Math.min(bounds[i], value);
                        bounds[3 + i] = Math.max(bounds[3 + i], value);
                    }
                    putYUp(bin, l.normals + 12 * v, a / len, 0f, 1f / len);
                    bin.putFloat(l.uvs + 8 * v, cx / (float) n).putFloat(l.uvs + 8 * v + 4, 1f - cy / (float) n);
                    SyntheticCollada.influences(px, segment, nearest, weights);
                    for (int k = 0; k < 4; k++) {
                        bin.put(l.joints + 4 * v + k, (byte) nearest[k]);
                        bin.putFloat(l.weights + 16 * v + 4 * k, weights[k]);
                    }
                    v++;
                }
            }
        }
        return bounds;
    }

    /** (x, y, z) of the Z-up COLLADA file as glTF's Y-up (x, z, -y). */
    private static void putYUp(ByteBuffer bin, int at, float x, float y, float z) {
        bin.putFloat(at, x).putFloat(at + 4, z).putFloat(at + 8, -y);
    }

    /** Two triangles per quad, corners 0 1 2 and 0 2 3, as a triangulated polygon. */
    private static void writeIndices(ByteBuffer bin, Layout l, int quads) {
        int at = l.indices;
        for (int q = 0; q < quads; q++) {
            int v = 4 * q;
            int[] tri = {v, v + 1, v + 2, v, v + 2, v + 3};
            for (int i : tri) {
                bin.putInt(at, i);
                at += 4;
            }
        }
    }

    /** Joint j at x = j * segment: its inverse bind matrix moves it back (column-major). */
    private static void writeBindMatrices(ByteBuffer bin, Layout l) {
        float segment = 4f / SyntheticCollada.JOINTS;
        for (int j = 0; j < SyntheticCollada.JOINTS; j++) {
            float[] m = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -j * segment, 0, 0, 1};
            for (int i = 0; i < 16; i++) {
                bin.putFloat(l.bind + 64 * j + 4 * i, m[i]);
            }
        }
    }

    /**
     * The COLLADA keys rotate each joint about its Z-up Y axis by 0.3 sin(k pi / 2); about glTF's
     * Y-up axes that is a rotation about -Z: quaternion (0, 0, -sin(a/2), cos(a/2)).
     */
    private static void writeKeys(ByteBuffer bin, Layout l) {
        for (int k = 0; k < SyntheticCollada.KEYS; k++) {
            bin.putFloat(l.times + 4 * k, k * 0.25f);
        }
        int at = l.rotations;
        for (int j = 0; j < SyntheticCollada.JOINTS; j++) {
            for (int k = 0; k < SyntheticCollada.KEYS; k++) {
                double angle = Math.sin(k * Math.PI / 2) * 0.3;
                bin.putFloat(at, 0f).putFloat(at + 4, 0f).putFloat(at + 8, (float) -Math.sin(angle / 2))
                        .putFloat(at + 12, (float) Math.cos(angle / 2));
                at += 16;
            }
        }
    }

    private static String json(Layout l, float[] bounds) throws IOException {
        ObjectMapper mapper = new ObjectMapper();
        ObjectNode root = mapper.createObjectNode();
        root.putObject("asset").put("version", "2.0").put("generator", "skinlab SyntheticGltf");
        root.put("scene", 0);
        root.putArray("scenes").addObject().putArray("nodes").add(0);
        writeNodes(root.putArray("nodes"));
        ObjectNode attributes = mapper.createObjectNode().put("POSITION", 0).put("NORMAL", 1).put("TEXCOORD_0", 2)
                .put("JOINTS_0", 3).put("WEIGHTS_0", 4);
        ObjectNode primitive = root.putArray("meshes").addObject().put("name", "grid").putArray("primitives").addObject();
        primitive.set("attributes", attributes);
        primitive.put("indices", 5);
        ObjectNode skin = root.putArray("skins").addObject().put("inverseBindMatrices", 6).put("skeleton", 1);
        ArrayNode skinJoints = skin.putArray("joints");
        for (int j = 0; j < SyntheticCollada.JOINTS; j++) {
            skinJoints.add(1 + j);
        }
        writeAnimation(root.putArray("animations").addObject().put("name", "wave"));
        writeAccessors(root.putArray("accessors"), l, bounds);
        writeViews(root.putArray("bufferViews"), l);
        root.putArray("buffers").addObject().put("byteLength", l.total);
        return mapper.writeValueAsString(root);
    }

    /** Node 0 the armature, 1.. the joint chain, last the skinned mesh (a child of the armature). */
    private static void writeNodes(ArrayNode nodes) {
        float segment = 4f / SyntheticCollada.JOINTS;
        int mesh = 1 + SyntheticCollada.JOINTS;
        nodes.addObject().put("name", "Armature").putArray("children").add(1).add(mesh);
        for (int j = 0; j < SyntheticCollada.JOINTS; j++) {
            ObjectNode joint = nodes.addObject().put("name", "Bone" + j);
            joint.putArray("translation").add(j == 0 ? 0f : segment).add(0f).add(0f);
            if (j + 1 < SyntheticCollada.JOINTS) {
                joint.putArray("children").add(2 + j);
            }
        }
        nodes.addObject().put("name", "grid").put("mesh", 0).put("skin", 0);
    }

    private static void writeAnimation(ObjectNode animation) {
        ArrayNode samplers = animation.putArray("samplers");
        ArrayNode channels = animation.putArray("channels");
        for (int j = 0; j < SyntheticCollada.JOINTS; j++) {
            samplers.addObject().put("input", 7).put("output", 8 + j).put("interpolation", "LINEAR");
            channels.addObject().put("sampler", j).putObject("target").put("node", 1 + j).put("path", "rotation");
        }
    }

    private static void writeAccessors(ArrayNode accessors, Layout l, float[] bounds) {
        ObjectNode positions = accessor(accessors, 0, FLOAT, l.vertices, "VEC3");
        ArrayNode lo = positions.putArray("min");
        ArrayNode hi = positions.putArray("max");
        for (int i = 0; i < 3; i++) {
            lo.add(bounds[i]);
            hi.add(bounds[3 + i]);
        }
        accessor(accessors, 1, FLOAT, l.vertices, "VEC3");
        accessor(accessors, 2, FLOAT, l.vertices, "VEC2");
        accessor(accessors, 3, UNSIGNED_BYTE, l.vertices, "VEC4");
        accessor(accessors, 4, FLOAT, l.vertices, "VEC4");
        accessor(accessors, 5, UNSIGNED_INT, 6 * l.quads, "SCALAR");
        accessor(accessors, 6, FLOAT, SyntheticCollada.JOINTS, "MAT4");
        ObjectNode times = accessor(accessors, 7, FLOAT, SyntheticCollada.KEYS, "SCALAR");
        times.putArray("min").add(0f);
        times.putArray("max").add((SyntheticCollada.KEYS - 1) * 0.25f);
        for (int j = 0; j < SyntheticCollada.JOINTS; j++) {
            accessor(accessors, 8, FLOAT, SyntheticCollada.KEYS, "VEC4").put("byteOffset", 16 * SyntheticCollada.KEYS * j);
        }
    }

    private static ObjectNode accessor(ArrayNode accessors, int view, int type, int count, String shape) {
        return accessors.addObject().put("bufferView", view).put("componentType", type).put("count", count)
                .put("type", shape);
    }

    private static void writeViews(ArrayNode views, Layout l) {
        int[] starts = {l.positions, l.normals, l.uvs, l.joints, l.weights, l.indices, l.bind, l.times, l.rotations,
            l.total};
        for (int i = 0; i + 1 < starts.length; i++) {
            ObjectNode view = views.addObject().put("buffer", 0).put("byteOffset", starts[i])
                    .put("byteLength", starts[i + 1] - starts[i]);
            if (i <= 4) {
                view.put("target", ARRAY_BUFFER);
            } else if (i == 5) {
                view.put("target", ELEMENT_ARRAY_BUFFER);
            }
        }
    }

    /** The GLB container: 12-byte header, the JSON chunk padded with spaces, the BIN chunk. */
    private static void writeGlb(Path file, byte[] json, byte[] bin) throws IOException {
        int jsonLength = (json.length + 3) & ~3;
        int total = 12 + 8 + jsonLength + 8 + bin.length;
        ByteBuffer head = ByteBuffer.allocate(12 + 8 + jsonLength + 8).order(ByteOrder.LITTLE_ENDIAN);
        head.putInt(0x46546C67).putInt(2).putInt(total);
        head.putInt(jsonLength).putInt(0x4E4F534A).put(json);
        while (head.position() < 20 + jsonLength) {
            head.put((byte) ' ');
        }
        head.putInt(bin.length).putInt(0x004E4942);
        try (OutputStream out = Files.newOutputStream(file)) {
            out.write(head.array());
            out.write(bin);
        }
    }
}
