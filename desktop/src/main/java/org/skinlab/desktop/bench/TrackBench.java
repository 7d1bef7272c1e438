package org.skinlab.desktop.bench;

import java.io.IOException;
import java.io.UncheckedIOException;
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
import org.skinlab.internal.bench.Rounds;
import org.skinlab.internal.bench.Spread;

/**
 * The timing of {@code skinlab bench track}: BoofCV's squareHamming detector with its default
 * settings (detection and each marker's pose), our {@link FiducialTracker#detect} (whole frame),
 * our {@link FiducialTracker#track} (the frames in order, near the last markers first) and, when
 * python3 has cv2, OpenCV's ArUco ({@link OpenCvAruco}). After one pass each that records the ids
 * found and a shared warm-up, each round runs every contender once over all frames, one after the
 * other, so that they share the machine's state, each round starting one contender further along
 * ({@link Rounds#interleaved}); at least the rounds asked for, more while the time given lasts. A
 * contender's run is its median frame of a round.
 */
public final class TrackBench {
    /**
     * What the rounds gave, per contender in the order of {@code names}.
     *
     * @param names       the contenders
     * @param ids         per contender and frame, the ids it found (sorted)
     * @param median      the median of its per-frame milliseconds over all rounds
     * @param mean        their mean
     * @param runs        per contender, its median frame of each round, in round order
     * @param rounds      how many rounds ran
     * @param regionShare the share of frames in which track found every marker near the last ones
     * @param opencv      OpenCV's version, or why it did not run
     */
    public record Result(List<String> names, List<List<List<Integer>>> ids, double[] median, double[] mean,
            Spread[] runs, int rounds, double regionShare, String opencv) {
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
     * @param opencvScript OpenCV's contender, or null to leave it out
     * @param work         a folder for OpenCV's copy of the frames
     * @param clock        {@code wall} or {@code cpu} (the thread's CPU time, on a machine shared with other work)
     * @param minRounds    the fewest timed rounds
     * @param seconds      timed rounds go on until they have taken about this long
     */
    public static Result measure(TrackBenchVideo video, MarkerDictionary dict, double markerSizeMm, Path opencvScript,
            Path work, String clock, double warmupSeconds, int minRounds, double seconds) throws IOException {
        return new TrackBench(video.frames(), clock).run(video.camera(), dict, markerSizeMm / 1000, opencvScript, work,
                warmupSeconds, minRounds, seconds);
    }

    private Result run(CameraIntrinsics k, MarkerDictionary dict, double markerMetres, Path opencvScript, Path work,
            double warmupSeconds, int minRounds, double seconds) throws IOException {
        List<String> names = new ArrayList<>(List.of("BoofCV squareHamming, default settings",
                "skinlab detect (whole frame)", "skinlab track (near the last markers first)"));
        FiducialTracker ours = new FiducialTracker(TrackerConfig.of(dict, markerMetres), k);
        List<Pass> passes = new ArrayList<>(List.of(boofPass(BoofSquareHamming.defaults(dict, markerMetres, k)),
                detectPass(ours), trackPass(ours)));
        OpenCvAruco.Failure why = new OpenCvAruco.Failure();
        why.reason = "not compared";
        OpenCvAruco opencv = opencvScript == null ? null
                : OpenCvAruco.start(opencvScript, work, frames, k, dict, markerMetres, clock, why);
        try {
            if (opencv != null) {
                names.add("OpenCV " + opencv.version() + " ArUco, default parameters");
                passes.add(opencvPass(opencv));
            }
            List<List<List<Integer>>> ids = new ArrayList<>();
            long idsStart = System.nanoTime();
            for (Pass p : passes) {
                List<List<Integer>> found = new ArrayList<>();
                p.run(new double[n], found);
                ids.add(found);
            }
            double roundSeconds = (System.nanoTime() - idsStart) * 1e-9;
            warmUp(passes, warmupSeconds);
            foundInRegion = 0;
            int c = passes.size();
            int rounds = Math.max(minRounds, (int) Math.ceil(seconds / roundSeconds));
            double[][] times = new double[c][rounds * n];
            Spread[] runs;
            try {
                runs = Rounds.interleaved(c, rounds, (i, round) -> {
                    double[] ms = new double[n];
                    try {
                        passes.get(i).run(ms, null);
                    } catch (IOException e) {
                        throw new UncheckedIOException(e);
                    }
                    System.arraycopy(ms, 0, times[i], round * n, n);
                    return Spread.of(ms).median();
                });
            } catch (UncheckedIOException e) {
                throw e.getCause();
            }
            double[] median = new double[c];
            double[] mean = new double[c];
            for (int i = 0; i < c; i++) {
                median[i] = Spread.of(times[i]).median();
                mean[i] = Arrays.stream(times[i]).average().orElse(0);
            }
            return new Result(names, ids, median, mean, runs, rounds, foundInRegion / (double) (rounds * n),
                    opencv != null ? opencv.version() : why.reason);
        } finally {
            if (opencv != null) {
                opencv.close();
            }
        }
    }

    /** Every pass, over and over, for {@code warmupSeconds} (none for 0). */
    private void warmUp(List<Pass> passes, double warmupSeconds) throws IOException {
        double[] scratch = new double[n];
        long warmEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
        while (System.nanoTime() < warmEnd) {
            for (Pass p : passes) {
                p.run(scratch, null);
            }
        }
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
