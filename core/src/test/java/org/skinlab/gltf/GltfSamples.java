package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.Optional;
import java.util.stream.Stream;

import org.skinlab.testing.TestPaths;

/**
 * Where tests find third-party glTF samples (never committed; {@code tools/gltf/gltf-samples.py}
 * lists them, where each comes from and its checksum): the folder named by the system property
 * {@code skinlab.gltfSamples}, else by the environment variable {@code SKINLAB_GLTF_SAMPLES},
 * else {@code ../shared/gltf-samples} beside the repository. Layout {@code <folder>/<Name>/<file>}.
 */
final class GltfSamples {
    private GltfSamples() {
    }

    static Path folder() {
        String property = System.getProperty("skinlab.gltfSamples");
        if (property != null && !property.isEmpty()) {
            return Paths.get(property);
        }
        String env = System.getenv("SKINLAB_GLTF_SAMPLES");
        if (env != null && !env.isEmpty()) {
            return Paths.get(env);
        }
        return TestPaths.shared().resolve("gltf-samples");
    }

    /**
     * The sample file of that name in any sample's folder; skips the calling test when the samples
     * folder is absent, fails when the folder is there but lacks the file.
     */
    static Path fileOrSkip(String fileName) throws IOException {
        Path folder = folder();
        // One reason for every sample (the test's name says which file), so the summary counts them together.
        assumeTrue(Files.isDirectory(folder), () -> "glTF samples folder " + folder + " not found (set "
                + "-Dskinlab.gltfSamples or SKINLAB_GLTF_SAMPLES; tools/gltf/gltf-samples.py lists the files)");
        Optional<Path> found;
        try (Stream<Path> files = Files.find(folder, 2, (p, a) -> a.isRegularFile()
                && p.getFileName().toString().equals(fileName))) {
            found = files.sorted().findFirst();
        }
        assertTrue(found.isPresent(), () -> "glTF sample " + fileName + " not found under " + folder
                + " although the samples folder is there (tools/gltf/gltf-samples.py says where it comes from)");
        return found.get();
    }
}
