package org.skinlab.gltf;

import static org.skinlab.gltf.CheckedDocument.oneOf;
import static org.skinlab.gltf.CheckedDocument.ref;
import static org.skinlab.gltf.CheckedDocument.required;
import static org.skinlab.gltf.AccessorFormat.BYTE;
import static org.skinlab.gltf.AccessorFormat.FLOAT;
import static org.skinlab.gltf.AccessorFormat.SHORT;
import static org.skinlab.gltf.AccessorFormat.UNSIGNED_BYTE;
import static org.skinlab.gltf.AccessorFormat.UNSIGNED_SHORT;

import java.util.Arrays;
import java.util.List;

/**
 * The part of {@link GltfDocumentChecks} about one animation: its samplers' accessors (key times
 * are float scalars with bounds, outputs have the target's format and the count the interpolation
 * needs) and its channels (never a node given by a matrix). Morph weight channels and a target
 * animated twice are {@link AnimationReader}'s checks.
 */
final class AnimationChecks {
    private static final List<String> PATHS = Arrays.asList("translation", "rotation", "scale", "weights");

    private final CheckedDocument doc;

    AnimationChecks(CheckedDocument doc) {
        this.doc = doc;
    }

    void check(JsonNode animation) throws GltfException {
        required(animation, "channels", "samplers");
        int samplers = CheckedDocument.objects(animation, "samplers");
        for (int s = 0; s < samplers; s++) {
            checkSampler(animation.get("samplers").get(s));
        }
        int channels = CheckedDocument.objects(animation, "channels");
        for (int c = 0; c < channels; c++) {
            JsonNode channel = animation.get("channels").get(c);
            required(channel, "sampler", "target");
            int sampler = ref(channel, "sampler", samplers, "samplers of the animation");
            JsonNode target = channel.get("target").objectOrMissing();
            required(target, "path");
            String path = target.get("path").string();
            doc.extensions(target, "target");
            doc.extensions(channel, "channel");
            if (!target.has("node")) {
                continue;
            }
            int node = ref(target, "node", doc.nodes, "nodes");
            if (!PATHS.contains(path)) {
                // An open list in the schema: the importer skips the channel with a warning.
                continue;
            }
            if (path.equals("weights")) {
                // Morph weight channels, and two channels on one target, are the reading's
                // checks (AnimationReader).
                continue;
            }
            checkTarget(target, doc.node(node));
            checkOutput(channel.get("sampler"), animation.get("samplers").get(sampler), doc.node(node), path);
        }
        doc.extensions(animation, "animation");
    }

    private void checkSampler(JsonNode sampler) throws GltfException {
        required(sampler, "input", "output");
        JsonNode input = doc.accessor(ref(sampler, "input", doc.accessors, "accessors"));
        ref(sampler, "output", doc.accessors, "accessors");
        String interpolation = oneOf(sampler.get("interpolation"), "LINEAR", "LINEAR", "STEP", "CUBICSPLINE");
        if (!input.get("type").string().equals("SCALAR") || (int) input.get("componentType").number() != FLOAT) {
            throw sampler.get("input").error("key times are float SCALARs");
        }
        if (!input.has("min") || !input.has("max")) {
            throw sampler.get("input").error("the key times' accessor needs min and max");
        }
        if (interpolation.equals("CUBICSPLINE") && input.get("count").number() < 2) {
            throw sampler.get("input").error("CUBICSPLINE needs at least two keys");
        }
        for (String key : new String[] {"input", "output"}) {
            JsonNode accessor = doc.accessor((int) sampler.get(key).number());
            if (accessor.has("bufferView")
                    && doc.bufferView((int) accessor.get("bufferView").number()).has("byteStride")) {
                doc.strideNotAllowed(sampler.get(key), "the sampler's " + key + " values");
            }
        }
    }


    private static void checkTarget(JsonNode target, JsonNode node) throws GltfException {
        if (node.has("matrix")) {
            throw target.error("the node has a matrix; only translation, rotation and scale can be animated");
        }
    }

    private void checkOutput(JsonNode where, JsonNode sampler, JsonNode node, String path) throws GltfException {
        JsonNode input = doc.accessor((int) sampler.get("input").number());
        JsonNode output = doc.accessor((int) sampler.get("output").number());
        String type = output.get("type").string();
        int component = (int) output.get("componentType").number();
        boolean normalized = output.get("normalized").bool(false);
        boolean ints = normalized && (component == BYTE || component == UNSIGNED_BYTE || component == SHORT
                || component == UNSIGNED_SHORT);
        boolean ok;
        int width = 1;
        switch (path) {
            case "rotation":
                ok = type.equals("VEC4") && (component == FLOAT || ints);
                break;
            case "weights":
                ok = type.equals("SCALAR") && (component == FLOAT || ints);
                width = doc.mesh((int) node.get("mesh").number()).get("primitives").get(0).get("targets").size();
                break;
            default:
                ok = type.equals("VEC3") && (component == FLOAT || doc.used.contains("KHR_mesh_quantization"));
        }
        if (!ok) {
            throw where.error("the output accessor (" + type + " of " + component + ") cannot animate " + path);
        }
        long keys = (long) input.get("count").number();
        long perKey = width * (sampler.get("interpolation").string("LINEAR").equals("CUBICSPLINE") ? 3L : 1L);
        if ((long) output.get("count").number() != keys * perKey) {
            throw where.error("the output has " + (long) output.get("count").number() + " values for " + keys
                    + " keys; " + perKey + " per key expected");
        }
    }
}
