package org.skinlab.desktop.eval;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import boofcv.concurrency.BoofConcurrency;
import georegression.struct.se.Se3_F64;

import org.knowm.xchart.XYChart;
import org.skinlab.ar.BoofSquareHamming;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.MarkerDetection;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.internal.synthetic.DetectionTally;
import org.skinlab.internal.synthetic.MarkerShot;
import org.skinlab.internal.synthetic.MarkerShots;
import org.skinlab.internal.synthetic.NegativeFrames;

/**
 * Section "tracking": our marker tracker ({@link FiducialTracker#detect}, the whole frame) on
 * synthetic frames of known pose ({@link MarkerShots#central}: a 10 cm ArUco MIP_36h12 marker,
 * 640x480 at 60 degrees, blur, noise, uneven light, every fifth partly covered; the set
 * TrackerEvaluationTest measures) in bins of distance and tilt: how many are found and the median
 * position and rotation errors of the found; how many markers it and BoofCV's own detector with
 * its default settings ({@link BoofSquareHamming}) report on frames without one
 * ({@link NegativeFrames}: clutter, other dictionaries' codes; FarTiltedDetectionTest's and
 * TrackerEvaluationTest's sets); and the time per frame of both, and of our video search, on a
 * video ({@link EvalTrackingTimes}). Each bin draws from its own seed, so a quick run's frames are
 * the first of a full run's.
 */
final class EvalTrackingSection implements EvalSection {
    static final double HORIZONTAL_FOV = 60;
    static final CameraIntrinsics CAMERA = CameraIntrinsics.fromHorizontalFov(640, 480, HORIZONTAL_FOV);
    /** The clutter frames' camera: the rule decides per square, and small frames render fast. */
    static final CameraIntrinsics CLUTTER_CAMERA = CameraIntrinsics.fromHorizontalFov(320, 240, HORIZONTAL_FOV);
    static final double MARKER_METRES = 0.10;
    /** Distance bins' edges (metres); 0.9-1.1 is the "about 1 m" of the accuracy goals. */
    static final double[] DISTANCES = {0.3, 0.6, 0.9, 1.1, 1.5, 2.0};
    /** The distance bin ({@link #DISTANCES}' index) pooled over tilts up to {@link #GOAL_TILT} for the goals. */
    static final int ABOUT_ONE_METRE = 2;
    static final double GOAL_TILT = 60;
    /** The tracker's accuracy goals at about 1 m (docs/ar.md): median errors at most these. */
    static final double GOAL_POSITION_MM = 2;
    static final double GOAL_ROTATION_DEGREES = 0.4;
    /** Tilt bands' edges (degrees). */
    static final double[] TILTS = {0, 20, 40, 60, 70};
    /** The tests' seeds: FarTiltedDetectionTest's clutter, TrackerEvaluationTest's negative frames. */
    static final long CLUTTER_SEED = 1803;
    static final long MIXED_SEED = 505;
    private static final long BIN_SEED = 1900;

    /** The timed video: a loop of this many frames (bench track's default), of which a run times the first. */
    static final int VIDEO_LOOP = 60;

    /**
     * @param perBin             frames of each bin of distance and tilt
     * @param videoFrames        the timed video's frames, the first of its loop
     * @param videoWarmupSeconds its warm-up after a first pass (the accuracy's frames warmed detect up)
     */
    private record Sizes(int perBin, int clutter, int mixed, int videoFrames, double videoWarmupSeconds) {
    }

    private static Sizes sizes(boolean quick) {
        return quick ? new Sizes(4, 100, 9, 10, 0) : new Sizes(30, 1000, 90, VIDEO_LOOP, 2);
    }

    @Override
    public String key() {
        return "tracking";
    }

    @Override
    public String title() {
        return "Tracking";
    }

    @Override
    public double estimatedSeconds(EvalContext context) {
        return context.quick() ? 30 : 280;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        Sizes sizes = sizes(context.quick());
        boolean concurrent = BoofConcurrency.USE_CONCURRENT;
        FiducialTracker.runOnCallingThread();
        try {
            measure(context, results, sizes);
        } finally {
            BoofConcurrency.USE_CONCURRENT = concurrent;
        }
    }

