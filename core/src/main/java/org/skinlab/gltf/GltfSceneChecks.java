package org.skinlab.gltf;

import static org.skinlab.gltf.CheckedDocument.oneOf;
import static org.skinlab.gltf.CheckedDocument.ref;
import static org.skinlab.gltf.CheckedDocument.required;
import static org.skinlab.gltf.AccessorFormat.BYTE;
import static org.skinlab.gltf.GltfDocumentChecks.ELEMENT_ARRAY_BUFFER;
import static org.skinlab.gltf.GltfDocumentChecks.ARRAY_BUFFER;
import static org.skinlab.gltf.AccessorFormat.FLOAT;
import static org.skinlab.gltf.AccessorFormat.SHORT;
import static org.skinlab.gltf.AccessorFormat.UNSIGNED_BYTE;
import static org.skinlab.gltf.AccessorFormat.UNSIGNED_INT;
import static org.skinlab.gltf.AccessorFormat.UNSIGNED_SHORT;

import java.util.Arrays;
import java.util.HashMap;
import java.util.HashSet;
import java.util.Map;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The part of {@link GltfDocumentChecks} about meshes (attribute names and formats, morph
 * targets, indices), nodes (hierarchy, transforms, skins, weights), scenes, skins and animations.
 */
final class GltfSceneChecks {
    private static final Pattern INDEXED = Pattern.compile("(TEXCOORD|COLOR|JOINTS|WEIGHTS)_(0|[1-9][0-9]*)");
    private static final Set<String> PLAIN = new HashSet<>(Arrays.asList("POSITION", "NORMAL", "TANGENT"));

    private final CheckedDocument doc;
    private final boolean quantized;
    /** How each buffer view is used by the primitives checked so far: as vertex or index data. */
    private final Map<Integer, String> viewUse = new HashMap<>();
    /** Each node's parent (-1 for none), filled while checking the nodes. */
    private final int[] parent;

    GltfSceneChecks(CheckedDocument doc) {
        this.doc = doc;
        this.quantized = doc.used.contains("KHR_mesh_quantization");
        this.parent = new int[doc.nodes];
        Arrays.fill(parent, -1);
    }

    void checkAll() throws GltfException {
        for (int i = 0; i < doc.meshes; i++) {
            checkMesh(doc.mesh(i));
        }
        for (int i = 0; i < doc.nodes; i++) {
            checkNode(doc.node(i), i);
        }
        for (int i = 0; i < doc.scenes; i++) {
            JsonNode scene = doc.root.get("scenes").get(i);
            JsonNode nodes = scene.get("nodes");
            // That they are roots is the scene's reading's check (SceneReader).
            CheckedDocument.indices(nodes, doc.nodes, "nodes");
            doc.extensions(scene, "scene");
        }
        for (int i = 0; i < doc.skins; i++) {
            checkSkin(doc.root.get("skins").get(i));
        }
        for (int i = 0; i < doc.animations; i++) {
            new AnimationChecks(doc).check(doc.root.get("animations").get(i));
        }
    }

    // ------------------------------------------------------------------------------------ meshes

    private void checkMesh(JsonNode mesh) throws GltfException {
        required(mesh, "primitives");
        int primitives = CheckedDocument.objects(mesh, "primitives");
        int targets = -1;
        for (int p = 0; p < primitives; p++) {
            JsonNode primitive = mesh.get("primitives").get(p);
            int n = checkPrimitive(primitive);
            if (targets >= 0 && n != targets) {
                throw primitive.error("has " + n + " morph targets, the mesh's first primitive " + targets);
            }
            targets = n;
        }
        JsonNode weights = mesh.get("weights").arrayOrMissing();
        if (!weights.isMissing() && weights.size() != targets) {
            throw weights.error(weights.size() + " weights for " + targets + " morph targets");
        }
        for (int i = 0; i < weights.size(); i++) {
            weights.get(i).number();
        }
        doc.extensions(mesh, "mesh");
    }

