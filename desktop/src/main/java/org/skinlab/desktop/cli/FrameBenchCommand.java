package org.skinlab.desktop.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.internal.bench.FrameBench;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.JavaRuntime;
import org.skinlab.desktop.ModelFileSearch;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.bench.BenchCorpus;
import org.skinlab.desktop.bench.FrameBenchTable;
import org.skinlab.desktop.bench.JitWarmup;
import org.skinlab.desktop.bench.PaletteBench;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.PositionSharing;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code skinlab bench frame}: the time of one animation frame of characters ({@link FrameBench}:
 * sample, skinning matrices, skin), minimum and median in microseconds per frame.
 *
 * <p>One file and one method (the default: the default character, LBS) print two lines. Several
 * files, or {@code --method both|all}, print a markdown table with a row per file and a column per
 * method, each row as soon as its file is measured; several files default to both methods and to
 * shorter timings (0.5 s of warm-up and 1 s of frames per file and method instead of 2 s and 3 s;
 * a method's first file still warms up for 2 s, while the JIT compiles its kernels), so that
 * {@code --all-corpus} stays under a minute. {@code --json} prints one line per file
 * and method. A file that cannot be imported is one line on stderr; the others are measured, and
 * the status is then 3. With {@code --blend} (one file) a mixer directs the frame
 * ({@link BlendFrameBench}): the mixer's step is timed apart from the pose and the skinning.
 */
@Command(name = "frame", mixinStandardHelpOptions = true,
        description = {"Time of one frame (sample, skinning matrices, skin) of characters, in microseconds.",
            "One file and method: two lines; several files or --method both|all: a markdown table, one row per file.",
            "With --blend (one file): the frame a mixer directs; the mixer's step (advance, sample every clip, blend)"
                    + " apart from pose and skin, in ns per joint per layer, and the bytes allocated per step."})
public final class FrameBenchCommand implements Callable<Integer> {
    static final Path DEFAULT_FILE = Path.of("assets/characters/humanoid-walk.dae");
    private static final double FIRST_WARMUP = 2.0;

    @Parameters(arity = "0..*", paramLabel = "FILE",
            description = "model files (.dae, .gltf, .glb) or folders (default without --all-corpus: "
                    + "assets/characters/humanoid-walk.dae)")
    List<Path> files = new ArrayList<>();

    @Option(names = "--all-corpus",
            description = "also our assets/characters/*.dae and every .dae of the shared corpus that has a skin")
    boolean allCorpus;

    @Option(names = "--corpus", paramLabel = "DIR", description = "the shared corpus of --all-corpus (default: "
            + BenchCorpus.SHARED_CORPUS + " beside the repository root, else beside the current directory)")
    Path corpus;

    @Option(names = "--method", paramLabel = MethodKeys.KEYS_OR_ALL + "|both",
            description = "skinning method; both: lbs and dqs; all: every method (default: lbs for one file, both"
                    + " for several)")
    String method;

    @Option(names = "--normals", paramLabel = "exact|blended|none",
            description = "normal rule: renormalised inverse-transpose, the blended matrix, or none: positions only"
                    + " (lbs and dqs) (default: ${DEFAULT-VALUE})")
    String normals = "exact";

    @Option(names = "--warmup-seconds", paramLabel = "S",
            description = "warm-up per file and method (default: 2 for one file and method or --blend, else 0.5, and 2 for"
                    + " each method's first file)")
    Double warmupSeconds;

    @Option(names = "--seconds", paramLabel = "S",
            description = "timed frames per file and method, at least 5 (default: 3 for one file and method or"
                    + " --blend, else 1)")
    Double seconds;

    @Option(names = "--share-positions", paramLabel = "auto|always|never",
            description = "skin each position shared by several render vertices once: where it pays (what the"
                    + " runtime does), always, or never (default: ${DEFAULT-VALUE})")
    String sharePositions = "auto";

    @Option(names = "--palette-only",
            description = "time only the joint palette (sample, skinning matrices, dual quaternions), no skinning")
    boolean paletteOnly;

    @Option(names = "--json", description = "print one line of JSON per file and method")
    boolean json;

    @Mixin
    BlendOptions blendOptions;

    @Spec
    CommandSpec spec;

    /** A file to measure; one of the shared corpus is measured only if it has a skin. */
    private record Input(Path path, boolean needsSkin) {
        String name() {
            return path.getFileName().toString();
        }
    }

    @Override
    public Integer call() {
        NormalTransform rule = parseNormals();
        PositionSharing sharing;
        try {
            sharing = PositionSharing.fromKey(sharePositions);
        } catch (IllegalArgumentException e) {
            throw usage("--share-positions: " + e.getMessage());
        }
        BlendSpec blend = blendOptions.spec("bench frame");
        List<Input> inputs = inputs();
        List<SkinningMethod> methods = parseMethods(inputs.size());
        for (SkinningMethod m : methods) {
            if (rule == NormalTransform.NONE && !m.skinsPositionsOnly()) {
                throw usage("--normals none: " + m.key() + " has no positions-only kernel (lbs and dqs have)");
            }
        }
        boolean single = inputs.size() == 1 && methods.size() == 1;
        double warmup = secondsOption("--warmup-seconds", warmupSeconds, single ? FIRST_WARMUP : 0.5);
        double timed = secondsOption("--seconds", seconds, single ? 3.0 : 1.0);
        if (blend != null) {
            if (inputs.size() != 1 || allCorpus || paletteOnly) {
                throw usage("--blend measures one file (the clips are its own), without --all-corpus or"
                        + " --palette-only");
            }
            // One file: every method warms up and times as a single file and method does.
            return new BlendFrameBench(inputs.get(0).path(), blend, rule, normals.toLowerCase(Locale.ROOT), sharing,
                    json).run(methods, secondsOption("--warmup-seconds", warmupSeconds, FIRST_WARMUP),
                    secondsOption("--seconds", seconds, 3.0), spec.commandLine().getOut(), spec.commandLine().getErr());
        }
        // The JIT compiles a method's kernels during its first file's warm-up (the Vector API is
        // slow until it has: milliseconds per frame); later files only need their own shapes.
        Set<SkinningMethod> warmed = EnumSet.noneOf(SkinningMethod.class);
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        FrameBenchTable table = !json && !single && !paletteOnly
                ? startTable(out, inputs, methods, warmup, timed) : null;
        int status = ExitCodes.OK;
        for (Input input : inputs) {
            Model model;
            try {
                model = ModelFiles.load(input.path()).model;
            } catch (CommandFailure e) {
                err.println("skinlab: " + SkinlabCommand.oneLine(e.getMessage()));
                err.flush();
                status = Math.max(status, ExitCodes.INVALID_FILE);
                continue;
            }
            if (input.needsSkin() && model.instances().stream().noneMatch(MeshInstance::isSkinned)) {
                continue;
            }
            if (paletteOnly) {
                printPalette(out, input.name(), PaletteBench.measure(new SkinnedModel(model,
                        model.clips().isEmpty() ? null : model.clips().get(0), rule, EnumSet.of(SkinningMethod.LBS)),
                        warmupSeconds == null ? FIRST_WARMUP : warmup, timed));
                continue;
            }
            measureFile(out, input.name(), new FrameBench(model, rule, sharing, methods, JitWarmup.WARMUP), methods, warmed, warmup,
                    timed, table);
        }
        return status;
    }

    /** The table of several files or methods: its caption and header, printed before the first file is measured. */
    private FrameBenchTable startTable(PrintWriter out, List<Input> inputs, List<SkinningMethod> methods, double warmup,
            double timed) {
        FrameBenchTable table = new FrameBenchTable(methods,
                inputs.stream().mapToInt(i -> i.name().length()).max().orElse(0));
        out.println(caption(warmup, timed));
        out.println();
        out.print(table.header());
        out.flush();
        return table;
    }

    /**
     * Times one file's frame with each method and prints it: a JSON line per method, a row of the
     * table, or the two lines of a single file and method. A method's first file warms up longer.
     */
    private void measureFile(PrintWriter out, String name, FrameBench bench, List<SkinningMethod> methods,
            Set<SkinningMethod> warmed, double warmup, double timed, FrameBenchTable table) {
        List<FrameBench.Timing> timings = new ArrayList<>();
        for (SkinningMethod m : methods) {
            double w = warmupSeconds == null && warmed.add(m) ? Math.max(warmup, FIRST_WARMUP) : warmup;
            FrameBench.Timing timing = bench.measure(m, w, timed);
            timings.add(timing);
            if (json) {
                out.println(toJson(name, bench.shape(), timing));
            }
        }
        if (table != null) {
            out.print(table.row(name, bench.shape(), timings));
        } else if (!json) {
            printTwoLines(out, name, bench.shape(), timings.get(0));
        }
        out.flush();
    }

    /** {@code --palette-only}'s report of one file: each part's minimum, median and mean, as text or JSON. */
    private void printPalette(PrintWriter out, String name, PaletteBench.Samples samples) {
        double[][] stats = samples.stats();
        List<String> parts = PaletteBench.PARTS;
        if (json) {
            ObjectMapper mapper = new ObjectMapper();
            ObjectNode root = mapper.createObjectNode();
            root.put("benchmark", "frame-palette");
            root.put("file", name);
            root.put("joints", samples.joints());
            root.put("frames", samples.frames());
            for (int p = 0; p < parts.size(); p++) {
                ObjectNode part = root.putObject(parts.get(p));
                part.put("minMicros", round(stats[p][0]));
                part.put("medianMicros", round(stats[p][1]));
                part.put("meanMicros", round(stats[p][2]));
            }
            try {
                out.println(mapper.writeValueAsString(root));
            } catch (JsonProcessingException e) {
                throw new IllegalStateException(e);
            }
        } else {
            out.printf(Locale.ROOT, "palette of %s: %d joints, %d frames (slerp)%n", name, samples.joints(),
                    samples.frames());
            for (int p = 0; p < parts.size(); p++) {
                out.printf(Locale.ROOT, "%-16s min %.3f µs, median %.3f µs, mean %.3f µs%n", parts.get(p), stats[p][0],
                        stats[p][1], stats[p][2]);
            }
        }
        out.flush();
    }

    /**
     * The files in order: the FILE arguments (folders searched for .dae), or the default
     * character; with --all-corpus then our characters and the shared corpus. All are checked
     * to exist before anything is measured; a file named twice is measured once.
     */
    private List<Input> inputs() {
        List<Input> inputs = new ArrayList<>();
        List<Path> given = files.isEmpty() && !allCorpus ? List.of(DEFAULT_FILE) : files;
        for (ModelFileSearch.Entry e : ModelFileSearch.expand(given)) {
            inputs.add(new Input(e.path(), false));
        }
        if (allCorpus) {
            Path here = Path.of("");
            Path root = BenchCorpus.repositoryRoot(here);
            if (root == null) {
                throw usage("--all-corpus: run it inside the skinlab repository (no folder at or above "
                        + here.toAbsolutePath() + " holds settings.gradle and " + BenchCorpus.CHARACTERS + ")");
            }
            Path shared = corpus != null ? corpus : BenchCorpus.sharedCorpus(root, here);
            if (shared == null) {
                throw usage("--all-corpus: no shared corpus at " + root.resolve(BenchCorpus.SHARED_CORPUS).normalize()
                        + " (beside the repository) or " + here.toAbsolutePath().resolve(BenchCorpus.SHARED_CORPUS)
                                .normalize() + "; give its folder with --corpus DIR");
            }
            if (!Files.isDirectory(shared)) {
                throw usage("--corpus: not a folder: " + shared);
            }
            for (ModelFileSearch.Entry e : BenchCorpus.characters(root)) {
                inputs.add(new Input(e.path(), false));
            }
            for (ModelFileSearch.Entry e : BenchCorpus.corpusFiles(shared)) {
                inputs.add(new Input(e.path(), true));
            }
        }
        Set<Path> seen = new HashSet<>();
        inputs.removeIf(i -> !seen.add(i.path().toAbsolutePath().normalize()));
        return inputs;
    }

    private List<SkinningMethod> parseMethods(int files) {
        if (method == null) {
            return files == 1 ? List.of(SkinningMethod.LBS) : List.of(SkinningMethod.LBS, SkinningMethod.DQS);
        }
        if (method.equalsIgnoreCase("both")) {
            return List.of(SkinningMethod.LBS, SkinningMethod.DQS);
        }
        try {
            return MethodKeys.parseOneOrAll(method);
        } catch (IllegalArgumentException e) {
            throw usage(e.getMessage() + " (or both)");
        }
    }

    private NormalTransform parseNormals() {
        switch (normals.toLowerCase(Locale.ROOT)) {
            case "exact":
                return NormalTransform.INVERSE_TRANSPOSE;
            case "blended":
                return NormalTransform.BLENDED_MATRIX;
            case "none":
                return NormalTransform.NONE;
            default:
                throw usage("unknown normal rule \"" + normals + "\" (expected exact, blended or none)");
        }
    }

    private double secondsOption(String option, Double given, double byDefault) {
        double s = given != null ? given : byDefault;
        if (!(s >= 0 && s <= 3600)) {
            throw usage(option + " must be between 0 and 3600 seconds");
        }
        return s;
    }

    private static String formatSeconds(double s) {
        return s == Math.rint(s) ? String.valueOf((long) s) : String.valueOf(s);
    }

    /** The line above the table: the Java, the normal rule and the timings. */
    private String caption(double warmup, double timed) {
        String first = warmupSeconds == null ? " (" + formatSeconds(FIRST_WARMUP) + " s for a method's first file)" : "";
        return String.format(Locale.ROOT, "bench frame: %s; normals %s; per file and method %s s of warm-up%s, then"
                + " %s s of frames (sample, skinning matrices, skin; one thread); µs per frame, median / min",
                JavaRuntime.describe(), normals.toLowerCase(Locale.ROOT), formatSeconds(warmup), first,
                formatSeconds(timed));
    }

    /** One file and method: the shape, kernel and Java, then the times. */
    private void printTwoLines(PrintWriter out, String name, FrameBench.Shape shape, FrameBench.Timing t) {
        out.printf(Locale.ROOT, "frame of %s: %d positions skinned, %d render vertices, %d joints, at most %d"
                + " influences per position, %s, normals %s, %s, %s%n", name, shape.positionsSkinned(),
                shape.renderVertices(), shape.joints(), shape.influences(), t.method().key(),
                normals.toLowerCase(Locale.ROOT), t.kernel(), JavaRuntime.describe());
        out.printf(Locale.ROOT, "min %.2f µs, median %.2f µs per frame (%d frames: sample, skinning matrices, skin);"
                + " median %.2f ns per position skinned%n", t.minMicros(), t.medianMicros(), t.frames(),
                nanosPerPosition(t.medianMicros(), shape));
    }

    private String toJson(String name, FrameBench.Shape shape, FrameBench.Timing t) {
        ObjectMapper mapper = new ObjectMapper();
        ObjectNode root = mapper.createObjectNode();
        root.put("benchmark", "frame");
        root.put("file", name);
        root.put("method", t.method().key());
        root.put("normals", normals.toLowerCase(Locale.ROOT));
        root.put("positionsSkinned", shape.positionsSkinned());
        root.put("renderVertices", shape.renderVertices());
        root.put("joints", shape.joints());
        root.put("influences", shape.influences());
        root.put("frames", t.frames());
        root.put("minMicrosPerFrame", round(t.minMicros()));
        root.put("medianMicrosPerFrame", round(t.medianMicros()));
        root.put("medianNanosPerPosition", round(nanosPerPosition(t.medianMicros(), shape)));
        root.put("implementation", t.kernel());
        root.put("java", JavaRuntime.version());
        root.put("javaVendor", JavaRuntime.vendor());
        try {
            return mapper.writeValueAsString(root);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }

    /**
     * A frame's time per position skinned, in ns: what the methods cost per vertex, compared at the
     * same mesh (posing is in the frame too, the same for every method).
     */
    private static double nanosPerPosition(double micros, FrameBench.Shape shape) {
        return 1000 * micros / Math.max(1, shape.positionsSkinned());
    }

    private static double round(double d) {
        return Math.round(d * 1000.0) / 1000.0;
    }

    private static CommandFailure usage(String message) {
        return new CommandFailure(ExitCodes.USAGE, "bench frame: " + message, null);
    }
}
