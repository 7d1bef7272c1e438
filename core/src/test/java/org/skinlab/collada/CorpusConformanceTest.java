package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.TreeMap;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.ImportWarning;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.model.Skin;
import org.skinlab.testing.TestPaths;

/**
 * Every file of the third-party corpus ({@code ../shared/corpus}; skipped, saying so, when absent)
 * imports with the counts an independent reader finds in its XML: per geometry the positions,
 * triangles (fan-triangulated, lines excluded), skinned or static, joints and largest influence
 * count; per clip the name and the channels that drive scene transforms; and exactly the expected
 * warnings, no others.
 *
 * <p>The expected table is the output of {@code core/src/test/tools/corpus_counts.py} (Python,
 * xml.etree only, no code shared with the importer), pasted unchanged; see that script for what
 * each record means. Rerun it and paste again when the corpus changes.
 */
class CorpusConformanceTest {
    /** Output of {@code python3 core/src/test/tools/corpus_counts.py} (do not edit by hand). */
    private static final String EXPECTED = """
            mesh | K01_simple_bone.dae | Cube-mesh | 8 | 12 | skinned | 2 | 2
            mesh | M02_cube_utf16le.dae | box-lib | 8 | 12 | static | 0 | 0
            mesh | M03_cube_empty_tags.dae | box-lib | 8 | 12 | static | 0 | 0
            noasset | M03_cube_empty_tags.dae
            nomaterial | M03_cube_empty_tags.dae | Box | #Blue
            mesh | S01_cowboy.dae | Cube-mesh | 740 | 1420 | skinned | 16 | 6
            clip | S01_cowboy.dae | default | 16
            mesh | S02_bob_lamp.dae | Sword-mesh | 102 | 106 | skinned | 32 | 1
            mesh | S02_bob_lamp.dae | lamp_top-mesh | 26 | 22 | skinned | 32 | 1
            mesh | S02_bob_lamp.dae | lamp_body-mesh | 16 | 16 | skinned | 32 | 1
            mesh | S02_bob_lamp.dae | Helmet-mesh | 64 | 78 | skinned | 32 | 1
            mesh | S02_bob_lamp.dae | Head-mesh | 99 | 177 | skinned | 2 | 2
            mesh | S02_bob_lamp.dae | Body-mesh | 342 | 628 | skinned | 31 | 4
            clip | S02_bob_lamp.dae | default | 33
            lines | S02_bob_lamp.dae | Sword-mesh | lines
            mesh | S03_stormtrooper.dae | Stormtroopermesh-mesh | 3275 | 6518 | skinned | 52 | 6
            clip | S03_stormtrooper.dae | default | 65
            mesh | S11_box_nested_animation.dae | Cube-mesh | 8 | 12 | skinned | 1 | 1
            clip | S11_box_nested_animation.dae | default | 1
            mesh | S12_library_animation_clips.dae | id-mesh-10 | 72 | 52 | skinned | 5 | 2
            clip | S12_library_animation_clips.dae | bend | 6
            clip | S12_library_animation_clips.dae | turn | 6
            badsums | S12_library_animation_clips.dae | id-controller-12 | 2 | 72
            mesh | S13_letter_f_animated.dae | Cube_001-mesh | 32 | 60 | skinned | 2 | 2
            clip | S13_letter_f_animated.dae | default | 2
            mesh | S14_two_skinned_cubes.dae | Cube_001-mesh | 16 | 24 | skinned | 2 | 1
            clip | S14_two_skinned_cubes.dae | default | 2
            mesh | S15_leg_control_bones.dae | Cube-mesh | 28 | 52 | skinned | 4 | 3
            clip | S15_leg_control_bones.dae | default | 9
            mesh | S16_suzanne_lines.dae | suz_v_group-mesh | 1856 | 3570 | skinned | 21 | 3
            clip | S16_suzanne_lines.dae | default | 21
            lines | S16_suzanne_lines.dae | suz_v_group-mesh | lines
            unweighted | S16_suzanne_lines.dae | suz_armature_suz-skin | 45 | 1856
            mesh | S17_trion_scene.dae | Cube_001-mesh | 8 | 12 | skinned | 8 | 1
            mesh | S17_trion_scene.dae | Cylinder-mesh | 192 | 380 | static | 0 | 0
            mesh | S17_trion_scene.dae | Cube-mesh | 48 | 92 | static | 0 | 0
            clip | S17_trion_scene.dae | default | 8
            mesh | T01_cinema4d.dae | ID5 | 433 | 756 | static | 0 | 0
            mesh | T01_cinema4d.dae | ID14 | 266 | 528 | static | 0 | 0
            mesh | T01_cinema4d.dae | ID23 | 8 | 12 | static | 0 | 0
            mesh | T02_duck_maya.dae | LOD3spShape-lib | 2108 | 4212 | static | 0 | 0
            """;

