package org.skinlab.gltf;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.skinlab.model.Image;
import org.skinlab.model.Material;
import org.skinlab.model.Texture;
import org.skinlab.model.TextureTransform;

/**
 * Reads {@code /materials}, {@code /textures} and {@code /images}. A metallic-roughness material
 * becomes a LAMBERT material: diffuse = {@code baseColorFactor}, diffuse texture =
 * {@code baseColorTexture}, emission = {@code emissiveFactor} and {@code emissiveTexture};
 * metallic, roughness, normal and occlusion maps are not read (the viewer shades diffuse only).
 * {@code KHR_materials_unlit} makes it CONSTANT, its emission the base colour and texture.
 * Opacity is the base colour's alpha for {@code alphaMode} BLEND, else 1. A texture's
 * {@link Texture#texcoord()} is {@code TEXCOORD_n} for its {@code texCoord} n.
 *
 * <p>{@code alphaMode}, {@code alphaCutoff} and {@code doubleSided} are carried as they are;
 * {@code KHR_texture_transform} on a texture becomes its {@link TextureTransform} (its
 * {@code texCoord} replaces the texture's). Images are never decoded here: a data URI or buffer
 * view image keeps its encoded bytes and media type, a file image becomes its path inside the
 * document's folder (checked like buffer URIs, not read).
 */
final class MaterialReader {
    private final GltfContext ctx;
    private final UriResolver uris;
    private final Buffers buffers;
    private final List<Image> images = new ArrayList<>();
    private final JsonNode textures;
    private final List<Material> materials = new ArrayList<>();
    /** Per material, the texCoord number its base colour texture uses, or -1 without one. */
    private final List<Integer> baseTexCoords = new ArrayList<>();

    MaterialReader(GltfContext ctx, UriResolver uris, Buffers buffers, JsonNode root) throws GltfException {
        this.ctx = ctx;
        this.uris = uris;
        this.buffers = buffers;
        JsonNode imageList = root.get("images").arrayOrMissing();
        for (int i = 0; i < imageList.size(); i++) {
            images.add(image(imageList.get(i), i));
        }
        this.textures = root.get("textures").arrayOrMissing();
        int samplers = root.get("samplers").arrayOrMissing().size();
        for (int t = 0; t < textures.size(); t++) {
            JsonNode sampler = textures.get(t).get("sampler");
            if (!sampler.isMissing()) {
                sampler.index(samplers, "samplers");
            }
            JsonNode source = textures.get(t).get("source");
            if (!source.isMissing()) {
                source.index(images.size(), "images");
            }
        }
        JsonNode list = root.get("materials").arrayOrMissing();
        for (int m = 0; m < list.size(); m++) {
            materials.add(material(list.get(m), m));
        }
    }

    List<Image> images() {
        return images;
    }

    List<Material> materials() {
        return materials;
    }

    /** The texCoord set number material {@code m}'s base colour texture uses, or -1. */
    int baseTexCoord(int m) {
        return baseTexCoords.get(m);
    }

    private Image image(JsonNode image, int index) throws GltfException {
        String name = image.get("name").string(null);
        JsonNode uriNode = image.get("uri");
        String uri = uriNode.string(null);
        String mimeType = image.get("mimeType").string(null);
        String id = "/images/" + index;
        if (uri == null) {
            int view = image.get("bufferView").index(buffers.viewCount(), "bufferViews");
            if (mimeType == null) {
                throw image.error("an image in a buffer view needs a mimeType");
            }
            byte[] bytes;
            try {
                bytes = buffers.copy(view);
            } catch (GltfException e) {
                // A picture is not needed to pose the model: drawn untextured, as a missing file is.
                ctx.warn(image.path(), "its buffer view's data cannot be had (" + e.getMessage() + ")");
                bytes = null;
            }
            return new Image(id, name, null, null, checked(mimeType, image), bytes);
        }
        if (image.has("bufferView")) {
            throw image.error("an image has either a uri or a bufferView, not both");
        }
        if (UriResolver.isDataUri(uri)) {
            String type = mimeType != null ? mimeType : UriResolver.dataMediaType(uri);
            return new Image(id, name, null, null, checked(type, image),
                    uris.decodeData(uri, uriNode.path(), GltfLimits.MAX_FILE_BYTES));
        }
        Path file = uris.linkCheckedFile(uri, uriNode.path());
        return new Image(id, name, uri, file, mimeType, null);
    }

