package org.skinlab.gltf;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeSet;

import org.skinlab.model.Mesh;
import org.skinlab.model.MeshPart;

/**
 * Reads {@code /meshes} into {@link MeshData}. A mesh's primitives become one {@link Mesh}:
 * primitives with the same attributes (and targets) share one block of vertices, each other
 * primitive adds its own. glTF has no separate position index space; vertices that agree in
 * position, skin influences and morph offsets share one model position ({@link PositionWelder}),
 * which skin influences and morph offsets are stored per.
 *
 * <p>TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN become triangles (strip triangle i is
 * {@code (v_i, v_(i+1+i%2), v_(i+2-i%2))} and fan triangle i {@code (v_(i+1), v_(i+2), v_0)}, as
 * the specification orders them); points and lines are skipped with a warning, as is a primitive
 * without POSITION. A primitive without NORMAL gets no normals when no primitive of the mesh has
 * them (renderers then use face normals, as for COLLADA), else zeros with a warning; missing
 * TEXCOORD sets are zeros and a missing COLOR_0 is white, with a warning. Texture coordinates are
 * turned into the model's convention, v up from the image's bottom: v = 1 - v_glTF.
 */
final class MeshReader {
    private static final String[] TRIANGLE_MODES = {"points", "lines", "line_loop", "line_strip", "triangles",
            "triangle_strip", "triangle_fan"};

    private final GltfContext ctx;
    private final Accessors accessors;
    private final boolean quantized;
    private final int materialCount;

    MeshReader(GltfContext ctx, Accessors accessors, boolean quantized, int materialCount) {
        this.ctx = ctx;
        this.accessors = accessors;
        this.quantized = quantized;
        this.materialCount = materialCount;
    }

    /** A block of vertices: the attributes (and targets) of one or more primitives. */
    private static final class Block {
        final JsonNode primitive;
        final JsonNode attributes;
        final int count;
        int start;

        Block(JsonNode primitive, int count) throws GltfException {
            this.primitive = primitive;
            this.attributes = primitive.get("attributes");
            this.count = count;
        }
    }

    /** The primitives that are drawn, each with its block of vertices (blocks in first-use order). */
    private static final class Layout {
        final Map<String, Block> blocks = new LinkedHashMap<>();
        final List<Block> blockOfPart = new ArrayList<>();
        final List<JsonNode> partPrimitives = new ArrayList<>();
        int targetCount;
        int positions;
    }

