package org.skinlab.android;

import static android.opengl.GLES30.*;

import java.util.IdentityHashMap;
import java.util.Map;

import org.skinlab.android.logic.GlesShaders;
import org.skinlab.android.logic.ModelTextures;
import org.skinlab.android.logic.TexturePixels;
import org.skinlab.model.Image;

/**
 * The GL textures of one model's decoded pictures (GL thread only), each uploaded once when a part
 * first needs it: RGBA8 with mipmaps, repeating (glTF's default sampler), trilinear.
 */
final class TexturesGl {
    private final ModelTextures pictures;
    private final Map<Image, Integer> ids = new IdentityHashMap<>();

    TexturesGl(ModelTextures pictures) {
        this.pictures = pictures;
    }

    /** The texture of {@code image}, or 0 when it has no decoded picture. */
    int texture(Image image) {
        Integer known = ids.get(image);
        if (known != null) {
            return known;
        }
        TexturePixels p = pictures.of(image);
        int id = p == null ? 0 : upload(p);
        ids.put(image, id);
        return id;
    }

    private static int upload(TexturePixels p) {
        int[] t = new int[1];
        glGenTextures(1, t, 0);
        glActiveTexture(GL_TEXTURE0 + GlesShaders.BASE_TEXTURE_UNIT); // not the palette's unit
        glBindTexture(GL_TEXTURE_2D, t[0]);
        glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, p.width(), p.height(), 0, GL_RGBA, GL_UNSIGNED_BYTE,
                p.rgba().duplicate());
        glGenerateMipmap(GL_TEXTURE_2D);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
        glBindTexture(GL_TEXTURE_2D, 0);
        return t[0];
    }

    void release() {
        for (int id : ids.values()) {
            if (id != 0) {
                glDeleteTextures(1, new int[] {id}, 0);
            }
        }
        ids.clear();
    }
}