    /** The media type; one that is neither PNG nor JPEG is kept with a warning (renderers say they cannot show it). */
    private String checked(String mimeType, JsonNode image) {
        if (!mimeType.equals("image/png") && !mimeType.equals("image/jpeg")) {
            ctx.warn(image.path(), "image type \"" + mimeType + "\" is neither PNG nor JPEG");
        }
        return mimeType;
    }

    private Material material(JsonNode material, int index) throws GltfException {
        String name = material.get("name").string(null);
        Material.Builder b = new Material.Builder(GltfImporter.materialSymbol(index), name != null ? name
                : GltfImporter.materialSymbol(index)).shading(Material.Shading.LAMBERT);
        JsonNode pbr = material.get("pbrMetallicRoughness").objectOrMissing();
        float[] baseColor = pbr.get("baseColorFactor").floats(4, new float[] {1, 1, 1, 1});
        b.diffuse(baseColor);
        JsonNode baseTexture = pbr.get("baseColorTexture");
        Texture base = baseTexture.isMissing() ? null : texture(baseTexture);
        b.diffuseTexture(base);
        baseTexCoords.add(base == null ? -1 : texCoordNumber(base));
        float[] emissive = material.get("emissiveFactor").floats(3, new float[3]);
        b.emission(new float[] {emissive[0], emissive[1], emissive[2], 1f});
        JsonNode emissiveTexture = material.get("emissiveTexture");
        if (!emissiveTexture.isMissing()) {
            b.emissionTexture(texture(emissiveTexture));
        }
        // Textures the viewer does not show must still name a texture.
        for (JsonNode info : new JsonNode[] {pbr.get("metallicRoughnessTexture"), material.get("normalTexture"),
                material.get("occlusionTexture")}) {
            if (!info.isMissing()) {
                info.get("index").index(textures.size(), "textures");
            }
        }
        JsonNode alphaNode = material.get("alphaMode");
        Material.AlphaMode alphaMode;
        try {
            alphaMode = Material.AlphaMode.valueOf(alphaNode.string("OPAQUE"));
        } catch (IllegalArgumentException e) {
            throw alphaNode.error("unknown alphaMode \"" + alphaNode.string() + "\"");
        }
        b.alphaMode(alphaMode);
        double cutoff = material.get("alphaCutoff").number(0.5);
        if (cutoff < 0) {
            throw material.get("alphaCutoff").error("alphaCutoff must not be negative");
        }
        b.alphaCutoff((float) cutoff);
        b.doubleSided(material.get("doubleSided").bool(false));
        b.opacity(alphaMode == Material.AlphaMode.BLEND ? Math.max(0f, Math.min(1f, baseColor[3])) : 1f);
        if (material.get("extensions").objectOrMissing().has(Extensions.MATERIALS_UNLIT)) {
            // Unlit: the base colour is what is seen, as COLLADA's constant shading shows its emission.
            b.shading(Material.Shading.CONSTANT).emission(baseColor).emissionTexture(base);
        }
        return b.build();
    }

    private static int texCoordNumber(Texture t) {
        return Integer.parseInt(t.texcoord().substring("TEXCOORD_".length()));
    }

    /** A textureInfo: its texture's image, texCoord set and KHR_texture_transform. */
    private Texture texture(JsonNode info) throws GltfException {
        int t = info.get("index").index(textures.size(), "textures");
        int texCoord = info.get("texCoord").integer(0, 31, 0);
        JsonNode source = textures.get(t).get("source");
        if (source.isMissing()) {
            ctx.warn(textures.get(t).path(), "no source image (an extension's image format?); drawn untextured");
            return null;
        }
        Image image = images.get(source.index(images.size(), "images"));
        JsonNode transform = info.get("extensions").objectOrMissing().get(Extensions.TEXTURE_TRANSFORM);
        if (transform.isMissing()) {
            return new Texture(image, "TEXCOORD_" + texCoord);
        }
        float[] offset = transform.get("offset").floats(2, new float[] {0, 0});
        float[] scale = transform.get("scale").floats(2, new float[] {1, 1});
        float rotation = (float) transform.get("rotation").number(0);
        texCoord = transform.get("texCoord").integer(0, 31, texCoord);
        return new Texture(image, "TEXCOORD_" + texCoord,
                TextureTransform.fromGltf(offset[0], offset[1], rotation, scale[0], scale[1]));
    }
}
