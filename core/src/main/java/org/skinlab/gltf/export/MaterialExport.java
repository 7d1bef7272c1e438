package org.skinlab.gltf.export;

import java.io.IOException;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;

import org.skinlab.model.Image;
import org.skinlab.model.Material;
import org.skinlab.model.Texture;
import org.skinlab.model.TextureTransform;

import com.fasterxml.jackson.core.JsonGenerator;

/**
 * Materials, textures and images, as glTF's metallic-roughness model reads back into what the
 * importer makes of it: base colour = the diffuse colour and texture (for CONSTANT shading, the
 * emission, with {@code KHR_materials_unlit}), emissive = the emission; metallic 0, and roughness
 * from the specular exponent ({@code sqrt(2 / (shininess + 2))}, the Blinn-Phong to microfacet
 * correspondence; 1 without one). {@code alphaMode} as read, except that a BLEND material that is
 * fully opaque and untextured (every COLLADA material) is written OPAQUE; {@code doubleSided} as
 * read. A texture's coordinate transform becomes {@code KHR_texture_transform} (shear, which it
 * cannot hold, is dropped). Images are embedded (PNG and JPEG, told by their bytes); any other
 * image, or one whose file cannot be read, is left out with a warning.
 */
final class MaterialExport {
    static final String UNLIT = "KHR_materials_unlit";
    static final String TEXTURE_TRANSFORM = "KHR_texture_transform";
    /** Larger image files are left out (with a warning) rather than read into memory. */
    static final long MAX_IMAGE_BYTES = 256L << 20;

    /** A material as drawn with one texture coordinate set. */
    private record Key(Material material, int texCoord) {
    }

    /** An embedded image: its view and media type. */
    private record Embedded(int view, String mimeType, String name) {
    }

    /** A glTF texture and the set and transform a material samples it with. */
    private record TextureRef(int texture, int texCoord, TextureTransform transform) {
    }

    private final BinaryChunk bin;
    private final List<String> warnings;
    private final java.util.Set<String> extensions;
    private final Map<Key, Integer> materialIndex = new HashMap<>();
    private final List<Key> materials = new ArrayList<>();
    private final Map<Image, Integer> imageIndex = new IdentityHashMap<>();
    private final List<Embedded> images = new ArrayList<>();
    private final List<Integer> textureImages = new ArrayList<>();
    private final Map<Integer, Integer> textureOfImage = new HashMap<>();

    MaterialExport(BinaryChunk bin, List<String> warnings, java.util.Set<String> extensions) {
        this.bin = bin;
        this.warnings = warnings;
        this.extensions = extensions;
    }

    /**
     * The glTF material of {@code m} drawn with texture coordinate set {@code texCoord} (-1: none),
     * or -1 for {@link Material#DEFAULT} (glTF's default material).
     */
    int material(Material m, int texCoord) {
        if (m == Material.DEFAULT) {
            return -1;
        }
        Key key = new Key(m, texCoord);
        Integer index = materialIndex.get(key);
        if (index == null) {
            index = materials.size();
            materials.add(key);
            materialIndex.put(key, index);
            if (m.shading() == Material.Shading.CONSTANT) {
                extensions.add(UNLIT);
            }
        }
        return index;
    }

    private int image(Image image) {
        Integer index = imageIndex.get(image);
        if (index != null) {
            return index;
        }
        byte[] bytes = image.bytes();
        String label = image.file() != null ? image.file().toString() : image.uri() != null ? image.uri() : image.id();
        if (bytes == null && image.file() != null) {
            try {
                if (Files.size(image.file()) > MAX_IMAGE_BYTES) {
                    throw new IOException("larger than " + (MAX_IMAGE_BYTES >> 20) + " MiB");
                }
                bytes = Files.readAllBytes(image.file());
            } catch (IOException | SecurityException e) {
                warnings.add("image " + label + " cannot be read (" + e.getMessage() + "); left out");
            }
        } else if (bytes == null) {
            warnings.add("image " + label + " is not embedded and names no file; left out");
        }
        String type = bytes == null ? null : mediaType(bytes);
        if (bytes != null && type == null) {
            warnings.add("image " + label + " is neither PNG nor JPEG; left out");
        }
        index = type == null ? -1 : images.size();
        if (type != null) {
            images.add(new Embedded(bin.view(bytes), type, image.name()));
        }
        imageIndex.put(image, index);
        return index;
    }

    /** PNG or JPEG by the file's signature; null for anything else. */
    static String mediaType(byte[] b) {
        if (b.length >= 8 && (b[0] & 0xff) == 0x89 && b[1] == 'P' && b[2] == 'N' && b[3] == 'G') {
            return "image/png";
        }
        if (b.length >= 3 && (b[0] & 0xff) == 0xff && (b[1] & 0xff) == 0xd8 && (b[2] & 0xff) == 0xff) {
            return "image/jpeg";
        }
        return null;
    }

    private TextureRef texture(Texture t, int texCoord) {
        if (t == null || texCoord < 0) {
            return null;
        }
        int image = image(t.image());
        if (image < 0) {
            return null;
        }
        Integer texture = textureOfImage.get(image);
        if (texture == null) {
            texture = textureImages.size();
            textureImages.add(image);
            textureOfImage.put(image, texture);
        }
        return new TextureRef(texture, texCoord, t.transform());
    }

    /** Resolves textures (embedding images) for every material so far; call before {@link #writeJson}. */
    private List<TextureRef[]> resolve() {
        List<TextureRef[]> refs = new ArrayList<>();
        for (Key k : materials) {
            Material m = k.material;
            boolean unlit = m.shading() == Material.Shading.CONSTANT;
            TextureRef base = texture(unlit ? m.emissionTexture() : m.diffuseTexture(), k.texCoord);
            TextureRef emissive = unlit ? null : texture(m.emissionTexture(), k.texCoord);
            refs.add(new TextureRef[] {base, emissive});
        }
        return refs;
    }

