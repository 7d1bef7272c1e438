package org.skinlab.desktop.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

import boofcv.alg.geo.calibration.CalibrationObservation;

import org.skinlab.internal.ar.CalibrationTarget;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.LensDistortion;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ar.CameraCalibration;
import org.skinlab.desktop.ar.CameraImage;
import org.skinlab.desktop.ar.GrayImages;
import org.skinlab.desktop.ar.IntrinsicsFile;
import org.skinlab.desktop.ar.TargetDetector;
import org.skinlab.desktop.ar.ViewCollector;
import org.skinlab.desktop.ar.WebcamSource;

import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code skinlab calibrate}: the camera's intrinsics and lens from photos of the printed target
 * ({@code skinlab calibration-target}), written as the intrinsics file of {@code skinlab ar} and
 * {@code skinlab track}, with a report: which photos show the target (and why the others do not),
 * the reprojection error, the result, and what the photos miss.
 */
@Command(name = "calibrate", mixinStandardHelpOptions = true,
        description = {"Calibrate a camera from photos of the printed target (skinlab calibration-target).",
                "Writes its focal lengths, principal point and lens distortion (k1, k2, p1, p2) as the intrinsics file "
                        + "of skinlab ar/track --intrinsics, and reports the error and what the photos miss."})
public final class CalibrateCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    static final class Source {
        @Option(names = "--images", paramLabel = "DIR", description = "a folder of photos of the target (.png/.jpg, name order)")
        Path images;