    private void measure(EvalContext context, ObjectNode results, Sizes sizes) {
        putSetup(results, sizes);
        int bins = (DISTANCES.length - 1) * (TILTS.length - 1);
        // Progress in about a positive frame's time: a clutter frame is smaller, a mixed one has 4x4
        // rays, a video frame is rendered once and searched whole 12 times.
        double video = sizes.videoFrames() * 3 + 10 * sizes.videoWarmupSeconds();
        double total = bins * sizes.perBin() + video + sizes.clutter() * 0.3 + sizes.mixed() * 2;

        FiducialTracker ours = new FiducialTracker(TrackerConfig.defaults(MARKER_METRES), CAMERA);
        BoofSquareHamming boof = BoofSquareHamming.defaults(MarkerDictionary.DEFAULT, MARKER_METRES, CAMERA);
        MarkerShots shots = MarkerShots.central(CAMERA, MarkerDictionary.DEFAULT, MARKER_METRES);
        Se3_F64 pose = new Se3_F64();
        int frame = 0;
        DetectionTally all = new DetectionTally();
        DetectionTally aboutOneMetre = new DetectionTally();
        int boofAll = 0;
        ArrayNode table = results.putArray("bins");
        for (int d = 0; d + 1 < DISTANCES.length; d++) {
            for (int t = 0; t + 1 < TILTS.length; t++) {
                Random random = new Random(BIN_SEED + 100 * d + t);
                DetectionTally tally = new DetectionTally();
                int boofFound = 0;
                for (int i = 0; i < sizes.perBin(); i++) {
                    MarkerShot shot = shots.shot(random, DISTANCES[d], DISTANCES[d + 1], TILTS[t], TILTS[t + 1]);
                    List<MarkerDetection> found = ours.detect(shot.image());
                    boofFound += boofFinds(boof, shot, pose);
                    tally.add(shot.marker(), found);
                    all.add(shot.marker(), found);
                    if (d == ABOUT_ONE_METRE && TILTS[t + 1] <= GOAL_TILT) {
                        aboutOneMetre.add(shot.marker(), found);
                    }
                    frame++;
                    context.progress(frame / total);
                }
                boofAll += boofFound;
                putBin(table.addObject(), d, t, tally, boofFound);
            }
        }
        putSummary(results, all, boofAll, aboutOneMetre);

        EvalTrackingTimes.measure(results.putObject("time"), sizes.videoFrames(), VIDEO_LOOP,
                sizes.videoWarmupSeconds());
        context.progress((frame + video) / total);

        falseMarkers(context, results, sizes, ours, frame + video, total);
    }

    /** Bin {@code d}, {@code t}: its distances and tilts, what our tracker found and what BoofCV's did. */
    private static void putBin(ObjectNode bin, int d, int t, DetectionTally tally, int boofFound) {
        bin.put("distanceMin", DISTANCES[d]);
        bin.put("distanceMax", DISTANCES[d + 1]);
        bin.put("tiltMin", TILTS[t]);
        bin.put("tiltMax", TILTS[t + 1]);
        tally(bin, tally);
        bin.put("boofFound", boofFound);
    }

    /** How often BoofCV's default finds the shot's marker (with each marker's pose, as it is timed). */
    private static int boofFinds(BoofSquareHamming boof, MarkerShot shot, Se3_F64 pose) {
        int n = boof.detect(shot.image());
        int found = 0;
        for (int m = 0; m < n; m++) {
            boof.pose(m, pose);
            found += boof.id(m) == shot.marker().pattern().id() ? 1 : 0;
        }
        return found;
    }

    /** The camera, marker and dictionary every bin uses. */
    private static void putSetup(ObjectNode results, Sizes sizes) {
        ObjectNode camera = results.putObject("camera");
        camera.put("width", CAMERA.width());
        camera.put("height", CAMERA.height());
        camera.put("horizontalFovDegrees", HORIZONTAL_FOV);
        camera.put("fx", EvalReport.round(CAMERA.fx()));
        results.put("markerMm", EvalReport.round(1000 * MARKER_METRES));
        results.put("dictionary", MarkerDictionary.DEFAULT.key());
        results.put("framesPerBin", sizes.perBin());
    }

    /** Detection over all bins and about a metre away. */
    private static void putSummary(ObjectNode results, DetectionTally all, int boofAll, DetectionTally aboutOneMetre) {
        ObjectNode overall = results.putObject("all");
        tally(overall, all);
        overall.put("boofFound", boofAll);
        ObjectNode one = results.putObject("aboutOneMetre");
        one.put("distanceMin", DISTANCES[ABOUT_ONE_METRE]);
        one.put("distanceMax", DISTANCES[ABOUT_ONE_METRE + 1]);
        one.put("tiltMax", GOAL_TILT);
        one.put("goalPositionMm", GOAL_POSITION_MM);
        one.put("goalRotationDegrees", GOAL_ROTATION_DEGREES);
        tally(one, aboutOneMetre);
    }

