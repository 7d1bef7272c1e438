package org.skinlab.desktop.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.TreeSet;
import java.util.concurrent.Callable;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import boofcv.concurrency.BoofConcurrency;
import georegression.struct.se.Se3_F64;

import org.skinlab.ar.BoofSquareHamming;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.MarkerDetection;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.desktop.ExitCodes;

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

    @Option(names = "--seconds", paramLabel = "S", description = "timed rounds for this long (default: ${DEFAULT-VALUE})")
    double seconds = 6.0;

    @Option(names = "--clock", paramLabel = "wall|cpu",
            description = "time each frame by the wall clock, or by the CPU time of the thread (on a machine shared"
                    + " with other work) (default: ${DEFAULT-VALUE})")
    String clock = "wall";

    @Option(names = "--json", description = "print the result as one line of JSON")
    boolean json;

    /** One contender's pass over the frames: its per-frame milliseconds to {@code ms}, the ids found to {@code ids}. */
    private interface Pass {
        void run(double[] ms, List<List<Integer>> ids) throws IOException;
    }

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
        List<GrayImage> list = video.frames();
        int n = list.size();
        CameraIntrinsics k = video.camera();
        TrackerConfig config = TrackerConfig.of(dict, markerSizeMm / 1000);
        FiducialTracker ours = new FiducialTracker(config, k);
        BoofSquareHamming boof = BoofSquareHamming.defaults(dict, markerSizeMm / 1000, k);
        Se3_F64 pose = new Se3_F64();
        int[] inRegion = new int[1];
        OpenCvAruco.Failure why = new OpenCvAruco.Failure();
        OpenCvAruco opencv = OpenCvAruco.start(opencvScript, work, list, k, dict, markerSizeMm / 1000, clock, why);
        try {
            List<String> names = new ArrayList<>(List.of("BoofCV squareHamming, default settings",
                    "skinlab detect (whole frame)", "skinlab track (near the last markers first)"));
            List<Pass> passes = new ArrayList<>(List.of(
                (ms, ids) -> {
                    for (int i = 0; i < n; i++) {
                        long start = now();
                        int found = boof.detect(list.get(i));
                        for (int m = 0; m < found; m++) {
                            boof.pose(m, pose);
                        }
                        ms[i] = (now() - start) * 1e-6;
                        if (ids != null) {
                            TreeSet<Integer> s = new TreeSet<>();
                            for (int m = 0; m < found; m++) {
                                s.add(boof.id(m));
                            }
                            ids.add(new ArrayList<>(s));
                        }
                    }
                },
                (ms, ids) -> {
                    for (int i = 0; i < n; i++) {
                        long start = now();
                        List<MarkerDetection> found = ours.detect(list.get(i));
                        ms[i] = (now() - start) * 1e-6;
                        record(found, ids);
                    }
                },
                (ms, ids) -> {
                    ours.reset();
                    for (int i = 0; i < n; i++) {
                        long start = now();
                        List<MarkerDetection> found = ours.track(list.get(i));
                        ms[i] = (now() - start) * 1e-6;
                        inRegion[0] += ours.lastFoundInRegion() ? 1 : 0;
                        record(found, ids);
                    }
                }));
            if (opencv != null) {
                names.add("OpenCV " + opencv.version() + " ArUco, default parameters");
                passes.add((ms, ids) -> {
                    System.arraycopy(opencv.round(), 0, ms, 0, n);
                    if (ids != null) {
                        ids.addAll(opencv.ids());
                    }
                });
            }
            int c = passes.size();
            double[] scratch = new double[n];
            long warmEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
            do {
                for (Pass p : passes) {
                    p.run(scratch, null);
                }
            } while (System.nanoTime() < warmEnd);
            List<List<List<Integer>>> ids = new ArrayList<>();
            for (Pass p : passes) {
                List<List<Integer>> found = new ArrayList<>();
                p.run(scratch, found);
                ids.add(found);
            }
            List<double[]> times = new ArrayList<>();
            inRegion[0] = 0;
            int rounds = 0;
            long end = System.nanoTime() + (long) (seconds * 1e9);
            do {
                for (Pass p : passes) {
                    double[] ms = new double[n];
                    p.run(ms, null);
                    times.add(ms);
                }
                rounds++;
            } while (System.nanoTime() < end || rounds < 3);
            double[] median = new double[c];
            double[] mean = new double[c];
            for (int i = 0; i < c; i++) {
                double[] all = new double[rounds * n];
                for (int r = 0; r < rounds; r++) {
                    System.arraycopy(times.get(r * c + i), 0, all, r * n, n);
                }
                Arrays.sort(all);
                median[i] = all[all.length / 2];
                mean[i] = Arrays.stream(all).average().orElse(0);
            }
            report(video, dict, names, ids, median, mean, rounds, inRegion[0] / (double) (rounds * n),
                    opencv != null ? opencv.version() : why.reason);
        } finally {
            if (opencv != null) {
                opencv.close();
            }
        }
        return ExitCodes.OK;
    }

    private final ThreadMXBean threads = ManagementFactory.getThreadMXBean();

    /** Nanoseconds of the chosen clock. */
    private long now() {
        return clock.equals("cpu") ? threads.getCurrentThreadCpuTime() : System.nanoTime();
    }

    private static void record(List<MarkerDetection> found, List<List<Integer>> ids) {
        if (ids != null) {
            TreeSet<Integer> s = new TreeSet<>();
            for (MarkerDetection d : found) {
                s.add(d.id());
            }
            ids.add(new ArrayList<>(s));
        }
    }

    private void report(TrackBenchVideo video, MarkerDictionary dict, List<String> names, List<List<List<Integer>>> ids,
            double[] median, double[] mean, int rounds, double regionShare, String opencv) {
        int n = video.frames().size();
        int c = names.size();
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
        PrintWriter out = spec.commandLine().getOut();
        String[] keys = {"boofcvDefault", "detect", "track", "opencv"};
        if (json) {
            ObjectNode o = new ObjectMapper().createObjectNode();
            o.put("video", video.name());
            o.put("frames", n);
            o.put("width", video.camera().width());
            o.put("height", video.camera().height());
            o.put("dictionary", dict.key());
            o.put("rounds", rounds);
            o.put("clock", clock);
            o.put("java", Runtime.version().toString());
            o.put("opencv", opencv);
            for (int i = 0; i < c; i++) {
                o.put(keys[i] + "Ms", median[i]);
                o.put(keys[i] + "MeanMs", mean[i]);
                o.put(keys[i] + "MarkersPerFrame", perFrame[i]);
                o.put(keys[i] + "FramesWithDetectIds", sameAsDetect[i]);
            }
            // The names of the first version of this report.
            o.put("markersPerFrameBoofcv", perFrame[0]);
            o.put("markersPerFrameDetect", perFrame[1]);
            o.put("markersPerFrameTrack", perFrame[2]);
            o.put("trackFoundInRegion", regionShare);
            out.println(o);
        } else {
            out.printf(Locale.ROOT,
                    "marker tracking, %s, %s, %d rounds, Java %s, one core (BoofCV's threads off), %s%n", video.name(),
                    dict.key(), rounds, Runtime.version(),
                    clock.equals("cpu") ? "the thread's CPU time per frame" : "wall clock per frame");
            out.printf(Locale.ROOT, "%-46s %10s %10s %9s %14s %s%n", "", "median ms", "mean ms", "vs BoofCV",
                    "markers/frame", "frames with detect's ids");
            for (int i = 0; i < c; i++) {
                out.printf(Locale.ROOT, "%-46s %10.2f %10.2f %8.2fx %14.2f %d of %d%n", names.get(i), median[i],
                        mean[i], median[i] / median[0], perFrame[i], sameAsDetect[i], n);
            }
            if (c < 4) {
                out.printf(Locale.ROOT, "OpenCV ArUco: %s%n", opencv);
            }
            out.printf(Locale.ROOT, "track found every marker near the last ones in %.0f%% of frames%s%n",
                    100 * regionShare, trackMismatches.isEmpty() ? ""
                            : "; other ids than detect in frames " + trackMismatches);
        }
        out.flush();
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
