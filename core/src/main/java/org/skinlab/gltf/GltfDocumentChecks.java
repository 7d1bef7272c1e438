package org.skinlab.gltf;

import static org.skinlab.gltf.AccessorFormat.BYTE;
import static org.skinlab.gltf.AccessorFormat.FLOAT;
import static org.skinlab.gltf.AccessorFormat.SHORT;
import static org.skinlab.gltf.AccessorFormat.UNSIGNED_BYTE;
import static org.skinlab.gltf.AccessorFormat.UNSIGNED_INT;
import static org.skinlab.gltf.AccessorFormat.UNSIGNED_SHORT;
import static org.skinlab.gltf.AccessorFormat.componentSize;
import static org.skinlab.gltf.AccessorFormat.components;
import static org.skinlab.gltf.AccessorFormat.elementSize;
import static org.skinlab.gltf.AccessorFormat.trailingPadding;
import static org.skinlab.gltf.CheckedDocument.oneOf;
import static org.skinlab.gltf.CheckedDocument.range;
import static org.skinlab.gltf.CheckedDocument.ref;
import static org.skinlab.gltf.CheckedDocument.required;

import java.util.Arrays;
import java.util.Set;

/**
 * A pass over the whole JSON document before anything is built, refusing what the glTF 2.0
 * specification (its JSON schema and its "valid glTF" rules, as the Khronos glTF-Validator checks
 * them) forbids but reading alone would not notice: every object is checked, used or not, so a
 * file the validator reports errors for is refused with the pointer of the first one we meet.
 *
 * <p>Here: the root (asset, extension lists), buffers, buffer views, accessors (sizes, alignment,
 * strides, sparse storage), cameras, images, samplers, textures, materials. Meshes, nodes,
 * scenes, skins and animations are {@link GltfSceneChecks}; the values inside the buffers
 * (bounds, indices, weights, key times) are {@link GltfDataChecks}. The content of an extension
 * we do not read is not judged (the importer warns that it is ignored).
 */
final class GltfDocumentChecks {
    static final int ARRAY_BUFFER = 34962;
    static final int ELEMENT_ARRAY_BUFFER = 34963;

    private final CheckedDocument doc;

    private GltfDocumentChecks(CheckedDocument doc) {
        this.doc = doc;
    }

    /** Refuses the document at its first violation of the specification (see the class comment). */
    static void check(JsonNode root, GltfContext ctx) throws GltfException {
        CheckedDocument doc = new CheckedDocument(ctx, root);
        new GltfDocumentChecks(doc).checkAll();
        new GltfSceneChecks(doc).checkAll();
    }

    private void checkAll() throws GltfException {
        checkRoot();
        for (int i = 0; i < doc.buffers; i++) {
            checkBuffer(doc.root.get("buffers").get(i));
        }
        for (int i = 0; i < doc.bufferViews; i++) {
            checkBufferView(doc.bufferView(i));
        }
        for (int i = 0; i < doc.accessors; i++) {
            checkAccessor(doc.accessor(i));
        }
        for (int i = 0; i < doc.cameras; i++) {
            checkCamera(doc.root.get("cameras").get(i));
        }
        for (int i = 0; i < doc.images; i++) {
            checkImage(doc.root.get("images").get(i));
        }
        for (int i = 0; i < doc.samplers; i++) {
            checkSampler(doc.root.get("samplers").get(i));
        }
        for (int i = 0; i < doc.textures; i++) {
            JsonNode texture = doc.root.get("textures").get(i);
            ref(texture, "sampler", doc.samplers, "samplers");
            ref(texture, "source", doc.images, "images");
            doc.extensions(texture, "texture");
        }
        for (int i = 0; i < doc.materials; i++) {
            checkMaterial(doc.root.get("materials").get(i));
        }
    }

