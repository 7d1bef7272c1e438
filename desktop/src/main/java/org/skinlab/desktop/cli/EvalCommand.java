package org.skinlab.desktop.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ObjectNode;

import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import me.tongfei.progressbar.ProgressBarConsumer;
import me.tongfei.progressbar.ProgressBarStyle;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.bench.BenchCorpus;

/**
 * {@code skinlab eval}: the thesis' evaluation redone on this machine, one report. Each
 * {@link EvalSection} measures into results.json; README.md and the figures are then written from
 * those results alone. See docs/evaluation.md.
 */
@Command(name = "eval", mixinStandardHelpOptions = true,
        description = {"The evaluation: measures every section and writes DIR/README.md, one PNG per figure and"
                + " DIR/results.json with every number. Sections: load (import time: our assets, the shared"
                + " corpus, the conformance suite, assimp beside), time (time per deformation: LBS, DQS, CoR; SIMD and"
                + " scalar; 4 influences and all; beside the thesis' table), crowds (characters per frame against threads"
                + " and characters on the CPU, drawn fps against copies with CPU and GPU skinning), quality (volume kept"
                + " over each clip, joint ring against twist, bulge against bend, largest distance between methods, the"
                + " error of capping influences), pictures (the viewer's screenshots of each method at each asset's"
                + " extreme pose, and the difference view), tracking (markers found and pose error per distance and"
                + " tilt, false markers, time per frame beside BoofCV's detector), advice (what it means for AR on a"
                + " phone: time against vertices, influences and joints with fitted lines; a recommendation per use"
                + " drawn from the other sections).",
            "Run it from the repository (it reads assets/ and ../shared), under xvfb-run -a without a display (the pictures"
                + " and the drawn crowds need one). The full run takes about 10 minutes on 2 cores; --quick under 3."})
public final class EvalCommand implements Callable<Integer> {
    /** The sections in report order; a new section is one entry here. */
    static final List<EvalSection> SECTIONS = List.of(new EvalLoadSection(), new EvalTimeSection(),
            new EvalCrowdsSection(), new EvalQualitySection(), new EvalPicturesSection(), new EvalTrackingSection(),
            new EvalAdviceSection());

    @Option(names = "--out", paramLabel = "DIR", description = "where the report goes (default: ${DEFAULT-VALUE})")
    Path out = Path.of("docs/evaluation");

    @Option(names = "--quick", description = "fewer files and shorter measurements (under 3 minutes): a smoke run,"
            + " not figures to quote")
    boolean quick;