    /** Checks a primitive; returns its number of morph targets. */
    private int checkPrimitive(JsonNode primitive) throws GltfException {
        required(primitive, "attributes");
        JsonNode attributes = primitive.get("attributes").objectOrMissing(); // required, so an object
        long count = -1;
        Map<String, Integer> sets = new HashMap<>();
        for (String name : attributes.keys()) {
            JsonNode a = attributes.get(name);
            JsonNode accessor = doc.accessor(a.index(doc.accessors, "accessors"));
            checkAttributeName(a, name, sets);
            checkAttributeFormat(a, name, accessor);
            checkVertexBufferView(a, accessor);
            long n = (long) accessor.get("count").number();
            if (count >= 0 && n != count) {
                throw a.error("has " + n + " elements, the primitive's other attributes " + count);
            }
            count = n;
        }
        for (Map.Entry<String, Integer> set : sets.entrySet()) {
            for (int k = 0; k < set.getValue(); k++) {
                if (!attributes.has(set.getKey() + "_" + k)) {
                    throw attributes.get(set.getKey() + "_" + set.getValue()).error(set.getKey() + "_" + k
                            + " is missing before it");
                }
            }
        }
        if (attributes.has("POSITION") && !doc.accessor(attributes.get("POSITION").index(doc.accessors, "accessors"))
                .has("min")) {
            throw attributes.get("POSITION").error("a POSITION accessor needs min and max");
        }
        if (sets.getOrDefault("JOINTS", 0) != sets.getOrDefault("WEIGHTS", 0)) {
            throw attributes.error("JOINTS_n and WEIGHTS_n come in pairs");
        }
        checkIndices(primitive);
        int material = ref(primitive, "material", doc.materials, "materials");
        if (material >= 0) {
            checkTexCoords(primitive, doc.root.get("materials").get(material), sets.getOrDefault("TEXCOORD", 0));
        }
        oneOf(primitive.get("mode"), 4, 0, 1, 2, 3, 4, 5, 6);
        JsonNode targets = primitive.get("targets").arrayOrMissing();
        for (int t = 0; t < targets.size(); t++) {
            checkTarget(targets.get(t).objectOrMissing(), attributes, count);
        }
        doc.extensions(primitive, "primitive");
        return targets.size();
    }

    private static void checkAttributeName(JsonNode a, String name, Map<String, Integer> sets) throws GltfException {
        if (PLAIN.contains(name) || name.startsWith("_")) {
            return;
        }
        Matcher m = INDEXED.matcher(name);
        if (!m.matches()) {
            return; // refused by the reading (MeshReader), which names the semantics
        }
        int set = Integer.parseInt(m.group(2).length() > 6 ? "999999" : m.group(2));
        sets.merge(m.group(1), set + 1, Math::max);
    }

    private void checkAttributeFormat(JsonNode a, String name, JsonNode accessor) throws GltfException {
        String type = accessor.get("type").string();
        int component = (int) accessor.get("componentType").number();
        boolean normalized = accessor.get("normalized").bool(false);
        String semantic = name.contains("_") && !name.startsWith("_") ? name.substring(0, name.indexOf('_')) : name;
        boolean ok;
        switch (semantic) {
            case "POSITION":
                ok = type.equals("VEC3") && (component == FLOAT || quantized && component != UNSIGNED_INT);
                break;
            case "NORMAL":
                ok = type.equals("VEC3") && (component == FLOAT || quantized && normalized
                        && (component == BYTE || component == SHORT));
                break;
            case "TANGENT":
                ok = type.equals("VEC4") && (component == FLOAT || quantized && normalized
                        && (component == BYTE || component == SHORT));
                break;
            case "TEXCOORD":
                ok = type.equals("VEC2") && (component == FLOAT || normalized && (component == UNSIGNED_BYTE
                        || component == UNSIGNED_SHORT) || quantized && component != UNSIGNED_INT);
                break;
            case "COLOR":
                ok = (type.equals("VEC3") || type.equals("VEC4")) && (component == FLOAT
                        || normalized && (component == UNSIGNED_BYTE || component == UNSIGNED_SHORT));
                break;
            case "JOINTS":
                ok = type.equals("VEC4") && !normalized && (component == UNSIGNED_BYTE || component == UNSIGNED_SHORT);
                break;
            case "WEIGHTS":
                ok = type.equals("VEC4") && (component == FLOAT
                        || normalized && (component == UNSIGNED_BYTE || component == UNSIGNED_SHORT));
                break;
            default:
                ok = component != UNSIGNED_INT;
        }
        if (!ok) {
            throw a.error(name + " cannot be a " + type + " of component type " + component
                    + (normalized ? " (normalized)" : ""));
        }
    }