    private void checkRoot() throws GltfException {
        JsonNode root = doc.root;
        // The asset (its presence and version) is the importer's first reading.
        JsonNode asset = root.get("asset").objectOrMissing();
        asset.get("copyright").string("");
        asset.get("generator").string("");
        Set<String> requiredExtensions = CheckedDocument.stringSet(root.get("extensionsRequired"));
        JsonNode requiredList = root.get("extensionsRequired");
        int i = 0;
        for (String name : requiredExtensions) {
            if (!doc.used.contains(name)) {
                throw requiredList.get(i).error("the required extension " + name + " is not in extensionsUsed");
            }
            i++;
        }
        if (doc.used.contains("KHR_mesh_quantization") && !requiredExtensions.contains("KHR_mesh_quantization")) {
            JsonNode usedList = root.get("extensionsUsed");
            int at = Arrays.asList(doc.used.toArray()).indexOf("KHR_mesh_quantization");
            throw usedList.get(at).error("KHR_mesh_quantization must also be in extensionsRequired");
        }
        ref(root, "scene", doc.scenes, "scenes");
        doc.extensions(root, "root");
    }



    private void checkBuffer(JsonNode buffer) throws GltfException {
        required(buffer, "byteLength");
        buffer.get("byteLength").integer(1, Long.MAX_VALUE >> 11);
        JsonNode uri = buffer.get("uri");
        if (!uri.isMissing()) {
            if (UriResolver.isDataUri(uri.string())) {
                CheckedDocument.dataUri(uri, "", "application/octet-stream", "application/gltf-buffer");
            }
        }
        doc.extensions(buffer, "buffer");
    }

    private void checkBufferView(JsonNode view) throws GltfException {
        required(view, "buffer", "byteLength");
        int buffer = ref(view, "buffer", doc.buffers, "buffers");
        long offset = view.get("byteOffset").integer(0, Integer.MAX_VALUE, 0);
        long length = view.get("byteLength").integer(1, Integer.MAX_VALUE);
        long bufferLength = (long) doc.root.get("buffers").get(buffer).get("byteLength").number();
        if (offset + length > bufferLength) {
            throw view.get("byteLength").error("bytes " + offset + " to " + (offset + length)
                    + " do not fit in buffer " + buffer + " of " + bufferLength + " bytes");
        }
        JsonNode stride = view.get("byteStride");
        if (!stride.isMissing()) {
            int s = stride.integer(4, 252);
            if (s % 4 != 0) {
                throw stride.error("byteStride " + s + " is not a multiple of 4");
            }
            if (s > length) {
                throw stride.error("byteStride " + s + " is longer than the view (" + length + " bytes)");
            }
        }
        int target = oneOf(view.get("target"), 0, ARRAY_BUFFER, ELEMENT_ARRAY_BUFFER);
        if (target == ELEMENT_ARRAY_BUFFER && !stride.isMissing()) {
            doc.strideNotAllowed(stride, "indices (target 34963)");
        }
        doc.extensions(view, "bufferView");
    }

    private void checkAccessor(JsonNode accessor) throws GltfException {
        required(accessor, "componentType", "count", "type");
        int componentType = oneOf(accessor.get("componentType"), 0, BYTE, UNSIGNED_BYTE, SHORT, UNSIGNED_SHORT,
                UNSIGNED_INT, FLOAT);
        long count = accessor.get("count").integer(1, Integer.MAX_VALUE);
        if (accessor.get("normalized").bool(false) && (componentType == FLOAT || componentType == UNSIGNED_INT)) {
            throw accessor.get("normalized").error("only byte and short components can be normalized");
        }
        // The checks that follow the accessor's references rely on these indices.
        int view = ref(accessor, "bufferView", doc.bufferViews, "bufferViews");
        JsonNode byteOffset = accessor.get("byteOffset");
        long offset = byteOffset.integer(0, Integer.MAX_VALUE, 0);
        if (view < 0 && !byteOffset.isMissing()) {
            throw byteOffset.error("byteOffset needs a bufferView");
        }
        String type = accessor.get("type").string();
        if (components(type) == 0) {
            // The schema leaves the list open (a later glTF may add types): an accessor of a type
            // we do not know is refused only by whatever uses it.
            doc.ctx.warn(accessor.get("type").path(), "unknown accessor type \"" + type + "\"; the accessor cannot be read");
            return;
        }
        for (String bound : new String[] {"min", "max"}) {
            JsonNode values = accessor.get(bound);
            if (!values.isMissing() && values.size() != components(type)) {
                throw values.error(type + " needs " + components(type) + " values, found " + values.size());
            }
            for (int i = 0; i < values.size(); i++) {
                values.get(i).number();
            }
        }
        if (view >= 0) {
            checkAccessorFits(accessor, doc.bufferView(view), offset, count, type, componentType);
        }
        checkSparse(accessor, count, type, componentType);
        doc.extensions(accessor, "accessor");
    }