    /** What the table says about one file. */
    private static final class Expected {
        final List<String[]> meshes = new ArrayList<>();
        final List<String[]> clips = new ArrayList<>();
        /** Pairs of (element part, message part) every warning must match, one warning each. */
        final List<String[]> warnings = new ArrayList<>();
    }

    private static Map<String, Expected> table() {
        Map<String, Expected> files = new TreeMap<>();
        for (String line : EXPECTED.strip().split("\n")) {
            String[] f = line.strip().split(" \\| ");
            Expected e = files.computeIfAbsent(f[1], k -> new Expected());
            switch (f[0]) {
                case "mesh":
                    e.meshes.add(f);
                    break;
                case "clip":
                    e.clips.add(f);
                    break;
                case "lines":
                    e.warnings.add(new String[] {"<" + f[3] + "> in <geometry id=\"" + f[2] + "\">",
                        "line primitives are not drawn; skipped"});
                    break;
                case "noasset":
                    e.warnings.add(new String[] {"<COLLADA>", "no <asset>; assuming Y_UP and 1 unit = 1 meter"});
                    break;
                case "unweighted":
                    e.warnings.add(new String[] {"<vertex_weights> in <controller id=\"" + f[2] + "\">",
                        f[3] + " of " + f[4] + " positions have no influences"});
                    break;
                case "nomaterial":
                    e.warnings.add(new String[] {"<instance_material> in <node id=\"" + f[2] + "\">",
                        "target=\"" + f[3] + "\" refers to nothing in the file; drawn with the default material"});
                    break;
                case "badsums":
                    e.warnings.add(new String[] {"<vertex_weights> in <controller id=\"" + f[2] + "\">",
                        f[3] + " of " + f[4] + " positions have weights that do not sum to 1"});
                    break;
                default:
                    throw new IllegalStateException("unknown record: " + line);
            }
        }
        return files;
    }

    private static List<Path> corpusFiles() throws IOException {
        Path corpus = TestPaths.corpusOrSkip();
        try (Stream<Path> s = Files.list(corpus)) {
            return s.filter(p -> p.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".dae")).sorted()
                    .collect(Collectors.toList());
        }
    }

    @Test
    void tableCoversExactlyTheCorpusFiles() throws IOException {
        // A file added to the corpus must not pass unchecked: rerun the script.
        List<String> names = corpusFiles().stream().map(p -> p.getFileName().toString()).collect(Collectors.toList());
        assertEquals(new ArrayList<>(table().keySet()), names);
    }

    @TestFactory
    Stream<DynamicTest> everyCorpusFileMatchesTheIndependentCounts() throws IOException {
        Map<String, Expected> table = table();
        return corpusFiles().stream().map(file -> DynamicTest.dynamicTest(file.getFileName().toString(), () -> {
            String name = file.getFileName().toString();
            Expected expected = table.get(name);
            assertTrue(expected != null, () -> name + " is not in the table; rerun corpus_counts.py");
            check(ColladaImporter.read(file), expected);
        }));
    }

    private static void check(Model m, Expected expected) {
        List<String> meshes = new ArrayList<>();
        for (Mesh mesh : m.meshes()) {
            Optional<Skin> skin = m.skinOf(mesh);
            meshes.add(String.join(" | ", mesh.id(), "" + mesh.positionCount(), "" + mesh.triangleCount(),
                    skin.isPresent() ? "skinned" : "static", "" + skin.map(Skin::jointCount).orElse(0),
                    "" + skin.map(Skin::maxInfluences).orElse(0)));
        }
        assertEquals(expected.meshes.stream().map(f -> String.join(" | ", List.of(f).subList(2, 8)))
                .collect(Collectors.toList()), meshes, "meshes: geometry | positions | triangles | skinned | joints | max");

        List<String> clips = new ArrayList<>();
        for (AnimationClip clip : m.clips()) {
            clips.add(clip.name() + " | " + clip.channels().size());
        }
        assertEquals(expected.clips.stream().map(f -> f[2] + " | " + f[3]).collect(Collectors.toList()), clips,
                "clips: name | channels");

        List<ImportWarning> left = new ArrayList<>(m.warnings());
        for (String[] w : expected.warnings) {
            Optional<ImportWarning> match = left.stream()
                    .filter(x -> x.element().startsWith(w[0]) && x.message().startsWith(w[1])).findFirst();
            assertTrue(match.isPresent(), () -> "missing warning " + w[0] + ": " + w[1] + " among " + m.warnings());
            left.remove(match.get());
        }
        assertEquals(List.of(), left, "unexpected warnings");
    }
}
