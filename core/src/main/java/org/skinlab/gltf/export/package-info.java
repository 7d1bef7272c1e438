/**
 * The glTF 2.0 exporter: {@link org.skinlab.gltf.export.GltfExporter} writes a
 * {@link org.skinlab.model.Model} (from COLLADA or glTF) as a binary glTF file with skinlab's
 * bind-time data for its skinning methods (the {@code SKINLAB_skinning} primitive extension and the
 * {@code _COR_CENTER} attribute), so engines that cannot compute them (three.js, jMonkeyEngine) can
 * skin with CoR. Offline work. See docs/integrations.md.
 */
package org.skinlab.gltf.export;
