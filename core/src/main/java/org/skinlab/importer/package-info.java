/**
 * The format-neutral entry point: {@link org.skinlab.importer.ModelImporter} tells COLLADA from
 * glTF by content (the GLB magic, or the first non-blank byte) and hands the file to
 * {@link org.skinlab.collada.ColladaImporter} or {@link org.skinlab.gltf.GltfImporter}; both
 * produce the same {@link org.skinlab.model.Model} and throw an
 * {@link org.skinlab.model.ImportException}.
 * Depends on the two importers and {@code org.skinlab.model} only.
 */
package org.skinlab.importer;
