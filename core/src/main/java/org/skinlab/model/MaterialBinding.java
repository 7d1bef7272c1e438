package org.skinlab.model;

/**
 * What a mesh instance draws for one material symbol of its primitives
 * ({@code <bind_material><instance_material symbol target>}).
 *
 * @param symbol       the symbol the primitives use ({@link MeshPart#material()})
 * @param material     the bound material
 * @param texCoordSet  the index (into {@link Mesh#texCoords(int)}) of the texture coordinate set
 *                     the material's {@link Material#baseTexture()} uses, from {@code <bind_vertex_input>}
 *                     (the first set when the file binds none); -1 when there is no texture or
 *                     the mesh has no texture coordinates
 */
public record MaterialBinding(String symbol, Material material, int texCoordSet) {
}