    /** Vertex data: 4-byte aligned, interleaved views have a stride, views are not index views. */
    private void checkVertexBufferView(JsonNode a, JsonNode accessor) throws GltfException {
        if (!accessor.has("bufferView")) {
            return;
        }
        int view = (int) accessor.get("bufferView").number();
        JsonNode bufferView = doc.bufferView(view);
        if ((int) bufferView.get("target").number(ARRAY_BUFFER) != ARRAY_BUFFER
                || "index".equals(viewUse.put(view, "vertex"))) {
            throw a.error("vertex data in buffer view " + view + ", which holds indices");
        }
        long offset = (long) accessor.get("byteOffset").number(0) + (long) bufferView.get("byteOffset").number(0);
        long stride = (long) bufferView.get("byteStride").number(0);
        if (offset % 4 != 0 || stride % 4 != 0) {
            throw a.error("vertex data start at byte " + offset + " of the buffer, not a multiple of 4");
        }
        if (stride == 0 && sharedWithAnEarlierAccessor(view, (int) a.number())) {
            throw a.error("buffer view " + view + " holds several accessors but has no byteStride");
        }
    }

    private boolean sharedWithAnEarlierAccessor(int view, int accessor) throws GltfException {
        for (int i = 0; i < accessor; i++) {
            JsonNode v = doc.accessor(i).get("bufferView");
            if (!v.isMissing() && (int) v.number() == view) {
                return true;
            }
        }
        return false;
    }

    private void checkIndices(JsonNode primitive) throws GltfException {
        int indices = ref(primitive, "indices", doc.accessors, "accessors");
        if (indices < 0) {
            return;
        }
        JsonNode accessor = doc.accessor(indices);
        int component = (int) accessor.get("componentType").number();
        if (!accessor.get("type").string().equals("SCALAR") || accessor.get("normalized").bool(false)
                || component != UNSIGNED_BYTE && component != UNSIGNED_SHORT && component != UNSIGNED_INT) {
            throw primitive.get("indices").error("indices are unsigned byte, short or int SCALARs");
        }
        if (accessor.has("bufferView")) {
            JsonNode view = doc.bufferView((int) accessor.get("bufferView").number());
            if (view.has("byteStride")) {
                doc.strideNotAllowed(primitive.get("indices"), "the indices");
            }
            if ((int) view.get("target").number(ELEMENT_ARRAY_BUFFER) != ELEMENT_ARRAY_BUFFER
                    || "vertex".equals(viewUse.put((int) accessor.get("bufferView").number(), "index"))) {
                throw primitive.get("indices").error("the indices' buffer view has the vertex buffer target");
            }
        }
    }

    /** Every texture the material uses reads a TEXCOORD set the primitive has. */
    private static void checkTexCoords(JsonNode primitive, JsonNode material, int sets) throws GltfException {
        JsonNode[] infos = {material.get("pbrMetallicRoughness").get("baseColorTexture"),
            material.get("pbrMetallicRoughness").get("metallicRoughnessTexture"), material.get("normalTexture"),
            material.get("occlusionTexture"), material.get("emissiveTexture")};
        for (JsonNode info : infos) {
            if (info.isMissing()) {
                continue;
            }
            int set = info.get("texCoord").integer(0, Integer.MAX_VALUE, 0);
            set = info.get("extensions").get("KHR_texture_transform").get("texCoord").integer(0, Integer.MAX_VALUE,
                    set);
            if (set >= sets) {
                throw primitive.get("material").error("the material reads TEXCOORD_" + set + " ("
                        + info.path() + "), which the primitive does not have");
            }
        }
    }

    private void checkTarget(JsonNode target, JsonNode attributes, long count) throws GltfException {
        for (String name : target.keys()) {
            JsonNode a = target.get(name);
            if (!PLAIN.contains(name) && !name.startsWith("_") && !INDEXED.matcher(name).matches()) {
                throw a.error("\"" + name + "\" is not a morph target attribute");
            }
            JsonNode accessor = doc.accessor(a.index(doc.accessors, "accessors"));
            if (!attributes.has(name)) {
                throw a.error("a morph target's " + name + " without the primitive's own");
            }
            if ((long) accessor.get("count").number() != count) {
                throw a.error("has " + (long) accessor.get("count").number() + " elements, the primitive " + count);
            }
            if (name.equals("POSITION") && !accessor.has("min")) {
                throw a.error("a POSITION accessor needs min and max");
            }
            checkVertexBufferView(a, accessor);
        }
    }

    // ------------------------------------------------------------------------------------- nodes