    /** The mesh, or null when none of its primitives is drawn (warned). */
    MeshData read(JsonNode meshNode, int index) throws GltfException {
        Layout layout = layout(meshNode);
        if (layout.partPrimitives.isEmpty()) {
            return null;
        }
        List<Block> blocks = new ArrayList<>(layout.blocks.values());
        int positions = layout.positions;
        // Positions, normals, colours, two texture coordinate sets, the position map and the
        // mesh's own copies of them; further sets and morph targets are charged as they come.
        ctx.charge(2L * (3 + 1 + 3 + 4 + 2 * 2 + 2) * positions, meshNode.path());
        Vertices v = new Vertices(positions);
        for (Block b : blocks) {
            v.read(b);
        }
        for (Block b : blocks) {
            v.warnGaps(b);
        }
        TriangleList triangles = new TriangleList();
        List<MeshPart> parts = new ArrayList<>();
        int[] partMaterials = new int[layout.partPrimitives.size()];
        for (int i = 0; i < partMaterials.length; i++) {
            JsonNode primitive = layout.partPrimitives.get(i);
            int first = triangles.size() / 3;
            triangles(primitive, layout.blockOfPart.get(i), triangles);
            JsonNode material = primitive.get("material");
            partMaterials[i] = material.isMissing() ? -1 : material.index(materialCount, "materials");
            parts.add(new MeshPart(TRIANGLE_MODES[primitive.get("mode").integer(0, 6, 4)],
                    partMaterials[i] < 0 ? null : GltfImporter.materialSymbol(partMaterials[i]), first,
                    triangles.size() / 3 - first));
        }
        float[][] targetPositions = new float[layout.targetCount][];
        float[][] targetNormals = new float[layout.targetCount][];
        for (int t = 0; t < targetPositions.length; t++) {
            ctx.charge(6L * positions, meshNode.get("primitives").path());
            targetPositions[t] = new float[3 * positions];
            for (Block b : blocks) {
                readTarget(b, t, targetPositions, targetNormals, positions);
            }
        }
        Influences influences = new Influences(accessors, positions);
        for (Block b : blocks) {
            influences.read(b.attributes, b.start, b.count);
        }
        ctx.charge(8L * positions, meshNode.path()); // the welder's maps and table (at most 4 slots per vertex)
        int[] vertexStart = influences.start();
        PositionWelder weld = new PositionWelder(v.positions, vertexStart, influences.joints(), influences.weights(),
                targetPositions);
        for (int t = 0; t < targetPositions.length; t++) {
            targetPositions[t] = weld.perPosition(targetPositions[t], 3);
        }
        int[] start = weld.influenceStart();
        Mesh mesh = new Mesh("/meshes/" + index, meshNode.get("name").string(null), weld.perPosition(v.positions, 3),
                weld.positionOfVertex, v.normals, v.texCoords, v.texCoordNumbers, v.colors, triangles.toArray(), parts);
        return new MeshData(index, mesh, targetPositions, targetNormals, defaultWeights(meshNode, layout.targetCount),
                partMaterials, start, weld.influenceJoints(start), weld.influenceWeights(start), influences.maxJoint,
                influences.maxJointPath, influences.withoutJoints);
    }

    /** Which primitives are drawn and which vertex block each uses; morph target counts checked. */
    private Layout layout(JsonNode meshNode) throws GltfException {
        JsonNode primitives = meshNode.get("primitives");
        if (primitives.size() == 0) {
            throw primitives.error("a mesh needs at least one primitive");
        }
        Layout layout = new Layout();
        for (int p = 0; p < primitives.size(); p++) {
            JsonNode primitive = primitives.get(p);
            int mode = primitive.get("mode").integer(0, 6, 4);
            JsonNode targets = primitive.get("targets").arrayOrMissing();
            if (p > 0 && targets.size() != layout.targetCount) {
                throw targets.error(targets.size() + " morph targets, but the mesh's first primitive has "
                        + layout.targetCount);
            }
            layout.targetCount = targets.size();
            JsonNode attributes = primitive.get("attributes").objectOrMissing();
            if (mode < 4) {
                ctx.warn(primitive.path(), "mode " + mode + " (" + TRIANGLE_MODES[mode] + ") is not drawn; skipped");
                continue;
            }
            checkAttributeNames(attributes);
            if (!attributes.has("POSITION")) {
                ctx.warn(attributes.path(), "no POSITION attribute; the primitive is skipped");
                continue;
            }
            String key = attributeKey(attributes) + "|" + targetKey(targets);
            Block block = layout.blocks.get(key);
            if (block == null) {
                block = new Block(primitive, accessors.elementCount(accessors.resolve(attributes.get("POSITION"))));
                block.start = layout.positions;
                layout.positions += block.count;
                if (layout.positions > GltfLimits.MAX_ACCESSOR_VALUES) {
                    throw meshNode.error("more than " + GltfLimits.MAX_ACCESSOR_VALUES + " vertices");
                }
                layout.blocks.put(key, block);
            }
            layout.blockOfPart.add(block);
            layout.partPrimitives.add(primitive);
        }
        return layout;
    }

