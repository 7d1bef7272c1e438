package org.skinlab.desktop.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.FiducialTracker;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.MarkerDetection;
import org.skinlab.ar.MarkerDictionary;
import org.skinlab.ar.TrackerConfig;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ar.GrayImages;
import org.skinlab.desktop.ar.IntrinsicsFile;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code skinlab track}: the marker tracker on a folder of images, written as JSON other tools
 * score (docs/ar.md, "skinlab track"). Each image is searched whole ({@link FiducialTracker#detect}),
 * independently of the others; with {@code --sequence} the images are the frames of a video, in
 * name order, and each is searched near the markers of the frame before first
 * ({@link FiducialTracker#track}), as the AR view does. The JSON is the same either way, each
 * frame's {@code millis} the time of its search.
 */
@Command(name = "track", mixinStandardHelpOptions = true,
        description = "Find the markers in a folder of images and write their ids, corners and poses as JSON.")
public final class TrackCommand implements Callable<Integer> {
    @Spec
    CommandSpec spec;

    @Option(names = "--images", required = true, paramLabel = "DIR", description = "folder of .png/.jpg images, read in name order")
    Path images;

    @Option(names = "--intrinsics", paramLabel = "FILE",
            description = "camera intrinsics: our JSON {\"width\",\"height\",\"fx\",\"fy\",\"cx\",\"cy\"[,\"k1\",\"k2\",\"k3\",\"p1\",\"p2\"]}, OpenCV's calibration YAML/XML or BoofCV's intrinsic.yaml (scaled to images of the same aspect)")
    Path intrinsics;

    @Option(names = "--fov", paramLabel = "DEG", description = "without --intrinsics: the horizontal field of view (default: ${DEFAULT-VALUE})")
    double fov = 60;

    @Option(names = "--marker-size", required = true, paramLabel = "MM", description = "the printed black square's width in mm")
    double markerSizeMm;

    @Option(names = "--dictionary", paramLabel = "NAME", description = "marker dictionary (default: aruco_mip_36h12)")
    String dictionary = MarkerDictionary.DEFAULT.key();

    @Option(names = "--id", paramLabel = "N", description = "report only this marker id (default: every id)")
    int id = -1;

    @Option(names = "--sequence",
            description = "the images are a video's frames in name order: search near the last markers first")
    boolean sequence;

    @Option(names = "--json", required = true, paramLabel = "OUT", description = "where to write the JSON ('-' for standard output)")
    String json;

    @Override
    public Integer call() throws IOException {
        List<Path> files;
        TrackerConfig config;
        CameraIntrinsics given;
        try {
            files = GrayImages.list(images);
            config = TrackerConfig.of(MarkerDictionary.byName(dictionary), markerSizeMm / 1000).withTargetId(id);
            given = intrinsics != null ? IntrinsicsFile.read(intrinsics) : null;
        } catch (IllegalArgumentException | IOException e) {
            throw new CommandFailure(ExitCodes.USAGE, e.getMessage(), e);
        }
        if (sequence) {
            FiducialTracker.runOnCallingThread();
        }
        ObjectMapper mapper = new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT);
        ObjectNode root = mapper.createObjectNode();
        ArrayNode frames = root.putArray("frames");
        FiducialTracker tracker = null;
        for (Path file : files) {
            GrayImage image;
            try {
                image = GrayImages.read(file);
            } catch (IllegalArgumentException e) {
                throw new CommandFailure(ExitCodes.INVALID_FILE, e.getMessage(), e);
            }
            if (tracker == null || tracker.intrinsics().width() != image.width()
                    || tracker.intrinsics().height() != image.height()) {
                CameraIntrinsics k;
                try {
                    k = given != null ? IntrinsicsFile.forImage(given, image.width(), image.height(), file.toString())
                            : CameraIntrinsics.fromHorizontalFov(image.width(), image.height(), fov);
                } catch (IllegalArgumentException e) {
                    throw new CommandFailure(ExitCodes.INVALID_FILE, e.getMessage(), e);
                }
                tracker = new FiducialTracker(config, k);
            }
            long start = System.nanoTime();
            List<MarkerDetection> found = sequence ? tracker.track(image) : tracker.detect(image);
            double millis = (System.nanoTime() - start) * 1e-6;
            TrackJson.addFrame(frames, file.getFileName().toString(), millis, found);
        }
        String text = mapper.writeValueAsString(root) + "\n";
        if ("-".equals(json)) {
            spec.commandLine().getOut().print(text);
            spec.commandLine().getOut().flush();
        } else {
            Path out = Path.of(json);
            if (out.getParent() != null) {
                Files.createDirectories(out.getParent());
            }
            Files.writeString(out, text);
        }
        return ExitCodes.OK;
    }
}
