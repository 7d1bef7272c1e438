package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.skinlab.desktop.Cli;
import org.skinlab.skinning.SkinningMethod;

/**
 * The report committed in docs/evaluation/ is current by construction: a full run (not
 * {@code --quick}) of every section the code has, covering every skinning method, every asset
 * of assets/ (each .dae and .glb) and every file of the shared corpus, every timing in repeated
 * runs, named by the commit that produced it, every number of its text from its results.json.
 * A new method, asset or section fails this test until the report is made again
 * ({@code JAVA_OPTS=-Xmx2g xvfb-run -a skinlab eval}, docs/evaluation.md).
 */
class CommittedReportTest {
    private static Path dir;
    private static JsonNode results;
    private static String readme;

    @BeforeAll
    static void read() throws IOException {
        dir = Cli.root().resolve("docs/evaluation");
        results = new ObjectMapper().readTree(dir.resolve("results.json").toFile());
        readme = Files.readString(dir.resolve("README.md"));
    }

    @Test
    void isAFullRunOfEverySectionTheCodeHas() {
        assertFalse(results.get("quick").asBoolean(), "the committed report is a full run, not --quick");
        assertEquals(Evaluation.SECTIONS.stream().map(EvalSection::key).collect(Collectors.toList()),
                Cli.keys(results.get("sections")), "every section, in order: make the report again");
        for (EvalSection s : Evaluation.SECTIONS) {
            assertTrue(readme.contains("## " + s.title() + "\n"), s.title());
            assertFalse(results.at("/sections/" + s.key()).has("skipped"), s.key() + " was skipped: "
                    + results.at("/sections/" + s.key() + "/skipped"));
        }
        assertTrue(results.at("/machine/commit").asText().matches("[0-9a-f]{40}"),
                "the report names the commit that produced it: " + results.at("/machine/commit"));
        assertTrue(readme.contains(results.at("/machine/commit").asText()), "the header names the commit");
    }

    @Test
    void coversEveryAssetFileAndTheCorpus() throws IOException {
        Set<String> loaded = new TreeSet<>();
        for (JsonNode g : results.at("/sections/load/groups")) {
            for (JsonNode f : g.path("files")) {
                loaded.add(f.get("file").asText());
            }
        }
        for (String asset : files(Cli.root().resolve("assets"), ".dae", ".glb")) {
            assertTrue(loaded.contains(asset), asset + " is not in the load section: make the report again");
        }
        Path corpus = Cli.shared().resolve("corpus");
        if (Files.isDirectory(corpus)) {
            for (String file : files(corpus, ".dae")) {
                assertTrue(loaded.contains(file), "corpus file " + file + " is not in the load section");
            }
        }
        Set<String> skinned = new TreeSet<>(files(Cli.root().resolve("assets"), ".dae"));
        for (String section : List.of("time", "quality")) {
            Set<String> covered = new TreeSet<>();
            results.at("/sections/" + section + "/assets").forEach(a -> covered.add(a.get("file").asText()));
            assertTrue(covered.containsAll(skinned), section + " lacks " + difference(skinned, covered));
            for (String name : EvalTimeSection.CORPUS) {
                assertTrue(!Files.isDirectory(corpus) || covered.contains(name), section + " lacks " + name);
            }
        }
    }

    @Test
    void coversEverySkinningMethod() {
        for (JsonNode asset : results.at("/sections/time/assets")) {
            for (String kernels : List.of("fastest", "scalar")) {
                for (SkinningMethod m : SkinningMethod.values()) {
                    assertTrue(EvalTimeSection.run(asset, m, kernels, "all") != null,
                            asset.get("file") + " has no " + kernels + " " + m + " timing");
                }
            }
        }
        for (JsonNode asset : results.at("/sections/quality/assets")) {
            for (SkinningMethod m : SkinningMethod.values()) {
                assertTrue(asset.at("/methods/" + m.key()).isObject(), asset.get("file") + " lacks " + m);
            }
            int methods = SkinningMethod.values().length;
            assertEquals(methods * (methods - 1) / 2, asset.get("pairs").size(), "every pair of methods");
        }
    }

    @Test
    void everyTimingKeepsItsRunsAndEveryPrintedNumberIsAResult() throws Exception {
        List<JsonNode> spreads = new ArrayList<>();
        collectSpreads(results.get("sections"), spreads);
        assertTrue(spreads.size() > 100, "only " + spreads.size() + " timings with runs");
        for (JsonNode s : spreads) {
            assertTrue(s.get("runs").size() >= org.skinlab.internal.bench.Rounds.MIN_RUNS, s.toString());
        }
        EvalReportCheck.figuresAndNumbers(dir, results, readme);
    }

    static void collectSpreads(JsonNode node, List<JsonNode> out) {
        if (node.isObject() && node.has("runs") && node.has("median")) {
            out.add(node);
            return;
        }
        for (JsonNode child : node) {
            collectSpreads(child, out);
        }
    }

    private static List<String> files(Path folder, String... endings) throws IOException {
        try (Stream<Path> all = Files.walk(folder)) {
            return all.filter(Files::isRegularFile).map(p -> p.getFileName().toString())
                    .filter(n -> Stream.of(endings).anyMatch(n::endsWith)).sorted().collect(Collectors.toList());
        }
    }

    private static Set<String> difference(Set<String> a, Set<String> b) {
        Set<String> d = new TreeSet<>(a);
        d.removeAll(b);
        return d;
    }
}