    private void checkAccessorFits(JsonNode accessor, JsonNode view, long offset, long count, String type,
            int componentType) throws GltfException {
        JsonNode where = accessor.has("byteOffset") ? accessor.get("byteOffset") : accessor;
        int size = componentSize(componentType);
        if (offset % size != 0) {
            throw where.error("byteOffset " + offset + " is not a multiple of the component size " + size);
        }
        if (type.startsWith("MAT") && offset % 4 != 0) {
            throw where.error("a matrix's columns start at multiples of 4 bytes; byteOffset is " + offset);
        }
        long viewOffset = (long) view.get("byteOffset").number(0);
        if ((viewOffset + offset) % size != 0) {
            throw accessor.error("the data start at byte " + (viewOffset + offset)
                    + " of the buffer, not a multiple of the component size " + size);
        }
        long element = elementSize(type, componentType);
        long stride = (long) view.get("byteStride").number(0);
        if (stride != 0 && stride < element) {
            throw accessor.error("the view's byteStride " + stride + " is shorter than an element (" + element
                    + " bytes)");
        }
        // The last element's trailing column padding need not be there (as the validator reads it).
        long needed = offset + (count - 1) * Math.max(stride, element) + element - trailingPadding(type, componentType);
        long length = (long) view.get("byteLength").number();
        if (needed > length) {
            throw where.error(count + " elements from byte " + offset + " need " + needed
                    + " bytes; the buffer view has " + length);
        }
    }

    private void checkSparse(JsonNode accessor, long count, String type, int componentType) throws GltfException {
        JsonNode sparse = accessor.get("sparse").objectOrMissing();
        if (sparse.isMissing()) {
            return;
        }
        required(sparse, "count", "indices", "values");
        long n = sparse.get("count").integer(1, Integer.MAX_VALUE);
        if (n > count) {
            throw sparse.get("count").error("sparse count " + n + " exceeds the accessor's count " + count);
        }
        JsonNode indices = sparse.get("indices").objectOrMissing();
        required(indices, "bufferView", "componentType");
        int indexType = oneOf(indices.get("componentType"), 0, UNSIGNED_BYTE, UNSIGNED_SHORT, UNSIGNED_INT);
        sparseStorage(indices, n * componentSize(indexType));
        JsonNode values = sparse.get("values").objectOrMissing();
        required(values, "bufferView");
        sparseStorage(values, n * elementSize(type, componentType));
    }

    private void sparseStorage(JsonNode part, long bytes) throws GltfException {
        int view = ref(part, "bufferView", doc.bufferViews, "bufferViews");
        JsonNode bufferView = doc.bufferView(view);
        if (bufferView.has("byteStride")) {
            throw part.get("bufferView").error("a sparse accessor's buffer view has no byteStride");
        }
        long offset = part.get("byteOffset").integer(0, Integer.MAX_VALUE, 0);
        long length = (long) bufferView.get("byteLength").number();
        if (offset + bytes > length) {
            throw part.error(bytes + " bytes from byte " + offset + " do not fit in buffer view " + view + " of "
                    + length + " bytes");
        }
    }

    private void checkCamera(JsonNode camera) throws GltfException {
        required(camera, "type");
        String type = camera.get("type").string();
        if (!type.equals("perspective") && !type.equals("orthographic")) {
            doc.ctx.warn(camera.get("type").path(), "unknown camera type \"" + type + "\"");
            return;
        }
        String other = type.equals("perspective") ? "orthographic" : "perspective";
        if (camera.has(other)) {
            throw camera.error("a " + type + " camera has an " + other + " object");
        }
        required(camera, type);
        JsonNode p = camera.get(type).objectOrMissing();
        if (type.equals("perspective")) {
            required(p, "yfov", "znear");
            positive(p.get("yfov"));
            positive(p.get("znear"));
            if (p.has("aspectRatio")) {
                positive(p.get("aspectRatio"));
            }
            if (p.has("zfar") && positive(p.get("zfar")) <= p.get("znear").number()) {
                throw p.error("zfar is not beyond znear");
            }
        } else {
            required(p, "xmag", "ymag", "zfar", "znear");
            for (String mag : new String[] {"xmag", "ymag"}) {
                if (p.get(mag).number() == 0) {
                    throw p.get(mag).error(mag + " is 0");
                }
            }
            range(p.get("znear"), 0, Double.MAX_VALUE, 0);
            if (positive(p.get("zfar")) <= p.get("znear").number()) {
                throw p.error("zfar is not beyond znear");
            }
        }
        doc.extensions(camera, "camera");
    }

