package org.skinlab.desktop.eval;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.render.DrawSettings;

/**
 * One asset's pictures for the pictures section: the rest pose, every method at the extreme
 * pose in the checker view (two methods a picture where the viewer splits its view: one frame,
 * one camera) and the difference view at the asset's own scale, with the numbers measured in
 * them.
 */
final class PictureAsset {
    /** The viewer's pictures of an asset: the panels each holds, and the arguments (besides the pose). */
    private static final List<List<String>> SHOTS = List.of(
            List.of("--bind-pose", "--view", "checker", "--method", "lbs"),
            List.of("--view", "checker", "--method", "lbs", "--split", "dqs"),
            List.of("--view", "checker", "--method", "cor", "--split", "bfdqs"),
            List.of("--view", "checker", "--method", "stbs-lbs", "--split", "stbs-dqs"),
            List.of("--view", "checker", "--method", "spline"));

    private final ViewerProcess viewer;
    private final Path file;
    private final int width;
    private final int height;
    private final Path work;

    PictureAsset(ViewerProcess viewer, Path file, int width, int height, Path work) {
        this.viewer = viewer;
        this.file = file;
        this.width = width;
        this.height = height;
        this.work = work;
    }

    /** Draws the asset into {@code panels} (by file name) and its numbers into {@code asset}. */
    void draw(int perSecond, ObjectNode asset, Map<String, List<BufferedImage>> panels) {
        String name = file.getFileName().toString();
        asset.put("file", name);
        PicturePose pose = PicturePose.of(ModelFiles.load(file).model, perSecond);
        asset.put("clipSeconds", EvalReport.round(pose.clipSeconds()));
        asset.put("time", EvalReport.round(pose.elapsed()));
        asset.put("maxLbsDqsPercent", EvalReport.round(100 * pose.relative()));
        asset.put("yawDegrees", EvalReport.round(pose.yawDegrees()));
        asset.put("rule", pose.rule());
        // Red at the pose's own largest distance, so the whole scale is used; the viewer's default without one.
        double scale = pose.relative() > 0 ? roundUp(100 * pose.relative()) : 100 * DrawSettings.DIFFERENCE_FULL;
        asset.put("differenceScalePercent", scale);
        List<String> at = List.of("--time", ViewerProcess.seconds(pose.elapsed()), "--yaw",
                ViewerProcess.seconds(pose.yawDegrees()));
        long start = System.nanoTime();
        List<BufferedImage> drawn = new ArrayList<>();
        for (List<String> shot : SHOTS) {
            List<String> arguments = new ArrayList<>(shot);
            if (!shot.contains("--bind-pose")) {
                arguments.addAll(at);
            }
            List<BufferedImage> images = render(viewer, file, arguments, shot.contains("--split") ? 2 * width : width,
                    height, work.resolve("shot.png"), asset);
            if (images == null) {
                return;
            }
            drawn.addAll(images);
        }
        List<String> difference = new ArrayList<>(List.of("--view", "difference", "--method", "lbs",
                "--difference-scale", EvalReport.format(asset.get("differenceScalePercent"))));
        difference.addAll(at);
        List<BufferedImage> images = render(viewer, file, difference, width, height, work.resolve("shot.png"), asset);
        if (images == null) {
            return;
        }
        drawn.addAll(images);
        asset.put("renderSeconds", EvalReport.round((System.nanoTime() - start) / 1e9));
        measure(drawn, asset);
        panels.put(name, drawn);
    }

    /** Coverage per panel, and the model's pixels that differ between LBS and DQS, and DQS and CoR. */
    private static void measure(List<BufferedImage> drawn, ObjectNode asset) {
        List<String> keys = EvalPicturesSection.panels();
        boolean[][] models = new boolean[drawn.size()][];
        ObjectNode coverage = asset.putObject("coveragePercent");
        for (int i = 0; i < drawn.size(); i++) {
            models[i] = PanelPixels.model(drawn.get(i));
            coverage.put(keys.get(i), EvalReport.round(PanelPixels.coveragePercent(models[i])));
        }
        int lbs = keys.indexOf("lbs");
        int dqs = keys.indexOf("dqs");
        int cor = keys.indexOf("cor");
        int rest = keys.indexOf("rest");
        asset.put("lbsDqsPixelsPercent", EvalReport.round(PanelPixels.differingPercent(drawn.get(lbs), models[lbs],
                drawn.get(dqs), models[dqs])));
        asset.put("dqsCorPixelsPercent", EvalReport.round(PanelPixels.differingPercent(drawn.get(dqs), models[dqs],
                drawn.get(cor), models[cor])));
        asset.put("restDqsPixelsPercent", EvalReport.round(PanelPixels.differingPercent(drawn.get(rest),
                models[rest], drawn.get(dqs), models[dqs])));
    }

    /** Two significant digits, rounded up: a scale whose red is at or just beyond the largest distance. */
    static double roundUp(double percent) {
        double magnitude = Math.pow(10, Math.floor(Math.log10(percent)) - 1);
        return EvalReport.round(Math.ceil(percent / magnitude - 1e-9) * magnitude);
    }

    /**
     * The viewer's picture, cut into its halves when {@code width} holds a split view's two; null
     * (and the reason in {@code node}'s "skipped") when the viewer wrote none.
     */
    static List<BufferedImage> render(ViewerProcess viewer, Path file, List<String> arguments, int width, int height,
            Path png, ObjectNode node) {
        String failed = viewer.screenshot(file, arguments, width, height, png);
        BufferedImage image = failed == null ? EvalPicturesSection.read(png) : null;
        if (image == null) {
            node.put("skipped", failed != null ? failed : "the viewer's picture is not a PNG");
            return null;
        }
        if (!arguments.contains("--split")) {
            return List.of(image);
        }
        int half = image.getWidth() / 2;
        return List.of(image.getSubimage(0, 0, half, image.getHeight()),
                image.getSubimage(half, 0, image.getWidth() - half, image.getHeight()));
    }
}