    /** {@code materials}, {@code textures} and {@code images}, each only when there is one. */
    void writeJson(JsonGenerator g) throws IOException {
        if (materials.isEmpty()) {
            return;
        }
        List<TextureRef[]> refs = resolve();
        g.writeArrayFieldStart("materials");
        for (int i = 0; i < materials.size(); i++) {
            writeMaterial(g, materials.get(i).material, refs.get(i));
        }
        g.writeEndArray();
        if (!textureImages.isEmpty()) {
            g.writeArrayFieldStart("textures");
            for (int image : textureImages) {
                g.writeStartObject();
                g.writeNumberField("source", image);
                g.writeEndObject();
            }
            g.writeEndArray();
            g.writeArrayFieldStart("images");
            for (Embedded e : images) {
                g.writeStartObject();
                if (e.name != null) {
                    g.writeStringField("name", e.name);
                }
                g.writeNumberField("bufferView", e.view);
                g.writeStringField("mimeType", e.mimeType);
                g.writeEndObject();
            }
            g.writeEndArray();
        }
    }

    private void writeMaterial(JsonGenerator g, Material m, TextureRef[] refs) throws IOException {
        boolean unlit = m.shading() == Material.Shading.CONSTANT;
        g.writeStartObject();
        if (m.name() != null) {
            g.writeStringField("name", m.name());
        }
        float[] base = unlit ? m.emission() : m.diffuse();
        if (base == null) {
            base = new float[] {1f, 1f, 1f, 1f};
        }
        Material.AlphaMode mode = m.alphaMode();
        if (mode == Material.AlphaMode.BLEND) {
            // COLLADA's opacity is the blended alpha; glTF's is the base colour's.
            base[3] = m.opacity();
            if (m.opacity() == 1f && refs[0] == null) {
                mode = Material.AlphaMode.OPAQUE;
            }
        }
        g.writeObjectFieldStart("pbrMetallicRoughness");
        BinaryChunk.writeFloats(g, "baseColorFactor", clamp(base));
        if (refs[0] != null) {
            writeTextureInfo(g, "baseColorTexture", refs[0]);
        }
        g.writeNumberField("metallicFactor", 0f);
        g.writeNumberField("roughnessFactor", m.shininess() > 0f ? (float) Math.sqrt(2.0 / (m.shininess() + 2.0)) : 1f);
        g.writeEndObject();
        float[] emission = m.emission();
        if (!unlit && emission != null && (emission[0] != 0f || emission[1] != 0f || emission[2] != 0f)) {
            float[] rgb = clamp(new float[] {emission[0], emission[1], emission[2]});
            BinaryChunk.writeFloats(g, "emissiveFactor", rgb);
        }
        if (refs[1] != null) {
            if (emission == null || emission[0] == 0f && emission[1] == 0f && emission[2] == 0f) {
                BinaryChunk.writeFloats(g, "emissiveFactor", new float[] {1f, 1f, 1f});
            }
            writeTextureInfo(g, "emissiveTexture", refs[1]);
        }
        if (mode != Material.AlphaMode.OPAQUE) {
            g.writeStringField("alphaMode", mode.name());
        }
        if (mode == Material.AlphaMode.MASK && m.alphaCutoff() != 0.5f) {
            g.writeNumberField("alphaCutoff", m.alphaCutoff());
        }
        if (m.doubleSided()) {
            g.writeBooleanField("doubleSided", true);
        }
        if (unlit) {
            g.writeObjectFieldStart("extensions");
            g.writeObjectFieldStart(UNLIT);
            g.writeEndObject();
            g.writeEndObject();
        }
        g.writeEndObject();
    }

    private static float[] clamp(float[] colour) {
        for (int i = 0; i < colour.length; i++) {
            colour[i] = Math.max(0f, Math.min(1f, colour[i]));
        }
        return colour;
    }

    private void writeTextureInfo(JsonGenerator g, String name, TextureRef t) throws IOException {
        g.writeObjectFieldStart(name);
        g.writeNumberField("index", t.texture);
        if (t.texCoord != 0) {
            g.writeNumberField("texCoord", t.texCoord);
        }
        if (!t.transform.isIdentity()) {
            extensions.add(TEXTURE_TRANSFORM);
            writeTransform(g, t.transform.values());
        }
        g.writeEndObject();
    }

    /**
     * The model's transform (v up) in glTF's convention (v down), conjugated by {@code v -> 1 - v}
     * (the inverse of {@link TextureTransform#fromGltf}), split into offset, rotation and scale.
     */
    private static void writeTransform(JsonGenerator g, float[] m) throws IOException {
        float a = m[0];
        float b = -m[1];
        float offsetU = m[1] + m[2];
        float d = -m[3];
        float e = m[4];
        float offsetV = 1f - m[4] - m[5];
        // [a b; d e] = [c sx, s sy; -s sx, c sy]
        double rotation = Math.atan2(-d, a);
        double c = Math.cos(rotation);
        double s = Math.sin(rotation);
        float scaleU = (float) Math.hypot(a, d);
        float scaleV = (float) (s * b + c * e);
        g.writeObjectFieldStart("extensions");
        g.writeObjectFieldStart(TEXTURE_TRANSFORM);
        BinaryChunk.writeFloats(g, "offset", new float[] {offsetU, offsetV});
        g.writeNumberField("rotation", (float) rotation);
        BinaryChunk.writeFloats(g, "scale", new float[] {scaleU, scaleV});
        g.writeEndObject();
        g.writeEndObject();
    }
}
