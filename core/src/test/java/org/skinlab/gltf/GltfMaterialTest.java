package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Base64;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.model.Image;
import org.skinlab.model.Material;
import org.skinlab.model.MaterialBinding;
import org.skinlab.model.Model;
import org.skinlab.model.Texture;
import org.skinlab.model.TextureTransform;

/** Materials, textures and images: what glTF gives, carried into the model without decoding. */
class GltfMaterialTest {
    private static final byte[] PNG_SIGNATURE = {(byte) 0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};

    private static Model model(String materials, String images, String textures, String texCoords) throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0); // 0
        f.floats("VEC2", 0, 0, 1, 0, 0, 1); // 1
        f.floats("VEC2", 0.5, 0.5, 0.5, 0.5, 0.5, 0.5); // 2
        f.view(PNG_SIGNATURE, 0); // view 3
        // Valid glTF declares the extensions it uses.
        List<String> used = new ArrayList<>();
        for (String extension : new String[] {"KHR_texture_transform", "KHR_materials_unlit"}) {
            if (materials.contains(extension)) {
                used.add("\"" + extension + "\"");
            }
        }
        String declared = used.isEmpty() ? "" : "\"extensionsUsed\":[" + String.join(",", used) + "],";
        return GltfFixture.read(f.gltf(declared + "\"materials\":[" + materials + "]," + list("images", images)
                + list("textures", textures) + "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0"
                + texCoords + "},\"material\":0}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}]"));
    }

    /** A top-level array, left out when empty (the specification forbids empty ones). */
    private static String list(String name, String elements) {
        return elements.isEmpty() ? "" : "\"" + name + "\":[" + elements + "],";
    }

    @Test
    void pbrBaseColourEmissionAlphaAndSides() throws Exception {
        Material m = model("{\"name\":\"skin\",\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0.5,0.25,0.4]},"
                + "\"emissiveFactor\":[0.1,0.2,0.3],\"alphaMode\":\"MASK\",\"alphaCutoff\":0.3,\"doubleSided\":true}",
                "", "", "").materials().get(0);
        assertEquals("skin", m.name());
        assertArrayEquals(new float[] {1, 0.5f, 0.25f, 0.4f}, m.diffuse());
        assertArrayEquals(new float[] {0.1f, 0.2f, 0.3f, 1f}, m.emission());
        assertEquals(Material.AlphaMode.MASK, m.alphaMode());
        assertEquals(0.3f, m.alphaCutoff());
        assertTrue(m.doubleSided());
        assertEquals(1f, m.opacity(), "only BLEND blends");
    }

    @Test
    void defaultsAreTheSpecificationsAndBlendTakesTheAlpha() throws Exception {
        Material m = model("{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,1,1,0.25]},\"alphaMode\":\"BLEND\"}",
                "", "", "").materials().get(0);
        assertEquals(0.25f, m.opacity());
        assertEquals(0.5f, m.alphaCutoff());
        assertFalse(m.doubleSided());
        Material plain = model("{}", "", "", "").materials().get(0);
        assertEquals(Material.AlphaMode.OPAQUE, plain.alphaMode());
        assertArrayEquals(new float[] {1, 1, 1, 1}, plain.diffuse());
    }

    @Test
    void unlitMaterialsAreConstantShadedWithTheBaseColour() throws Exception {
        Model model = model("{\"pbrMetallicRoughness\":{\"baseColorFactor\":[1,0,0,1],\"baseColorTexture\":{\"index\":0}},"
                + "\"extensions\":{\"KHR_materials_unlit\":{}}}", "{\"bufferView\":3,\"mimeType\":\"image/png\"}",
                "{\"source\":0}", ",\"TEXCOORD_0\":1");
        Material m = model.materials().get(0);
        assertEquals(Material.Shading.CONSTANT, m.shading());
        assertArrayEquals(new float[] {1, 0, 0, 1}, m.emission());
        assertSame(m.diffuseTexture(), m.baseTexture());
    }

    @Test
    void colladaDefaultsAreUnchanged() {
        Material m = new Material.Builder("m", "m").build();
        assertEquals(Material.AlphaMode.BLEND, m.alphaMode());
        assertTrue(m.doubleSided());
    }

    @Test
    void baseTextureFromABufferViewWithItsTexCoordSetAndEmbeddedBytes() throws Exception {
        Model model = model("{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0,\"texCoord\":1}}}",
                "{\"bufferView\":3,\"mimeType\":\"image/png\",\"name\":\"skin.png\"}", "{\"source\":0}",
                ",\"TEXCOORD_0\":1,\"TEXCOORD_1\":2");
        Texture t = model.materials().get(0).baseTexture();
        Image image = t.image();
        assertArrayEquals(PNG_SIGNATURE, image.bytes());
        assertEquals("image/png", image.mimeType());
        assertNull(image.file());
        assertTrue(t.transform().isIdentity());
        MaterialBinding binding = model.instances().get(0).material("/materials/0");
        assertEquals(1, binding.texCoordSet());
        assertEquals(image, model.images().get(0));
    }

    @Test
    void dataUriImageKeepsItsBytes() throws Exception {
        String uri = "data:image/png;base64," + Base64.getEncoder().encodeToString(PNG_SIGNATURE);
        Model model = model("{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0}}}",
                "{\"uri\":\"" + uri + "\"}", "{\"source\":0}", ",\"TEXCOORD_0\":1");
        assertArrayEquals(PNG_SIGNATURE, model.images().get(0).bytes());
        assertEquals("image/png", model.images().get(0).mimeType());
        assertEquals(0, model.instances().get(0).material("/materials/0").texCoordSet());
    }

    @Test
    void textureTransformIsConjugatedIntoTheModelsConvention() throws Exception {
        Model model = model("{\"pbrMetallicRoughness\":{\"baseColorTexture\":{\"index\":0,\"extensions\":"
                + "{\"KHR_texture_transform\":{\"offset\":[0.5,0.25],\"rotation\":1.5707963,\"scale\":[2,3],"
                + "\"texCoord\":1}}}}}", "{\"bufferView\":3,\"mimeType\":\"image/png\"}", "{\"source\":0}",
                ",\"TEXCOORD_0\":1,\"TEXCOORD_1\":2");
        TextureTransform t = model.materials().get(0).baseTexture().transform();
        assertEquals(1, model.instances().get(0).material("/materials/0").texCoordSet(), "texCoord override");
        // In glTF's convention: (u, v) = (0.1, 0.2) -> S (0.2, 0.6) -> R(90deg) (0.6, -0.2) -> T (1.1, 0.05).
        // The same point in the model's convention is (0.1, 0.8) and must go to (1.1, 0.95).
        float[] p = t.apply(0.1f, 0.8f, new float[2]);
        assertArrayEquals(new float[] {1.1f, 0.95f}, p, 1e-6f);
    }

    @Test
    void imageFileIsItsPathInTheFolderNotOpened(@org.junit.jupiter.api.io.TempDir java.nio.file.Path dir)
            throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0);
        java.nio.file.Path gltf = dir.resolve("doc.gltf");
        java.nio.file.Files.write(gltf, f.gltf("\"images\":[{\"uri\":\"tex/skin%20tone.png\"}]").getBytes(
                java.nio.charset.StandardCharsets.UTF_8));
        Image image = GltfImporter.read(gltf).images().get(0);
        assertEquals(dir.toAbsolutePath().resolve("tex").resolve("skin tone.png"), image.file());
        assertEquals("tex/skin%20tone.png", image.uri());
        assertNull(image.bytes(), "the file does not exist: the importer never opened it");
    }

    @Test
    void imageFileOutsideTheFolderIsRefused() {
        GltfException e = assertThrows(GltfException.class, () -> model("{}", "{\"uri\":\"../x.png\"}", "", ""));
        assertEquals("/images/0/uri", e.path());
    }
}
