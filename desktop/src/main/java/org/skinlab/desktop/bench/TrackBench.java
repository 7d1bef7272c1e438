package org.skinlab.desktop.bench;

import java.io.IOException;
import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.TreeSet;

import georegression.struct.se.Se3_F64;

import org.skinlab.ar.BoofSquareHamming;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.MarkerDetection;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.TrackerConfig;

/**
 * The timing of {@code skinlab bench track}: BoofCV's squareHamming detector with its default
 * settings (detection and each marker's pose), our {@link FiducialTracker#detect} (whole frame),
 * our {@link FiducialTracker#track} (the frames in order, near the last markers first) and, when
 * python3 has cv2, OpenCV's ArUco ({@link OpenCvAruco}). After a shared warm-up and one pass each
 * that records the ids found, each round runs every contender once over all frames, one after the
 * other, so that they share the machine's state; at least 3 rounds, and on for the time given.
 */
public final class TrackBench {
    /**
     * What the rounds gave, per contender in the order of {@code names}.
     *
     * @param names       the contenders
     * @param ids         per contender and frame, the ids it found (sorted)
     * @param median      the median of its per-frame milliseconds over all rounds
     * @param mean        their mean
     * @param rounds      how many rounds ran
     * @param regionShare the share of frames in which track found every marker near the last ones
     * @param opencv      OpenCV's version, or why it did not run
     */
    public record Result(List<String> names, List<List<List<Integer>>> ids, double[] median, double[] mean,
            int rounds, double regionShare, String opencv) {
    }

    /** One contender's pass over the frames: its per-frame milliseconds to {@code ms}, the ids found to {@code ids}. */
    private interface Pass {
        void run(double[] ms, List<List<Integer>> ids) throws IOException;
    }

    private final ThreadMXBean threads = ManagementFactory.getThreadMXBean();
    private final String clock;
    private final List<GrayImage> frames;
    private final int n;
    private int foundInRegion;

    private TrackBench(List<GrayImage> frames, String clock) {
        this.frames = frames;
        this.n = frames.size();
        this.clock = clock;
    }

    /**
     * Times every contender on {@code video}'s frames.
     *
     * @param clock {@code wall} or {@code cpu} (the thread's CPU time, on a machine shared with other work)
     * @param work  a folder for OpenCV's copy of the frames
     */
    public static Result measure(TrackBenchVideo video, MarkerDictionary dict, double markerSizeMm, Path opencvScript,
            Path work, String clock, double warmupSeconds, double seconds) throws IOException {
        return new TrackBench(video.frames(), clock).run(video.camera(), dict, markerSizeMm / 1000, opencvScript, work,
                warmupSeconds, seconds);
    }

    private Result run(CameraIntrinsics k, MarkerDictionary dict, double markerMetres, Path opencvScript, Path work,
            double warmupSeconds, double seconds) throws IOException {
        List<String> names = new ArrayList<>(List.of("BoofCV squareHamming, default settings",
                "skinlab detect (whole frame)", "skinlab track (near the last markers first)"));
        FiducialTracker ours = new FiducialTracker(TrackerConfig.of(dict, markerMetres), k);
        List<Pass> passes = new ArrayList<>(List.of(boofPass(BoofSquareHamming.defaults(dict, markerMetres, k)),
                detectPass(ours), trackPass(ours)));
        OpenCvAruco.Failure why = new OpenCvAruco.Failure();
        OpenCvAruco opencv = OpenCvAruco.start(opencvScript, work, frames, k, dict, markerMetres, clock, why);
        try {
            if (opencv != null) {
                names.add("OpenCV " + opencv.version() + " ArUco, default parameters");
                passes.add(opencvPass(opencv));
            }
            warmUp(passes, warmupSeconds);
            List<List<List<Integer>>> ids = new ArrayList<>();
            for (Pass p : passes) {
                List<List<Integer>> found = new ArrayList<>();
                p.run(new double[n], found);
                ids.add(found);
            }
            foundInRegion = 0;
            List<double[]> times = new ArrayList<>();
            int rounds = timedRounds(passes, seconds, times);
            int c = passes.size();
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
            return new Result(names, ids, median, mean, rounds, foundInRegion / (double) (rounds * n),
                    opencv != null ? opencv.version() : why.reason);
        } finally {
            if (opencv != null) {
                opencv.close();
            }
        }
    }

    private void warmUp(List<Pass> passes, double warmupSeconds) throws IOException {
        double[] scratch = new double[n];
        long warmEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
        do {
            for (Pass p : passes) {
                p.run(scratch, null);
            }
        } while (System.nanoTime() < warmEnd);
    }

    /** Rounds of every pass, each's times appended to {@code times} (round by round); returns the count. */
    private int timedRounds(List<Pass> passes, double seconds, List<double[]> times) throws IOException {
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
        return rounds;
    }

    private Pass boofPass(BoofSquareHamming boof) {
        Se3_F64 pose = new Se3_F64();
        return (ms, ids) -> {
            for (int i = 0; i < n; i++) {
                long start = now();
                int found = boof.detect(frames.get(i));
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
        };
    }

    private Pass detectPass(FiducialTracker ours) {
        return (ms, ids) -> {
            for (int i = 0; i < n; i++) {
                long start = now();
                List<MarkerDetection> found = ours.detect(frames.get(i));
                ms[i] = (now() - start) * 1e-6;
                record(found, ids);
            }
        };
    }

    private Pass trackPass(FiducialTracker ours) {
        return (ms, ids) -> {
            ours.reset();
            for (int i = 0; i < n; i++) {
                long start = now();
                List<MarkerDetection> found = ours.track(frames.get(i));
                ms[i] = (now() - start) * 1e-6;
                foundInRegion += ours.lastFoundInRegion() ? 1 : 0;
                record(found, ids);
            }
        };
    }

    private Pass opencvPass(OpenCvAruco opencv) {
        return (ms, ids) -> {
            System.arraycopy(opencv.round(), 0, ms, 0, n);
            if (ids != null) {
                ids.addAll(opencv.ids());
            }
        };
    }

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
}
