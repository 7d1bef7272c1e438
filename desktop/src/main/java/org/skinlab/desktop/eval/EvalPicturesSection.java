package org.skinlab.desktop.eval;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import javax.imageio.ImageIO;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.desktop.ModelFileSearch;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;

/**
 * Section "pictures": every method at each asset's extreme pose, beside the rest pose, and the
 * difference view, as the viewer draws them ({@code skinlab view --screenshot}, a child JVM per
 * picture: {@link ViewerProcess} says why). The surface carries the viewer's checker pattern,
 * fixed to the rest shape, so a twist shows; the pose and the camera come from the data
 * ({@link PicturePose}); the difference view's colour scale is the asset's own (red at the largest
 * LBS-DQS distance of the pose), with its colour bar. For the whole-turn cylinders, LBS and DQS at
 * angles either side of a half turn ({@link #STRIP_DEGREES}, the clip times the quality section
 * found). Measured in the pictures ({@link PanelPixels}): each panel's coverage, the share of
 * the model's pixels that differ between LBS and DQS and between DQS and CoR, and a control at the
 * bind pose, where the methods agree.
 *
 * <p>The pictures are not numbers for results.json: {@link #measure} keeps them for
 * {@link #report} of the same run; a report written again from results.json alone links the
 * figures already in the folder.
 */
final class EvalPicturesSection implements EvalSection {
    private static final String QUICK = "assets/cylinders/cylinder-twist-high.dae";
    /** The angles of the whole-turn strips (those the quality section measures at). */
    static final double[] STRIP_DEGREES = {90, 170, 190, 270, 360};
    private static final double[] QUICK_STRIP_DEGREES = {170, 190};
    /** Which assets get a strip: the whole-turn cylinders. */
    private static final String STRIP_KIND = "-full";
    /** An asset's panels: their keys in results, in the sheet's order. */
    private static final List<String> PANELS = List.of("rest", "lbs", "dqs", "cor", "bfdqs", "stbs-lbs", "stbs-dqs",
            "spline", "difference");
    private static final List<String> LABELS = List.of("rest (bind pose)", "LBS (linear blend)",
            "DQS (dual quaternions)", "CoR (centres of rotation)", "BFDQS (bulge-free DQS)",
            "STBS on LBS (stretch, twist)", "STBS on DQS", "spline skinning", "LBS shape coloured by |LBS - DQS|");

    /** Each asset's panels (in {@link #PANELS} order) and strips from the last {@link #measure}, by file name. */
    private final Map<String, List<BufferedImage>> pictures = new HashMap<>();
    private final Map<String, List<BufferedImage>> strips = new HashMap<>();
    private ViewerProcess viewer;

    @Override
    public String key() {
        return "pictures";
    }

    @Override
    public String title() {
        return "Pictures";
    }

    @Override
    public double estimatedSeconds(EvalContext context) {
        // About 3 s a child JVM here: 6 per asset, the control and the strips.
        return context.quick() ? 30 : 270;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        pictures.clear();
        strips.clear();
        viewer = context.viewer();
        boolean quick = context.quick();
        int width = quick ? 400 : 480;
        int height = quick ? 300 : 360;
        int perSecond = quick ? EvalQualitySection.QUICK_SAMPLES_PER_SECOND : EvalQualitySection.SAMPLES_PER_SECOND;
        results.put("panelWidth", width);
        results.put("panelHeight", height);
        results.put("samplesPerSecond", perSecond);
        results.put("pixelTolerance", PanelPixels.TOLERANCE);
        results.put("levelAxis", PicturePose.LEVEL);
        if (!ViewerProcess.displayAvailable()) {
            results.put("skipped", "no display (DISPLAY and WAYLAND_DISPLAY are unset), so the viewer cannot draw;"
                    + " run the evaluation under xvfb-run");
            context.say("pictures skipped: no display");
            return;
        }
        List<Path> files = files(context, quick, results);
        List<Path> stripFiles = files.stream().filter(f -> f.getFileName().toString().contains(STRIP_KIND))
                .toList();
        Path work = temporaryFolder();
        try {
            int steps = files.size() + stripFiles.size() + 1;
            int[] done = {0};
            ArrayNode assets = results.putArray("assets");
            for (Path file : files) {
                new PictureAsset(viewer, file, width, height, work).draw(perSecond, assets.addObject(), pictures);
                context.progress((double) ++done[0] / steps);
            }
            control(files.get(0), width, height, work, results.putObject("control"));
            context.progress((double) ++done[0] / steps);
            ArrayNode stripNodes = results.putArray("strips");
            for (Path file : stripFiles) {
                strip(context, file, quick ? QUICK_STRIP_DEGREES : STRIP_DEGREES, width, height, work,
                        stripNodes.addObject());
                context.progress((double) ++done[0] / steps);
            }
        } finally {
            delete(work);
        }
    }

    /** Every skinned asset of ours and the corpus' characters (quick: one cylinder and the whole-turn twist). */
    private static List<Path> files(EvalContext context, boolean quick, ObjectNode results) {
        List<Path> files = new ArrayList<>();
        ArrayNode skipped = results.putArray("corpusSkipped");
        if (quick) {
            files.add(context.root().resolve(QUICK));
            Path full = context.root().resolve("assets/cylinders/cylinder-twist-full.dae");
            if (Files.isRegularFile(full)) {
                files.add(full);
            }
            return files;
        }
        for (ModelFileSearch.Entry e : ModelFileSearch.expand(List.of(context.root().resolve("assets")),
                ModelFileSearch.COLLADA)) {
            Model model = ModelFiles.load(e.path()).model;
            if (model.instances().stream().anyMatch(MeshInstance::isSkinned) && !model.clips().isEmpty()) {
                files.add(e.path());
            }
        }
        for (String name : EvalTimeSection.CORPUS) {
            Path f = context.corpus() == null ? null : context.corpus().resolve(name);
            if (f != null && Files.isRegularFile(f)) {
                files.add(f);
            } else {
                skipped.add(name + ": not in the shared corpus at " + context.corpusPlace());
            }
        }
        return files;
    }

