package org.skinlab.model;

/**
 * A texture an effect samples: the image, the name the effect gives the texture coordinates it
 * uses ({@code <texture texcoord="UVSET0">}; glTF: {@code TEXCOORD_n}), which a
 * {@link MaterialBinding} maps to one of the mesh's texture coordinate sets, and the transform
 * applied to those coordinates ({@link TextureTransform#IDENTITY} unless glTF's
 * KHR_texture_transform gives one).
 *
 * @param image     the image
 * @param texcoord  the effect's texture coordinate name, or null
 * @param transform the texture coordinate transform, never null
 */
public record Texture(Image image, String texcoord, TextureTransform transform) {
    /**
     * A texture.
     *
     * @param image     the image
     * @param texcoord  the effect's texture coordinate name, or null
     * @param transform the texture coordinate transform ({@link TextureTransform#IDENTITY} for none)
     * @throws IllegalArgumentException when {@code transform} is null
     */
    public Texture {
        if (transform == null) {
            throw new IllegalArgumentException("a texture's transform is never null (use IDENTITY)");
        }
    }

    /**
     * A texture without a coordinate transform.
     *
     * @param image    the image
     * @param texcoord the effect's texture coordinate name (e.g. "UVSET0", "TEXCOORD_0"), or null
     */
    public Texture(Image image, String texcoord) {
        this(image, texcoord, TextureTransform.IDENTITY);
    }
}
