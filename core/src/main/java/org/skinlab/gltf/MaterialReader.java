package org.skinlab.gltf;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.skinlab.model.Image;
import org.skinlab.model.Material;
import org.skinlab.model.Texture;

/**
 * Reads {@code /materials}, {@code /textures} and {@code /images}. A metallic-roughness material
 * becomes a LAMBERT material: diffuse = {@code baseColorFactor}, diffuse texture =
 * {@code baseColorTexture}, emission = {@code emissiveFactor} and {@code emissiveTexture};
 * metallic, roughness, normal and occlusion maps are not read (the viewer shades diffuse only).
 * Opacity is the base colour's alpha for {@code alphaMode} BLEND, else 1. A texture's
 * {@link Texture#texcoord()} is {@code TEXCOORD_n} for its {@code texCoord} n.
 *
 * <p>Images are never decoded here: a file image becomes its path inside the document's folder
 * (checked like buffer URIs).
 */
final class MaterialReader {
    private final GltfContext ctx;
    private final UriResolver uris;
    private final List<Image> images = new ArrayList<>();
    private final JsonNode textures;
    private final List<Material> materials = new ArrayList<>();
    /** Per material, the texCoord number its base colour texture uses, or -1 without one. */
    private final List<Integer> baseTexCoords = new ArrayList<>();

    MaterialReader(GltfContext ctx, UriResolver uris, JsonNode root) throws GltfException {
        this.ctx = ctx;
        this.uris = uris;
        JsonNode imageList = root.get("images").arrayOrMissing();
        for (int i = 0; i < imageList.size(); i++) {
            images.add(image(imageList.get(i), i));
        }
        this.textures = root.get("textures").arrayOrMissing();
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
        String uri = image.get("uri").string(null);
        String id = "/images/" + index;
        if (uri == null) {
            image.get("bufferView").integer(0, Integer.MAX_VALUE);
            return new Image(id, name, null, null);
        }
        if (UriResolver.isDataUri(uri)) {
            return new Image(id, name, null, null);
        }
        Path file = uris.file(uri, image.get("uri").path());
        return new Image(id, name, uri, file);
    }

    private Material material(JsonNode material, int index) throws GltfException {
        String name = material.get("name").string(null);
        Material.Builder b = new Material.Builder(GltfImporter.materialSymbol(index), name != null ? name
                : GltfImporter.materialSymbol(index)).shading(Material.Shading.LAMBERT);
        JsonNode pbr = material.get("pbrMetallicRoughness").objectOrMissing();
        float[] base = pbr.get("baseColorFactor").floats(4, new float[] {1, 1, 1, 1});
        b.diffuse(base);
        JsonNode baseTexture = pbr.get("baseColorTexture");
        int texCoord = -1;
        if (!baseTexture.isMissing()) {
            texCoord = baseTexture.get("texCoord").integer(0, 31, 0);
            b.diffuseTexture(texture(baseTexture, texCoord));
        }
        baseTexCoords.add(texCoord);
        float[] emissive = material.get("emissiveFactor").floats(3, new float[3]);
        b.emission(new float[] {emissive[0], emissive[1], emissive[2], 1f});
        JsonNode emissiveTexture = material.get("emissiveTexture");
        if (!emissiveTexture.isMissing()) {
            b.emissionTexture(texture(emissiveTexture, emissiveTexture.get("texCoord").integer(0, 31, 0)));
        }
        String alphaMode = material.get("alphaMode").string("OPAQUE");
        if (!alphaMode.equals("OPAQUE") && !alphaMode.equals("MASK") && !alphaMode.equals("BLEND")) {
            throw material.get("alphaMode").error("unknown alphaMode \"" + alphaMode + "\"");
        }
        b.opacity(alphaMode.equals("BLEND") ? Math.max(0f, Math.min(1f, base[3])) : 1f);
        return b.build();
    }

    private Texture texture(JsonNode info, int texCoord) throws GltfException {
        int t = info.get("index").index(textures.size(), "textures");
        JsonNode source = textures.get(t).get("source");
        if (source.isMissing()) {
            ctx.warn(textures.get(t).path(), "no source image (an extension's image format?); drawn untextured");
            return null;
        }
        Image image = images.get(source.index(images.size(), "images"));
        return new Texture(image, "TEXCOORD_" + texCoord);
    }
}
