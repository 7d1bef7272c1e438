package org.skinlab.desktop.eval;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Instant;
import java.util.Collection;
import java.util.List;
import java.util.stream.Collectors;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ObjectNode;

import me.tongfei.progressbar.ProgressBar;
import me.tongfei.progressbar.ProgressBarBuilder;
import me.tongfei.progressbar.ProgressBarConsumer;
import me.tongfei.progressbar.ProgressBarStyle;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;

/**
 * One run of the evaluation: each {@link EvalSection} measures into results.json, then README.md
 * and the figures are written from those results alone ({@link #write}; {@link #rewrite} writes
 * them again from a results.json on disk). See docs/evaluation.md.
 */
public final class Evaluation {
    /**
     * The sections in the order they measure (a section may argue from those before it); the
     * report puts the summaries ({@link EvalSection#summary}) first, then the others in this order.
     * A new section is one entry here.
     */
    static final List<EvalSection> SECTIONS = List.of(new EvalLoadSection(), new EvalTimeSection(),
            new EvalPhoneSection(), new EvalCrowdsSection(), new EvalQualitySection(), new EvalPicturesSection(),
            new EvalTrackingSection(), new EvalArFrameSection(), new EvalAdviceSection(), new EvalClaimsSection());

    /** The results' file in the report's folder. */
    static final String RESULTS = "results.json";
    private static final ObjectMapper MAPPER = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);

    private final List<EvalSection> sections;
    private final EvalContext context;
    private final Path out;
    private final PrintWriter err;

    /**
     * The sections named by {@code keys} (all when empty; see {@link #keys()}) of a run from
     * repository {@code root} into folder {@code out}, saying what it skips and the progress bar on
     * {@code err}; {@code skinlabMain} is the class whose {@code main} runs {@code skinlab}'s
     * commands (the pictures are drawn by its {@code view} in a child JVM).
     */
    public Evaluation(Collection<String> keys, boolean quick, Path root, Path out, PrintWriter err,
            Class<?> skinlabMain) {
        this.sections = keys.isEmpty() ? SECTIONS
                : SECTIONS.stream().filter(s -> keys.contains(s.key())).collect(Collectors.toList());
        this.context = new EvalContext(quick, root, err, new ViewerProcess(skinlabMain));
        this.out = out;
        this.err = err;
    }

    /**
     * The real video (an MP4 JCodec decodes, or a folder of frames) that the "ar-frame" section
     * times, seen through {@code intrinsics} (or null), its markers of {@code dictionary}; without
     * this call, the synthetic demo video.
     */
    public Evaluation withArVideo(Path video, Path intrinsics, String dictionary) {
        context.useArVideo(video, intrinsics, dictionary);
        return this;
    }

    /** The sections' keys, in the order they measure. */
    public static List<String> keys() {
        return SECTIONS.stream().map(EvalSection::key).collect(Collectors.toList());
    }

    /** What a run wrote: the number of figures and the seconds it measured for. */
    public static final class Written {
        public final int figures;
        public final double seconds;

        Written(int figures, double seconds) {
            this.figures = figures;
            this.seconds = seconds;
        }
    }

    /**
     * Measures every section, then writes results.json, README.md and the figures ({@link #write});
     * {@code args} is the command line.
     */
    public Written run(List<String> args) throws IOException {
        Files.createDirectories(out);
        context.useEarlier(earlierSections(out));
        ObjectNode results = MAPPER.createObjectNode();
        EvalMachine.describe(results.putObject("machine"), args, context.root());
        results.put("quick", context.quick());
        results.put("started", Instant.now().toString());
        long start = System.nanoTime();
        measure(results.putObject("sections"));
        results.put("seconds", EvalReport.round((System.nanoTime() - start) / 1e9));
        EvalNoise.summarise(results.get("sections"), results.at("/machine/loadAverageStart").asDouble(),
                results.putObject("noise"));
        return write(out, results);
    }

    /**
     * Writes {@code results} as {@code out}/results.json, and README.md and the figures from them
     * alone, measuring nothing: the sections the results hold, the summaries first (derived again
     * from the others' results: an added phone changes the claims). A figure that a section cannot
     * draw again from its results (the pictures) is kept as the run that measured drew it, when its
     * PNG is in the folder ({@link EvalReport#existing}); nothing is deleted.
     */
    static Written write(Path out, ObjectNode results) throws IOException {
        Files.createDirectories(out);
        ObjectNode bySection = (ObjectNode) results.get("sections");
        List<EvalSection> written = new java.util.ArrayList<>();
        for (EvalSection s : SECTIONS) {
            if (s.summary() && bySection.has(s.key())) {
                s.derive(bySection::get, bySection.putObject(s.key()));
                written.add(s);
            }
        }
        SECTIONS.stream().filter(s -> !s.summary() && bySection.has(s.key())).forEach(written::add);
        MAPPER.writeValue(out.resolve(RESULTS).toFile(), results);
        EvalReport report = new EvalReport(out, results.get("machine"));
        header(report, results, written);
        for (EvalSection s : written) {
            report.heading(2, s.title());
            s.report(results.get("sections").get(s.key()), report);
        }
        Files.writeString(out.resolve("README.md"), report.markdown());
        return new Written(report.figures().size(), results.get("seconds").asDouble());
    }

    /**
     * Writes README.md and the figures again from {@code out}/results.json alone, measuring
     * nothing ({@link #write}).
     *
     * @throws CommandFailure (usage) when the folder holds no readable results.json
     */
    public static Written rewrite(Path out) throws IOException {
        return write(out, readResults(out));
    }

    /**
     * {@code out}/results.json, as an earlier run wrote it.
     *
     * @throws CommandFailure (usage) naming the file when it is missing, not JSON or not a run's results
     */
    static ObjectNode readResults(Path out) {
        Path file = out.resolve(RESULTS);
        if (!Files.isRegularFile(file)) {
            throw new CommandFailure(ExitCodes.USAGE, file + ": not found (skinlab eval writes it)", null);
        }
        JsonNode tree;
        try {
            tree = MAPPER.readTree(file.toFile());
        } catch (IOException e) {
            throw new CommandFailure(ExitCodes.USAGE, file + ": not readable as JSON: " + e.getMessage(), e);
        }
        for (String field : new String[] {"machine", "sections", "seconds", "quick", "started"}) {
            if (tree == null || !tree.isObject() || !tree.has(field)) {
                throw new CommandFailure(ExitCodes.USAGE, file + ": /" + field + ": missing (not the results of"
                        + " skinlab eval)", null);
            }
        }
        return (ObjectNode) tree;
    }

    /** The sections of the results.json already in {@code out}, or null when there is none or it is not readable. */
    private static JsonNode earlierSections(Path out) {
        try {
            JsonNode earlier = MAPPER.readTree(out.resolve(RESULTS).toFile());
            return earlier != null && earlier.path("sections").isObject() ? earlier.get("sections") : null;
        } catch (IOException e) {
            return null; // none, or not ours: this run replaces it
        }
    }

    /** Each section's measurements into its node of {@code bySection}, behind one progress bar. */
    private void measure(ObjectNode bySection) {
        long[] lengths = new long[sections.size()];
        for (int i = 0; i < sections.size(); i++) {
            lengths[i] = Math.max(1, Math.round(10 * sections.get(i).estimatedSeconds(context)));
        }
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
    }

    private static void header(EvalReport report, ObjectNode results, List<EvalSection> sections) {
        report.heading(1, "Evaluation");
        report.paragraph("Generated by `" + results.at("/machine/command").asText() + "` at commit `"
                + results.at("/machine/commit").asText() + "`" + (results.at("/machine/uncommittedChanges").asBoolean()
                        ? " with uncommitted changes" : "")
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
        if (results.has("noise")) {
            report.paragraph(EvalNoise.paragraph(results));
        }
    }

    private static long total(long[] lengths) {
        long t = 0;
        for (long l : lengths) {
            t += l;
        }
        return t;
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
}
