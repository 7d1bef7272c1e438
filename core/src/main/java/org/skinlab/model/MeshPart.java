package org.skinlab.model;

/**
 * A run of a mesh's triangles that came from one primitive element ({@code <triangles>},
 * {@code <polylist>}, ...) and shares its material symbol.
 *
 * @param primitive     the element it came from, e.g. "polylist"
 * @param material      the primitive's material symbol, or null
 * @param firstTriangle index of the first triangle in {@link Mesh#triangles()}
 * @param triangleCount number of triangles
 */
public record MeshPart(String primitive, String material, int firstTriangle, int triangleCount) {
}