    private void checkNode(JsonNode node, int index) throws GltfException {
        ref(node, "camera", doc.cameras, "cameras");
        // A second parent or a cycle is refused by the scene's reading (SceneReader); here the
        // first parent counts, and every walk upwards is bounded.
        for (int child : CheckedDocument.indices(node.get("children"), doc.nodes, "nodes")) {
            if (parent[child] < 0 && child != index) {
                parent[child] = index;
            }
        }
        int mesh = ref(node, "mesh", doc.meshes, "meshes");
        // A skin or weights without a mesh is refused by the reading (InstanceBuilder).
        int skin = ref(node, "skin", doc.skins, "skins");
        if (skin >= 0 && mesh >= 0 && !skinned(doc.mesh(mesh))) {
            throw node.error("a skin on mesh " + mesh + ", which has no JOINTS_0 and WEIGHTS_0");
        }
        JsonNode weights = node.get("weights").arrayOrMissing();
        if (!weights.isMissing() && mesh >= 0) {
            int targets = doc.mesh(mesh).get("primitives").get(0).get("targets").size();
            if (weights.size() != targets) {
                throw weights.error(weights.size() + " weights for the mesh's " + targets + " morph targets");
            }
            weights.floats();
        }
        checkTransform(node);
        doc.extensions(node, "node");
    }

    private static boolean skinned(JsonNode mesh) throws GltfException {
        JsonNode attributes = mesh.get("primitives").get(0).get("attributes");
        return attributes.has("JOINTS_0") && attributes.has("WEIGHTS_0");
    }

    private static void checkTransform(JsonNode node) throws GltfException {
        JsonNode matrix = node.get("matrix");
        if (!matrix.isMissing()) {
            // A matrix beside translation, rotation or scale is refused by the scene's reading.
            float[] m = matrix.floats(16, null);
            if (m[3] != 0 || m[7] != 0 || m[11] != 0 || m[15] != 1) {
                throw matrix.error("not an affine transform (its last row is not 0 0 0 1)");
            }
            double det = m[0] * (m[5] * m[10] - m[9] * m[6]) - m[4] * (m[1] * m[10] - m[9] * m[2])
                    + m[8] * (m[1] * m[6] - m[5] * m[2]);
            if (det == 0) {
                throw matrix.error("a singular matrix cannot be decomposed into translation, rotation, scale");
            }
        }
        node.get("translation").floats(3, null);
        node.get("scale").floats(3, null);
        // A rotation that is not a unit quaternion is normalised by the reading (SceneReader).
        node.get("rotation").floats(4, null);
    }


    /** The root of node {@code i}'s tree (where a cycle, refused later, closes: any of its nodes). */
    private int rootOf(int i) {
        int r = i;
        for (int steps = 0; parent[r] >= 0 && steps < parent.length; steps++) {
            r = parent[r];
        }
        return r;
    }

    // ------------------------------------------------------------------------------------- skins

    private void checkSkin(JsonNode skin) throws GltfException {
        required(skin, "joints");
        int[] joints = CheckedDocument.indices(skin.get("joints"), doc.nodes, "nodes");
        int root = rootOf(joints[0]);
        for (int j : joints) {
            if (rootOf(j) != root) {
                throw skin.get("joints").error("joints " + joints[0] + " and " + j + " have no common root");
            }
        }
        int skeleton = ref(skin, "skeleton", doc.nodes, "nodes");
        if (skeleton >= 0) {
            for (int j : joints) {
                if (!isAncestorOrSelf(skeleton, j)) {
                    throw skin.get("skeleton").error("node " + skeleton + " is not an ancestor of joint " + j);
                }
            }
        }
        int ibm = ref(skin, "inverseBindMatrices", doc.accessors, "accessors");
        if (ibm >= 0) {
            JsonNode accessor = doc.accessor(ibm);
            JsonNode where = skin.get("inverseBindMatrices");
            if (!accessor.get("type").string().equals("MAT4") || (int) accessor.get("componentType").number() != FLOAT) {
                throw where.error("inverse bind matrices are MAT4 of floats");
            }
            if ((long) accessor.get("count").number() < joints.length) {
                throw where.error((long) accessor.get("count").number() + " inverse bind matrices for "
                        + joints.length + " joints");
            }
            if (accessor.has("bufferView") && doc.bufferView((int) accessor.get("bufferView").number())
                    .has("byteStride")) {
                doc.strideNotAllowed(where, "the inverse bind matrices");
            }
        }
        doc.extensions(skin, "skin");
    }

    private boolean isAncestorOrSelf(int ancestor, int node) {
        for (int n = node, steps = 0; n >= 0 && steps <= parent.length; n = parent[n], steps++) {
            if (n == ancestor) {
                return true;
            }
        }
        return false;
    }
}