    private static double positive(JsonNode n) throws GltfException {
        double v = n.number();
        if (v <= 0) {
            throw n.error(v + " is not positive");
        }
        return v;
    }

    private void checkImage(JsonNode image) throws GltfException {
        if (image.has("uri") == image.has("bufferView")) {
            throw image.error("an image has either a uri or a bufferView");
        }
        boolean webp = doc.used.contains("EXT_texture_webp");
        String[] types = webp ? new String[] {"image/jpeg", "image/png", "image/webp"}
                : new String[] {"image/jpeg", "image/png"};
        String mimeType = oneOf(image.get("mimeType"), "", types);
        if (image.has("bufferView")) {
            int view = ref(image, "bufferView", doc.bufferViews, "bufferViews");
            if (mimeType.isEmpty()) {
                throw image.get("bufferView").error("an image in a buffer view needs a mimeType");
            }
            if (doc.bufferView(view).has("byteStride")) {
                doc.strideNotAllowed(image.get("bufferView"), "an image's bytes");
            }
        } else {
            if (UriResolver.isDataUri(image.get("uri").string())) {
                CheckedDocument.dataUri(image.get("uri"), mimeType, types);
            }
        }
        doc.extensions(image, "image");
    }

    private void checkSampler(JsonNode sampler) throws GltfException {
        oneOf(sampler.get("magFilter"), 0, 9728, 9729);
        oneOf(sampler.get("minFilter"), 0, 9728, 9729, 9984, 9985, 9986, 9987);
        oneOf(sampler.get("wrapS"), 0, 33071, 33648, 10497);
        oneOf(sampler.get("wrapT"), 0, 33071, 33648, 10497);
        doc.extensions(sampler, "sampler");
    }

    private void checkMaterial(JsonNode material) throws GltfException {
        JsonNode pbr = material.get("pbrMetallicRoughness").objectOrMissing();
        if (!pbr.isMissing()) {
            CheckedDocument.numbers(pbr.get("baseColorFactor"), 4, 0, 1);
            range(pbr.get("metallicFactor"), 0, 1, 1);
            range(pbr.get("roughnessFactor"), 0, 1, 1);
            textureInfo(pbr.get("baseColorTexture"));
            textureInfo(pbr.get("metallicRoughnessTexture"));
            doc.extensions(pbr, "pbrMetallicRoughness");
        }
        textureInfo(material.get("normalTexture"));
        textureInfo(material.get("occlusionTexture"));
        range(material.get("occlusionTexture").get("strength"), 0, 1, 1);
        textureInfo(material.get("emissiveTexture"));
        CheckedDocument.numbers(material.get("emissiveFactor"), 3, 0, 1);
        oneOf(material.get("alphaMode"), "OPAQUE", "OPAQUE", "MASK", "BLEND");
        range(material.get("alphaCutoff"), 0, Double.MAX_VALUE, 0.5);
        material.get("doubleSided").bool(false);
        doc.extensions(material, "material");
    }

    private void textureInfo(JsonNode info) throws GltfException {
        if (info.isMissing()) {
            return;
        }
        info.objectOrMissing();
        required(info, "index");
        ref(info, "index", doc.textures, "textures");
        info.get("texCoord").integer(0, Integer.MAX_VALUE, 0);
        doc.extensions(info, "textureInfo");
        JsonNode transform = info.get("extensions").get("KHR_texture_transform");
        if (!transform.isMissing()) {
            CheckedDocument.numbers(transform.get("offset"), 2, -Double.MAX_VALUE, Double.MAX_VALUE);
            CheckedDocument.numbers(transform.get("scale"), 2, -Double.MAX_VALUE, Double.MAX_VALUE);
            transform.get("rotation").number(0);
            transform.get("texCoord").integer(0, Integer.MAX_VALUE, 0);
        }
    }
}
