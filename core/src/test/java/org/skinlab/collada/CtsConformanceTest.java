package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.regex.Pattern;
import java.util.stream.Collectors;
import java.util.stream.Stream;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.skinlab.model.ImportWarning;
import org.skinlab.model.MaterialBinding;
import org.skinlab.model.Material;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.model.Morph;
import org.skinlab.model.Skin;
import org.skinlab.model.Texture;
import org.skinlab.testing.TestPaths;

/**
 * Every file of the Khronos COLLADA conformance suite subset ({@code ../shared/cts}, read in place
 * from its zip; skipped, saying so, when absent) imports as the table
 * {@code resources/conformance/cts-1.4.1-expected.txt} says: loaded, with its meshes (positions,
 * triangles, skin), morphs (targets, method, sums of the morphed positions), scene (nodes and
 * instances), materials (name, diffuse colour, texture file), clips and the exporter quirks it
 * must warn about; or refused for a reason docs/importer.md defends.
 *
 * <p>The table is the output of {@code core/src/test/tools/cts_expected.py}, an independent reader
 * (Python, xml.etree, no code shared with the importer) whose docstring states every rule. Files
 * are read with their path inside the zip as their location, so relative URLs (images, documents
 * naming themselves) resolve as they would on disk.
 */
class CtsConformanceTest {
    private static final String TABLE = "/conformance/cts-1.4.1-expected.txt";
    /** Morph sums: the table's are double precision to 4 decimals, ours float; both sum the same values. */
    private static final double SUM_TOLERANCE = 2e-3;
    private static final float COLOUR_TOLERANCE = 1e-6f;

    /** Each quirk kind of the table, and the warning that says it (at least one per file, only then). */
    private static final Map<String, Pattern> QUIRK_WARNINGS = new LinkedHashMap<>();

    static {
        QUIRK_WARNINGS.put("decimal-comma", Pattern.compile("decimal comma"));
        QUIRK_WARNINGS.put("unnamed-params", Pattern.compile("no <param> of this accessor has a name"));
        QUIRK_WARNINGS.put("2d-positions", Pattern.compile("has 2 components per element; read as X Y with Z = 0"));
        QUIRK_WARNINGS.put("count-mismatch", Pattern.compile("values; the values present are read"
                + "|whole elements present are read|; they are read"));
        QUIRK_WARNINGS.put("non-finite", Pattern.compile("NaN or infinite values .* read as 0"));
        QUIRK_WARNINGS.put("dropped-input", Pattern.compile("that input is dropped"));
        QUIRK_WARNINGS.put("self-url", Pattern.compile("names this document by its file name"));
        QUIRK_WARNINGS.put("vertex-ref", Pattern.compile("the only one a VERTEX input can name"));
        QUIRK_WARNINGS.put("accessor-ref", Pattern.compile("refers to nothing in the file; its <source>'s own <"));
        QUIRK_WARNINGS.put("library-skeleton", Pattern.compile("lives in <library_nodes>"));
        QUIRK_WARNINGS.put("morph-on-skin", Pattern.compile("morph on skin controller"));
    }

    /** Refusal reasons of the table, and what the importer's message must say. */
    private static final Map<String, String> REFUSALS = Map.of(
            "another-document", "points into another document; only references within the file are supported",
            "malformed-xml", "malformed XML");

    private static ZipFile zip;

    @BeforeAll
    static void open() throws IOException {
        Path file = TestPaths.shared().resolve("cts/collada-cts-1.4.1-subset.zip");
        if (Files.isRegularFile(file)) {
            zip = new ZipFile(file.toFile());
        }
    }

    @AfterAll
    static void close() throws IOException {
        if (zip != null) {
            zip.close();
        }
    }

    private static ZipFile zipOrSkip() {
        assumeTrue(zip != null, () -> "conformance suite not found at " + TestPaths.shared().resolve("cts")
                + ": CTS conformance tests skipped");
        return zip;
    }

