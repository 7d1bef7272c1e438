package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertFalse;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import com.code_intelligence.jazzer.junit.DictionaryEntries;
import com.code_intelligence.jazzer.junit.FuzzTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;
import org.skinlab.model.Model;
import org.skinlab.testing.ImporterFuzzing;
import org.skinlab.testing.TestPaths;

/**
 * Coverage-guided fuzzing of {@link GltfImporter} with Jazzer: any bytes must give a model or a
 * {@link GltfException} (the rule is {@link ImporterFuzzing#check}), quickly (5 s per input when
 * fuzzing).
 *
 * <p>Seeds: every {@code .gltf} and {@code .glb} of our assets and fixtures, the synthetic glTF
 * fixtures ({@code resources/gltf}), and the small hand-made files of
 * {@code resources/org/skinlab/gltf/fuzz-seeds} (written by {@code core/src/test/tools/gltf_fuzz_seeds.py};
 * together they reach every part of the importer). {@code gradle test} runs it over the seeds and
 * the committed findings in {@code GltfImporterFuzzTestInputs/importGivesAModelOrARefusal/} under
 * the test resources (Jazzer's regression mode); {@code gradle fuzz -Pminutes=N} fuzzes it. The
 * fuzzed file claims to be {@code fuzz.glb} in an empty folder: the importer tells JSON from GLB
 * by the magic, not the name, and no relative URI finds a file. See docs/importer.md, "Fuzzing".
 */
class GltfImporterFuzzTest {
    static Stream<Arguments> seeds() throws IOException {
        return ImporterFuzzing.seeds(List.of("assets", "core/src/test/resources/fixtures",
                "core/src/test/resources/gltf", "core/src/test/resources/org/skinlab/gltf/fuzz-seeds"),
                ".gltf", ".glb");
    }

    /** The hand-made seeds are valid glTF (the validator says so): each must load, or it seeds less. */
    @Test
    void theHandMadeSeedsLoad() throws Exception {
        Path folder = TestPaths.root().resolve("core/src/test/resources/org/skinlab/gltf/fuzz-seeds");
        try (Stream<Path> files = Files.list(folder)) {
            for (Path file : files.sorted().collect(Collectors.toList())) {
                Model m = GltfImporter.read(file);
                assertFalse(m.meshes().isEmpty(), () -> file + " has no mesh");
                assertFalse(m.instances().isEmpty(), () -> file + " draws nothing");
            }
        }
    }

    /*
     * The dictionary gives the mutator whole tokens of the format: the GLB magic and chunk types,
     * the property names and enumerations the readers switch on, data URI prefixes, and numbers at
     * the edges of what they check (component types, targets, sizes near the int limits).
     */
    @DictionaryEntries({
        "glTF", "JSON", "BIN\u0000", "\"asset\"", "\"version\"", "\"2.0\"", "\"minVersion\"", "\"extensionsUsed\"",
        "\"extensionsRequired\"", "\"extensions\"", "\"extras\"", "\"scene\"", "\"scenes\"", "\"nodes\"",
        "\"children\"", "\"mesh\"", "\"meshes\"", "\"skin\"", "\"skins\"", "\"joints\"", "\"skeleton\"",
        "\"inverseBindMatrices\"", "\"matrix\"", "\"translation\"", "\"rotation\"", "\"scale\"", "\"weights\"",
        "\"primitives\"", "\"attributes\"", "\"indices\"", "\"mode\"", "\"targets\"", "\"material\"",
        "\"POSITION\"", "\"NORMAL\"", "\"TANGENT\"", "\"TEXCOORD_0\"", "\"TEXCOORD_1\"", "\"COLOR_0\"",
        "\"JOINTS_0\"", "\"WEIGHTS_0\"", "\"JOINTS_1\"", "\"WEIGHTS_1\"", "\"_CUSTOM\"", "\"accessors\"",
        "\"bufferView\"", "\"bufferViews\"", "\"byteOffset\"", "\"byteLength\"", "\"byteStride\"", "\"target\"",
        "\"componentType\"", "\"normalized\"", "\"count\"", "\"type\"", "\"min\"", "\"max\"", "\"sparse\"",
        "\"values\"", "\"SCALAR\"", "\"VEC2\"", "\"VEC3\"", "\"VEC4\"", "\"MAT2\"", "\"MAT3\"", "\"MAT4\"",
        "\"buffers\"", "\"buffer\"", "\"uri\"", "data:application/octet-stream;base64,",
        "data:application/gltf-buffer;base64,", "data:image/png;base64,", "\"animations\"", "\"channels\"",
        "\"samplers\"", "\"sampler\"", "\"input\"", "\"output\"", "\"interpolation\"", "\"LINEAR\"", "\"STEP\"",
        "\"CUBICSPLINE\"", "\"node\"", "\"path\"", "\"materials\"", "\"pbrMetallicRoughness\"",
        "\"baseColorFactor\"", "\"baseColorTexture\"", "\"index\"", "\"texCoord\"", "\"emissiveFactor\"",
        "\"alphaMode\"", "\"MASK\"", "\"BLEND\"", "\"alphaCutoff\"", "\"doubleSided\"", "\"textures\"",
        "\"source\"", "\"images\"", "\"mimeType\"", "\"image/png\"", "\"cameras\"", "\"perspective\"",
        "\"KHR_mesh_quantization\"", "\"KHR_texture_transform\"", "\"KHR_draco_mesh_compression\"",
        "\"offset\"", "5120", "5121", "5122", "5123", "5125", "5126", "34962", "34963", "null", "true", "-1",
        "1e39", "NaN", "2147483647", "2147483648", "4294967295", "4294967296", "9007199254740993",
        "\"../x.bin\"", "\"%2e%2e/x.bin\"", "\"/etc/passwd\"", "\"file:///x.bin\"",
    })
    // Regression mode: the first input also pays for Jazzer's setup, hence 30 s; when fuzzing,
    // gradle/fuzz.gradle bounds each input to 5 s.
    @Timeout(value = 30, unit = TimeUnit.SECONDS, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
    @MethodSource("seeds")
    @FuzzTest
    void importGivesAModelOrARefusal(byte[] data) throws Throwable {
        ImporterFuzzing.check(data, "fuzz.glb", GltfImporter::read, GltfException.class);
    }
}