    /** {@code mesh.weights}, one per morph target, zeros when absent. */
    private static float[] defaultWeights(JsonNode meshNode, int targetCount) throws GltfException {
        JsonNode weights = meshNode.get("weights");
        if (weights.isMissing()) {
            return new float[targetCount];
        }
        if (weights.size() != targetCount) {
            throw weights.error(weights.size() + " weights for " + targetCount + " morph targets");
        }
        return weights.floats();
    }

    /** Attribute names are the specification's semantics or application-specific ones starting with "_". */
    private static void checkAttributeNames(JsonNode attributes) throws GltfException {
        for (String name : attributes.keys()) {
            if (!name.startsWith("_") && !name.matches("POSITION|NORMAL|TANGENT|(TEXCOORD|COLOR|JOINTS|WEIGHTS)_(0|[1-9][0-9]*)")) {
                throw attributes.get(name).error("\"" + name + "\" is no attribute semantic (nor an application's,"
                        + " which would start with _)");
            }
        }
    }

    private static String attributeKey(JsonNode attributes) throws GltfException {
        StringBuilder sb = new StringBuilder();
        for (String k : attributes.keys()) {
            sb.append(k).append('=').append(attributes.get(k).number()).append(',');
        }
        return sb.toString();
    }

    private static String targetKey(JsonNode targets) throws GltfException {
        StringBuilder sb = new StringBuilder();
        for (int t = 0; t < targets.size(); t++) {
            sb.append(attributeKey(targets.get(t).objectOrMissing())).append(';');
        }
        return sb.toString();
    }

    /** The vertex attributes of all blocks, concatenated. */
    private final class Vertices {
        final int total;
        /** Null until read; the accessor's own (cached, never written) array when one block is the mesh. */
        float[] positions;
        float[] normals;
        float[] colors;
        final List<float[]> texCoords = new ArrayList<>();
        int[] texCoordNumbers;

        Vertices(int total) {
            this.total = total;
        }

        void read(Block b) throws GltfException {
            JsonNode a = b.attributes;
            positions = attribute(a.get("POSITION"), b, positions, positionFormats());
            if (a.has("NORMAL")) {
                normals = attribute(a.get("NORMAL"), b, normals, normalFormats());
            }
            if (a.has("COLOR_0")) {
                if (colors == null) {
                    colors = new float[4 * total];
                    Arrays.fill(colors, 1f);
                }
                readColors(a.get("COLOR_0"), b);
            }
            TreeSet<Integer> sets = new TreeSet<>();
            for (String key : a.keys()) {
                if (key.startsWith("TEXCOORD_")) {
                    sets.add(setNumber(a.get(key), key));
                }
            }
            for (int set : sets) {
                float[] uv = texCoordSet(set);
                copy(a.get("TEXCOORD_" + set), "VEC2", b, uv, 2, texCoordFormats());
                // glTF's v runs down from the image's top; the model's (COLLADA's) runs up from its bottom.
                for (int i = 2 * b.start + 1; i < 2 * (b.start + b.count); i += 2) {
                    uv[i] = 1f - uv[i];
                }
            }
        }

        /** After all blocks are read: says where a block lacks what others have. */
        void warnGaps(Block b) throws GltfException {
            JsonNode a = b.attributes;
            if (normals != null && !a.has("NORMAL")) {
                ctx.warn(a.path(), "no NORMAL while other primitives of the mesh have one; its normals are zero");
            }
            if (colors != null && !a.has("COLOR_0")) {
                ctx.warn(a.path(), "no COLOR_0 while other primitives of the mesh have one; its colour is white");
            }
            for (int i = 0; texCoordNumbers != null && i < texCoordNumbers.length; i++) {
                if (!a.has("TEXCOORD_" + texCoordNumbers[i])) {
                    ctx.warn(a.path(), "no TEXCOORD_" + texCoordNumbers[i]
                            + " while other primitives of the mesh have it; its texture coordinates there are zero");
                }
            }
        }