    /**
     * Markers reported on frames with none: ours and BoofCV's default cap (no camera: the tests'
     * count, ids only), the clutter frames and then the other dictionaries' codes.
     */
    private static void falseMarkers(EvalContext context, ObjectNode results, Sizes sizes, FiducialTracker ours,
            double done, double total) {
        FiducialTracker oursSmall = new FiducialTracker(TrackerConfig.defaults(MARKER_METRES), CLUTTER_CAMERA);
        BoofSquareHamming boof = BoofSquareHamming.capped(MarkerDictionary.DEFAULT,
                MarkerDictionary.DEFAULT.minimumHamming());
        NegativeFrames clutter = new NegativeFrames(CLUTTER_CAMERA);
        Random random = new Random(CLUTTER_SEED);
        int[] falseMarkers = new int[2];
        for (int i = 0; i < sizes.clutter(); i++) {
            GrayImage image = clutter.clutter(random);
            falseMarkers[0] += oursSmall.detect(image).size();
            falseMarkers[1] += boof.detect(image);
            context.progress((done + 0.3 * (i + 1)) / total);
        }
        negatives(results.putObject("clutter"), CLUTTER_CAMERA, sizes.clutter(), falseMarkers);
        done += 0.3 * sizes.clutter();

        NegativeFrames mixed = new NegativeFrames(CAMERA);
        random = new Random(MIXED_SEED);
        falseMarkers = new int[2];
        for (int i = 0; i < sizes.mixed(); i++) {
            GrayImage image = mixed.mixed(random, i);
            falseMarkers[0] += ours.detect(image).size();
            falseMarkers[1] += boof.detect(image);
            context.progress((done + 2.0 * (i + 1)) / total);
        }
        negatives(results.putObject("otherCodes"), CAMERA, sizes.mixed(), falseMarkers);
    }

    private static void tally(ObjectNode node, DetectionTally t) {
        node.put("frames", t.frames());
        node.put("found", t.found());
        node.put("wrongIds", t.wrongIds());
        node.put("foundPercent", EvalReport.round(100 * t.rate()));
        putOrNull(node, "medianPositionMm", 1000 * t.positionError(0.5));
        putOrNull(node, "medianRotationDegrees", t.rotationError(0.5));
    }

    private static void putOrNull(ObjectNode node, String name, double value) {
        if (Double.isNaN(value)) {
            node.putNull(name);
        } else {
            node.put(name, EvalReport.round(value));
        }
    }

    private static void negatives(ObjectNode node, CameraIntrinsics k, int frames, int[] falseMarkers) {
        node.put("frames", frames);
        node.put("width", k.width());
        node.put("height", k.height());
        node.put("ours", falseMarkers[0]);
        node.put("boofDefault", falseMarkers[1]);
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        report.paragraph("Our tracker (`FiducialTracker.detect`, the whole frame) on synthetic frames of known pose"
                + " (`MarkerShots.central`): a " + EvalReport.num(results, "/markerMm") + " mm ArUco MIP_36h12 marker"
                + " seen by a " + EvalReport.num(results, "/camera/width") + "x" + EvalReport.num(results, "/camera/height")
                + " camera with a " + EvalReport.num(results, "/camera/horizontalFovDegrees") + " degree field of view"
                + " (fx " + EvalReport.num(results, "/camera/fx") + " px), a random code anywhere near the image's"
                + " middle, turned about its normal, tilted about a random axis in its plane; each frame blurred,"
                + " noisy and lit unevenly, every fifth with a disc over part of the code (docs/ar.md). "
                + EvalReport.num(results, "/framesPerBin") + " frames per bin of distance and tilt, each bin from its"
                + " own seed. Found: detections with the marker's id; the errors are the found markers' medians"
                + " against the rendered pose. BoofCV's own detector with its default settings ran on the same"
                + " frames.");
        binTable(results, report);
        aboutOneMetreReport(results, report);
        binFigure(results, "foundPercent", "found (%)", "tracking-found.png",
                "Markers found against distance, a line per tilt band", report);
        binFigure(results, "medianPositionMm", "median position error (mm)", "tracking-position-error.png",
                "Median position error against distance, a line per tilt band", report);
        binFigure(results, "medianRotationDegrees", "median rotation error (degrees)", "tracking-rotation-error.png",
                "Median rotation error against distance, a line per tilt band", report);
        falseMarkersReport(results, report);
        EvalTrackingTimes.report(results, report);
    }

