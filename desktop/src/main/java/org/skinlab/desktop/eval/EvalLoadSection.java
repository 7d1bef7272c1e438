package org.skinlab.desktop.eval;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.TreeMap;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.internal.bench.Rounds;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ModelFileSearch;
import org.skinlab.desktop.bench.AssimpBaseline;
import org.skinlab.desktop.bench.BenchCorpus;
import org.skinlab.desktop.bench.ParseTimer;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.ImportException;

/**
 * Section "load": import time of every model file of our assets ({@code assets/**}: COLLADA and
 * their glTF twins), of the shared corpus and of the shared conformance suite (read in place from
 * its zip), with {@link ParseTimer} (the timing of {@code bench parse}) in {@link Rounds#MIN_RUNS}
 * runs per file, assimp's runs interleaved with ours when its native library loads; against the
 * thesis' requirement that a file loads in under 10 s, judged on the slowest single import of all
 * runs. A file our importer refuses (the suite has a few made to be refused) is counted and named,
 * not timed. Then each {@code .glb} of our assets against its {@code .dae} ({@link AssetTwins}).
 */
final class EvalLoadSection implements EvalSection {
    static final double REQUIREMENT_SECONDS = 10;
    /** The groups of files, in report order: key and title. */
    private static final String[][] GROUPS = {{"assets", "our assets (assets/)"}, {"corpus", "the shared corpus"},
        {"cts", "the shared conformance suite"}};

    @Override
    public String key() {
        return "load";
    }

    @Override
    public String title() {
        return "Load: import time";
    }

    @Override
    public double estimatedSeconds(EvalContext context) {
        return context.quick() ? 5 : 30;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        boolean quick = context.quick();
        double warmup = quick ? 0.5 : 3;
        int imports = quick ? 1 : 5;
        results.put("requirementSeconds", REQUIREMENT_SECONDS);
        results.put("runsPerFile", Rounds.MIN_RUNS);
        results.put("importsPerRun", imports);
        results.put("ctsImportsPerRun", 1);
        results.put("warmupSeconds", warmup);
        int assimpFlags = -1;
        try {
            String version = AssimpBaseline.loadAndVersion();
            assimpFlags = AssimpBaseline.FAIR_FLAGS;
            results.put("assimpVersion", version);
            results.put("assimpFlags", AssimpBaseline.describe(assimpFlags));
        } catch (IllegalStateException e) {
            results.put("assimpMissing", e.getMessage());
            context.say("no assimp: " + e.getMessage());
        }
        List<ParseTimer.Input> assets = files(ModelFileSearch.expand(List.of(context.root().resolve("assets"))));
        List<ParseTimer.Input> corpus = context.corpus() == null ? List.of()
                : files(BenchCorpus.corpusFiles(context.corpus()));
        List<ParseTimer.Input> cts = context.cts() == null ? List.of() : ctsFiles(context.cts(), quick ? 8 : 1);
        int total = assets.size() + corpus.size() + cts.size();
        // Ours and assimp over our assets and the corpus in one timer: one shared warm-up.
        List<ParseTimer.Input> withAssimp = new ArrayList<>(assets);
        withAssimp.addAll(corpus);
        List<ParseTimer.Result> measured = new ParseTimer(warmup, Rounds.MIN_RUNS, imports, assimpFlags, true, null,
                "").onProgress(n -> context.progress((double) n / total)).measure(withAssimp);
        List<ParseTimer.Result> suite = cts.isEmpty() ? List.of()
                : new ParseTimer(warmup, Rounds.MIN_RUNS, 1, assimpFlags, true, null, "")
                        .onProgress(n -> context.progress((double) (withAssimp.size() + n) / total)).measure(cts);
        ObjectNode groups = results.putObject("groups");
        group(groups, 0, measured.subList(0, assets.size()), null);
        group(groups, 1, measured.subList(assets.size(), measured.size()),
                context.corpus() == null ? "no shared corpus at " + context.corpusPlace() : null);
        group(groups, 2, suite, context.cts() == null ? "no conformance suite at " + context.ctsPlace() : null);
        if (quick && !cts.isEmpty()) {
            results.put("ctsEvery", 8);
        }
        requirement(results, groups);
        twins(results.putObject("twins"), assets);
    }

    private static List<ParseTimer.Input> files(List<ModelFileSearch.Entry> entries) {
        List<ParseTimer.Input> inputs = new ArrayList<>();
        for (ModelFileSearch.Entry e : entries) {
            try {
                inputs.add(new ParseTimer.Input(e.path().getFileName().toString(), Files.readAllBytes(e.path()),
                        e.path()));
            } catch (IOException ex) {
                throw new CommandFailure(ExitCodes.INVALID_FILE, e.path() + ": cannot be read: " + ex.getMessage(), ex);
            }
        }
        return inputs;
    }