    @Option(names = "--only", paramLabel = "SECTION", split = ",",
            description = "only these sections (comma-separated), of: load, time, crowds, quality, pictures, tracking,"
                    + " advice")
    List<String> only = new ArrayList<>();

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        List<EvalSection> sections = selected();
        Path root = BenchCorpus.repositoryRoot(Path.of(""));
        if (root == null) {
            throw usage("run it inside the skinlab repository (no folder at or above "
                    + Path.of("").toAbsolutePath() + " holds settings.gradle and " + BenchCorpus.CHARACTERS + ")");
        }
        if (Files.exists(out) && !Files.isDirectory(out)) {
            throw usage("--out: not a folder: " + out);
        }
        Files.createDirectories(out);
        PrintWriter err = spec.commandLine().getErr();
        EvalContext context = new EvalContext(quick, root, err);
        ObjectMapper mapper = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);
        ObjectNode results = mapper.createObjectNode();
        EvalMachine.describe(results.putObject("machine"), spec.commandLine().getParseResult().originalArgs());
        results.put("quick", quick);
        results.put("started", Instant.now().toString());
        long[] lengths = new long[sections.size()];
        for (int i = 0; i < sections.size(); i++) {
            lengths[i] = Math.max(1, Math.round(10 * sections.get(i).estimatedSeconds(context)));
        }
        long start = System.nanoTime();
        ObjectNode bySection = results.putObject("sections");
        context.useResults(bySection);
        ProgressBarBuilder builder = new ProgressBarBuilder().setTaskName("eval").setInitialMax(total(lengths))
                .setStyle(ProgressBarStyle.ASCII).setUnit("s", 10).setUpdateIntervalMillis(500);
        if (System.console() == null) {
            // A log or a pipe, not a terminal: a line every 10 s, on the command's error stream.
            builder.setConsumer(new LineConsumer(err)).setUpdateIntervalMillis(10_000);
        }
        try (ProgressBar bar = builder.build()) {
            context.useBar(bar);
            for (int i = 0; i < sections.size(); i++) {
                EvalSection s = sections.get(i);
                context.startSection(s.key(), lengths[i]);
                s.measure(context, bySection.putObject(s.key()));
                context.progress(1);
            }
        }
        results.put("seconds", EvalReport.round((System.nanoTime() - start) / 1e9));
        mapper.writeValue(out.resolve("results.json").toFile(), results);
        EvalReport report = new EvalReport(out, results.get("machine"));
        header(report, results, sections);
        for (EvalSection s : sections) {
            report.heading(2, s.title());
            s.report(bySection.get(s.key()), report);
        }
        Files.writeString(out.resolve("README.md"), report.markdown());
        PrintWriter o = spec.commandLine().getOut();
        o.printf(Locale.ROOT, "eval: %s and %d figure%s in %s (%s)%n", "README.md, results.json",
                report.figures().size(), report.figures().size() == 1 ? "" : "s", out,
                Duration.ofSeconds(Math.round(results.get("seconds").asDouble())).toString().substring(2)
                        .toLowerCase(Locale.ROOT));
        o.flush();
        return ExitCodes.OK;
    }

    private static void header(EvalReport report, ObjectNode results, List<EvalSection> sections) {
        report.heading(1, "Evaluation");
        report.paragraph("Generated by `" + results.at("/machine/command").asText() + "`"
                + (results.get("quick").asBoolean() ? " (quick: fewer files and short measurements; not figures to"
                        + " quote)" : "") + ", started `" + results.get("started").asText() + "`, in "
                + EvalReport.num(results, "/seconds") + " s. Every number below is in `results.json`; how each is"
                + " measured: docs/evaluation.md.");
        for (String line : EvalMachine.lines(results.get("machine"))) {
            report.line("- `" + line + "`");
        }
        report.line("");
        report.paragraph("Sections: " + sections.stream().map(EvalSection::title).collect(Collectors.joining(", "))
                + ".");
    }

    /** The bar as whole lines on a writer, for logs. */
    private static final class LineConsumer implements ProgressBarConsumer {
        private final PrintWriter out;

        LineConsumer(PrintWriter out) {
            this.out = out;
        }

        @Override
        public int getMaxRenderedLength() {
            return 100;
        }

        @Override
        public void accept(String rendered) {
            out.println(rendered.trim());
            out.flush();
        }

        @Override
        public void close() {
            out.flush();
        }
    }

    private static long total(long[] lengths) {
        long t = 0;
        for (long l : lengths) {
            t += l;
        }
        return t;
    }

    /** The sections --only names, in report order; all without it. */
    private List<EvalSection> selected() {
        if (only.isEmpty()) {
            return SECTIONS;
        }
        Set<String> wanted = new LinkedHashSet<>();
        for (String o : only) {
            String key = o.trim().toLowerCase(Locale.ROOT);
            if (SECTIONS.stream().noneMatch(s -> s.key().equals(key))) {
                throw usage("--only: unknown section \"" + o + "\" (valid: "
                        + SECTIONS.stream().map(EvalSection::key).collect(Collectors.joining(", ")) + ")");
            }
            wanted.add(key);
        }
        return SECTIONS.stream().filter(s -> wanted.contains(s.key())).collect(Collectors.toList());
    }

    private static CommandFailure usage(String message) {
        return new CommandFailure(ExitCodes.USAGE, "eval: " + message, null);
    }
}