    /** A row per bin of distance and tilt, and one of all frames. */
    private static void binTable(JsonNode results, EvalReport report) {
        report.header("distance m", "tilt degrees", "found", "found %", "wrong ids", "median position error mm",
                "median rotation error degrees", "BoofCV default found");
        JsonNode bins = results.get("bins");
        for (int i = 0; i < bins.size(); i++) {
            String p = "/bins/" + i;
            report.row(EvalReport.num(results, p + "/distanceMin") + "-" + EvalReport.num(results, p + "/distanceMax"),
                    EvalReport.num(results, p + "/tiltMin") + "-" + EvalReport.num(results, p + "/tiltMax"),
                    EvalReport.num(results, p + "/found") + " of " + EvalReport.num(results, p + "/frames"),
                    EvalReport.num(results, p + "/foundPercent"), EvalReport.num(results, p + "/wrongIds"),
                    EvalReport.numOrDash(results, p + "/medianPositionMm"),
                    EvalReport.numOrDash(results, p + "/medianRotationDegrees"), EvalReport.num(results, p + "/boofFound"));
        }
        report.row("all", "all", EvalReport.num(results, "/all/found") + " of " + EvalReport.num(results, "/all/frames"),
                EvalReport.num(results, "/all/foundPercent"), EvalReport.num(results, "/all/wrongIds"),
                EvalReport.numOrDash(results, "/all/medianPositionMm"),
                EvalReport.numOrDash(results, "/all/medianRotationDegrees"), EvalReport.num(results, "/all/boofFound"));
        report.line("");
    }

    /** The frames at about 1 m against the tracker's goals. */
    private static void aboutOneMetreReport(JsonNode results, EvalReport report) {
        report.paragraph("At about 1 m (" + EvalReport.num(results, "/aboutOneMetre/distanceMin") + "-"
                + EvalReport.num(results, "/aboutOneMetre/distanceMax") + " m, tilts up to "
                + EvalReport.num(results, "/aboutOneMetre/tiltMax") + " degrees, "
                + EvalReport.num(results, "/aboutOneMetre/frames") + " frames): "
                + EvalReport.num(results, "/aboutOneMetre/found") + " found, median position error "
                + EvalReport.numOrDash(results, "/aboutOneMetre/medianPositionMm") + " mm, rotation "
                + EvalReport.numOrDash(results, "/aboutOneMetre/medianRotationDegrees") + " degrees (the tracker's"
                + " goals, docs/ar.md: at most " + EvalReport.num(results, "/aboutOneMetre/goalPositionMm") + " mm and "
                + EvalReport.num(results, "/aboutOneMetre/goalRotationDegrees") + " degrees).");
    }

    /** Markers reported on frames that show none: ours against BoofCV's. */
    private static void falseMarkersReport(JsonNode results, EvalReport report) {
        report.heading(3, "False markers");
        report.paragraph("Markers reported on frames that show none of the dictionary's (`NegativeFrames`): "
                + EvalReport.num(results, "/clutter/frames") + " frames of " + EvalReport.num(results, "/clutter/width")
                + "x" + EvalReport.num(results, "/clutter/height") + " with clutter (dark boxes, squares of random bits,"
                + " checkerboards, text, textures, framed pictures, other dictionaries' codes, our codes with a few"
                + " bits flipped), and " + EvalReport.num(results, "/otherCodes/frames") + " frames of "
                + EvalReport.num(results, "/otherCodes/width") + "x" + EvalReport.num(results, "/otherCodes/height")
                + " with printed AprilTag 36h11, ArUco 6x6 and MIP_25h7 codes among clutter. BoofCV accepts a square"
                + " up to the dictionary's minimum Hamming distance from a code; our rule weighs each wrong bit by"
                + " the confidence it was read with.");
        report.header("frames", "false markers, ours", "false markers, BoofCV default");
        report.row("clutter, " + EvalReport.num(results, "/clutter/frames"), EvalReport.num(results, "/clutter/ours"),
                EvalReport.num(results, "/clutter/boofDefault"));
        report.row("other codes, " + EvalReport.num(results, "/otherCodes/frames"),
                EvalReport.num(results, "/otherCodes/ours"), EvalReport.num(results, "/otherCodes/boofDefault"));
        report.line("");
    }

    /** A bin measure against the distance bins' middles, one line per tilt band. */
    private static void binFigure(JsonNode results, String measure, String axis, String png, String caption,
            EvalReport report) {
        XYChart chart = EvalCharts.xy(caption, "distance (m)", axis);
        List<Double> bands = new ArrayList<>();
        for (JsonNode bin : results.get("bins")) {
            if (!bands.contains(bin.get("tiltMin").asDouble())) {
                bands.add(bin.get("tiltMin").asDouble());
            }
        }
        for (double band : bands) {
            List<Double> x = new ArrayList<>();
            List<Double> y = new ArrayList<>();
            String name = null;
            for (JsonNode bin : results.get("bins")) {
                if (bin.get("tiltMin").asDouble() == band && bin.get(measure).isNumber()) {
                    x.add((bin.get("distanceMin").asDouble() + bin.get("distanceMax").asDouble()) / 2);
                    y.add(bin.get(measure).asDouble());
                    name = "tilt " + EvalReport.format(bin.get("tiltMin")) + "-" + EvalReport.format(bin.get("tiltMax"))
                            + " degrees";
                }
            }
            if (!x.isEmpty()) {
                chart.addSeries(name, x, y);
            }
        }
        report.figure(png, caption, chart);
    }
}
