package org.skinlab.desktop.cli;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import boofcv.struct.calib.CameraPinholeBrown;

import org.skinlab.ar.BoofCameras;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;
import org.skinlab.desktop.ar.DemoVideo;
import org.skinlab.desktop.ar.GrayImages;
import org.skinlab.desktop.ar.IntrinsicsFile;

/**
 * The frames {@code skinlab bench track} times, with their camera: the synthetic demo video, or a
 * folder of a real video's frames (optionally resampled, the camera with them).
 *
 * @param name   what the report calls them
 * @param frames the frames, all of the camera's size
 * @param camera their camera
 */
record TrackBenchVideo(String name, List<GrayImage> frames, CameraIntrinsics camera) {

    /** {@code count} frames of {@link DemoVideo} at 640x480 with a 60 degree field of view. */
    static TrackBenchVideo synthetic(int count) {
        CameraIntrinsics k = CameraIntrinsics.fromHorizontalFov(640, 480, 60);
        DemoVideo demo = new DemoVideo(k, count);
        List<GrayImage> frames = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            frames.add(demo.frame(i));
        }
        return new TrackBenchVideo(count + " synthetic 640x480 frames (skinlab ar-demo's video)", frames, k);
    }

    /**
     * The images of {@code dir} in name order; the camera from {@code intrinsics} (our JSON, or
     * BoofCV's intrinsic.yaml with its lens) or a 60 degree field of view; resampled to
     * {@code width x height} when those are positive.
     */
    static TrackBenchVideo images(Path dir, Path intrinsics, int width, int height) throws IOException {
        List<GrayImage> frames = new ArrayList<>();
        for (Path file : GrayImages.list(dir)) {
            frames.add(GrayImages.read(file));
        }
        GrayImage first = frames.get(0);
        for (int i = 1; i < frames.size(); i++) {
            if (frames.get(i).width() != first.width() || frames.get(i).height() != first.height()) {
                throw new IllegalArgumentException(dir + ": frame " + i + " is " + frames.get(i).width() + "x"
                        + frames.get(i).height() + ", the first " + first.width() + "x" + first.height());
            }
        }
        CameraIntrinsics k;
        if (intrinsics == null) {
            k = CameraIntrinsics.fromHorizontalFov(first.width(), first.height(), 60);
        } else {
            String file = intrinsics.getFileName().toString().toLowerCase(Locale.ROOT);
            boolean yaml = file.endsWith(".yaml") || file.endsWith(".yml");
            k = yaml ? boofYaml(intrinsics) : IntrinsicsFile.read(intrinsics);
            k = IntrinsicsFile.forImage(k, first.width(), first.height(), dir.toString());
        }
        String name = frames.size() + " frames of " + dir.getFileName() + " (" + first.width() + "x" + first.height();
        if (width > 0 && height > 0 && (width != first.width() || height != first.height())) {
            frames.replaceAll(g -> GrayImages.scaled(g, width, height));
            k = k.scaledTo(width, height);
            name += ", resampled to " + width + "x" + height;
        }
        return new TrackBenchVideo(name + ")", frames, k);
    }

    /**
     * The pinhole and radial-tangential terms of BoofCV's intrinsic.yaml, read line by line:
     * enough for the calibrated videos of BoofCV-Data, not a YAML parser.
     */
    private static CameraIntrinsics boofYaml(Path file) throws IOException {
        CameraPinholeBrown c = new CameraPinholeBrown(2);
        List<Double> radial = new ArrayList<>();
        boolean inRadial = false;
        for (String raw : Files.readAllLines(file, StandardCharsets.UTF_8)) {
            String line = raw.strip();
            if (inRadial && line.startsWith("- ")) {
                radial.add(number(file, "radial", line.substring(2)));
                continue;
            }
            inRadial = line.equals("radial:");
            int colon = line.indexOf(':');
            if (colon < 0 || line.startsWith("#")) {
                continue;
            }
            String key = line.substring(0, colon).strip();
            String value = line.substring(colon + 1).strip();
            switch (key) {
                case "fx" -> c.fx = number(file, key, value);
                case "fy" -> c.fy = number(file, key, value);
                case "cx" -> c.cx = number(file, key, value);
                case "cy" -> c.cy = number(file, key, value);
                case "skew" -> c.skew = number(file, key, value);
                case "width" -> c.width = (int) number(file, key, value);
                case "height" -> c.height = (int) number(file, key, value);
                case "t1" -> c.t1 = number(file, key, value);
                case "t2" -> c.t2 = number(file, key, value);
                default -> { }
            }
        }
        if (c.fx <= 0 || c.fy <= 0 || c.width <= 0 || c.height <= 0) {
            throw new IllegalArgumentException(file + ": no pinhole fx, fy, width and height");
        }
        c.radial = radial.stream().mapToDouble(Double::doubleValue).toArray();
        return BoofCameras.fromBoof(c);
    }

    private static double number(Path file, String key, String value) {
        try {
            return Double.parseDouble(value);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(file + ": \"" + key + "\" is not a number: " + value);
        }
    }
}
