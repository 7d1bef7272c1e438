package org.skinlab.desktop.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.JavaRuntime;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.bench.ArFrameBench;
import org.skinlab.desktop.bench.ArFrameBench.Stage;
import org.skinlab.desktop.bench.ArFrameBench.Timing;
import org.skinlab.desktop.bench.ArFrameBench.VariantResult;
import org.skinlab.desktop.bench.ArFrameInput;
import org.skinlab.desktop.bench.ArFrameJson;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.desktop.viewer.ModelLibrary;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code skinlab bench ar-frame}: one AR frame end to end, per stage (decode, track, pose, skin,
 * draw), on a video, an image folder or the synthetic demo video; a table of each stage's median
 * and range over the runs against a 60 Hz frame, and optionally the JSON of {@link ArFrameJson}.
 * The measuring is {@link ArFrameBench}'s.
 */
@Command(name = "ar-frame", mixinStandardHelpOptions = true,
        description = {"One AR frame end to end, per stage: decode, track, pose, skin, draw (glFinish), in ms against a"
                + " 60 Hz frame's 16.7 ms.", "Without --video or --images: the synthetic demo video, encoded to a"
                + " temporary MP4 with JCodec so that decoding is real."})
public final class ArFrameBenchCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    static final class Source {
        @Option(names = "--video", paramLabel = "FILE", description = "an MP4 (H.264) JCodec decodes")
        Path video;

