package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;

import org.junit.jupiter.api.Test;
import org.skinlab.desktop.Cli;

/**
 * {@code skinlab eval --quick}'s load section ({@link EvalQuickRun}, whose report
 * {@link EvaluationTest} checks): it imports every model file of assets/ (found here by walking
 * the folder, so an asset added later is expected too) and, when present, the shared corpus and
 * conformance suite; every timing is taken in at least 5 runs whose median is stored
 * ({@link SpreadCheck}), ours and assimp's in as many runs; the requirement is judged on the slowest
 * single import of each group and of all; and every .glb of our assets agrees with its .dae within
 * the stated tolerance (the check's failing side: {@link AssetTwinsTest}).
 */
class EvalLoadTest {
    @Test
    void quickLoadTimesEveryFileInRunsAndJudgesTheSlowestImport() throws IOException {
        EvalQuickRun run = EvalQuickRun.get();
        JsonNode s = run.section("load");
        assertTrue(EvalReportCheck.linked(run.readme).containsAll(List.of("load-files.png")), run.readme);
        JsonNode groups = s.get("groups");
        assertEquals(List.of("assets", "corpus", "cts"), Cli.keys(groups));

        List<String> expected = modelFiles(Cli.root().resolve("assets"));
        List<String> timed = new ArrayList<>();
        groups.get("assets").get("files").forEach(f -> timed.add(f.get("file").asText()));
        Collections.sort(timed);
        assertEquals(expected, timed, "every model file of assets/ is timed");
        assertTrue(timed.contains("humanoid-walk.dae") && timed.contains("humanoid-walk.glb"), timed.toString());

        double slowestOfAll = 0;
        boolean allMeet = true;
        int imported = 0;
        for (String key : List.of("assets", "corpus", "cts")) {
            JsonNode g = groups.get(key);
            if (g.has("skipped")) {
                assertFalse(key.equals("assets"), "our assets are always there");
                continue;
            }
            double slowest = 0;
            String slowestFile = null;
            int under = 0;
            int count = 0;
            for (JsonNode f : g.get("files")) {
                String where = "/groups/" + key + "/" + f.get("file").asText();
                if (f.has("error")) {
                    assertFalse(f.has("oursMs"), where);
                    continue;
                }
                count++;
                SpreadCheck.check(f.get("oursMs"), where + "/oursMs");
                // A run is the median of its imports, so no run is slower than the slowest import.
                double slowestImport = f.get("slowestImportMs").asDouble();
                assertTrue(f.at("/oursMs/max").asDouble() <= slowestImport, where);
                if (slowestImport > slowest) {
                    slowest = slowestImport;
                    slowestFile = f.get("file").asText();
                }
                under += slowestImport < 1000 * s.get("requirementSeconds").asDouble() ? 1 : 0;
                if (f.has("assimpMs")) {
                    SpreadCheck.check(f.get("assimpMs"), where + "/assimpMs");
                    assertEquals(f.at("/oursMs/runs").size(), f.at("/assimpMs/runs").size(), where);
                    SpreadCheck.ratio(f.get("assimpRatio").asDouble(), 1, f.at("/assimpMs/median").asDouble(),
                            f.at("/oursMs/median").asDouble(), where + "/assimpRatio");
                }
            }
            assertEquals(count, g.get("imported").asInt(), key);
            assertEquals(under, g.get("underRequirement").asInt(), key);
            assertEquals(under == count, g.get("allMeetRequirement").asBoolean(), key);
            assertEquals(slowest, g.get("slowestImportMs").asDouble(), 0, key);
            assertEquals(slowestFile, g.get("slowestFile").asText(), key);
            slowestOfAll = Math.max(slowestOfAll, slowest);
            allMeet &= under == count;
            imported += count;
        }
        assertEquals(slowestOfAll, s.get("slowestImportMs").asDouble(), 0);
        assertEquals(allMeet, s.get("allMeetRequirement").asBoolean());
        assertEquals(imported, s.get("importedFiles").asInt());
    }

    /**
     * Every .glb of assets/ with a .dae beside it is compared, and agrees: the same triangles,
     * joints and clip length, every point paired, and the largest distance within the tolerance
     * the report states (10 millionths of the model's size; core's AssetTwinsTest holds every
     * method to it at and between every key).
     */
    @Test
    void quickLoadFindsEveryGlbTwinLikeItsDae() throws IOException {
        EvalQuickRun run = EvalQuickRun.get();
        JsonNode twins = run.section("load").get("twins");
        assertEquals(AssetTwins.TOLERANCE_PPM, twins.get("tolerancePpm").asDouble(), 0);
        List<String> expected;
        try (Stream<Path> files = Files.walk(Cli.root().resolve("assets"))) {
            expected = files.filter(p -> p.getFileName().toString().endsWith(".glb"))
                    .filter(p -> Files.isRegularFile(p.resolveSibling(p.getFileName().toString()
                            .replaceAll("\\.glb$", ".dae"))))
                    .map(p -> p.getFileName().toString()).sorted().collect(Collectors.toList());
        }
        List<String> compared = new ArrayList<>();
        for (JsonNode pair : twins.get("pairs")) {
            String where = pair.toString();
            compared.add(pair.get("glb").asText());
            assertFalse(pair.has("error"), where);
            assertEquals(pair.get("daeTriangles").asLong(), pair.get("glbTriangles").asLong(), where);
            assertEquals(pair.get("daeJoints").asInt(), pair.get("glbJoints").asInt(), where);
            assertEquals(pair.get("daeClipSeconds").asDouble(), pair.get("glbClipSeconds").asDouble(), 1e-6, where);
            assertEquals(0, pair.get("unpairedPoints").asInt(), where);
            assertTrue(pair.get("maxDistancePpm").asDouble() <= twins.get("tolerancePpm").asDouble(), where);
            assertTrue(pair.get("agrees").asBoolean(), where);
        }
        Collections.sort(compared);
        assertEquals(expected, compared, "every .glb beside a .dae is compared");
        assertTrue(compared.size() >= 7, "assets/README.md lists 7 twins: " + compared);
        assertEquals(compared.size(), twins.get("agreeing").asInt());
        assertTrue(twins.get("allAgree").asBoolean());
        assertTrue(run.readme.contains(".glb | triangles .dae / .glb"), "the twins' table is printed");
    }

    /** The model files of {@code dir} and below (COLLADA and glTF, as the importer reads), by name, sorted. */
    private static List<String> modelFiles(Path dir) throws IOException {
        try (Stream<Path> files = Files.walk(dir)) {
            return files.filter(Files::isRegularFile).map(p -> p.getFileName().toString())
                    .filter(n -> {
                        String l = n.toLowerCase(Locale.ROOT);
                        return l.endsWith(".dae") || l.endsWith(".glb") || l.endsWith(".gltf");
                    }).sorted().collect(Collectors.toList());
        }
    }
}
