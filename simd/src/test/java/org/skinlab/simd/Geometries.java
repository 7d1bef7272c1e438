package org.skinlab.simd;

import java.nio.file.Files;
import java.nio.file.Path;

import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinnedGeometry;

/** Test input: the default asset's skinned meshes (random rigs: core's {@code RandomRigs}). */
final class Geometries {
    private Geometries() {
    }

    /**
     * The skinned mesh of the default asset, assets/characters/humanoid-walk.dae, bound for CoR (its
     * triangles give real centres of rotation).
     */
    static SkinnedGeometry humanoid() throws Exception {
        Path root = Path.of(System.getProperty("skinlab.root", "..")).toAbsolutePath().normalize();
        Path file = root.resolve("assets/characters/humanoid-walk.dae");
        if (!Files.isRegularFile(file)) {
            throw new IllegalStateException("default asset missing: " + file);
        }
        Model model = ColladaImporter.read(file);
        for (MeshInstance instance : model.instances()) {
            if (instance.isSkinned()) {
                return SkinnedGeometry.of(instance).withCentresOfRotation();
            }
        }
        throw new IllegalStateException(file + " has no skinned mesh");
    }
}
