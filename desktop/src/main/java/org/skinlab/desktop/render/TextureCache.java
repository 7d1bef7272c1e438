package org.skinlab.desktop.render;

import static org.lwjgl.opengl.GL33C.*;

import java.io.IOException;
import java.nio.ByteBuffer;
import java.nio.IntBuffer;
import java.nio.file.Files;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.lwjgl.stb.STBImage;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.system.MemoryUtil;
import org.skinlab.model.Image;

/**
 * The GL textures of a model's images, each loaded once with stb_image from the bytes the document
 * embeds or else from the image's file. An image that cannot be loaded (no data, unreadable, not a
 * picture, too large) gets texture 0 (the material's colour is
 * drawn) and one warning line. Window thread only.
 */
public final class TextureCache implements AutoCloseable {
    /** Larger pictures are refused: a texture this size already takes 1 GiB. */
    static final int MAX_SIDE = 16384;

    private final Map<String, Integer> textures = new HashMap<>();
    private final List<String> warnings = new ArrayList<>();

    /** The texture of {@code image}, or 0 when it has none. */
    public int texture(Image image) {
        if (image == null) {
            return 0;
        }
        String key = image.file() != null ? image.file().toAbsolutePath().normalize().toString() : "#" + image.id();
        Integer known = textures.get(key);
        if (known != null) {
            return known;
        }
        int id = load(image);
        textures.put(key, id);
        return id;
    }

    private int load(Image image) {
        String name = image.file() != null ? String.valueOf(image.file().getFileName()) : image.id();
        byte[] bytes = image.bytes(); // embedded in the document (glTF), else read from the file
        if (bytes == null && image.file() == null) {
            warnings.add("texture " + name + ": not a local file (" + image.uri() + ")");
            return 0;
        }
        try {
            bytes = bytes != null ? bytes : Files.readAllBytes(image.file());
        } catch (IOException e) {
            warnings.add("texture " + name + ": " + (Files.exists(image.file()) ? "cannot be read" : "file not found"));
            return 0;
        }
        ByteBuffer encoded = MemoryUtil.memAlloc(Math.max(1, bytes.length));
        try (MemoryStack stack = MemoryStack.stackPush()) {
            encoded.put(bytes).flip();
            IntBuffer w = stack.mallocInt(1);
            IntBuffer h = stack.mallocInt(1);
            IntBuffer channels = stack.mallocInt(1);
            if (!STBImage.stbi_info_from_memory(encoded, w, h, channels)) {
                warnings.add("texture " + name + ": " + STBImage.stbi_failure_reason());
                return 0;
            }
            if (w.get(0) > MAX_SIDE || h.get(0) > MAX_SIDE) {
                warnings.add("texture " + name + ": " + w.get(0) + "x" + h.get(0) + " pixels is larger than "
                        + MAX_SIDE + " per side");
                return 0;
            }
            // The model's (0, 0) is the image's bottom left (COLLADA's; the glTF importer flips v to
            // match), OpenGL's first row is its bottom. The
            // flag is stb's global state: set for this call only.
            STBImage.stbi_set_flip_vertically_on_load(true);
            ByteBuffer pixels = STBImage.stbi_load_from_memory(encoded, w, h, channels, 4);
            STBImage.stbi_set_flip_vertically_on_load(false);
            if (pixels == null) {
                warnings.add("texture " + name + ": " + STBImage.stbi_failure_reason());
                return 0;
            }
            try {
                int id = glGenTextures();
                glBindTexture(GL_TEXTURE_2D, id);
                glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
                glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, w.get(0), h.get(0), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                        pixels);
                glGenerateMipmap(GL_TEXTURE_2D);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
                glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
                glBindTexture(GL_TEXTURE_2D, 0);
                return id;
            } finally {
                STBImage.stbi_image_free(pixels);
            }
        } finally {
            MemoryUtil.memFree(encoded);
        }
    }

    /** One line per image that could not be loaded. */
    public List<String> warnings() {
        return warnings;
    }

    /** Deletes every texture (e.g. when the model changes). */
    public void clear() {
        for (int id : textures.values()) {
            if (id != 0) {
                glDeleteTextures(id);
            }
        }
        textures.clear();
        warnings.clear();
    }

    @Override
    public void close() {
        clear();
    }
}