        private float[] texCoordSet(int number) throws GltfException {
            int i = texCoordNumbers == null ? -1 : Arrays.binarySearch(texCoordNumbers, number);
            if (i >= 0) {
                return texCoords.get(i);
            }
            if (texCoords.size() >= 2) {
                ctx.charge(4L * total, "/meshes");
            }
            int at = texCoordNumbers == null ? 0 : -i - 1;
            int[] numbers = new int[texCoords.size() + 1];
            for (int k = 0, j = 0; k < numbers.length; k++) {
                numbers[k] = k == at ? number : texCoordNumbers[j++];
            }
            texCoordNumbers = numbers;
            float[] set = new float[2 * total];
            texCoords.add(at, set);
            return set;
        }

        private void readColors(JsonNode ref, Block b) throws GltfException {
            int acc = accessors.resolve(ref);
            String type = accessors.components(acc) == 3 ? "VEC3" : "VEC4";
            accessors.expect(acc, ref.path(), type, "5126", "5121n", "5123n");
            checkCount(acc, ref, b);
            float[] data = accessors.floats(acc);
            int width = type.equals("VEC3") ? 3 : 4;
            for (int i = 0; i < b.count; i++) {
                System.arraycopy(data, width * i, colors, 4 * (b.start + i), width);
            }
        }

        /**
         * A VEC3 attribute of block {@code b} in {@code dest} (made when null): the accessor's own
         * array when the block is all the mesh's vertices, which the mesh copies and nothing writes.
         */
        private float[] attribute(JsonNode ref, Block b, float[] dest, String[] formats) throws GltfException {
            if (dest != null || b.count != total) {
                float[] to = dest == null ? new float[3 * total] : dest;
                copy(ref, "VEC3", b, to, 3, formats);
                return to;
            }
            int acc = accessors.resolve(ref);
            accessors.expect(acc, ref.path(), "VEC3", formats);
            checkCount(acc, ref, b);
            return accessors.floats(acc);
        }

        private void copy(JsonNode ref, String type, Block b, float[] dest, int width, String[] formats)
                throws GltfException {
            int acc = accessors.resolve(ref);
            accessors.expect(acc, ref.path(), type, formats);
            checkCount(acc, ref, b);
            System.arraycopy(accessors.floats(acc), 0, dest, width * b.start, width * b.count);
        }
    }

    private void checkCount(int acc, JsonNode ref, Block b) throws GltfException {
        if (accessors.elementCount(acc) != b.count) {
            throw ref.error("accessor " + acc + " has " + accessors.elementCount(acc) + " elements but POSITION has "
                    + b.count);
        }
    }

    private static int setNumber(JsonNode ref, String key) throws GltfException {
        try {
            int n = Integer.parseInt(key.substring("TEXCOORD_".length()));
            if (n < 0 || n > 31) {
                throw ref.error("texture coordinate set " + n + " is out of range");
            }
            return n;
        } catch (NumberFormatException e) {
            throw ref.error("\"" + key + "\" is not TEXCOORD_ and a set number");
        }
    }

    private void readTarget(Block b, int t, float[][] positions, float[][] normals, int total) throws GltfException {
        JsonNode target = b.primitive.get("targets").get(t).objectOrMissing();
        if (target.has("POSITION")) {
            int acc = accessors.resolve(target.get("POSITION"));
            accessors.expect(acc, target.get("POSITION").path(), "VEC3", quantized
                    ? new String[] {"5126", "5120", "5120n", "5122", "5122n"} : new String[] {"5126"});
            checkCount(acc, target.get("POSITION"), b);
            System.arraycopy(accessors.floats(acc), 0, positions[t], 3 * b.start, 3 * b.count);
        }
        if (target.has("NORMAL")) {
            int acc = accessors.resolve(target.get("NORMAL"));
            accessors.expect(acc, target.get("NORMAL").path(), "VEC3", normalFormats());
            checkCount(acc, target.get("NORMAL"), b);
            normals[t] = normals[t] == null ? new float[3 * total] : normals[t];
            System.arraycopy(accessors.floats(acc), 0, normals[t], 3 * b.start, 3 * b.count);
        }
    }