    /** Every {@code every}-th .dae of the zip in name order, its path in the zip as its location. */
    private static List<ParseTimer.Input> ctsFiles(Path zip, int every) {
        List<ParseTimer.Input> inputs = new ArrayList<>();
        try (ZipFile z = new ZipFile(zip.toFile())) {
            List<String> names = new ArrayList<>();
            for (ZipEntry e : Collections.list(z.entries())) {
                if (!e.isDirectory() && e.getName().toLowerCase(Locale.ROOT).endsWith(".dae")) {
                    names.add(e.getName());
                }
            }
            Collections.sort(names);
            for (int i = 0; i < names.size(); i += every) {
                try (InputStream in = z.getInputStream(z.getEntry(names.get(i)))) {
                    inputs.add(new ParseTimer.Input(names.get(i), in.readAllBytes(), Path.of(names.get(i))));
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException(zip + ": cannot be read", e);
        }
        return inputs;
    }

    /** Group {@code GROUPS[index]}: each file's runs, its slowest import, assimp's runs beside. */
    private static void group(ObjectNode groups, int index, List<ParseTimer.Result> results, String skipped) {
        ObjectNode g = groups.putObject(GROUPS[index][0]);
        g.put("title", GROUPS[index][1]);
        if (skipped != null) {
            g.put("skipped", skipped);
            return;
        }
        int imported = 0;
        int under = 0;
        double slowest = 0;
        String slowestFile = null;
        List<Double> medians = new ArrayList<>();
        ArrayNode files = g.putArray("files");
        for (ParseTimer.Result r : results) {
            ObjectNode f = files.addObject();
            f.put("file", r.name);
            f.put("kilobytes", EvalReport.round(r.bytes / 1e3));
            if (r.error != null) {
                f.put("error", r.error);
                continue;
            }
            imported++;
            f.put("triangles", r.triangles);
            EvalReport.putSpread(f, "oursMs", r.runs);
            f.put("slowestImportMs", EvalReport.round(r.max()));
            medians.add(r.median());
            if (r.max() > slowest) {
                slowest = r.max();
                slowestFile = r.name;
            }
            if (r.max() < REQUIREMENT_SECONDS * 1000) {
                under++;
            }
            if (r.assimpRuns != null) {
                EvalReport.putSpread(f, "assimpMs", r.assimpRuns);
                f.put("assimpRatio", EvalReport.round(r.assimpRatio()));
            } else if (r.assimpError != null) {
                f.put("assimpError", r.assimpError);
            }
        }
        assimpSummary(g, files);
        g.put("fileCount", results.size());
        g.put("imported", imported);
        g.put("refused", results.size() - imported);
        g.put("underRequirement", under);
        g.put("allMeetRequirement", under == imported);
        if (slowestFile != null) {
            g.put("slowestImportMs", EvalReport.round(slowest));
            g.put("slowestFile", slowestFile);
            Collections.sort(medians);
            g.put("medianFileMs", EvalReport.round(medians.get(medians.size() / 2)));
            g.put("sumOfMediansMs", EvalReport.round(medians.stream().mapToDouble(Double::doubleValue).sum()));
        }
    }

    /** How many files assimp imported and refused, and the median file's assimp / ours. */
    private static void assimpSummary(ObjectNode g, JsonNode files) {
        int imported = 0;
        int refused = 0;
        List<Double> ratios = new ArrayList<>();
        Map<String, Integer> messages = new TreeMap<>();
        for (JsonNode f : files) {
            if (f.has("assimpRatio")) {
                imported++;
                ratios.add(f.get("assimpRatio").asDouble());
            } else if (f.has("assimpError")) {
                refused++;
                messages.merge(f.get("assimpError").asText(), 1, Integer::sum);
            }
        }
        if (imported + refused == 0) {
            return;
        }
        g.put("assimpImported", imported);
        g.put("assimpRefused", refused);
        ArrayNode why = g.putArray("assimpRefusals");
        messages.forEach((message, count) -> why.addObject().put("message", message).put("files", count));
        if (!ratios.isEmpty()) {
            Collections.sort(ratios);
            g.put("medianAssimpRatio", ratios.get(ratios.size() / 2));
        }
    }

    /** Over every group measured: the slowest import, and whether every file meets the requirement. */
    private static void requirement(ObjectNode results, JsonNode groups) {
        double slowest = 0;
        boolean all = true;
        int files = 0;
        for (JsonNode g : groups) {
            if (g.has("slowestImportMs")) {
                slowest = Math.max(slowest, g.get("slowestImportMs").asDouble());
                all &= g.get("allMeetRequirement").asBoolean();
                files += g.get("imported").asInt();
            }
        }
        results.put("importedFiles", files);
        results.put("slowestImportMs", slowest);
        results.put("allMeetRequirement", all);
    }

    /** Each .glb of our assets against the .dae beside it with the same name. */
    private static void twins(ObjectNode twins, List<ParseTimer.Input> assets) {
        twins.put("tolerancePpm", AssetTwins.TOLERANCE_PPM);
        twins.put("samePositionPpm", AssetTwins.SAME_POSITION_PPM);
        ArrayNode fractions = twins.putArray("clipFractions");
        for (double f : AssetTwins.CLIP_FRACTIONS) {
            fractions.add(f);
        }
        ArrayNode pairs = twins.putArray("pairs");
        ArrayNode alone = twins.putArray("withoutTwin");
        int agreeing = 0;
        double worst = 0;
        for (ParseTimer.Input in : assets) {
            Path file = in.location();
            String name = file.getFileName().toString();
            String lower = name.toLowerCase(Locale.ROOT);
            String stem = name.substring(0, name.lastIndexOf('.'));
            Path dae = file.resolveSibling(stem + ".dae");
            if (lower.endsWith(".dae") && !Files.isRegularFile(file.resolveSibling(stem + ".glb"))
                    || lower.endsWith(".glb") && !Files.isRegularFile(dae)) {
                alone.add(name);
            }
            if (!lower.endsWith(".glb") || !Files.isRegularFile(dae)) {
                continue;
            }
            ObjectNode p = pairs.addObject();
            p.put("glb", name);
            p.put("dae", dae.getFileName().toString());
            try {
                AssetTwins.Comparison c = AssetTwins.compare(ModelImporter.read(dae), ModelImporter.read(file));
                p.put("daeTriangles", c.triangles()[0]);
                p.put("glbTriangles", c.triangles()[1]);
                p.put("daeJoints", c.joints()[0]);
                p.put("glbJoints", c.joints()[1]);
                p.put("daeClipSeconds", EvalReport.round(c.clipSeconds()[0]));
                p.put("glbClipSeconds", EvalReport.round(c.clipSeconds()[1]));
                p.put("glbPoints", c.glbPoints());
                p.put("unpairedPoints", c.unpaired());
                p.put("maxDistancePpm", EvalReport.round(c.maxDistancePpm()));
                p.put("agrees", c.agrees());
                agreeing += c.agrees() ? 1 : 0;
                worst = Math.max(worst, c.maxDistancePpm());
            } catch (IOException | ImportException | RuntimeException e) {
                p.put("error", String.valueOf(e.getMessage()));
            }
        }
        twins.put("pairCount", pairs.size());
        twins.put("agreeing", agreeing);
        twins.put("allAgree", agreeing == pairs.size());
        twins.put("maxDistancePpm", EvalReport.round(worst));
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        boolean assimp = results.has("assimpVersion");
        introduce(results, assimp, report);
        JsonNode groups = results.get("groups");
        List<EvalLoadFigures.Row> rows = new ArrayList<>();
        for (String[] key : GROUPS) {
            JsonNode g = groups.get(key[0]);
            String at = "/groups/" + key[0];
            report.heading(3, capitalised(g.get("title").asText()));
            if (g.has("skipped")) {
                report.paragraph("Skipped: `" + g.get("skipped").asText() + "`.");
                continue;
            }
            groupSummary(results, g, at, report);
            if (g.has("assimpImported")) {
                assimpSummary(results, g, at, report);
            }
            if (key[0].equals("cts")) {
                refusals(results, at, report);
                EvalLoadFigures.suite(g, report);
                continue;
            }
            fileTable(results, g, at, report, rows);
            if (key[0].equals("assets")) {
                twinReport(results, report);
            }
        }
        if (!rows.isEmpty()) {
            EvalLoadFigures.files(rows, assimp, report);
        }
    }

    /** How the files are timed, the thesis' requirement and whether every file meets it, assimp beside. */
    private static void introduce(JsonNode results, boolean assimp, EvalReport report) {
        report.paragraph("Each file is read into memory; after a shared warm-up of "
                + EvalReport.num(results, "/warmupSeconds") + " s it is imported in "
                + EvalReport.num(results, "/runsPerFile") + " runs of " + EvalReport.num(results, "/importsPerRun")
                + " import(s) each (files of the conformance suite " + EvalReport.num(results, "/ctsImportsPerRun")
                + "), a run's time the median of its imports. Per file: the median of the runs, the fastest and the"
                + " slowest run, and the slowest single import of all runs, which the thesis' requirement judges:"
                + " every file loads in under " + EvalReport.num(results, "/requirementSeconds") + " s. "
                + (results.get("allMeetRequirement").asBoolean() ? "Every one of the "
                        + EvalReport.num(results, "/importedFiles") + " files imported meets it"
                        : "Not every file imported meets it")
                + " (the slowest import of all: " + EvalReport.num(results, "/slowestImportMs") + " ms). "
                + (assimp ? "assimp `" + results.get("assimpVersion").asText() + "` (LWJGL, flags `"
                        + results.get("assimpFlags").asText() + "`) imports every file from the same bytes with the"
                        + " same protocol, its runs interleaved with ours (ours first in one run, assimp's in the"
                        + " next); assimp / ours (of the medians) above one means we are faster."
                        : "assimp is absent here (`" + results.get("assimpMissing").asText() + "`)."));
    }

    /** Group {@code g} (at {@code at}): how many files meet the requirement, its slowest import, its median file. */
    private static void groupSummary(JsonNode results, JsonNode g, String at, EvalReport report) {
        report.paragraph(EvalReport.num(results, at + "/underRequirement") + " of "
                + EvalReport.num(results, at + "/imported") + " imported files meet the requirement"
                + (g.has("slowestFile") ? " (the slowest single import of any file and run: "
                        + EvalReport.num(results, at + "/slowestImportMs") + " ms, `" + g.get("slowestFile").asText()
                        + "`)" : "") + "; "
                + EvalReport.num(results, at + "/refused") + " of " + EvalReport.num(results, at + "/fileCount")
                + " refused" + (g.has("medianFileMs") ? "; the median file imports in "
                        + EvalReport.num(results, at + "/medianFileMs") + " ms, all of them in "
                        + EvalReport.num(results, at + "/sumOfMediansMs") + " ms" : "") + "."
                + (results.has("ctsEvery") && at.endsWith("/cts")
                        ? " Quick run: one file in " + EvalReport.num(results, "/ctsEvery") + " of the suite, in"
                                + " name order." : ""));
    }

    /** What assimp imports and refuses of group {@code g}, with its messages. */
    private static void assimpSummary(JsonNode results, JsonNode g, String at, EvalReport report) {
        report.paragraph("assimp imports " + EvalReport.num(results, at + "/assimpImported") + " of these files"
                + " and refuses " + EvalReport.num(results, at + "/assimpRefused")
                + (g.has("medianAssimpRatio") ? "; over the files both import, the median of assimp / ours is "
                        + EvalReport.num(results, at + "/medianAssimpRatio") : "") + ".");
        JsonNode why = g.get("assimpRefusals");
        for (int k = 0; k < why.size(); k++) {
            report.line("- assimp refuses " + EvalReport.num(results, at + "/assimpRefusals/" + k + "/files")
                    + " file(s) with `" + why.get(k).get("message").asText().replace('`', '\'') + "`");
        }
        if (why.size() > 0) {
            report.line("");
        }
    }

    /** One row per file of group {@code g}; adds each imported file's row to {@code rows} for the figure. */
    private static void fileTable(JsonNode results, JsonNode g, String at, EvalReport report,
            List<EvalLoadFigures.Row> rows) {
        report.header("file", "kB", "triangles", "median ms", "runs ms", "slowest import ms", "assimp median ms",
                "assimp runs ms", "assimp / ours");
        JsonNode files = g.get("files");
        for (int f = 0; f < files.size(); f++) {
            String p = at + "/files/" + f;
            JsonNode file = files.get(f);
            String name = "`" + file.get("file").asText() + "`";
            if (file.has("error")) {
                report.row(name, EvalReport.num(results, p + "/kilobytes"), "refused", "-", "-", "-", "-", "-", "-");
                continue;
            }
            boolean theirs = file.has("assimpMs");
            report.row(name, EvalReport.num(results, p + "/kilobytes"), EvalReport.num(results, p + "/triangles"),
                    EvalReport.num(results, p + "/oursMs/median"), range(results, p + "/oursMs"),
                    EvalReport.num(results, p + "/slowestImportMs"),
                    theirs ? EvalReport.num(results, p + "/assimpMs/median")
                            : file.has("assimpError") ? "refused" : "-",
                    theirs ? range(results, p + "/assimpMs") : "-", EvalReport.numOrDash(results, p + "/assimpRatio"));
            rows.add(new EvalLoadFigures.Row(file.get("file").asText(), file.get("oursMs"), file.get("assimpMs")));
        }
        report.line("");
    }

    /** A spread's fastest to slowest run, "min-max". */
    private static String range(JsonNode results, String spread) {
        return EvalReport.num(results, spread + "/min") + "-" + EvalReport.num(results, spread + "/max");
    }

    private static void refusals(JsonNode results, String at, EvalReport report) {
        JsonNode files = results.at(at + "/files");
        for (JsonNode f : files) {
            if (f.has("error")) {
                report.line("- refused `" + f.get("file").asText() + "`: `" + f.get("error").asText()
                        .replace('`', '\'') + "`");
            }
        }
        report.line("");
    }

    /** The .glb twins against their .dae files: a row per pair, the largest distance a column. */
    private static void twinReport(JsonNode results, EvalReport report) {
        JsonNode twins = results.get("twins");
        if (twins.get("pairs").isEmpty()) {
            report.paragraph("**The glTF twins.** No `.glb` of our assets has a `.dae` of the same name beside it.");
            return;
        }
        report.paragraph("**The glTF twins.** Each `.glb` of our assets is to hold the scene of the `.dae` beside it"
                + " (assets/README.md), checked here: the same triangles, skin joints and clip length, and the same"
                + " points where LBS puts them at " + fractions(results) + " of the first clip, each file imported"
                + " and skinned by core"
                + " and brought to Y-up metres by its own up axis. A .glb point is paired with the .dae point at its"
                + " bind position (within " + EvalReport.num(results, "/twins/samePositionPpm") + " millionth of the"
                + " model's size); the column is the largest distance between paired points over those times, in"
                + " millionths of the model's size (its bind box' diagonal). The tolerance, "
                + EvalReport.num(results, "/twins/tolerancePpm") + " millionths, is what the files' float text"
                + " allows; a broken export lands orders of magnitude beyond it. "
                + EvalReport.num(results, "/twins/agreeing") + " of " + EvalReport.num(results, "/twins/pairCount")
                + " twins agree"
                + " (the largest distance of all: " + EvalReport.num(results, "/twins/maxDistancePpm")
                + " millionths)." + (twins.get("withoutTwin").size() == 0 ? ""
                        : " Without a twin: " + quoted(twins.get("withoutTwin")) + "."));
        report.header(".glb", "triangles .dae / .glb", "joints .dae / .glb", "clip s .dae / .glb",
                "points paired", "largest distance, millionths of the size", "agrees");
        JsonNode pairs = twins.get("pairs");
        for (int i = 0; i < pairs.size(); i++) {
            String p = "/twins/pairs/" + i;
            JsonNode pair = pairs.get(i);
            if (pair.has("error")) {
                report.row("`" + pair.get("glb").asText() + "`", "not compared: `" + pair.get("error").asText()
                        .replace('`', '\'') + "`", "-", "-", "-", "-", "no");
                continue;
            }
            report.row("`" + pair.get("glb").asText() + "`",
                    EvalReport.num(results, p + "/daeTriangles") + " / " + EvalReport.num(results, p + "/glbTriangles"),
                    EvalReport.num(results, p + "/daeJoints") + " / " + EvalReport.num(results, p + "/glbJoints"),
                    EvalReport.num(results, p + "/daeClipSeconds") + " / "
                            + EvalReport.num(results, p + "/glbClipSeconds"),
                    pair.get("unpairedPoints").asInt() == 0 ? "all " + EvalReport.num(results, p + "/glbPoints")
                            : EvalReport.num(results, p + "/unpairedPoints") + " of "
                                    + EvalReport.num(results, p + "/glbPoints") + " unpaired",
                    EvalReport.num(results, p + "/maxDistancePpm"), pair.get("agrees").asBoolean() ? "yes" : "**no**");
        }
        report.line("");
    }

    private static String fractions(JsonNode results) {
        List<String> f = new ArrayList<>();
        for (int i = 0; i < results.at("/twins/clipFractions").size(); i++) {
            f.add(EvalReport.num(results, "/twins/clipFractions/" + i));
        }
        return String.join(", ", f);
    }

    private static String quoted(JsonNode names) {
        List<String> q = new ArrayList<>();
        names.forEach(n -> q.add("`" + n.asText() + "`"));
        return String.join(", ", q);
    }

    private static String capitalised(String s) {
        return s.isEmpty() ? s : Character.toUpperCase(s.charAt(0)) + s.substring(1);
    }
}
