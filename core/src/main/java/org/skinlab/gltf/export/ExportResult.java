package org.skinlab.gltf.export;

import java.util.List;

/**
 * What {@link GltfExporter} wrote.
 *
 * @param meshes   glTF meshes written (one per placed mesh)
 * @param vertices vertices over all meshes
 * @param clips    animations written
 * @param methods  the skinning method keys the skinned primitives declare, in the order lbs, dqs, cor
 * @param bytes    the GLB's length in bytes
 * @param warnings what was left out or changed (images that are neither PNG nor JPEG, clips that
 *                 animate nothing exported, vertices given a normal), one line each
 */
public record ExportResult(int meshes, int vertices, int clips, List<String> methods, long bytes,
        List<String> warnings) {
    /**
     * A result; the lists are copied.
     *
     * @param meshes   glTF meshes written
     * @param vertices vertices over all meshes
     * @param clips    animations written
     * @param methods  the method keys declared
     * @param bytes    the GLB's length in bytes
     * @param warnings what was left out or changed
     */
    public ExportResult {
        methods = List.copyOf(methods);
        warnings = List.copyOf(warnings);
    }
}