    private String[] positionFormats() {
        return quantized ? new String[] {"5126", "5120", "5120n", "5121", "5121n", "5122", "5122n", "5123", "5123n"}
                : new String[] {"5126"};
    }

    private String[] normalFormats() {
        return quantized ? new String[] {"5126", "5120n", "5122n"} : new String[] {"5126"};
    }

    private String[] texCoordFormats() {
        return quantized ? new String[] {"5126", "5120", "5120n", "5121", "5121n", "5122", "5122n", "5123", "5123n"}
                : new String[] {"5126", "5121n", "5123n"};
    }

    /** Appends a primitive's triangles (block-relative indices made mesh-wide). */
    private void triangles(JsonNode primitive, Block block, TriangleList out) throws GltfException {
        int mode = primitive.get("mode").integer(0, 6, 4);
        JsonNode indicesNode = primitive.get("indices");
        int[] indices;
        if (indicesNode.isMissing()) {
            indices = null;
        } else {
            int acc = accessors.resolve(indicesNode);
            accessors.expect(acc, indicesNode.path(), "SCALAR", "5121", "5123", "5125");
            indices = accessors.ints(acc);
            long restart = Accessors.restartValue(accessors.node(acc).get("componentType").integer(0, Integer.MAX_VALUE));
            for (int i = 0; i < indices.length; i++) {
                if (indices[i] == restart) { // (unsigned int indices that large fail the range check below)
                    throw indicesNode.error("index " + i + " is the primitive restart value " + restart
                            + ", which glTF does not allow");
                }
                if (indices[i] >= block.count) {
                    throw indicesNode.error("index " + i + " is " + (indices[i] == Integer.MAX_VALUE ? "2147483647 or more"
                            : Integer.toString(indices[i])) + " but the primitive has " + block.count + " vertices");
                }
            }
        }
        int n = indices == null ? block.count : indices.length;
        int triangles = mode == 4 ? n / 3 : Math.max(0, n - 2);
        if (mode == 4 && n % 3 != 0) {
            ctx.warn(primitive.path(), n + " vertices are not whole triangles; the last " + n % 3 + " are ignored");
        }
        if (out.size() / 3 + (long) triangles > GltfLimits.MAX_TRIANGLES) {
            throw primitive.error("more than " + GltfLimits.MAX_TRIANGLES + " triangles in the mesh");
        }
        ctx.charge(2L * 3 * triangles, primitive.path()); // the list and the mesh's copy
        out.reserve(3 * triangles);
        for (int i = 0; i < triangles; i++) {
            int a;
            int b;
            int c;
            if (mode == 4) {
                a = 3 * i;
                b = 3 * i + 1;
                c = 3 * i + 2;
            } else if (mode == 5) {
                a = i;
                b = i + 1 + i % 2;
                c = i + 2 - i % 2;
            } else {
                a = i + 1;
                b = i + 2;
                c = 0;
            }
            out.add(block.start + (indices == null ? a : indices[a]), block.start + (indices == null ? b : indices[b]),
                    block.start + (indices == null ? c : indices[c]));
        }
    }

    /** A growable list of triangle corners. */
    private static final class TriangleList {
        private int[] data = new int[0];
        private int size;

        /** Makes room for {@code more} corners at once (a primitive's triangles). */
        void reserve(int more) {
            if (size + more > data.length) {
                data = Arrays.copyOf(data, Math.max(size + more, data.length * 2));
            }
        }

        void add(int a, int b, int c) {
            reserve(3);
            data[size++] = a;
            data[size++] = b;
            data[size++] = c;
        }

        int size() {
            return size;
        }

        int[] toArray() {
            return size == data.length ? data : Arrays.copyOf(data, size);
        }
    }
}
