package org.skinlab.desktop.eval;

import java.awt.Color;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.knowm.xchart.XYChart;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.internal.bench.Rounds;
import org.skinlab.internal.bench.Spread;
import org.skinlab.desktop.bench.TrackBench;
import org.skinlab.desktop.bench.TrackBenchVideo;

/**
 * The tracking section's time per frame: {@code skinlab bench track}'s protocol ({@link TrackBench})
 * on frames of a video ({@link TrackBenchVideo#synthetic}, {@code skinlab ar-demo}'s), one thread,
 * by the wall clock: BoofCV's squareHamming with its default settings and our whole-frame search
 * ({@link FiducialTracker#detect}), both with each marker's pose, and our video search near the
 * last markers ({@link FiducialTracker#track}), in {@link Rounds#MIN_RUNS} runs interleaved
 * across the three ({@link Rounds#interleaved}), a run being a contender's median frame of one
 * pass over the frames in order. Ratios are stored as the ratio of the medians, with the spread
 * of the runs' own ratios (a run's contenders ran in the same round).
 */
final class EvalTrackingTimes {
    static final Color DETECT = new Color(0x1f77b4);
    static final Color BOOF = new Color(0xff7f0e);
    static final Color TRACK = new Color(0x2ca02c);

    private EvalTrackingTimes() {
    }

