package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ModelFileSearch;
import org.skinlab.desktop.bench.BenchCorpus;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.PositionSharing;
import org.skinlab.skinning.NormalTransform;

/**
 * {@code skinlab bench frame}: the structure of its outputs (two lines, table, JSON Lines) and
 * which files it measures, with tiny timings (nothing here asserts a speed).
 */
class FrameBenchCommandTest {
    private static final ObjectMapper JSON = new ObjectMapper();
    private static final String[] FAST = {"--warmup-seconds", "0", "--seconds", "0"};
    private static final List<String> KEYS = List.of("benchmark", "file", "method", "normals", "positionsSkinned",
            "renderVertices", "joints", "influences", "frames", "minMicrosPerFrame", "medianMicrosPerFrame",
            "medianNanosPerPosition", "implementation", "java", "javaVendor");
    private static final String HEADER = "| file | positions skinned | render vertices | joints | influences | kernel"
            + " | LBS frame | DQS frame |";
    private static final String CELL = "[0-9]+\\.[0-9]{2} / [0-9]+\\.[0-9]{2}";

    /** A static triangle: a file without a skin. */
    private static final String STATIC = ExitStatusTest.BROKEN.replace("<p>0 1 3</p>", "<p>0 1 2</p>");

    @TempDir
    Path dir;

    private static Cli bench(String... args) {
        List<String> all = new ArrayList<>(List.of("bench", "frame"));
        all.addAll(Arrays.asList(args));
        all.addAll(Arrays.asList(FAST));
        return Cli.run(all.toArray(String[]::new));
    }

    /** The counts of the table and JSON, computed here from the model's geometries. */
    private static List<Integer> shape(Path file) throws Exception {
        return shape(file, PositionSharing.AUTO);
    }