    /** The table's records per file, in order. */
    private static Map<String, List<String[]>> table() throws IOException {
        Map<String, List<String[]>> files = new LinkedHashMap<>();
        try (InputStream in = CtsConformanceTest.class.getResourceAsStream(TABLE);
                BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                if (line.isBlank() || line.startsWith("#")) {
                    continue;
                }
                String[] f = line.split(" \\| ", -1);
                files.computeIfAbsent(f[1], k -> new ArrayList<>()).add(f);
            }
        }
        return files;
    }

    private static List<String> daeEntries(ZipFile z) {
        return z.stream().map(ZipEntry::getName).filter(n -> n.toLowerCase(Locale.ROOT).endsWith(".dae")).sorted()
                .collect(Collectors.toList());
    }

    @Test
    void tableCoversExactlyTheSuitesFiles() throws IOException {
        // A file added to the archive must not pass unchecked: rerun cts_expected.py.
        assertEquals(daeEntries(zipOrSkip()), new ArrayList<>(table().keySet()));
    }

    @Test
    void theRefusalsAreTheDeliberateOnes() throws IOException {
        // docs/importer.md defends these four; a new refusal must be added there, not just here.
        List<String> refused = table().values().stream().map(records -> records.get(0))
                .filter(f -> f[2].equals("refused")).map(f -> f[1] + " | " + f[3]).collect(Collectors.toList());
        assertEquals(List.of(
                "StandardDataSets/xml/uri/external_references/controller/controller.dae | another-document",
                "StandardDataSets/xml/uri/external_references/geometry/geometry.dae | another-document",
                "StandardDataSets/xml/uri/external_references/node/node.dae | another-document",
                "StandardDataSets/xml/uri/external_references/visual_scene/visual_scene.dae | another-document"),
                refused);
    }

    @TestFactory
    Stream<DynamicTest> everyFileImportsAsTheIndependentReaderExpects() throws IOException {
        ZipFile z = zipOrSkip();
        Map<String, List<String[]>> table = table();
        return daeEntries(z).stream().map(path -> DynamicTest.dynamicTest(path.substring(path.lastIndexOf('/') + 1),
                () -> check(z, path, table.get(path))));
    }

    private static void check(ZipFile z, String path, List<String[]> expected) throws IOException {
        assertTrue(expected != null, () -> path + " is not in the table; rerun cts_expected.py");
        String name = path.substring(path.lastIndexOf('/') + 1);
        Model m;
        try (InputStream in = z.getInputStream(z.getEntry(path))) {
            m = ColladaImporter.read(in, name, Path.of(path));
        } catch (ColladaException e) {
            String[] outcome = expected.get(0);
            assertEquals("refused", outcome[2], () -> path + " refused: " + e.getMessage());
            assertTrue(e.problem().contains(REFUSALS.get(outcome[3])), () -> "refused for another reason than "
                    + outcome[3] + ": " + e.getMessage());
            assertTrue(e.getMessage().startsWith(name + ": "), e::getMessage);
            return;
        }
        assertEquals("loaded", expected.get(0)[2], () -> path + " was expected to be refused");
        assertEquals(records(expected, "mesh", 2), meshes(m), "meshes: id | positions | triangles | skin | joints | max");
        checkMorphs(records(expected, "morph", 2), m);
        assertEquals(records(expected, "scene", 2), List.of(m.nodes().size() + " | " + m.instances().size()),
                "scene: nodes | instances");
        assertEquals(records(expected, "instance", 2), instances(m), "instances: ordinal | node | mesh | kind");
        checkMaterials(expected.stream().filter(f -> f[0].equals("material")).collect(Collectors.toList()), m);
        assertEquals(records(expected, "clip", 2), m.clips().stream().map(c -> c.name() + " | " + c.channels().size())
                .collect(Collectors.toList()), "clips: name | channels");
        checkQuirks(records(expected, "quirk", 2), m);
    }

    /** The fields from {@code from} on of each record of a kind, joined as in the table. */
    private static List<String> records(List<String[]> expected, String kind, int from) {
        return expected.stream().filter(f -> f[0].equals(kind))
                .map(f -> String.join(" | ", List.of(f).subList(from, f.length))).collect(Collectors.toList());
    }

    private static List<String> meshes(Model m) {
        List<String> rows = new ArrayList<>();
        for (Mesh mesh : m.meshes()) {
            Optional<Skin> skin = m.skinOf(mesh);
            rows.add(String.join(" | ", mesh.id(), "" + mesh.positionCount(), "" + mesh.triangleCount(),
                    skin.isPresent() ? "skinned" : "static", "" + skin.map(Skin::jointCount).orElse(0),
                    "" + skin.map(Skin::maxInfluences).orElse(0)));
        }
        return rows;
    }

    private static void checkMorphs(List<String> expected, Model m) {
        assertEquals(expected.size(), m.morphs().size(), () -> "morphs: " + expected + " vs " + m.morphs());
        for (int i = 0; i < expected.size(); i++) {
            String[] f = expected.get(i).split(" \\| ");
            Morph morph = m.morphs().get(i);
            String base = morph.base().id();
            // A morph on a morph names its innermost geometry in the table.
            for (Morph inner = morph; inner != null; ) {
                base = inner.base().id();
                String id = base;
                inner = m.morphs().stream().filter(x -> x.controllerId().equals(id)).findFirst().orElse(null);
            }
            assertEquals(String.join(" | ", f[0], f[1], f[2], f[3]), String.join(" | ", morph.controllerId(), base,
                    "" + morph.targets().size(), morph.method().name()), "morph: id | base | targets | method");
            String[] sums = f[4].split(" ");
            float[] p = morph.result().positions();
            for (int c = 0; c < 3; c++) {
                double sum = 0;
                for (int k = c; k < p.length; k += 3) {
                    sum += p[k];
                }
                assertEquals(Double.parseDouble(sums[c]), sum, SUM_TOLERANCE, "sum of coordinate " + c + " of "
                        + morph.controllerId());
            }
        }
    }

    private static List<String> instances(Model m) {
        List<String> rows = new ArrayList<>();
        for (int i = 0; i < m.instances().size(); i++) {
            MeshInstance inst = m.instances().get(i);
            String node = m.node(inst.node()).id();
            rows.add(String.join(" | ", "" + i, node == null ? "-" : node, inst.mesh().id(),
                    inst.isSkinned() ? "skinned" : "static"));
        }
        return rows;
    }

    private static void checkMaterials(List<String[]> expected, Model m) {
        List<String> symbols = new ArrayList<>();
        List<MaterialBinding> bindings = new ArrayList<>();
        for (Mesh mesh : m.meshes()) {
            for (MaterialBinding b : m.materialsOf(mesh)) {
                symbols.add(mesh.id() + " | " + b.symbol());
                bindings.add(b);
            }
        }
        assertEquals(expected.stream().map(f -> f[2] + " | " + f[3]).collect(Collectors.toList()), symbols,
                "material symbols: mesh | symbol");
        for (int i = 0; i < expected.size(); i++) {
            String[] f = expected.get(i);
            Material material = bindings.get(i).material();
            String where = "material of " + f[2] + " | " + f[3];
            boolean bound = material != Material.DEFAULT;
            assertEquals(f[4], bound ? material.name() : "-", where + ": name");
            float[] diffuse = bound ? material.diffuse() : null;
            if (f[5].equals("-")) {
                assertTrue(diffuse == null, () -> where + ": no diffuse colour expected, got "
                        + java.util.Arrays.toString(diffuse));
            } else {
                String[] rgba = f[5].split(" ");
                assertTrue(diffuse != null, where + ": diffuse " + f[5] + " expected");
                for (int c = 0; c < 4; c++) {
                    assertEquals(Float.parseFloat(rgba[c]), diffuse[c], COLOUR_TOLERANCE, where + ": diffuse " + c);
                }
            }
            Texture texture = bound ? material.baseTexture() : null;
            Path file = texture == null ? null : texture.image().file();
            if (f[6].equals("-")) {
                assertTrue(file == null, () -> where + ": no texture file expected, got " + file);
            } else {
                assertEquals(Path.of(f[6]), file, where + ": texture file");
            }
        }
    }

    private static void checkQuirks(List<String> expected, Model m) {
        Set<String> found = new LinkedHashSet<>();
        for (Map.Entry<String, Pattern> q : QUIRK_WARNINGS.entrySet()) {
            for (ImportWarning w : m.warnings()) {
                if (q.getValue().matcher(w.message()).find()) {
                    found.add(q.getKey());
                }
            }
        }
        if (!new ArrayList<>(found).equals(expected)) {
            fail("quirks warned " + found + ", expected " + expected + "; warnings: " + m.warnings());
        }
    }
}
