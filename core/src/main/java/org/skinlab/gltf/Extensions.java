package org.skinlab.gltf;

import java.util.Arrays;
import java.util.HashSet;
import java.util.Set;

/**
 * The extensions the importer understands. A required extension it does not support refuses
 * the file, naming the extension (Draco, meshopt and Basis/KTX2 data cannot be read without a
 * decoder); an unsupported extension that is only used is ignored with a warning.
 */
final class Extensions {
    static final String MESH_QUANTIZATION = "KHR_mesh_quantization";
    static final String TEXTURE_TRANSFORM = "KHR_texture_transform";
    static final String MATERIALS_UNLIT = "KHR_materials_unlit";
    private static final Set<String> SUPPORTED = new HashSet<>(Arrays.asList(MESH_QUANTIZATION, TEXTURE_TRANSFORM,
            MATERIALS_UNLIT));

    private Extensions() {
    }

    /** Whether the importer reads the extension's data (and the checks judge them). */
    static boolean isSupported(String name) {
        return SUPPORTED.contains(name);
    }

    /** Checks extensionsRequired and extensionsUsed; true when KHR_mesh_quantization is used. */
    static boolean check(GltfContext ctx, JsonNode root) throws GltfException {
        JsonNode required = root.get("extensionsRequired").arrayOrMissing();
        for (int i = 0; i < required.size(); i++) {
            String name = required.get(i).string();
            if (!SUPPORTED.contains(name)) {
                throw required.get(i).error("the file requires the extension " + name + why(name)
                        + ", which this importer does not support");
            }
        }
        JsonNode used = root.get("extensionsUsed").arrayOrMissing();
        boolean quantized = false;
        for (int i = 0; i < used.size(); i++) {
            String name = used.get(i).string();
            quantized |= name.equals(MESH_QUANTIZATION);
            if (!SUPPORTED.contains(name)) {
                ctx.warn(used.get(i).path(), "the extension " + name + " is not supported; what it adds is ignored");
            }
        }
        return quantized;
    }

    private static String why(String name) {
        switch (name) {
            case "KHR_draco_mesh_compression":
                return " (Draco-compressed geometry)";
            case "EXT_meshopt_compression":
                return " (meshoptimizer-compressed buffers)";
            case "KHR_texture_basisu":
                return " (KTX2/Basis Universal textures)";
            default:
                return "";
        }
    }
}
