package org.skinlab.desktop.cli;

import java.io.IOException;
import java.nio.file.Path;
import java.util.concurrent.Callable;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.ar.ArSession;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.app.AppOptions;
import org.skinlab.desktop.app.ArSetup;
import org.skinlab.desktop.app.SkinlabApp;
import org.skinlab.desktop.ar.ArFeed;
import org.skinlab.desktop.ar.FrameSource;
import org.skinlab.desktop.ar.ImageFolderSource;
import org.skinlab.desktop.ar.IntrinsicsFile;
import org.skinlab.desktop.ar.VideoFileSource;
import org.skinlab.desktop.ar.WebcamSource;
import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.desktop.viewer.DifferenceScale;

import picocli.CommandLine.ArgGroup;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code skinlab ar}: the viewer window in AR mode: camera frames (an image folder, a video file or
 * a webcam) as the background, tracked on their own thread, and the animated model standing on
 * the printed marker, with the whole toolbar (follow-camera included). {@code skinlab ar-demo}
 * writes frames to try it without a camera.
 */
@Command(name = "ar", mixinStandardHelpOptions = true,
        description = {"The viewer in AR mode: camera frames as background, the model standing on the printed marker.",
                "Try it without a camera: skinlab ar-demo DIR, then skinlab ar --images DIR --intrinsics DIR/intrinsics.json"})
public final class ArCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    static final class Source {
        @Option(names = "--images", paramLabel = "DIR", description = "a folder of camera frames (.png/.jpg, name order, looping)")
        Path images;

        @Option(names = "--video", paramLabel = "FILE", description = "a video file (MP4 with H.264), looping")
        Path video;

        @Option(names = "--webcam", description = "the default webcam")
        boolean webcam;
    }

    @ArgGroup(exclusive = true, multiplicity = "1")
    Source source;

    @Parameters(index = "0", arity = "0..1", paramLabel = "FILE",
            description = "a model file: .dae, .gltf or .glb (default: the bundled character)")
    Path file;

    @Option(names = "--marker-size", paramLabel = "MM", description = "the printed black square's width (default: ${DEFAULT-VALUE})")
    double markerSizeMm = 100;

    @Option(names = "--dictionary", paramLabel = "NAME", description = "marker dictionary (default: aruco_mip_36h12)")
    String dictionary = MarkerDictionary.DEFAULT.key();

    @Option(names = "--id", paramLabel = "N", description = "the marker id to follow (default: the nearest marker)")
    int id = -1;

    @Option(names = "--intrinsics", paramLabel = "FILE", description = "camera intrinsics: our JSON, OpenCV's calibration YAML/XML or BoofCV's intrinsic.yaml (default: from --fov)")
    Path intrinsics;

    @Option(names = "--fov", paramLabel = "DEG", description = "horizontal field of view without --intrinsics (default: ${DEFAULT-VALUE})")
    double fov = 60;

    @Option(names = "--fps", paramLabel = "N", description = "frames per second of --images and --video (default: ${DEFAULT-VALUE})")
    double fps = 30;

    @Mixin
    WindowOptions window = new WindowOptions();

    @Option(names = "--exit-after-frames", paramLabel = "N", description = "close after N frames")
    int exitAfterFrames;

    @Override
    public Integer call() {
        if (!(fps > 0 && fps <= 240)) {
            throw new CommandFailure(ExitCodes.USAGE, "--fps must be in (0, 240]", null);
        }
        FrameSource frames;
        try {
            frames = source.webcam ? new WebcamSource() : source.video != null ? new VideoFileSource(source.video, fps)
                    : new ImageFolderSource(source.images, fps);
        } catch (IllegalStateException e) {
            throw new CommandFailure(ExitCodes.UNAVAILABLE, e.getMessage(), e);
        } catch (IllegalArgumentException | IOException e) {
            throw new CommandFailure(ExitCodes.INVALID_FILE, e.getMessage(), e);
        }
        CameraIntrinsics k;
        TrackerConfig config;
        try {
            k = intrinsics != null
                    ? IntrinsicsFile.forImage(IntrinsicsFile.read(intrinsics), frames.width(), frames.height(),
                            "the frames of " + frames.name())
                    : CameraIntrinsics.fromHorizontalFov(frames.width(), frames.height(), fov);
            config = TrackerConfig.of(MarkerDictionary.byName(dictionary), markerSizeMm / 1000).withTargetId(id);
        } catch (IllegalArgumentException | IOException e) {
            frames.close();
            throw new CommandFailure(ExitCodes.USAGE, e.getMessage(), e);
        }
        FiducialTracker.runOnCallingThread();
        ArFeed feed = new ArFeed(frames, ArSession.of(new FiducialTracker(config, k)));
        AppOptions options = new AppOptions(file, window.method, RotationInterpolation.SLERP, true,
                DrawSettings.View.SHADED, DifferenceScale.DEFAULT, null, null, false, 0,
                AppOptions.DEFAULT_PITCH_DEGREES, window.screenshot, window.size.width(), window.size.height(),
                window.hideUi, window.script, exitAfterFrames, false);
        return SkinlabApp.run(options, new ArSetup(feed, k, markerSizeMm / 1000), spec.commandLine().getOut(),
                spec.commandLine().getErr());
    }
}
