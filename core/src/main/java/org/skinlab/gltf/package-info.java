/**
 * The glTF 2.0 importer: {@link org.skinlab.gltf.GltfImporter} reads a {@code .gltf} or
 * {@code .glb} into the same immutable {@link org.skinlab.model.Model} as the COLLADA importer,
 * through a JSON tree on jackson-core's streaming parser whose every value knows its JSON path.
 * Problems that make a file unusable are {@link org.skinlab.gltf.GltfException}s naming the file
 * and the JSON pointer; what is tolerated becomes a warning in the model. Offline work: runs once
 * per file, never per frame. See docs/importer.md ("glTF 2.0") for the mapping and the leniency
 * decisions.
 * Depends on {@code org.skinlab.model}, JOML and jackson-core only.
 */
package org.skinlab.gltf;
