package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.skinlab.collada.Snippets.oneWarning;

import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.skinlab.model.Material;
import org.skinlab.model.MaterialBinding;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;

/**
 * Materials, effects and images ({@code fixtures/materials/textured.dae}, whose comment lists
 * what each material exercises): profile_COMMON shading, colours given directly or through
 * {@code <param ref>}, textures through COLLADA 1.4.1's sampler and surface, 1.5's
 * {@code <instance_image>} and the bare image id exporters write, image paths resolved against the
 * document's folder, {@code <bind_vertex_input>}, opacity by the specification's rule, and every
 * problem warned, never refused.
 */
class MaterialImportTest {
    private static final String NAME = "materials/textured.dae";
    private static final Model MODEL = Fixtures.resource(NAME);
    private static final MeshInstance STRIP = MODEL.instances().get(0);

    private static MaterialBinding bound(String symbol) {
        return STRIP.material(symbol);
    }

    private static Material material(String symbol) {
        return bound(symbol).material();
    }

    @Test
    void everyMaterialOfTheLibraryIsReadInOrder() {
        assertEquals(9, MODEL.materials().size());
        assertEquals("Skin", MODEL.materials().get(0).name());
        assertEquals("direct-mat", MODEL.materials().get(1).name(), "no name attribute: the id");
        assertEquals("skin-mat", MODEL.materials().get(0).id());
    }

    @Test
    void textureThroughSamplerAndSurfaceUsesTheBoundTexcoordSet() {
        Material skin = material("skin");
        assertEquals(Material.Shading.PHONG, skin.shading());
        assertNull(skin.diffuse());
        assertEquals("skin-img", skin.diffuseTexture().image().id());
        assertEquals("UVSET0", skin.diffuseTexture().texcoord());
        assertSame(skin.diffuseTexture(), skin.baseTexture());
        assertEquals(Path.of("materials", "skin.png"), skin.diffuseTexture().image().file());
        assertEquals(1, bound("skin").texCoordSet(), "bind_vertex_input UVSET0 -> TEXCOORD set 1");
        assertArrayEquals(new float[] {0.5f, 0.5f, 0.5f, 1f}, skin.specular(), 0f);
        assertEquals(20f, skin.shininess(), 0f);
        assertArrayEquals(new float[] {0, 0, 0, 1}, skin.emission(), 0f);
    }

    @Test
    void textureNamingTheImageDirectlyAndAWindowsPathWithEscapes() {
        Material direct = material("direct");
        assertEquals("..\\textures\\wood%20grain.jpg", direct.diffuseTexture().image().uri());
        assertEquals(Path.of("textures", "wood grain.jpg"), direct.diffuseTexture().image().file());
        assertEquals(0, bound("direct").texCoordSet(), "no bind_vertex_input: the first set");
    }

    @Test
    void colladaOnePointFiveInstanceImageAndAFileUrl() {
        Material v15 = material("v15");
        assertEquals(Material.Shading.BLINN, v15.shading());
        assertEquals("brick-img", v15.diffuseTexture().image().id());
        assertEquals("file:///C:/maps/brick.png", v15.diffuseTexture().image().uri());
        // "C:/maps/brick.png" is absolute on Windows; elsewhere it is still the file the URL names.
        assertEquals(Path.of("C:/maps/brick.png").normalize(), v15.diffuseTexture().image().file());
        assertEquals(8f, v15.shininess(), 0f);
    }

    @Test
    void colourThroughParamRefAndOpacityByTheSpecificationsRules() {
        Material glass = material("paramref");
        assertArrayEquals(new float[] {0.25f, 0.5f, 0.75f, 1f}, glass.diffuse(), 0f);
        assertEquals(0.4f, glass.opacity(), 1e-6f, "A_ONE: transparent.a 0.5 * transparency 0.8");
        assertEquals(0.8f, material("rgbzero").opacity(), 1e-6f, "RGB_ZERO: 1 - luminance 0.2 * 1");
        assertEquals(1f, material("skin").opacity(), 0f, "neither given: opaque");
    }

    @Test
    void aMaterialTheRuleMakesInvisibleIsReadAsOpaqueWithAWarning() {
        assertEquals(1f, material("invisible").opacity(), 0f);
        oneWarning(MODEL, "material \"Oops\" (and maybe others) would be fully transparent by the specification's"
                + " rule (A_ONE, transparency 0.0); read as opaque");
    }

    @Test
    void constantShadingHasEmissionAndNoDiffuse() {
        Material glow = material("constant");
        assertEquals(Material.Shading.CONSTANT, glow.shading());
        assertNull(glow.diffuse());
        assertArrayEquals(new float[] {1, 1, 0, 1}, glow.emission(), 0f, "RGB gets alpha 1");
        assertEquals(-1, bound("constant").texCoordSet(), "no texture");
    }

    @Test
    void problemsAreWarnedAndTheMeshStillDrawn() {
        Material web = material("http");
        assertNull(web.diffuseTexture());
        assertSame(web.emissionTexture(), web.baseTexture(), "constant shading shows its emission texture");
        assertEquals("http://example.com/web.png", web.baseTexture().image().uri());
        assertNull(web.baseTexture().image().file());
        assertEquals(0, bound("http").texCoordSet());
        oneWarning(MODEL, "init_from \"http://example.com/web.png\" is not a file path; the texture cannot be loaded");

        Material lost = material("noeffect");
        assertEquals("Lost", lost.name());
        assertNull(lost.diffuse());
        assertNull(lost.diffuseTexture());
        oneWarning(MODEL, "url=\"#nowhere-fx\" refers to nothing in the file; ignored");

        assertSame(Material.DEFAULT, material("unbound"));
        oneWarning(MODEL, "material symbol unbound of mesh \"strip\" bound to no material; drawn with the default"
                + " material");
        assertEquals(4, MODEL.warnings().size(), () -> MODEL.warnings().toString());
    }

    @Test
    void aDanglingBindingForASymbolTheMeshDoesNotUseIsIgnoredQuietly() {
        // The FBX exporter binds materials of other objects too; one of them names nothing.
        String text = Fixtures.text(NAME).replace("<instance_material symbol=\"direct\" target=\"#direct-mat\"/>",
                "<instance_material symbol=\"direct\" target=\"#direct-mat\"/>"
                        + "<instance_material symbol=\"elsewhere\" target=\"#Map__1-Material\"/>");
        Model m = Fixtures.read(NAME, text);
        assertEquals(MODEL.warnings().size(), m.warnings().size(), () -> m.warnings().toString());
        assertEquals(9, m.instances().get(0).materials().size(), "the unused, dangling binding is left out");
    }

    @Test
    void imagesAreListedOncePerImageUsed() {
        assertEquals(4, MODEL.images().size());
        assertEquals("skin-img", MODEL.images().get(0).id());
    }

    @Test
    void aFileReadFromDiskResolvesImagesAgainstItsFolder() throws Exception {
        Path file = org.skinlab.testing.TestPaths.root().resolve("core/src/test/resources/fixtures/" + NAME);
        Model m = ColladaImporter.read(file);
        Path expected = file.toAbsolutePath().getParent().resolve("../textures/wood grain.jpg").normalize();
        assertEquals(expected, m.instances().get(0).material("direct").material().diffuseTexture().image().file());
    }
}
