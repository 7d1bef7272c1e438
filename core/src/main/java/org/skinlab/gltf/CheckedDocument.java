package org.skinlab.gltf;

import java.util.Arrays;
import java.util.Collections;
import java.util.HashSet;
import java.util.LinkedHashSet;
import java.util.Locale;
import java.util.Set;

/**
 * The document the checks ({@link GltfDocumentChecks} and the classes it calls) walk, with the
 * sizes of its top-level arrays (to resolve indices) and the small shared rules: required
 * properties, enumerations, indices, arrays of objects, extension objects.
 */
final class CheckedDocument {
    /**
     * Where each Khronos extension may appear (glTF extension registry); an extension object
     * elsewhere is misplaced. Extensions not listed are unknown to us and never misplaced.
     */
    private static final String[][] PLACES = {
        {"KHR_texture_transform", "textureInfo"},
        {"KHR_mesh_quantization"},
        {"KHR_materials_emissive_strength", "material"},
        {"KHR_materials_unlit", "material"},
        {"KHR_materials_anisotropy", "material"},
        {"KHR_materials_clearcoat", "material"},
        {"KHR_materials_dispersion", "material"},
        {"KHR_materials_ior", "material"},
        {"KHR_materials_iridescence", "material"},
        {"KHR_materials_pbrSpecularGlossiness", "material"},
        {"KHR_materials_sheen", "material"},
        {"KHR_materials_specular", "material"},
        {"KHR_materials_transmission", "material"},
        {"KHR_materials_volume", "material"},
        {"KHR_materials_variants", "root", "primitive"},
        {"KHR_lights_punctual", "root", "node"},
        {"KHR_node_visibility", "node"},
        {"KHR_animation_pointer", "target"},
        {"EXT_texture_webp", "texture"},
        {"EXT_texture_avif", "texture"},
        {"KHR_texture_basisu", "texture"},
        {"KHR_draco_mesh_compression", "primitive"},
        {"EXT_meshopt_compression", "buffer", "bufferView"},
        {"EXT_mesh_gpu_instancing", "node"},
    };

    final GltfContext ctx;
    final JsonNode root;
    final Set<String> used;
    final int accessors;
    final int animations;
    final int buffers;
    final int bufferViews;
    final int cameras;
    final int images;
    final int materials;
    final int meshes;
    final int nodes;
    final int samplers;
    final int scenes;
    final int skins;
    final int textures;

    CheckedDocument(GltfContext ctx, JsonNode root) throws GltfException {
        this.ctx = ctx;
        this.root = root;
        this.used = stringSet(root.get("extensionsUsed"));
        accessors = objects(root, "accessors");
        animations = objects(root, "animations");
        buffers = objects(root, "buffers");
        bufferViews = objects(root, "bufferViews");
        cameras = objects(root, "cameras");
        images = objects(root, "images");
        materials = objects(root, "materials");
        meshes = objects(root, "meshes");
        nodes = objects(root, "nodes");
        samplers = objects(root, "samplers");
        scenes = objects(root, "scenes");
        skins = objects(root, "skins");
        textures = objects(root, "textures");
    }

    JsonNode accessor(int i) throws GltfException {
        return root.get("accessors").get(i);
    }

    JsonNode bufferView(int i) throws GltfException {
        return root.get("bufferViews").get(i);
    }

    JsonNode node(int i) throws GltfException {
        return root.get("nodes").get(i);
    }

    JsonNode mesh(int i) throws GltfException {
        return root.get("meshes").get(i);
    }

    /** The element count of {@code parent[key]}, which must be a non-empty array of objects when present. */
    static int objects(JsonNode parent, String key) throws GltfException {
        JsonNode array = parent.get(key).arrayOrMissing();
        for (int i = 0; i < array.size(); i++) {
            array.get(i).objectOrMissing();
            if (!array.get(i).isObject()) {
                throw array.get(i).error("expected a JSON object");
            }
        }
        return array.size();
    }

    /** The distinct strings of a non-empty array (none when missing); a repeated string is refused. */
    static Set<String> stringSet(JsonNode array) throws GltfException {
        array.arrayOrMissing();
        Set<String> set = new LinkedHashSet<>();
        for (int i = 0; i < array.size(); i++) {
            if (!set.add(array.get(i).string())) {
                throw array.get(i).error("\"" + array.get(i).string() + "\" is listed twice");
            }
        }
        return set;
    }

    /** Refuses an object that lacks one of the properties the specification requires. */
    static void required(JsonNode object, String... keys) throws GltfException {
        for (String key : keys) {
            if (!object.has(key)) {
                throw object.error("the required property \"" + key + "\" is missing");
            }
        }
    }

    /** The index {@code object[key]} into an array of {@code count} {@code what}, or -1 when absent. */
    static int ref(JsonNode object, String key, int count, String what) throws GltfException {
        JsonNode n = object.get(key);
        return n.isMissing() ? -1 : n.index(count, what);
    }

