package org.skinlab.desktop.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import boofcv.concurrency.BoofConcurrency;

import org.skinlab.ar.BoofSquareHamming;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.internal.bench.Rounds;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.bench.OpenCvAruco;
import org.skinlab.desktop.bench.TrackBench;
import org.skinlab.desktop.bench.TrackBenchVideo;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code skinlab bench track}: milliseconds per frame of a video (the synthetic one of
 * {@link TrackBenchVideo#synthetic}, or a folder of a real video's frames) for BoofCV's
 * squareHamming detector with its default settings ({@link BoofSquareHamming}: detection and each
 * marker's pose), our {@link FiducialTracker#detect} (whole frame), our {@link FiducialTracker#track} (the frames in
 * order, near the last markers first) and OpenCV's ArUco detector with each marker's pose
 * ({@link OpenCvAruco}, when python3 has cv2). Each round runs every contender once over all
 * frames, one after the other, so that they share the machine's state; per contender the report
 * gives the median and the mean of its per-frame times over all rounds, the ratio of the medians to
 * BoofCV's default, and the markers each finds per frame; and in how many frames each found the
 * same ids as our whole-frame search. BoofCV's own threads are off: one core.
 */
@Command(name = "track", mixinStandardHelpOptions = true,
        description = "Marker tracking speed per frame: BoofCV's default detector, our detect, our track, OpenCV's ArUco.")
public final class TrackBenchCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--frames", paramLabel = "N", description = "frames of the synthetic video (default: ${DEFAULT-VALUE})")
    int frames = 60;

    @Option(names = "--images", paramLabel = "DIR",
            description = "a real video's frames (.png/.jpg, name order) instead of the synthetic video")
    Path images;

    @Option(names = "--intrinsics", paramLabel = "FILE",
            description = "with --images: their camera, our JSON, OpenCV's calibration YAML/XML or BoofCV's intrinsic.yaml"
                    + " (default: 60 degree field of view)")
    Path intrinsics;

    @Option(names = "--size", paramLabel = "WxH", description = "with --images: resample the frames to this size first")
    String size;

    @Option(names = "--dictionary", paramLabel = "NAME", description = "marker dictionary (default: aruco_mip_36h12)")
    String dictionary = MarkerDictionary.DEFAULT.key();

    @Option(names = "--marker-size", paramLabel = "MM", description = "the printed black square's width in mm (default: ${DEFAULT-VALUE})")
    double markerSizeMm = 100;

    @Option(names = "--opencv-script", paramLabel = "FILE", description = "OpenCV's contender (default: ${DEFAULT-VALUE})")
    Path opencvScript = Path.of("bench", "aruco_opencv.py");

    @Option(names = "--warmup-seconds", paramLabel = "S", description = "warm-up before timing (default: ${DEFAULT-VALUE})")
    double warmupSeconds = 2.0;

    @Option(names = "--seconds", paramLabel = "S", description = "timed rounds (at least 5) for about this long (default: ${DEFAULT-VALUE})")
    double seconds = 6.0;

    @Option(names = "--clock", paramLabel = "wall|cpu",
            description = "time each frame by the wall clock, or by the CPU time of the thread (on a machine shared"
                    + " with other work) (default: ${DEFAULT-VALUE})")
    String clock = "wall";

    @Option(names = "--json", description = "print the result as one line of JSON")
    boolean json;

    @Override
    public Integer call() throws IOException {
        if (frames < 2 || seconds <= 0 || warmupSeconds < 0 || !(markerSizeMm > 0)) {
            throw new CommandFailure(ExitCodes.USAGE, "need --frames >= 2, a positive --marker-size and positive times",
                    null);
        }
        TrackBenchVideo video;
        MarkerDictionary dict;
        try {
            dict = MarkerDictionary.byName(dictionary);
            int[] wh = size == null ? new int[] {0, 0} : parseSize(size);
            video = images == null ? TrackBenchVideo.synthetic(frames)
                    : TrackBenchVideo.images(images, intrinsics, wh[0], wh[1]);
        } catch (IllegalArgumentException e) {
            throw new CommandFailure(ExitCodes.USAGE, e.getMessage(), e);
        }
        if (!clock.equals("wall") && !clock.equals("cpu")) {
            throw new CommandFailure(ExitCodes.USAGE, "--clock must be wall or cpu: " + clock, null);
        }
        boolean concurrent = BoofConcurrency.USE_CONCURRENT;
        // One core: BoofCV would otherwise spread thresholding and resampling over a thread pool.
        BoofConcurrency.USE_CONCURRENT = false;
        Path work = Files.createTempDirectory("skinlab-bench-track");
        try {
            return run(video, dict, work);
        } finally {
            BoofConcurrency.USE_CONCURRENT = concurrent;
            try (Stream<Path> files = Files.walk(work)) {
                for (Path p : (Iterable<Path>) files.sorted(Comparator.reverseOrder())::iterator) {
                    Files.deleteIfExists(p);
                }
            }
        }
    }

    private Integer run(TrackBenchVideo video, MarkerDictionary dict, Path work) throws IOException {
        TrackBench.Result r = TrackBench.measure(video, dict, markerSizeMm, opencvScript, work, clock, warmupSeconds,
                Rounds.MIN_RUNS, seconds);
        Agreement agreement = Agreement.of(r.ids(), video.frames().size());
        PrintWriter out = spec.commandLine().getOut();
        if (json) {
            printJson(out, video, dict, r, agreement);
        } else {
            printText(out, video, dict, r, agreement);
        }
        out.flush();
        return ExitCodes.OK;
    }

    /**
     * How the contenders' ids compare with detect's (contender 1), frame by frame.
     *
     * @param perFrame        markers found per frame, on average
     * @param sameAsDetect    frames with the same ids as detect
     * @param trackMismatches the frames in which track (contender 2) found other ids than detect
     */
    private record Agreement(double[] perFrame, int[] sameAsDetect, List<Integer> trackMismatches) {
        static Agreement of(List<List<List<Integer>>> ids, int n) {
            int c = ids.size();
            double[] perFrame = new double[c];
            int[] sameAsDetect = new int[c];
            List<Integer> trackMismatches = new ArrayList<>();
            for (int i = 0; i < c; i++) {
                for (int f = 0; f < n; f++) {
                    perFrame[i] += ids.get(i).get(f).size();
                    if (ids.get(i).get(f).equals(ids.get(1).get(f))) {
                        sameAsDetect[i]++;
                    } else if (i == 2) {
                        trackMismatches.add(f);
                    }
                }
            }
            for (int i = 0; i < c; i++) {
                perFrame[i] /= n;
            }
            return new Agreement(perFrame, sameAsDetect, trackMismatches);
        }
    }

    private void printJson(PrintWriter out, TrackBenchVideo video, MarkerDictionary dict, TrackBench.Result r,
            Agreement a) {
        String[] keys = {"boofcvDefault", "detect", "track", "opencv"};
        ObjectNode o = new ObjectMapper().createObjectNode();
        o.put("video", video.name());
        o.put("frames", video.frames().size());
        o.put("width", video.camera().width());
        o.put("height", video.camera().height());
        o.put("dictionary", dict.key());
        o.put("rounds", r.rounds());
        o.put("clock", clock);
        o.put("java", Runtime.version().toString());
        o.put("opencv", r.opencv());
        for (int i = 0; i < r.names().size(); i++) {
            o.put(keys[i] + "Ms", r.median()[i]);
            o.put(keys[i] + "MeanMs", r.mean()[i]);
            o.put(keys[i] + "MarkersPerFrame", a.perFrame()[i]);
            o.put(keys[i] + "FramesWithDetectIds", a.sameAsDetect()[i]);
        }
        // The same counts under the names that scripts reading this report know.
        o.put("markersPerFrameBoofcv", a.perFrame()[0]);
        o.put("markersPerFrameDetect", a.perFrame()[1]);
        o.put("markersPerFrameTrack", a.perFrame()[2]);
        o.put("trackFoundInRegion", r.regionShare());
        out.println(o);
    }

    private void printText(PrintWriter out, TrackBenchVideo video, MarkerDictionary dict, TrackBench.Result r,
            Agreement a) {
        int n = video.frames().size();
        double[] median = r.median();
        out.printf(Locale.ROOT,
                "marker tracking, %s, %s, %d rounds, Java %s, one core (BoofCV's threads off), %s%n", video.name(),
                dict.key(), r.rounds(), Runtime.version(),
                clock.equals("cpu") ? "the thread's CPU time per frame" : "wall clock per frame");
        out.printf(Locale.ROOT, "%-46s %10s %10s %9s %14s %s%n", "", "median ms", "mean ms", "vs BoofCV",
                "markers/frame", "frames with detect's ids");
        for (int i = 0; i < r.names().size(); i++) {
            out.printf(Locale.ROOT, "%-46s %10.2f %10.2f %8.2fx %14.2f %d of %d%n", r.names().get(i), median[i],
                    r.mean()[i], median[i] / median[0], a.perFrame()[i], a.sameAsDetect()[i], n);
        }
        if (r.names().size() < 4) {
            out.printf(Locale.ROOT, "OpenCV ArUco: %s%n", r.opencv());
        }
        out.printf(Locale.ROOT, "track found every marker near the last ones in %.0f%% of frames%s%n",
                100 * r.regionShare(), a.trackMismatches().isEmpty() ? ""
                        : "; other ids than detect in frames " + a.trackMismatches());
    }

    private static int[] parseSize(String s) {
        String[] p = s.toLowerCase(Locale.ROOT).split("x");
        try {
            int[] wh = {Integer.parseInt(p[0].trim()), Integer.parseInt(p[1].trim())};
            if (p.length == 2 && wh[0] >= 16 && wh[1] >= 16 && wh[0] <= 8192 && wh[1] <= 8192) {
                return wh;
            }
        } catch (NumberFormatException | ArrayIndexOutOfBoundsException e) {
            // reported below
        }
        throw new IllegalArgumentException("--size must be WIDTHxHEIGHT, each 16 to 8192: " + s);
    }
}