    /** LBS against DQS at the bind pose, where both place every point alike. */
    private void control(Path file, int width, int height, Path work, ObjectNode control) {
        control.put("file", file.getFileName().toString());
        control.put("maxLbsDqsPercent", EvalReport.round(100 * PicturePose.bindPose(ModelFiles.load(file).model)));
        List<BufferedImage> split = PictureAsset.render(viewer, file, List.of("--bind-pose", "--view", "checker",
                "--method", "lbs", "--split", "dqs"), 2 * width, height, work.resolve("control.png"), control);
        if (split != null) {
            boolean[] lbs = PanelPixels.model(split.get(0));
            boolean[] dqs = PanelPixels.model(split.get(1));
            control.put("lbsCoveragePercent", EvalReport.round(PanelPixels.coveragePercent(lbs)));
            control.put("lbsDqsPixelsPercent", EvalReport.round(PanelPixels.differingPercent(split.get(0), lbs,
                    split.get(1), dqs)));
        }
    }

    /** LBS and DQS at each of {@code degrees}, at the clip times the quality section found for them. */
    private void strip(EvalContext context, Path file, double[] degrees, int width, int height, Path work,
            ObjectNode node) {
        String name = file.getFileName().toString();
        node.put("file", name);
        JsonNode quality = context.measured("quality");
        JsonNode asset = null;
        for (JsonNode a : quality == null ? List.<JsonNode>of() : quality.path("assets")) {
            asset = a.get("file").asText().equals(name) ? a : asset;
        }
        if (asset == null) {
            node.put("skipped", "the quality section, which finds the clip time of each angle, was not run");
            return;
        }
        PicturePose pose = PicturePose.of(ModelFiles.load(file).model, EvalQualitySection.QUICK_SAMPLES_PER_SECOND);
        node.put("yawDegrees", EvalReport.round(pose.yawDegrees()));
        node.put("rule", pose.rule());
        ArrayNode angles = node.putArray("angles");
        List<BufferedImage> lbs = new ArrayList<>();
        List<BufferedImage> dqs = new ArrayList<>();
        for (double d : degrees) {
            JsonNode at = EvalAdviceInputs.atAngle(asset, d);
            if (at == null) {
                continue;
            }
            ObjectNode a = angles.addObject().put("angleDegrees", d).put("time", at.get("time").asDouble());
            List<BufferedImage> split = PictureAsset.render(viewer, file, List.of("--view", "checker", "--method",
                    "lbs", "--split", "dqs", "--time", ViewerProcess.seconds(at.get("time").asDouble()), "--yaw",
                    ViewerProcess.seconds(pose.yawDegrees())), 2 * width, height, work.resolve("strip.png"), a);
            if (split == null) {
                return;
            }
            lbs.add(split.get(0));
            dqs.add(split.get(1));
        }
        List<BufferedImage> panels = new ArrayList<>(lbs);
        panels.addAll(dqs);
        strips.put(name, panels);
    }

    private static Path temporaryFolder() {
        try {
            return Files.createTempDirectory("skinlab-pictures");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot create a temporary folder for the pictures", e);
        }
    }

    private static void delete(Path dir) {
        try (Stream<Path> files = Files.walk(dir)) {
            files.sorted(Comparator.reverseOrder()).forEach(p -> p.toFile().delete());
        } catch (IOException e) {
            // a temporary folder left behind: nothing to report
        }
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        if (results.has("skipped")) {
            report.paragraph("Skipped: " + results.get("skipped").asText() + ".");
            return;
        }
        EvalPicturesReport.introduce(results, report);
        for (JsonNode s : results.get("corpusSkipped")) {
            report.paragraph("Skipped: `" + s.asText() + "`.");
        }
        EvalPicturesReport.table(results, report);
        EvalPicturesReport.control(results.get("control"), report);
        JsonNode assets = results.get("assets");
        for (int a = 0; a < assets.size(); a++) {
            JsonNode asset = assets.get(a);
            if (asset.has("skipped")) {
                continue;
            }
            String file = asset.get("file").asText();
            String png = "pictures-" + EvalQualityReport.stem(file) + ".png";
            String caption = "The rest pose, every method at the extreme pose, and the LBS-DQS difference, " + file;
            List<BufferedImage> panels = pictures.get(file);
            if (panels == null) {
                report.existing(png, caption);
                continue;
            }
            List<BufferedImage> shown = new ArrayList<>(panels);
            int last = shown.size() - 1;
            shown.set(last, PictureSheet.withColourBar(shown.get(last), "0 %",
                    EvalReport.format(asset.get("differenceScalePercent")) + " %"));
            report.image(png, caption, PictureSheet.grid(EvalPicturesReport.title(asset), shown, LABELS, 3));
        }
        JsonNode stripNodes = results.get("strips");
        for (int s = 0; s < stripNodes.size(); s++) {
            EvalPicturesReport.strip(results, s, strips.get(stripNodes.get(s).get("file").asText()), report);
        }
        pictures.clear();
        strips.clear();
    }

    /** The panels' keys in order (for the report's table). */
    static List<String> panels() {
        return PANELS;
    }

    /** Reads a viewer's picture back; null when it cannot be read. */
    static BufferedImage read(Path png) {
        try {
            return ImageIO.read(png.toFile());
        } catch (IOException e) {
            return null;
        }
    }
}