        @Option(names = "--images", paramLabel = "DIR", description = "a folder of frames (.png/.jpg, name order)")
        Path images;
    }

    @ArgGroup(exclusive = true)
    Source source;

    @Parameters(index = "0", arity = "0..1", paramLabel = "FILE",
            description = "the model on the marker: .dae, .gltf or .glb (default: the bundled character)")
    Path file;

    @Option(names = "--intrinsics", paramLabel = "FILE", description = "the camera: our JSON, OpenCV's or BoofCV's"
            + " calibration (default: from --fov; the demo video's own camera without a source)")
    Path intrinsics;

    @Option(names = "--fov", paramLabel = "DEG", description = "horizontal field of view without --intrinsics (default: ${DEFAULT-VALUE})")
    double fov = 60;

    @Option(names = "--dictionary", paramLabel = "NAME", description = "marker dictionary (default: aruco_mip_36h12)")
    String dictionary = MarkerDictionary.DEFAULT.key();

    @Option(names = "--marker-size", paramLabel = "MM", description = "the printed black square's width (default: ${DEFAULT-VALUE})")
    double markerSizeMm = 100;

    @Option(names = "--id", paramLabel = "N", description = "the marker id to follow (default: the nearest marker)")
    int id = -1;

    @Option(names = "--method", paramLabel = MethodKeys.KEYS_OR_ALL, split = ",",
            description = "skinning methods, comma-separated, or all (default: lbs)")
    List<String> methods = new ArrayList<>(List.of("lbs"));

    @Option(names = "--skinning", paramLabel = "cpu|gpu|both",
            description = "where the mesh is skinned: cpu, gpu (the vertex shader; methods without shader code stay on"
                    + " the CPU) or both (default: ${DEFAULT-VALUE})")
    String skinning = "both";

    @Option(names = "--runs", paramLabel = "N", description = "timed runs of each variant, interleaved (at least 5; default: ${DEFAULT-VALUE})")
    int runs = 5;

    @Option(names = "--frames", paramLabel = "N",
            description = "frames per run (default: every frame of the source once; it loops beyond)")
    int frames;

    @Option(names = "--demo-frames", paramLabel = "N", description = "frames of the synthetic video (default: ${DEFAULT-VALUE})")
    int demoFrames = 60;

    @Option(names = "--warmup-seconds", paramLabel = "S", description = "warm-up before timing, not counted (default: ${DEFAULT-VALUE})")
    double warmupSeconds = 3;

    @Option(names = "--json", paramLabel = "OUT", description = "also write the results as JSON ('-': stdout)")
    Path json;

    @Override
    public Integer call() throws IOException {
        List<ArFrameBench.Variant> variants = variants();
        if (runs < 5) {
            throw usage("--runs must be at least 5 (a median and a spread need them): " + runs);
        }
        if (frames < 0 || demoFrames < 2 || !(warmupSeconds >= 0)) {
            throw usage("--frames must be positive, --demo-frames at least 2, --warmup-seconds at least 0");
        }
        Path modelPath = file != null ? file : ModelLibrary.find().defaultModel();
        if (modelPath == null) {
            throw usage("no FILE given and no bundled assets found");
        }
        Model model = ModelFiles.load(modelPath).model;
        TrackerConfig tracking;
        try {
            tracking = TrackerConfig.of(MarkerDictionary.byName(dictionary), markerSizeMm / 1000).withTargetId(id);
        } catch (IllegalArgumentException e) {
            throw usage(e.getMessage());
        }
        PrintWriter out = spec.commandLine().getOut();
        Path work = null;
        try {
            ArFrameInput input;
            if (source == null) {
                if (intrinsics != null) {
                    throw usage("--intrinsics needs --video or --images (the demo video has its own camera)");
                }
                work = Files.createTempDirectory("skinlab-ar-frame");
                out.println("rendering and encoding " + demoFrames + " frames of the demo video ...");
                out.flush();
                input = ArFrameInput.synthetic(demoFrames, work);
            } else {
                Path path = source.video != null ? source.video : source.images;
                if (!Files.exists(path)) {
                    throw usage(path + ": no such " + (source.video != null ? "file" : "folder"));
                }
                if (intrinsics != null && !Files.isRegularFile(intrinsics)) {
                    throw usage("--intrinsics: no such file: " + intrinsics);
                }
                try {
                    input = ArFrameInput.file(path, intrinsics, fov, tracking);
                } catch (IllegalArgumentException e) {
                    throw new CommandFailure(ExitCodes.INVALID_FILE, e.getMessage(), e);
                }
            }
            try (input) {
                int perRun = frames > 0 ? frames : input.frameCount();
                if (perRun < 1) {
                    throw new CommandFailure(ExitCodes.INVALID_FILE, input.name() + ": its frame count is unknown;"
                            + " give --frames N", null);
                }
                ArFrameBench.Result result = measure(input, model, variants, perRun);
                print(out, result, modelPath);
                if (json != null) {
                    writeJson(result, modelPath);
                }
            }
        } finally {
            if (work != null) {
                Files.deleteIfExists(work);
            }
        }
        return ExitCodes.OK;
    }

    private ArFrameBench.Result measure(ArFrameInput input, Model model, List<ArFrameBench.Variant> variants, int perRun)
            throws IOException {
        ArFrameBench bench;
        try {
            bench = ArFrameBench.open(input.name(), input.frames(), input.camera(), input.tracking(), model);
        } catch (GlWindow.WindowUnavailableException e) {
            throw new CommandFailure(ExitCodes.UNAVAILABLE, e.getMessage(), e);
        }
        try (bench) {
            return bench.run(variants, runs, perRun, warmupSeconds, f -> { });
        }
    }

    /** The methods times where they are skinned, in that order. */
    private List<ArFrameBench.Variant> variants() {
        List<SkinningMethod> chosen = new ArrayList<>();
        for (String m : methods) {
            for (SkinningMethod method : MethodKeys.parseOneOrAll("--method", m.trim())) {
                if (!chosen.contains(method)) {
                    chosen.add(method);
                }
            }
        }
        List<Boolean> where;
        switch (skinning.toLowerCase(Locale.ROOT)) {
            case "cpu":
                where = List.of(false);
                break;
            case "gpu":
                where = List.of(true);
                break;
            case "both":
                where = List.of(false, true);
                break;
            default:
                throw usage("--skinning must be cpu, gpu or both: " + skinning);
        }
        List<ArFrameBench.Variant> variants = new ArrayList<>();
        for (SkinningMethod m : chosen) {
            for (boolean gpu : where) {
                variants.add(new ArFrameBench.Variant(m, gpu));
            }
        }
        return variants;
    }

    /** The table: a column per variant, a row per stage and the frame, median [min - max] of the runs. */
    private void print(PrintWriter out, ArFrameBench.Result r, Path modelPath) {
        out.printf(Locale.ROOT, "ar-frame: %s; model %s; %d runs of %d frames per variant, interleaved, after %s s of"
                + " warm-up; %s%n", r.source(), modelPath.getFileName(), r.runs(), r.framesPerRun(),
                trim(r.warmupSeconds()), JavaRuntime.describe());
        out.printf(Locale.ROOT, "renderer: %s, OpenGL %s%s%n", r.renderer(), r.glVersion(), r.softwareRenderer()
                ? " (a software rasteriser on the CPU: \"draw\" and GPU skinning run on the CPU cores, not a GPU)" : "");
        List<String> header = new ArrayList<>(List.of("stage"));
        for (VariantResult v : r.variants()) {
            header.add(v.variant().method().key().toUpperCase(Locale.ROOT) + ", " + (v.variant().gpuSkinning() ? "GPU"
                    : "CPU") + " skinning");
        }
        out.println("ms per frame: median of the runs [lowest - highest run]");
        row(out, header);
        List<String> rule = new ArrayList<>();
        header.forEach(h -> rule.add("---"));
        row(out, rule);
        for (Stage s : Stage.values()) {
            List<String> cells = new ArrayList<>(List.of(s.key()));
            r.variants().forEach(v -> cells.add(cell(v.stage(s))));
            row(out, cells);
        }
        List<String> frame = new ArrayList<>(List.of("frame (stages summed per run)"));
        r.variants().forEach(v -> frame.add(cell(v.frame())));
        row(out, frame);
        List<String> budget = new ArrayList<>(List.of(String.format(Locale.ROOT, "stage medians summed, of %.1f ms (60 Hz)",
                ArFrameBench.FRAME_BUDGET_MS)));
        r.variants().forEach(v -> budget.add(String.format(Locale.ROOT, "%.2f = %.0f%%", v.stageMediansMs(),
                100 * v.stageMediansMs() / ArFrameBench.FRAME_BUDGET_MS)));
        row(out, budget);
        List<String> shown = new ArrayList<>(List.of("frames with the model drawn (per run)"));
        r.variants().forEach(v -> shown.add(java.util.Arrays.toString(v.modelFrames())));
        row(out, shown);
        out.flush();
    }

    private static String cell(Timing t) {
        return String.format(Locale.ROOT, "%.2f [%.2f - %.2f]", t.median(), t.min(), t.max());
    }

    private static void row(PrintWriter out, List<String> cells) {
        out.println("| " + String.join(" | ", cells) + " |");
    }

    private static String trim(double d) {
        return d == Math.rint(d) ? String.valueOf((long) d) : String.valueOf(d);
    }

    private void writeJson(ArFrameBench.Result result, Path modelPath) throws IOException {
        ObjectMapper mapper = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);
        ObjectNode root = mapper.createObjectNode();
        root.put("benchmark", "ar-frame");
        root.put("model", modelPath.toString());
        root.put("java", JavaRuntime.describe());
        ArFrameJson.write(result, root);
        String text = mapper.writeValueAsString(root) + "\n";
        if (json.toString().equals("-")) {
            spec.commandLine().getOut().print(text);
            spec.commandLine().getOut().flush();
        } else {
            try {
                Files.writeString(json, text);
            } catch (IOException e) {
                throw usage("--json: cannot write " + json + ": " + e.getMessage());
            }
        }
    }

    private static CommandFailure usage(String message) {
        return new CommandFailure(ExitCodes.USAGE, message, null);
    }
}
