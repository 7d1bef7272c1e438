package org.skinlab.model;

/**
 * A texture an effect samples: the image, and the name the effect gives the texture coordinates
 * it uses ({@code <texture texcoord="UVSET0">}), which a {@link MaterialBinding} maps to one of
 * the mesh's texture coordinate sets.
 *
 * @param image    the image
 * @param texcoord the effect's texture coordinate name, or null
 */
public record Texture(Image image, String texcoord) {
}