    /**
     * The first {@code frames} frames of the synthetic video's loop of {@code loop} timed into
     * {@code time}, after a pass of each contender (which records what it finds) and
     * {@code warmupSeconds} more.
     */
    static void measure(ObjectNode time, int frames, int loop, double warmupSeconds) {
        TrackBenchVideo v = TrackBenchVideo.synthetic(frames, loop);
        TrackBench.Result r;
        try {
            r = TrackBench.measure(v, MarkerDictionary.DEFAULT, 1000 * EvalTrackingSection.MARKER_METRES, null, null,
                    "wall", warmupSeconds, Rounds.MIN_RUNS, 0);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        Spread boof = r.runs()[0];
        Spread detect = r.runs()[1];
        Spread track = r.runs()[2];
        time.put("frames", frames);
        time.put("loopFrames", loop);
        time.put("width", v.camera().width());
        time.put("height", v.camera().height());
        time.put("warmupSeconds", warmupSeconds);
        time.put("rounds", r.rounds());
        time.put("fullFrameEvery", FiducialTracker.FULL_FRAME_EVERY);
        EvalReport.putSpread(time, "boofDefaultMs", boof);
        EvalReport.putSpread(time, "detectMs", detect);
        EvalReport.putSpread(time, "trackMs", track);
        time.put("detectOverBoof", EvalReport.round(detect.median() / boof.median()));
        EvalReport.putSpread(time, "detectOverBoofRuns", ratios(detect, boof, 1));
        time.put("trackPercentOfDetect", EvalReport.round(100 * track.median() / detect.median()));
        EvalReport.putSpread(time, "trackPercentOfDetectRuns", ratios(track, detect, 100));
        time.put("detectOverTrack", EvalReport.round(detect.median() / track.median()));
        time.put("trackInRegionPercent", EvalReport.round(100 * r.regionShare()));
        int[] same = new int[3];
        int[] markers = new int[3];
        for (int c = 0; c < 3; c++) {
            for (int f = 0; f < frames; f++) {
                List<Integer> ids = r.ids().get(c).get(f);
                same[c] += ids.equals(r.ids().get(1).get(f)) ? 1 : 0;
                markers[c] += ids.size();
            }
        }
        time.put("boofMarkers", markers[0]);
        time.put("detectMarkers", markers[1]);
        time.put("trackMarkers", markers[2]);
        time.put("boofSameIdsAsDetect", same[0]);
        time.put("trackSameIdsAsDetect", same[2]);
    }

    /** Each round's {@code a} over {@code b}, times {@code scale}. */
    private static Spread ratios(Spread a, Spread b, double scale) {
        double[] x = a.runs();
        double[] y = b.runs();
        double[] r = new double[x.length];
        for (int i = 0; i < r.length; i++) {
            r[i] = scale * x[i] / y[i];
        }
        return Spread.of(r);
    }

    /** The times' text, table and figure. */
    static void report(JsonNode results, EvalReport report) {
        report.heading(3, "Time per frame");
        boolean loop = results.at("/time/frames").asInt() == results.at("/time/loopFrames").asInt();
        report.paragraph((loop ? "The " : "The first ") + EvalReport.num(results, "/time/frames") + " frames of"
                + " `skinlab ar-demo`'s synthetic video (" + (loop ? "one loop" : "of a loop of "
                        + EvalReport.num(results, "/time/loopFrames") + " frames") + ", "
                + EvalReport.num(results, "/time/width") + "x" + EvalReport.num(results, "/time/height") + ": the"
                + " default marker on a desk, a hand-held camera circling it at about half a metre, blur, noise,"
                + " uneven light, clutter on every fourth frame) in order, with `skinlab bench track`'s protocol:"
                + " BoofCV's default and our `detect` (the whole frame), both with each marker's pose, and `track`,"
                + " the video search near the last markers (the whole frame only on the first frame and every "
                + EvalReport.num(results, "/time/fullFrameEvery") + "th). One thread (BoofCV's pool off), each"
                + " frame by the wall clock. A pass of each (which records what it finds) and a warm-up of "
                + EvalReport.num(results, "/time/warmupSeconds") + " s come first, then "
                + EvalReport.num(results, "/time/rounds") + " rounds, each running every contender over the frames"
                + " and starting one contender further along than the last; a run is a contender's median frame of"
                + " a round. The table gives the median run, the fastest and the slowest, and the ratios of the"
                + " median runs with the range of each round's own ratio.");
        report.header("contender", "median ms", "runs ms", "of the medians", "the rounds' own",
                "frames with detect's ids");
        report.row("BoofCV default", EvalReport.num(results, "/time/boofDefaultMs/median"),
                range(results, "/time/boofDefaultMs"), "", "", EvalReport.num(results, "/time/boofSameIdsAsDetect"));
        report.row("`detect`", EvalReport.num(results, "/time/detectMs/median"), range(results, "/time/detectMs"),
                "detect / BoofCV's: " + EvalReport.num(results, "/time/detectOverBoof"),
                range(results, "/time/detectOverBoofRuns"), EvalReport.num(results, "/time/frames"));
        report.row("`track`", EvalReport.num(results, "/time/trackMs/median"), range(results, "/time/trackMs"),
                "track / detect: " + EvalReport.num(results, "/time/trackPercentOfDetect") + " %",
                range(results, "/time/trackPercentOfDetectRuns") + " %",
                EvalReport.num(results, "/time/trackSameIdsAsDetect"));
        report.line("");
        report.paragraph("Our whole-frame search takes " + EvalReport.num(results, "/time/detectOverBoof")
                + " times BoofCV's default per frame (rounds: " + range(results, "/time/detectOverBoofRuns")
                + "; the same square detector, our decision rule on its squares). The video search near the last"
                + " markers takes " + EvalReport.num(results, "/time/trackPercentOfDetect") + " % of `detect`'s time"
                + " per frame (rounds: " + range(results, "/time/trackPercentOfDetectRuns") + " %), "
                + EvalReport.num(results, "/time/detectOverTrack") + " times faster, with `detect`'s ids in "
                + EvalReport.num(results, "/time/trackSameIdsAsDetect") + " of "
                + EvalReport.num(results, "/time/frames")
                + " frames; it found every marker near the last ones in "
                + EvalReport.num(results, "/time/trackInRegionPercent") + " % of its frames.");
        figure(results, report);
    }

    private static String range(JsonNode results, String spread) {
        return EvalReport.num(results, spread + "/min") + "-" + EvalReport.num(results, spread + "/max");
    }

    /** Each contender's runs: the median with a bar from the fastest to the slowest run, a slot each. */
    private static void figure(JsonNode results, EvalReport report) {
        XYChart chart = EvalCharts.xy("Marker tracking: time per frame of the video, one thread", "contender",
                "ms, " + EvalCharts.SPREAD);
        EvalCharts.logY(chart);
        EvalCharts.categories(chart, List.of("BoofCV default", "detect", "track"), 0);
        String[] names = {"BoofCV squareHamming, default settings", "skinlab detect (whole frame)",
            "skinlab track (near the last markers)"};
        String[] spreads = {"/time/boofDefaultMs", "/time/detectMs", "/time/trackMs"};
        Color[] colours = {BOOF, DETECT, TRACK};
        for (int i = 0; i < names.length; i++) {
            EvalCharts.medians(chart, names[i], List.of((double) i), List.of(results.at(spreads[i])), colours[i],
                    false);
        }
        report.figure("tracking-time.png", "Time per frame of the video: median run, bars from the fastest to the"
                + " slowest run", chart);
    }
}