    /**
     * The counts with a choice of sharing: a geometry whose skinners (either method) skin each
     * position once deforms its positions, otherwise its points.
     */
    private static List<Integer> shape(Path file, PositionSharing sharing) throws Exception {
        Model model = ColladaImporter.read(file);
        int positions = 0;
        int vertices = 0;
        int joints = 0;
        int influences = 0;
        for (MeshInstance i : model.instances()) {
            SkinnedGeometry g = SkinnedGeometry.of(i);
            boolean shares = false;
            for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.LBS, SkinningMethod.DQS}) {
                shares |= Skinners.sharesPositions(Skinners.create(m, g, NormalTransform.INVERSE_TRANSPOSE, sharing));
            }
            positions += shares ? g.positionCount() : g.pointCount();
            vertices += g.vertexCount();
            joints += g.jointCount();
            influences = Math.max(influences, g.influencesPerPoint());
        }
        return List.of(positions, vertices, joints, influences);
    }

    private static List<JsonNode> jsonLines(Cli r) throws Exception {
        List<JsonNode> lines = new ArrayList<>();
        for (String line : r.out.split("\n")) {
            lines.add(JSON.readTree(line));
        }
        return lines;
    }

    /** The cells of a markdown table row. */
    private static List<String> cells(String row) {
        assertTrue(row.startsWith("| ") && row.endsWith(" |"), row);
        return Arrays.stream(row.substring(2, row.length() - 2).split(" \\| ")).map(String::trim).toList();
    }

    @Test
    void jsonReportsTheCharacterAndFrameTimes() throws Exception {
        List<Integer> shape = shape(Cli.defaultAsset());
        for (String method : new String[] {"lbs", "dqs"}) {
            Cli r = bench(Cli.defaultAsset().toString(), "--method", method, "--json");
            assertEquals(ExitCodes.OK, r.status, r::toString);
            assertEquals("", r.err);
            JsonNode root = JSON.readTree(r.out);
            assertEquals(KEYS, Cli.keys(root));
            assertEquals("frame", root.get("benchmark").asText());
            assertEquals("humanoid-walk.dae", root.get("file").asText());
            assertEquals(method, root.get("method").asText());
            assertEquals("exact", root.get("normals").asText());
            assertEquals(shape, List.of(root.get("positionsSkinned").intValue(), root.get("renderVertices").intValue(),
                    root.get("joints").intValue(), root.get("influences").intValue()));
            assertTrue(root.get("frames").intValue() >= 5, r::toString);
            double min = root.get("minMicrosPerFrame").doubleValue();
            assertTrue(min > 0 && min <= root.get("medianMicrosPerFrame").doubleValue(), r::toString);
            assertEquals(1000 * root.get("medianMicrosPerFrame").doubleValue() / root.get("positionsSkinned").intValue(),
                    root.get("medianNanosPerPosition").doubleValue(), 1e-3 + 1e-3 * root.get("medianNanosPerPosition")
                            .doubleValue(), "per position: the frame over the positions skinned");
            assertEquals("vector-256", root.get("implementation").asText());
            assertEquals(System.getProperty("java.version"), root.get("java").asText());
            assertEquals(System.getProperty("java.vendor"), root.get("javaVendor").asText());
        }
    }

    @Test
    void oneFileAndMethodPrintsTwoLines() throws Exception {
        List<Integer> shape = shape(Cli.defaultAsset());
        Cli r = bench(Cli.defaultAsset().toString(), "--method", "dqs");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        String[] lines = r.out.split("\n");
        assertEquals(2, lines.length, r::toString);
        assertEquals(String.format("frame of humanoid-walk.dae: %d positions skinned, %d render vertices, %d joints,"
                + " at most %d influences per position, dqs, normals exact, vector-256, Java %s (%s)", shape.get(0),
                shape.get(1), shape.get(2), shape.get(3), System.getProperty("java.version"),
                System.getProperty("java.vendor")), lines[0]);
        assertTrue(lines[1].matches("min [0-9.]+ µs, median [0-9.]+ µs per frame \\([0-9]+ frames: sample, skinning"
                + " matrices, skin\\); median [0-9.]+ ns per position skinned"), lines[1]);
    }

    @Test
    void severalFilesPrintATableWithBothMethodsByDefault() throws Exception {
        Path twist = Cli.root().resolve("assets/cylinders/cylinder-twist-low.dae");
        Cli r = bench(Cli.defaultAsset().toString(), twist.toString());
        assertEquals(ExitCodes.OK, r.status, r::toString);
        assertEquals("", r.err);
        String[] lines = r.out.split("\n");
        assertEquals(6, lines.length, r::toString);
        assertTrue(lines[0].startsWith("bench frame: Java " + System.getProperty("java.version") + " ("), lines[0]);
        assertEquals("", lines[1]);
        assertEquals(HEADER, String.join(" ", lines[2].split(" +")));
        assertTrue(lines[3].matches("\\|-+\\|(-+:\\|){4}-+\\|(-+:\\|){2}"), lines[3]);
        Path[] files = {Cli.defaultAsset(), twist};
        for (int f = 0; f < 2; f++) {
            List<String> row = cells(lines[4 + f]);
            assertEquals(8, row.size(), lines[4 + f]);
            assertEquals(files[f].getFileName().toString(), row.get(0));
            assertEquals(shape(files[f]), row.subList(1, 5).stream().map(Integer::valueOf).toList());
            assertEquals("vector-256", row.get(5));
            for (String cell : row.subList(6, 8)) {
                assertTrue(cell.matches(CELL), cell);
                String[] medianMin = cell.split(" / ");
                assertTrue(Double.parseDouble(medianMin[0]) >= Double.parseDouble(medianMin[1]), cell);
            }
        }
    }

    @Test
    void oneMethodGivesOneColumnAndBothGiveATableForOneFile() {
        Path twist = Cli.root().resolve("assets/cylinders/cylinder-twist-low.dae");
        Cli r = bench(Cli.defaultAsset().toString(), twist.toString(), "--method", "DQS");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        String[] lines = r.out.split("\n");
        assertEquals(List.of("file", "positions skinned", "render vertices", "joints", "influences", "kernel",
                "DQS frame"), cells(lines[2]));
        assertEquals(7, cells(lines[5]).size(), r::toString);

        r = bench(Cli.defaultAsset().toString(), "--method", "both");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        lines = r.out.split("\n");
        assertEquals(5, lines.length, r::toString);
        assertEquals("humanoid-walk.dae", cells(lines[4]).get(0));
        assertEquals(8, cells(lines[4]).size());

        r = bench(Cli.defaultAsset().toString(), "--method", "all");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        lines = r.out.split("\n");
        // Every method, in SkinningMethod's order.
        List<String> titles = new ArrayList<>();
        for (SkinningMethod m : SkinningMethod.values()) {
            titles.add(m.key().toUpperCase(java.util.Locale.ROOT) + " frame");
        }
        assertEquals(titles, cells(lines[2]).subList(6, 6 + titles.size()));
        assertEquals(6 + titles.size(), cells(lines[4]).size());
    }

    @Test
    void jsonGivesALinePerFileAndMethodInOrder() throws Exception {
        Path twist = Cli.root().resolve("assets/cylinders/cylinder-twist-low.dae");
        Cli r = bench(twist.toString(), Cli.defaultAsset().toString(), "--json", "--normals", "blended");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        List<JsonNode> lines = jsonLines(r);
        List<String> order = lines.stream().map(j -> j.get("file").asText() + " " + j.get("method").asText()).toList();
        assertEquals(List.of("cylinder-twist-low.dae lbs", "cylinder-twist-low.dae dqs", "humanoid-walk.dae lbs",
                "humanoid-walk.dae dqs"), order);
        for (JsonNode j : lines) {
            assertEquals(KEYS, Cli.keys(j));
            assertEquals("blended", j.get("normals").asText());
        }
    }

    @Test
    void positionsOnlyFramesForLbsAndDqs() throws Exception {
        Path bend = Cli.root().resolve("assets/cylinders/cylinder-bend.dae");
        for (String share : new String[] {"never", "always"}) {
            Cli r = bench(bend.toString(), "--json", "--normals", "none", "--method", "both", "--share-positions",
                    share);
            assertEquals(ExitCodes.OK, r.status, r::toString);
            List<JsonNode> lines = jsonLines(r);
            assertEquals(2, lines.size(), r::toString);
            for (JsonNode j : lines) {
                assertEquals("none", j.get("normals").asText());
                assertEquals(share.equals("always"), j.get("implementation").asText().contains("positions copied"),
                        j::toString);
            }
        }
    }

    @Test
    void allCorpusMeasuresOurCharactersAndTheSkinnedCorpusFilesAndGoesOnAfterABrokenOne() throws Exception {
        Path corpus = Files.createDirectories(dir.resolve("corpus"));
        Files.copy(Cli.root().resolve("assets/cylinders/cylinder-bend.dae"), corpus.resolve("b-skinned.dae"));
        Files.writeString(corpus.resolve("a-broken.dae"), ExitStatusTest.BROKEN);
        Files.writeString(corpus.resolve("c-static.dae"), STATIC);
        assertTrue(ColladaImporter.read(corpus.resolve("c-static.dae")).instances().stream()
                .noneMatch(MeshInstance::isSkinned), "the static file loads and has no skin");
        Cli r = bench("--all-corpus", "--corpus", corpus.toString(), "--json", "--method", "lbs");
        assertEquals(ExitCodes.INVALID_FILE, r.status, r::toString);
        List<String> files = jsonLines(r).stream().map(j -> j.get("file").asText()).toList();
        List<String> expected = new ArrayList<>(ourCharacters());
        expected.add("b-skinned.dae");
        assertEquals(expected, files);
        assertEquals(1, r.errLines().length, r::toString);
        assertTrue(r.errLines()[0].startsWith("skinlab: ") && r.errLines()[0].contains("a-broken.dae"), r::toString);
    }

    @Test
    void allCorpusFindsTheSharedCorpusBesideTheRepository() throws Exception {
        Path corpus = Cli.corpusOrSkip();
        List<String> expected = new ArrayList<>(ourCharacters());
        for (ModelFileSearch.Entry e : ModelFileSearch.expand(List.of(corpus))) {
            if (ColladaImporter.read(e.path()).instances().stream().anyMatch(MeshInstance::isSkinned)) {
                expected.add(e.path().getFileName().toString());
            }
        }
        assertTrue(expected.size() > 5, "the corpus has skinned files: " + expected);
        Cli r = bench("--all-corpus");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        List<String> rows = r.out.lines().skip(4).map(row -> cells(row).get(0)).toList();
        assertEquals(expected, rows);
        // A file named as well as found is measured once, where it was named.
        r = bench(Cli.defaultAsset().toString(), "--all-corpus", "--json", "--method", "lbs");
        List<String> namedFirst = new ArrayList<>(List.of(Cli.defaultAsset().getFileName().toString()));
        expected.stream().filter(f -> !namedFirst.contains(f)).forEach(namedFirst::add);
        assertEquals(namedFirst, jsonLines(r).stream().map(j -> j.get("file").asText()).toList());
    }

    /** The .dae files of assets/characters (humanoid-moves, humanoid-walk), in name order. */
    private static List<String> ourCharacters() {
        return BenchCorpus.characters(Cli.root()).stream().map(e -> e.path().getFileName().toString()).toList();
    }

    @Test
    void sharePositionsChoosesTheRoute() throws Exception {
        // The bend cylinder: 1118 render vertices on 1024 positions, where sharing does not pay.
        Path bend = Cli.root().resolve("assets/cylinders/cylinder-bend.dae");
        String[] expectedKernel = {"vector-256", "vector-256, each position once (vector-256 expansion)", "vector-256"};
        PositionSharing[] sharings = {PositionSharing.AUTO, PositionSharing.ALWAYS, PositionSharing.NEVER};
        for (int s = 0; s < sharings.length; s++) {
            Cli r = bench(bend.toString(), "--method", "both", "--share-positions", sharings[s].key());
            assertEquals(ExitCodes.OK, r.status, r::toString);
            List<String> row = cells(r.out.split("\n")[4]);
            assertEquals(shape(bend, sharings[s]), row.subList(1, 5).stream().map(Integer::valueOf).toList(),
                    sharings[s].key());
            assertEquals(expectedKernel[s], row.get(5), sharings[s].key());
        }
        assertEquals(List.of(1024, 1118), shape(bend, PositionSharing.ALWAYS).subList(0, 2));
        assertEquals(List.of(1118, 1118), shape(bend, PositionSharing.NEVER).subList(0, 2));
    }

    @Test
    void usageErrorsComeBeforeAnyMeasurement() {
        Cli r = bench("no-such-file.dae");
        assertEquals(ExitCodes.USAGE, r.status, r::toString);
        assertEquals("skinlab: file not found: no-such-file.dae", r.errLines()[0]);
        r = bench(Cli.defaultAsset().toString(), "no-such-file.dae", "--method", "both");
        assertEquals(ExitCodes.USAGE, r.status, r::toString);
        assertEquals("", r.out, "nothing measured");
        for (String[] bad : new String[][] {{"--method", "xyz"}, {"--normals", "flat"}, {"--seconds", "-1"},
            {"--warmup-seconds", "NaN"}, {"--all-corpus", "--corpus", dir.resolve("absent").toString()},
            {"--share-positions", "sometimes"}, {"--normals", "none", "--method", "cor"},
            {"--normals", "none", "--method", "all"}}) {
            List<String> args = new ArrayList<>(List.of(Cli.defaultAsset().toString()));
            args.addAll(List.of(bad));
            r = Cli.run(concat(List.of("bench", "frame"), args));
            assertEquals(ExitCodes.USAGE, r.status, r::toString);
            assertEquals(1, r.errLines().length, r::toString);
            assertTrue(r.errLines()[0].startsWith("skinlab: bench frame: "), r::toString);
            assertEquals("", r.out);
        }
    }

    private static String[] concat(List<String> a, List<String> b) {
        List<String> all = new ArrayList<>(a);
        all.addAll(b);
        return all.toArray(String[]::new);
    }
}