        @Option(names = "--webcam", description = "the default webcam: a view is taken about every second while the "
                + "target is in sight and differs from the views taken")
        boolean webcam;
    }

    @ArgGroup(exclusive = true, multiplicity = "1")
    Source source;

    @Mixin
    TargetOptions targetOptions;

    @Option(names = "--out", paramLabel = "FILE.json", required = true, description = "where to write the intrinsics")
    Path out;

    @Option(names = "--k3", description = "also estimate the radial term k3 (wide-angle lenses; default: k1, k2 only)")
    boolean k3;

    @Option(names = "--views", paramLabel = "N", description = "--webcam: views to collect (default: ${DEFAULT-VALUE})")
    int wantedViews = 15;

    @Option(names = "--max-seconds", paramLabel = "S", description = "--webcam: give up after S seconds (default: ${DEFAULT-VALUE})")
    int maxSeconds = 180;

    @Override
    public Integer call() {
        CalibrationTarget target = targetOptions.target();
        if (source.webcam && (wantedViews < CameraCalibration.MIN_VIEWS || wantedViews > 100 || maxSeconds < 1)) {
            throw new CommandFailure(ExitCodes.USAGE, "--views must be " + CameraCalibration.MIN_VIEWS + " to 100 and "
                    + "--max-seconds at least 1", null);
        }
        PrintWriter o = spec.commandLine().getOut();
        TargetDetector detector = new TargetDetector(target);
        o.println("target: " + target.describe() + " (" + target.points() + " points per view)");
        Views views = source.webcam ? fromWebcam(detector, o) : fromImages(detector, o);
        CameraCalibration.Result result;
        try {
            result = CameraCalibration.calibrate(detector.layout(), views.points, views.width, views.height, k3);
        } catch (IllegalArgumentException e) {
            throw new CommandFailure(ExitCodes.INVALID_FILE, views.what + ": " + e.getMessage(), e);
        }
        report(result, views, o);
        try {
            IntrinsicsFile.write(result.intrinsics(), out);
        } catch (IOException e) {
            throw new CommandFailure(ExitCodes.USAGE, "cannot write " + out + ": " + e.getMessage(), e);
        }
        o.println("wrote " + out + " (use it as: skinlab ar --intrinsics " + out + " ...)");
        o.flush();
        return ExitCodes.OK;
    }

    /** The views found, their names for the report, the image size, and what they came from. */
    private static final class Views {
        final List<CalibrationObservation> points = new ArrayList<>();
        final List<String> names = new ArrayList<>();
        int width;
        int height;
        String what;
    }

    private Views fromImages(TargetDetector detector, PrintWriter o) {
        List<Path> files;
        try {
            files = GrayImages.list(source.images);
        } catch (IllegalArgumentException | IOException e) {
            throw new CommandFailure(ExitCodes.USAGE, e.getMessage(), e);
        }
        Views v = new Views();
        v.what = source.images.toString();
        for (Path file : files) {
            String name = file.getFileName().toString();
            GrayImage image;
            try {
                image = GrayImages.read(file);
            } catch (IllegalArgumentException e) {
                o.println("  " + name + ": not used: " + e.getMessage());
                continue;
            }
            if (v.width == 0) {
                v.width = image.width();
                v.height = image.height();
            } else if (image.width() != v.width || image.height() != v.height) {
                o.println("  " + name + ": not used: " + image.width() + " x " + image.height() + ", the first image is "
                        + v.width + " x " + v.height + " (all photos must come from the same camera mode)");
                continue;
            }
            TargetDetector.View view = detector.detect(image);
            if (view.found()) {
                v.points.add(view.points());
                v.names.add(name);
                o.println("  " + name + ": found");
            } else {
                o.println("  " + name + ": not found: " + view.problem());
            }
            o.flush();
        }
        if (v.points.size() < CameraCalibration.MIN_VIEWS) {
            throw new CommandFailure(ExitCodes.INVALID_FILE, source.images + ": the target (" + detector.target().describe()
                    + ") is in " + v.points.size() + " of " + files.size() + " images; at least " + CameraCalibration.MIN_VIEWS
                    + " views are needed (10 to 20 recommended; the report above says why images were not used)", null);
        }
        o.println("views: " + v.points.size() + " of " + files.size() + " images (" + v.width + " x " + v.height + ")");
        return v;
    }

    private Views fromWebcam(TargetDetector detector, PrintWriter o) {
        WebcamSource camera;
        try {
            camera = new WebcamSource();
        } catch (IllegalStateException e) {
            // The same status as skinlab ar without a webcam; this command has no --video.
            throw new CommandFailure(ExitCodes.UNAVAILABLE, e.getMessage().replace(" or --video FILE", ""), e);
        }
        Views v = new Views();
        v.what = "the webcam " + camera.name();
        v.width = camera.width();
        v.height = camera.height();
        ViewCollector collector = new ViewCollector(detector);
        o.println("collecting " + wantedViews + " views from " + v.what + ": hold the target in sight, move and tilt it "
                + "between views; reach the image's corners and edges");
        o.flush();
        long start = System.nanoTime();
        long lastTry = 0;
        long lastHint = start;
        CameraImage frame = new CameraImage(camera.width(), camera.height());
        try {
            while (collector.views().size() < wantedViews && System.nanoTime() - start < maxSeconds * 1_000_000_000L) {
                camera.next(frame);
                long now = System.nanoTime();
                if (now - lastTry < 1_000_000_000L) {
                    continue;
                }
                lastTry = now;
                ViewCollector.Offer offer = collector.offer(frame.gray());
                if (offer.kept()) {
                    o.println("  view " + collector.views().size() + " of " + wantedViews + " taken");
                    lastHint = now;
                } else if (now - lastHint > 5_000_000_000L) {
                    o.println("  waiting: " + offer.reason());
                    lastHint = now;
                }
                o.flush();
            }
        } catch (IllegalStateException e) {
            throw new CommandFailure(ExitCodes.UNAVAILABLE, e.getMessage(), e);
        } finally {
            camera.close();
        }
        for (int i = 1; i <= collector.views().size(); i++) {
            v.points.add(collector.views().get(i - 1));
            v.names.add("view " + i);
        }
        if (v.points.size() < CameraCalibration.MIN_VIEWS) {
            throw new CommandFailure(ExitCodes.INVALID_FILE, v.what + ": only " + v.points.size() + " views of the target ("
                    + detector.target().describe() + ") in " + maxSeconds + " s; at least " + CameraCalibration.MIN_VIEWS
                    + " are needed", null);
        }
        if (v.points.size() < wantedViews) {
            o.println("time is up after " + maxSeconds + " s: calibrating with " + v.points.size() + " views");
        }
        return v;
    }

    private static void report(CameraCalibration.Result r, Views v, PrintWriter o) {
        CameraIntrinsics k = r.intrinsics();
        LensDistortion d = k.distortion();
        o.println(String.format(Locale.ROOT, "reprojection error (RMS per view): mean %.3f px, max %.3f px (%s)",
                r.meanRms(), r.maxRms(), v.names.get(r.worstView())));
        o.println(String.format(Locale.ROOT, "camera: %d x %d, fx %.2f fy %.2f px, principal point (%.2f, %.2f), "
                + "horizontal field of view %.1f deg", k.width(), k.height(), k.fx(), k.fy(), k.cx(), k.cy(),
                k.horizontalFovDegrees()));
        o.println(String.format(Locale.ROOT, "lens: k1 %.5f k2 %.5f k3 %.5f p1 %.6f p2 %.6f", d.k1(), d.k2(), d.k3(),
                d.p1(), d.p2()));
        double[] shift = CameraCalibration.cornerShift(k);
        o.println(String.format(Locale.ROOT, "the lens moves the image corners by %.1f, %.1f, %.1f, %.1f px "
                + "(top-left, top-right, bottom-right, bottom-left)", shift[0], shift[1], shift[2], shift[3]));
        for (String w : r.warnings()) {
            o.println("warning: " + w);
        }
        if (r.maxRms() > 1) {
            o.println(String.format(Locale.ROOT, "warning: a view's error is %.2f px (%s): a blurred photo or a target "
                    + "that was not flat; leave it out and calibrate again",
                    r.maxRms(), v.names.get(r.worstView())));
        }
    }
}
