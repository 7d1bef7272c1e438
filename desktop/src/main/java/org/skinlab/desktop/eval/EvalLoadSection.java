package org.skinlab.desktop.eval;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collections;
import java.util.List;
import java.util.Locale;
import java.util.zip.ZipEntry;
import java.util.zip.ZipFile;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.knowm.xchart.CategoryChart;
import org.knowm.xchart.CategoryChartBuilder;
import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.Styler;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ModelFileSearch;
import org.skinlab.desktop.bench.AssimpBaseline;
import org.skinlab.desktop.bench.BenchCorpus;
import org.skinlab.desktop.bench.ParseTimer;

/**
 * Section "load": import time of our assets, of the shared corpus and of the shared conformance
 * suite (read in place from its zip), with {@link ParseTimer} (the timing of {@code bench parse}),
 * against the thesis' requirement that a file loads in under 10 s, and assimp on our assets and the
 * corpus in the same run when its native library loads. A file our importer refuses (the suite has
 * a few made to be refused) is counted and named, not timed.
 */
final class EvalLoadSection implements EvalSection {
    static final double REQUIREMENT_SECONDS = 10;

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
        return context.quick() ? 4 : 25;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        boolean quick = context.quick();
        double warmup = quick ? 0.5 : 3;
        int runs = quick ? 3 : 25;
        results.put("requirementSeconds", REQUIREMENT_SECONDS);
        results.put("runsPerFile", runs);
        results.put("ctsRunsPerFile", quick ? 1 : 5);
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
        int[] done = {0};
        // Ours and assimp over our assets and the corpus in one timer: one shared warm-up.
        List<ParseTimer.Input> withAssimp = new ArrayList<>(assets);
        withAssimp.addAll(corpus);
        List<ParseTimer.Result> measured = new ParseTimer(warmup, runs, assimpFlags, true, null, "")
                .onProgress(n -> context.progress((double) n / total)).measure(withAssimp);
        done[0] = withAssimp.size();
        ArrayNode groups = results.putArray("groups");
        group(groups.addObject(), "assets", "our assets (assets/)", measured.subList(0, assets.size()), null);
        group(groups.addObject(), "corpus", "the shared corpus", measured.subList(assets.size(), measured.size()),
                context.corpus() == null ? "no shared corpus at " + context.corpusPlace() : null);
        List<ParseTimer.Result> suite = cts.isEmpty() ? List.of()
                : new ParseTimer(warmup, quick ? 1 : 5, assimpFlags, true, null, "")
                        .onProgress(n -> context.progress((double) (done[0] + n) / total)).measure(cts);
        group(groups.addObject(), "cts", "the shared conformance suite", suite,
                context.cts() == null ? "no conformance suite at " + context.ctsPlace() : null);
        if (quick && !cts.isEmpty()) {
            results.put("ctsEvery", 8);
        }
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

