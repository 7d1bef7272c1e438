package org.skinlab.desktop.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.concurrent.Callable;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.desktop.bench.ArFrameInput;
import org.skinlab.desktop.bench.BenchCorpus;
import org.skinlab.desktop.eval.EvalDeviceFiles;
import org.skinlab.desktop.eval.Evaluation;

/**
 * {@code skinlab eval}: the thesis' evaluation redone on this machine, one report. Parses the
 * options; {@link Evaluation} measures and writes the report. See docs/evaluation.md.
 */
@Command(name = "eval", mixinStandardHelpOptions = true,
        description = {"The evaluation: measures every section and writes DIR/README.md, one PNG per figure and"
                + " DIR/results.json with every number. Sections: load (import time: our assets, the shared"
                + " corpus, the conformance suite, assimp beside), time (time per deformation: LBS, DQS, CoR; SIMD and"
                + " scalar; 4 influences and all; beside the thesis' table), phone (phones added with --add-device beside the"
                + " thesis' Galaxy S7 and this machine's scalar kernels), crowds (characters per frame against threads"
                + " and characters on the CPU, drawn fps against copies with CPU and GPU skinning), quality (volume kept"
                + " over each clip, joint ring against twist, bulge against bend, largest distance between methods, the"
                + " error of capping influences), pictures (the viewer's screenshots of each method at each asset's"
                + " extreme pose, and the difference view), tracking (markers found and pose error per distance and"
                + " tilt, false markers, time per frame beside BoofCV's detector), ar-frame (an AR frame end to end per stage:"
                + " decode, track, pose, skin, draw, against 60 Hz; on --ar-video or the synthetic demo video), advice (what it means for AR on a"
                + " phone: time against vertices, influences and joints with fitted lines; a recommendation per use"
                + " drawn from the other sections).",
            "Run it from the repository (it reads assets/ and ../shared), under xvfb-run -a without a display (the pictures"
                + " and the drawn crowds need one). The full run takes about 10 minutes on 2 cores; --quick under 3.",
            "--add-device FILE measures nothing: it adds a phone's results-android.json (the Android app's Measure) to"
                + " DIR/results.json's phone section and writes DIR/README.md and the figures again from results.json."})
public final class EvalCommand implements Callable<Integer> {
    @Option(names = "--out", paramLabel = "DIR", description = "where the report goes (default: ${DEFAULT-VALUE})")
    Path out = Path.of("docs/evaluation");

    @Option(names = "--quick", description = "fewer files and shorter measurements (under 3 minutes): a smoke run,"
            + " not figures to quote")
    boolean quick;

    @Option(names = "--only", paramLabel = "SECTION", split = ",",
            description = "only these sections (comma-separated), of: load, time, phone, crowds, quality, pictures,"
                    + " tracking, ar-frame, advice, claims")
    List<String> only = new ArrayList<>();

    @Option(names = "--ar-video", paramLabel = "FILE", description = "a real camera video (MP4 with H.264 that JCodec"
            + " decodes, or a folder of frames) for the ar-frame section (default: the synthetic demo video)")
    Path arVideo;

    @Option(names = "--ar-intrinsics", paramLabel = "FILE", description = "--ar-video's camera: our JSON, OpenCV's or"
            + " BoofCV's calibration (default: a 60 degree field of view)")
    Path arIntrinsics;

    @Option(names = "--ar-dictionary", paramLabel = "NAME", description = "--ar-video's marker dictionary (default:"
            + " aruco_mip_36h12)")
    String arDictionary;