    /** The integer {@code n}, one of {@code allowed}, or {@code otherwise} when missing. */
    static int oneOf(JsonNode n, int otherwise, int... allowed) throws GltfException {
        if (n.isMissing()) {
            return otherwise;
        }
        int v = n.integer(Integer.MIN_VALUE, Integer.MAX_VALUE);
        for (int a : allowed) {
            if (v == a) {
                return v;
            }
        }
        throw n.error(v + " is not one of " + Arrays.toString(allowed));
    }

    /** The string {@code n}, one of {@code allowed}, or {@code otherwise} when missing. */
    static String oneOf(JsonNode n, String otherwise, String... allowed) throws GltfException {
        if (n.isMissing()) {
            return otherwise;
        }
        String v = n.string();
        if (!Arrays.asList(allowed).contains(v)) {
            throw n.error("\"" + v + "\" is not one of " + Arrays.toString(allowed));
        }
        return v;
    }

    /** A number within [min, max] ({@code otherwise} when missing). */
    static double range(JsonNode n, double min, double max, double otherwise) throws GltfException {
        if (n.isMissing()) {
            return otherwise;
        }
        double v = n.number();
        if (v < min || v > max) {
            throw n.error(v + " is outside [" + min + ", " + max + "]");
        }
        return v;
    }

    /** {@code n} numbers, each within [min, max], when present. */
    static void numbers(JsonNode array, int n, double min, double max) throws GltfException {
        if (array.isMissing()) {
            return;
        }
        if (array.size() != n) {
            throw array.error("expected " + n + " numbers, found " + array.size());
        }
        for (int i = 0; i < n; i++) {
            range(array.get(i), min, max, 0);
        }
    }

    /** A non-empty array of distinct indices into {@code count} {@code what}, when present. */
    static int[] indices(JsonNode array, int count, String what) throws GltfException {
        array.arrayOrMissing();
        int[] result = new int[array.size()];
        Set<Integer> seen = new HashSet<>();
        for (int i = 0; i < result.length; i++) {
            result[i] = array.get(i).index(count, what);
            if (!seen.add(result[i])) {
                throw array.get(i).error(what + " " + result[i] + " is listed twice");
            }
        }
        return result;
    }

    /**
     * Checks a {@code data:} URI's syntax (RFC 2397) without decoding it: a media type, one of
     * {@code types} (or, when {@code declared} is not empty, that one), parameters that are not
     * empty, and for base64 data a payload of whole base64 quads.
     */
    static void dataUri(JsonNode uriNode, String declared, String... types) throws GltfException {
        String uri = uriNode.string();
        int comma = uri.indexOf(',');
        if (comma < 0) {
            throw uriNode.error("a data URI without a comma before its data");
        }
        String[] header = uri.substring(5, comma).split(";", -1);
        String type = header[0].toLowerCase(Locale.ROOT);
        if (!Arrays.asList(types).contains(type)) {
            throw uriNode.error("a data URI of type \"" + type + "\"; expected one of " + Arrays.toString(types));
        }
        if (!declared.isEmpty() && !declared.equals(type)) {
            throw uriNode.error("a data URI of type \"" + type + "\" but the mimeType says " + declared);
        }
        for (int i = 1; i < header.length; i++) {
            if (header[i].isEmpty()) {
                throw uriNode.error("a data URI with an empty parameter (\"" + uri.substring(0, comma) + "\")");
            }
        }
        if (header[header.length - 1].equalsIgnoreCase("base64") && !isBase64(uri, comma + 1)) {
            throw uriNode.error("the data URI's payload is not base64");
        }
    }

    private static boolean isBase64(String s, int from) {
        int n = s.length() - from;
        if (n % 4 != 0) {
            return false;
        }
        for (int i = from; i < s.length(); i++) {
            char c = s.charAt(i);
            boolean padding = c == '=' && i >= s.length() - 2 && (i == s.length() - 1 || s.charAt(i + 1) == '=');
            if (!(c >= 'A' && c <= 'Z' || c >= 'a' && c <= 'z' || c >= '0' && c <= '9' || c == '+' || c == '/'
                    || padding)) {
                return false;
            }
        }
        return true;
    }

    /**
     * The extension objects of {@code object}, a {@code kind} of glTF object: each must be an
     * object, declared in {@code extensionsUsed}, and, for an extension we read, in a place where
     * the registry allows it (the content of an extension we do not read is not ours to judge).
     */
    void extensions(JsonNode object, String kind) throws GltfException {
        JsonNode extensions = object.get("extensions").objectOrMissing();
        for (String name : extensions.keys()) {
            JsonNode ext = extensions.get(name);
            if (!ext.isObject()) {
                throw ext.error("an extension must be a JSON object");
            }
            if (!used.contains(name)) {
                throw ext.error("the extension " + name + " is not declared in extensionsUsed");
            }
            if (Extensions.isSupported(name) && !placedIn(name).contains(kind)) {
                throw ext.error("the extension " + name + " does not belong on a " + kind);
            }
        }
    }

    private static Set<String> placedIn(String extension) {
        for (String[] p : PLACES) {
            if (p[0].equals(extension)) {
                return new HashSet<>(Arrays.asList(p).subList(1, p.length));
            }
        }
        return Collections.emptySet();
    }
}