    private static void group(ObjectNode g, String key, String title, List<ParseTimer.Result> results, String skipped) {
        g.put("key", key);
        g.put("title", title);
        if (skipped != null) {
            g.put("skipped", skipped);
            return;
        }
        int imported = 0;
        int under = 0;
        double slowest = 0;
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
            f.put("runs", r.millis.length);
            f.put("medianMillis", EvalReport.round(r.median()));
            f.put("slowestMillis", EvalReport.round(r.max()));
            medians.add(r.median());
            slowest = Math.max(slowest, r.max());
            if (r.max() < REQUIREMENT_SECONDS * 1000) {
                under++;
            }
            if (r.assimpMillis != null) {
                f.put("assimpMedianMillis", EvalReport.round(ParseTimer.Result.median(r.assimpMillis)));
                f.put("assimpRatio", EvalReport.round(r.assimpRatio()));
            } else if (r.assimpError != null) {
                f.put("assimpError", r.assimpError);
            }
        }
        assimpSummary(g, files);
        g.put("fileCount", results.size());
        g.put("imported", imported);
        g.put("refused", results.size() - imported);
        g.put("underRequirement", imported == 0 ? 0 : under);
        g.put("slowestMillis", EvalReport.round(slowest));
        double[] m = medians.stream().mapToDouble(Double::doubleValue).sorted().toArray();
        if (m.length > 0) {
        g.put("medianOfMediansMillis", EvalReport.round(m[m.length / 2]));
        g.put("sumOfMediansMillis", EvalReport.round(Arrays.stream(m).sum()));
    }
    }

    /** How many files assimp imported and refused, and the median file's assimp / ours. */
    private static void assimpSummary(ObjectNode g, JsonNode files) {
        int imported = 0;
        int refused = 0;
        List<Double> ratios = new ArrayList<>();
        java.util.Map<String, Integer> messages = new java.util.TreeMap<>();
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

    @Override
    public void report(JsonNode results, EvalReport report) {
        boolean assimp = results.has("assimpVersion");
        introduce(results, assimp, report);
        List<String[]> bars = new ArrayList<>();
        JsonNode groups = results.get("groups");
        for (int i = 0; i < groups.size(); i++) {
            JsonNode g = groups.get(i);
            String at = "/groups/" + i;
            report.heading(3, capitalised(g.get("title").asText()));
            if (g.has("skipped")) {
                report.paragraph("Skipped: `" + g.get("skipped").asText() + "`.");
                continue;
            }
            groupSummary(results, g, at, report);
            if (g.has("assimpImported")) {
        assimpSummary(results, g, at, report);
    }
    if (g.get("key").asText().equals("cts")) {
        refusals(results, at, report);
        ctsFigure(g, report);
        continue;
    }
    fileTable(results, g, at, report, bars);
}
if (!bars.isEmpty()) {
    filesFigure(bars, assimp, report);
}
    }

    /** How the files are timed, the thesis' requirement, and assimp beside (or why it is absent). */
    private static void introduce(JsonNode results, boolean assimp, EvalReport report) {
        report.paragraph("Each file is read into memory, then imported " + EvalReport.num(results, "/runsPerFile")
                + " times after a shared warm-up of " + EvalReport.num(results, "/warmupSeconds")
                + " s (files of the conformance suite " + EvalReport.num(results, "/ctsRunsPerFile")
                + " times); the median and the slowest import per file. The thesis' requirement: every file"
                + " loads in under " + EvalReport.num(results, "/requirementSeconds")
                + " s; a file meets it when its slowest import does. "
                + (assimp ? "assimp `" + results.get("assimpVersion").asText() + "` (LWJGL, flags `"
                        + results.get("assimpFlags").asText() + "`) imports our assets and the corpus from the same"
                        + " bytes right after ours, with the same protocol; assimp / ours above one means we are"
                        + " faster."
                        : "assimp is absent here (`" + results.get("assimpMissing").asText() + "`)."));
    }

    /** Group {@code g} (at {@code at}): how many files meet the requirement, and its median file. */
    private static void groupSummary(JsonNode results, JsonNode g, String at, EvalReport report) {
        report.paragraph(EvalReport.num(results, at + "/underRequirement") + " of "
                + EvalReport.num(results, at + "/imported") + " imported files meet the requirement (the"
                + " slowest import: " + EvalReport.num(results, at + "/slowestMillis") + " ms); "
                + EvalReport.num(results, at + "/refused") + " of " + EvalReport.num(results, at + "/fileCount")
                + " refused" + (g.has("medianOfMediansMillis") ? "; the median file imports in "
                        + EvalReport.num(results, at + "/medianOfMediansMillis") + " ms, all of them in "
                        + EvalReport.num(results, at + "/sumOfMediansMillis") + " ms" : "") + "."
                + (results.has("ctsEvery") && g.get("key").asText().equals("cts")
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

    /** One row per file of group {@code g}; adds each imported file's bar to {@code bars}. */
    private static void fileTable(JsonNode results, JsonNode g, String at, EvalReport report, List<String[]> bars) {
        report.header("file", "kB", "triangles", "median ms", "slowest ms", "assimp median ms", "assimp / ours");
        JsonNode files = g.get("files");
        for (int f = 0; f < files.size(); f++) {
            String p = at + "/files/" + f;
            JsonNode file = files.get(f);
            if (file.has("error")) {
                report.row("`" + file.get("file").asText() + "`", EvalReport.num(results, p + "/kilobytes"),
                        "refused", "-", "-", "-", "-");
                continue;
            }
            report.row("`" + file.get("file").asText() + "`", EvalReport.num(results, p + "/kilobytes"),
                    EvalReport.num(results, p + "/triangles"), EvalReport.num(results, p + "/medianMillis"),
                    EvalReport.num(results, p + "/slowestMillis"),
                    file.has("assimpError") ? "refused" : EvalReport.numOrDash(results, p + "/assimpMedianMillis"),
                    EvalReport.numOrDash(results, p + "/assimpRatio"));
            bars.add(new String[] {file.get("file").asText(), file.get("medianMillis").asText(),
                    file.path("assimpMedianMillis").asText("")});
        }
        report.line("");
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

    private static void filesFigure(List<String[]> bars, boolean assimp, EvalReport report) {
        CategoryChart chart = new CategoryChartBuilder().width(1000).height(560)
                .title("Import time per file (median)").xAxisTitle("file").yAxisTitle("ms").build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        chart.getStyler().setXAxisLabelRotation(60);
        List<String> names = new ArrayList<>();
        List<Double> ours = new ArrayList<>();
        List<Double> theirs = new ArrayList<>();
        for (String[] b : bars) {
            names.add(b[0]);
            ours.add(Double.parseDouble(b[1]));
            // A file assimp refuses gets no bar.
            theirs.add(b[2].isEmpty() ? 0.0 : Double.parseDouble(b[2]));
        }
        chart.addSeries("skinlab", names, ours);
        if (assimp) {
            chart.addSeries("assimp", names, theirs);
        }
        report.figure("load-files.png", "Import time per file, skinlab and assimp", chart);
    }

    private static void ctsFigure(JsonNode g, EvalReport report) {
        List<Double> ours = sortedMillis(g, "medianMillis");
        if (ours.isEmpty()) {
            return;
        }
        XYChart chart = new XYChartBuilder().width(1000).height(500)
                .title("Conformance suite: import time per file, each tool's sorted (the requirement is 10 000 ms)")
                .xAxisTitle("files, fastest first").yAxisTitle("median ms (log scale)").build();
        chart.getStyler().setYAxisLogarithmic(true);
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideNW);
        chart.addSeries("skinlab (" + ours.size() + " files imported)", ranks(ours.size()), ours);
        List<Double> theirs = sortedMillis(g, "assimpMedianMillis");
        if (!theirs.isEmpty()) {
            chart.addSeries("assimp (" + theirs.size() + " files imported)", ranks(theirs.size()), theirs);
        }
        report.figure("load-cts.png", "Conformance suite: import time per file, sorted", chart);
    }

    /** The files' values of {@code field}, sorted; a log axis has no zero, so values under the rounding are left out. */
    private static List<Double> sortedMillis(JsonNode g, String field) {
        List<Double> values = new ArrayList<>();
        for (JsonNode f : g.get("files")) {
            if (f.has(field) && f.get(field).asDouble() > 0) {
                values.add(f.get(field).asDouble());
            }
        }
        Collections.sort(values);
        return values;
    }

    private static List<Double> ranks(int n) {
        List<Double> rank = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            rank.add((double) (i + 1));
        }
        return rank;
    }

    private static String capitalised(String s) {
        return s.isEmpty() ? s : Character.toUpperCase(s.charAt(0)) + s.substring(1);
    }
}