    @Option(names = "--add-device", paramLabel = "FILE", description = "add a phone's results-android.json (the"
            + " Android app's Measure) to DIR/results.json and write the report again from it, measuring nothing")
    Path addDevice;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        if (addDevice != null) {
            return addDevice();
        }
        Set<String> sections = selected();
        Path root = BenchCorpus.repositoryRoot(Path.of(""));
        if (root == null) {
            throw usage("run it inside the skinlab repository (no folder at or above "
                    + Path.of("").toAbsolutePath() + " holds settings.gradle and " + BenchCorpus.CHARACTERS + ")");
        }
        if (Files.exists(out) && !Files.isDirectory(out)) {
            throw usage("--out: not a folder: " + out);
        }
        String dictionary = arVideo();
        PrintWriter err = spec.commandLine().getErr();
        Evaluation evaluation = new Evaluation(sections, quick, root, out, err, SkinlabMain.class);
        if (arVideo != null) {
            evaluation.withArVideo(arVideo, arIntrinsics, dictionary);
        }
        Evaluation.Written written = evaluation.run(spec.commandLine().getParseResult().originalArgs());
        PrintWriter o = spec.commandLine().getOut();
        o.printf(Locale.ROOT, "eval: %s and %d figure%s in %s (%s)%n", "README.md, results.json",
                written.figures, written.figures == 1 ? "" : "s", out,
                Duration.ofSeconds(Math.round(written.seconds)).toString().substring(2).toLowerCase(Locale.ROOT));
        o.flush();
        return ExitCodes.OK;
    }

    /**
     * Checks --ar-video and its options before anything is measured (the video's first frame is
     * decoded, the camera read): a usage error for a missing file or an option without
     * --ar-video, an unreadable video or camera file is status 3. Returns the dictionary's key.
     */
    private String arVideo() {
        if (arVideo == null) {
            if (arIntrinsics != null || arDictionary != null) {
                throw usage("--ar-intrinsics and --ar-dictionary describe --ar-video, which is not given");
            }
            return null;
        }
        if (!Files.exists(arVideo)) {
            throw usage("--ar-video: no such file or folder: " + arVideo);
        }
        if (arIntrinsics != null && !Files.isRegularFile(arIntrinsics)) {
            throw usage("--ar-intrinsics: no such file: " + arIntrinsics);
        }
        MarkerDictionary dictionary;
        try {
            dictionary = arDictionary == null ? MarkerDictionary.DEFAULT : MarkerDictionary.byName(arDictionary);
        } catch (IllegalArgumentException e) {
            throw usage("--ar-dictionary: " + e.getMessage());
        }
        try {
            ArFrameInput.file(arVideo, arIntrinsics, 60, TrackerConfig.defaults(0.1)).close();
            return dictionary.key();
        } catch (IllegalArgumentException | IOException e) {
            throw new CommandFailure(ExitCodes.INVALID_FILE, "eval: " + e.getMessage(), e);
        }
    }

    /** --add-device: the phone's file into the report, nothing measured. */
    private int addDevice() throws IOException {
        if (quick || !only.isEmpty() || arVideo != null) {
            throw usage("--add-device measures nothing: it takes no --quick, --only or --ar-video");
        }
        if (!Files.isDirectory(out)) {
            throw usage("--out: no report folder at " + out + " (skinlab eval writes one)");
        }
        EvalDeviceFiles.Added added = EvalDeviceFiles.add(out, addDevice);
        PrintWriter o = spec.commandLine().getOut();
        o.printf(Locale.ROOT, "eval: %s %s in %s; README.md and %d figure%s written from it%n",
                added.replaced() ? "replaced the earlier file of" : "added", added.device(), out.resolve("results.json"),
                added.written().figures, added.written().figures == 1 ? "" : "s");
        o.flush();
        return ExitCodes.OK;
    }

    /** The section keys --only names; empty (all) without it. */
    private Set<String> selected() {
        Set<String> wanted = new LinkedHashSet<>();
        for (String o : only) {
            String key = o.trim().toLowerCase(Locale.ROOT);
            if (!Evaluation.keys().contains(key)) {
                throw usage("--only: unknown section \"" + o + "\" (valid: " + String.join(", ", Evaluation.keys())
                        + ")");
            }
            wanted.add(key);
        }
        return wanted;
    }

    private static CommandFailure usage(String message) {
        return new CommandFailure(ExitCodes.USAGE, "eval: " + message, null);
    }
}
