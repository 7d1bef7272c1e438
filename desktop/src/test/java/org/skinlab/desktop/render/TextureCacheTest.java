package org.skinlab.desktop.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL33C.*;

import java.nio.ByteBuffer;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.lwjgl.stb.STBImageWrite;
import org.lwjgl.system.MemoryUtil;
import org.skinlab.model.Image;

/**
 * Images become GL textures once, the right way up for COLLADA's texture coordinates (t = 0 is
 * the image's bottom row, which GL's first row must hold), with mipmaps and repeat wrap; an image
 * that cannot be loaded gives texture 0 and one warning naming it.
 */
class TextureCacheTest {
    private static GlWindow window;

    @TempDir
    Path dir;

    @BeforeAll
    static void open() {
        GlTestDisplay.assume();
        window = GlTestDisplay.window("TextureCacheTest", 32, 32, false);
    }

    @AfterAll
    static void close() {
        if (window != null) {
            window.close();
        }
    }

    /**
     * An 8x4 picture: the top row green, below it the left half red and the right half blue
     * (wider than tall, so width and height cannot be mixed up).
     */
    private Path picture(String name) {
        int w = 8;
        int h = 4;
        ByteBuffer rgb = MemoryUtil.memAlloc(3 * w * h);
        try {
            for (int y = 0; y < h; y++) {
                for (int x = 0; x < w; x++) {
                    int o = 3 * (y * w + x);
                    boolean top = y == 0;
                    rgb.put(o, (byte) (!top && x < w / 2 ? 255 : 0));
                    rgb.put(o + 1, (byte) (top ? 255 : 0));
                    rgb.put(o + 2, (byte) (!top && x >= w / 2 ? 255 : 0));
                }
            }
            Path file = dir.resolve(name);
            assertTrue(STBImageWrite.stbi_write_png(file.toString(), w, h, 3, rgb, 3 * w), "PNG written");
            return file;
        } finally {
            MemoryUtil.memFree(rgb);
        }
    }

    private static Image image(String id, Path file) {
        return new Image(id, null, file == null ? "http://example.com/" + id : file.getFileName().toString(), file);
    }

    @Test
    void loadsOnceWithMipmapsAndTheBottomRowFirst() {
        Path file = picture("halves.png");
        TextureCache cache = new TextureCache();
        try {
            int id = cache.texture(image("a", file));
            assertNotEquals(0, id, cache.warnings().toString());
            // The same file under another image id (two <image>s naming one file) shares it.
            assertEquals(id, cache.texture(image("a", file)));
            assertEquals(id, cache.texture(image("b", dir.resolve("x/../halves.png"))));
            assertEquals(List.of(), cache.warnings());

            glBindTexture(GL_TEXTURE_2D, id);
            assertEquals(8, glGetTexLevelParameteri(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH));
            assertEquals(4, glGetTexLevelParameteri(GL_TEXTURE_2D, 0, GL_TEXTURE_HEIGHT));
            assertEquals(GL_RGBA8, glGetTexLevelParameteri(GL_TEXTURE_2D, 0, GL_TEXTURE_INTERNAL_FORMAT));
            // The mipmap chain down to 1x1 exists.
            assertEquals(4, glGetTexLevelParameteri(GL_TEXTURE_2D, 1, GL_TEXTURE_WIDTH));
            assertEquals(1, glGetTexLevelParameteri(GL_TEXTURE_2D, 3, GL_TEXTURE_WIDTH));
            assertEquals(GL_LINEAR_MIPMAP_LINEAR, glGetTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER));
            assertEquals(GL_REPEAT, glGetTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S));
            assertEquals(GL_REPEAT, glGetTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T));

            ByteBuffer texels = MemoryUtil.memAlloc(4 * 8 * 4);
            try {
                glPixelStorei(GL_PACK_ALIGNMENT, 1);
                glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, texels);
                // GL's row 0 (t = 0) is the image's bottom row: red then blue; row 3 (t = 1) green.
                assertTexel(texels, 0, 0, 255, 0, 0);
                assertTexel(texels, 7, 0, 0, 0, 255);
                assertTexel(texels, 0, 3, 0, 255, 0);
                assertTexel(texels, 7, 3, 0, 255, 0);
            } finally {
                MemoryUtil.memFree(texels);
            }
            glBindTexture(GL_TEXTURE_2D, 0);
            assertEquals(GL_NO_ERROR, glGetError());

            cache.close();
            assertFalse(glIsTexture(id), "close deletes the texture");
        } finally {
            cache.close();
        }
    }

    private static void assertTexel(ByteBuffer rgba, int x, int y, int r, int g, int b) {
        int o = 4 * (y * 8 + x);
        String at = "texel (" + x + ", " + y + ")";
        assertEquals(r, rgba.get(o) & 0xFF, at + " red");
        assertEquals(g, rgba.get(o + 1) & 0xFF, at + " green");
        assertEquals(b, rgba.get(o + 2) & 0xFF, at + " blue");
        assertEquals(255, rgba.get(o + 3) & 0xFF, at + " alpha (an RGB file is opaque)");
    }

    @Test
    void embeddedBytesAreLoadedWithoutAFile() throws Exception {
        byte[] png = java.nio.file.Files.readAllBytes(picture("embedded.png"));
        try (TextureCache cache = new TextureCache()) {
            int id = cache.texture(new Image("/images/0", null, null, null, "image/png", png));
            assertNotEquals(0, id, cache.warnings().toString());
            glBindTexture(GL_TEXTURE_2D, id);
            assertEquals(8, glGetTexLevelParameteri(GL_TEXTURE_2D, 0, GL_TEXTURE_WIDTH));
            glBindTexture(GL_TEXTURE_2D, 0);
            assertEquals(List.of(), cache.warnings());
        }
    }

    @Test
    void aMissingFileGivesZeroAndOneWarning() {
        try (TextureCache cache = new TextureCache()) {
            Image missing = image("m", dir.resolve("body.png"));
            assertEquals(0, cache.texture(missing));
            assertEquals(0, cache.texture(missing), "asked again");
            assertEquals(List.of("texture body.png: file not found"), cache.warnings());
        }
    }

    @Test
    void imagesThatAreNotLocalPicturesGiveZeroAndAWarningEach() throws Exception {
        Path junk = dir.resolve("junk.png");
        Files.writeString(junk, "not a picture");
        try (TextureCache cache = new TextureCache()) {
            assertEquals(0, cache.texture(null));
            assertEquals(0, cache.texture(image("web", null)));
            assertEquals(0, cache.texture(image("j", junk)));
            List<String> warnings = cache.warnings();
            assertEquals(2, warnings.size(), warnings.toString());
            assertTrue(warnings.get(0).startsWith("texture web: not a local file"), warnings.get(0));
            assertTrue(warnings.get(1).startsWith("texture junk.png: ") && warnings.get(1).length() > 19,
                    warnings.get(1));
        }
    }

    @Test
    void picturesWiderThanTheCapAreRefusedBeforeDecoding() {
        int w = TextureCache.MAX_SIDE + 1;
        ByteBuffer row = MemoryUtil.memCalloc(3 * w);
        Path wide = dir.resolve("wide.png");
        try {
            assertTrue(STBImageWrite.stbi_write_png(wide.toString(), w, 1, 3, row, 3 * w));
        } finally {
            MemoryUtil.memFree(row);
        }
        try (TextureCache cache = new TextureCache()) {
            assertEquals(0, cache.texture(image("w", wide)));
            assertEquals(List.of("texture wide.png: 16385x1 pixels is larger than 16384 per side"), cache.warnings());
        }
    }
}
