package org.skinlab.desktop.eval;

import java.awt.Color;
import java.awt.Font;
import java.awt.Graphics2D;
import java.awt.RenderingHints;
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

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.model.Model;
import org.skinlab.skinning.InfluenceCapError;
import org.skinlab.skinning.MethodComparison;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedModel;

/**
 * Section "pictures": each method at each asset's extreme pose, side by side, and the difference
 * view, as the viewer draws them. The pose is chosen from the data: the time of the first clip
 * (sampled as the quality section samples it) at which the largest distance between LBS and DQS
 * over the model's size ({@link MethodComparison}, what the viewer's difference view measures) is
 * largest; the camera turns around the model ({@code --yaw}) until the point furthest apart moves
 * square to its view, so the difference shows in the outline. The pictures are the viewer's own headless screenshots ({@code skinlab view
 * --screenshot}, in a child JVM each: {@link ViewerProcess} says why): LBS and DQS in one split
 * view (one frame, one camera), CoR, and the difference view (the LBS shape coloured by each
 * point's LBS-DQS distance). Measured per picture: the model's coverage and, between the LBS and
 * DQS pictures (and DQS and CoR), the share of the model's pixels that differ ({@link
 * PanelPixels}); as a control, the same for LBS and DQS at the first asset's bind pose, where the
 * methods agree.
 *
 * <p>The pictures themselves are not numbers for results.json: {@link #measure} keeps them for
 * {@link #report} of the same run, which composes each asset's into one figure and takes every
 * number from the results.
 */
final class EvalPicturesSection implements EvalSection {
    private static final List<String> QUICK = List.of("assets/cylinders/cylinder-twist-high.dae",
            "assets/characters/humanoid-walk.dae");
    private static final List<String> FULL = List.of("assets/cylinders/cylinder-twist-high.dae",
            "assets/cylinders/cylinder-bend.dae", "assets/characters/humanoid-walk.dae",
            "assets/creatures/tentacle-wave.dae", "assets/cylinders/cylinder-twist-low.dae");
    private static final String COWBOY = "S01_cowboy.dae";
    /** The panels of a figure, in order: results keys and labels. */
    private static final List<String> PANELS = List.of("lbs", "dqs", "cor", "difference");
    private static final int TITLE_HEIGHT = 30;
    private static final int LABEL_LINE = 20;
    private static final int GAP = 6;

    /** Each asset's panels (in {@link #PANELS} order) from the last {@link #measure}, by file name. */
    private final Map<String, BufferedImage[]> pictures = new HashMap<>();
    /** Draws the pictures; the last {@link #measure}'s. */
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
        // About 3 s a child JVM here: 3 per asset and the control (7 quick, 19 full).
        return context.quick() ? 18 : 60;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        pictures.clear();
        viewer = context.viewer();
        boolean quick = context.quick();
        int width = quick ? 480 : 640;
        int height = quick ? 360 : 480;
        results.put("panelWidth", width);
        results.put("panelHeight", height);
        if (quick) {
            results.put("samplesPerClip", EvalQualitySection.QUICK_SAMPLES);
        } else {
            results.put("samplesPerSecond", InfluenceCapError.SAMPLES_PER_SECOND);
        }
        results.put("differenceFullPercent", EvalReport.round(100 * DrawSettings.DIFFERENCE_FULL));
        results.put("pixelTolerance", PanelPixels.TOLERANCE);
        if (!ViewerProcess.displayAvailable()) {
            results.put("skipped", "no display (DISPLAY and WAYLAND_DISPLAY are unset), so the viewer cannot draw;"
                    + " run the evaluation under xvfb-run");
            context.say("pictures skipped: no display");
            return;
        }
        List<Path> files = new ArrayList<>();
        for (String f : quick ? QUICK : FULL) {
            files.add(context.root().resolve(f));
        }
        String cowboySkipped = null;
        if (!quick) {
            Path cowboy = context.corpus() == null ? null : context.corpus().resolve(COWBOY);
            if (cowboy != null && Files.isRegularFile(cowboy)) {
                files.add(cowboy);
            } else {
                cowboySkipped = "the shared corpus is absent (looked for " + context.corpusPlace().resolve(COWBOY)
                        + ")";
                context.say("pictures: " + COWBOY + " skipped: " + cowboySkipped);
            }
        }
        Path work;
        try {
            work = Files.createTempDirectory("skinlab-pictures");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot create a temporary folder for the pictures", e);
        }
        try {
            int steps = 3 * files.size() + 1;
            int[] done = {0};
            Runnable step = () -> context.progress((double) ++done[0] / steps);
            ArrayNode assets = results.putArray("assets");
            for (Path file : files) {
                asset(file, quick, width, height, work, assets.addObject(), step);
            }
            if (cowboySkipped != null) {
                assets.addObject().put("file", COWBOY).put("skipped", cowboySkipped);
            }
            control(files.get(0), width, height, work, results.putObject("control"));
            step.run();
        } finally {
            delete(work);
        }
    }

    private void asset(Path file, boolean quick, int width, int height, Path work, ObjectNode asset, Runnable step) {
        String name = file.getFileName().toString();
        asset.put("file", name);
        Model model = ModelFiles.load(file).model;
        Extreme extreme = extremePose(model, quick);
        asset.put("clipSeconds", EvalReport.round(extreme.clipSeconds));
        asset.put("time", EvalReport.round(extreme.elapsed));
        asset.put("maxLbsDqsPercent", EvalReport.round(100 * extreme.relative));
        asset.put("yawDegrees", EvalReport.round(extreme.yawDegrees));
        List<String> pose = List.of("--time", ViewerProcess.seconds(asset.get("time").asDouble()), "--yaw",
                ViewerProcess.seconds(asset.get("yawDegrees").asDouble()));
        long start = System.nanoTime();
        BufferedImage[] split = render(file, with(pose, "--method", "lbs", "--split", "dqs"), 2 * width, height,
                work.resolve("split.png"), asset);
        step.run();
        BufferedImage[] cor = split == null ? null : render(file, with(pose, "--method", "cor"), width, height,
                work.resolve("cor.png"), asset);
        step.run();
        BufferedImage[] difference = cor == null ? null : render(file, with(pose, "--method", "lbs", "--view",
                "difference"), width, height, work.resolve("difference.png"), asset);
        step.run();
        if (difference == null) {
            return;
        }
        asset.put("renderSeconds", EvalReport.round((System.nanoTime() - start) / 1e9));
        BufferedImage[] panels = {split[0], split[1], cor[0], difference[0]};
        boolean[][] models = new boolean[panels.length][];
        ObjectNode coverage = asset.putObject("coveragePercent");
        for (int i = 0; i < panels.length; i++) {
            models[i] = PanelPixels.model(panels[i]);
            coverage.put(PANELS.get(i), EvalReport.round(PanelPixels.coveragePercent(models[i])));
        }
        asset.put("lbsDqsPixelsPercent",
                EvalReport.round(PanelPixels.differingPercent(panels[0], models[0], panels[1], models[1])));
        asset.put("dqsCorPixelsPercent",
                EvalReport.round(PanelPixels.differingPercent(panels[1], models[1], panels[2], models[2])));
        pictures.put(name, panels);
    }

    private static List<String> with(List<String> pose, String... more) {
        List<String> all = new ArrayList<>(List.of(more));
        all.addAll(pose);
        return all;
    }

    /** LBS against DQS at the bind pose (time 0), where both place every point alike. */
    private void control(Path file, int width, int height, Path work, ObjectNode control) {
        control.put("file", file.getFileName().toString());
        control.put("time", 0);
        Model model = ModelFiles.load(file).model;
        control.put("maxLbsDqsPercent", EvalReport.round(100 * lbsDqsAt(model, 0f)));
        BufferedImage[] split = render(file, List.of("--method", "lbs", "--split", "dqs", "--time", "0"), 2 * width,
                height, work.resolve("control.png"), control);
        if (split != null) {
            boolean[] lbs = PanelPixels.model(split[0]);
            boolean[] dqs = PanelPixels.model(split[1]);
            control.put("lbsCoveragePercent", EvalReport.round(PanelPixels.coveragePercent(lbs)));
            control.put("lbsDqsPixelsPercent", EvalReport.round(PanelPixels.differingPercent(split[0], lbs, split[1],
                    dqs)));
        }
    }

    /**
     * The viewer's picture, cut into its halves when {@code width} holds a split view's two; null
     * (and the reason in {@code node}'s "skipped") when the viewer wrote none.
     */
    private BufferedImage[] render(Path file, List<String> arguments, int width, int height, Path png,
            ObjectNode node) {
        String failed = viewer.screenshot(file, arguments, width, height, png);
        BufferedImage image = null;
        if (failed == null) {
            try {
                image = ImageIO.read(png.toFile());
            } catch (IOException e) {
                failed = "the viewer's picture cannot be read: " + e.getMessage();
            }
        }
        if (image == null) {
            node.put("skipped", failed != null ? failed : "the viewer's picture is not a PNG");
            return null;
        }
        boolean split = arguments.contains("--split");
        if (!split) {
            return new BufferedImage[] {image};
        }
        int half = image.getWidth() / 2;
        return new BufferedImage[] {image.getSubimage(0, 0, half, image.getHeight()),
            image.getSubimage(half, 0, image.getWidth() - half, image.getHeight())};
    }

    /**
     * The sample of the first clip where LBS and DQS lie furthest apart: its time from the clip's
     * start, that distance over the model's size, the clip's length, and the yaw the camera looks
     * from so that the largest displacement lies across its view (shows in the silhouette).
     */
    private record Extreme(double elapsed, double relative, double clipSeconds, double yawDegrees) {
    }

    private static Extreme extremePose(Model model, boolean quick) {
        SkinnedModel skinned = new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0),
                NormalTransform.INVERSE_TRANSPOSE);
        float start = skinned.sampler().start();
        float end = skinned.sampler().end();
        float bestTime = start;
        double best = -1;
        List<MethodComparison> comparisons = comparisons(skinned);
        for (float t : EvalQualitySection.times(start, end, quick)) {
            double d = lbsDqs(skinned, comparisons, t);
            if (d > best) {
                best = d;
                bestTime = t;
            }
        }
        lbsDqs(skinned, comparisons, bestTime);
        return new Extreme(bestTime - start, Math.max(0, best), end - start, yawAcross(model, comparisons));
    }

    /**
     * The camera yaw (degrees, as {@code skinlab view --yaw} takes it, within 90 of the front) whose
     * view direction is square to the largest LBS-DQS displacement of the pose the comparisons
     * last measured, in the scene's Y-up frame; 0 when that displacement is vertical or none.
     */
    private static double yawAcross(Model model, List<MethodComparison> comparisons) {
        MethodComparison widest = null;
        for (MethodComparison c : comparisons) {
            if (widest == null || c.maxDistance() > widest.maxDistance()) {
                widest = c;
            }
        }
        if (widest == null || !(widest.maxDistance() > 0)) {
            return 0;
        }
        float[] d = widest.distances();
        int far = 0;
        for (int i = 1; i < d.length; i++) {
            if (d[i] > d[far]) {
                far = i;
            }
        }
        float[] lbs = widest.lbsPositions();
        float[] dqs = widest.dqsPositions();
        Vector3f v = new Vector3f(dqs[3 * far] - lbs[3 * far], dqs[3 * far + 1] - lbs[3 * far + 1],
                dqs[3 * far + 2] - lbs[3 * far + 2]);
        model.asset().toYUpMeters(new Matrix4f()).transformDirection(v);
        double horizontal = Math.hypot(v.x, v.z);
        if (horizontal < 1e-3 * v.length()) {
            return 0;
        }
        // The eye sits at (sin yaw, cos yaw) around the target: square to v when sin(yaw) v.x + cos(yaw) v.z = 0.
        double yaw = Math.toDegrees(Math.atan2(-v.z, v.x));
        if (yaw > 90) {
            yaw -= 180;
        } else if (yaw <= -90) {
            yaw += 180;
        }
        return yaw;
    }

    private static double lbsDqsAt(Model model, float elapsed) {
        SkinnedModel skinned = new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0),
                NormalTransform.INVERSE_TRANSPOSE);
        return lbsDqs(skinned, comparisons(skinned), skinned.sampler().start() + elapsed);
    }

    private static List<MethodComparison> comparisons(SkinnedModel skinned) {
        List<MethodComparison> comparisons = new ArrayList<>();
        for (int g = 0; g < skinned.geometries().size(); g++) {
            comparisons.add(new MethodComparison(skinned.geometries().get(g)));
        }
        return comparisons;
    }

    /**
     * The largest LBS-DQS distance over all geometries at clip time t, over the largest geometry's
     * size (as the viewer's probe measures it).
     */
    private static double lbsDqs(SkinnedModel skinned, List<MethodComparison> comparisons, float t) {
        skinned.pose(t, RotationInterpolation.SLERP);
        double max = 0;
        double size = 0;
        for (int g = 0; g < comparisons.size(); g++) {
            MethodComparison c = comparisons.get(g);
            c.compare(skinned.palette(g).matrices());
            max = Math.max(max, c.maxDistance());
            size = Math.max(size, c.size());
        }
        return size > 0 ? max / size : 0;
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
        introduce(results, report);
        List<String> skipped = table(results, report);
        report.line("");
        for (String s : skipped) {
            report.paragraph("Skipped " + s + ".");
        }
        controlParagraph(results.get("control"), report);
        sheets(results, report);
        pictures.clear();
    }

    /** What the pictures show and what is measured in them. */
    private static void introduce(JsonNode results, EvalReport report) {
        report.paragraph("Each asset at its extreme pose, drawn by the viewer (`skinlab view --screenshot --hide-ui`,"
                + " a panel of " + EvalReport.num(results, "/panelWidth") + " by " + EvalReport.num(results,
                        "/panelHeight") + " pixels): LBS, DQS, CoR, and the difference view. The pose is the time of"
                + " the first clip, sampled " + (results.has("samplesPerClip") ? EvalReport.num(results,
                        "/samplesPerClip") + " times from start to end" : EvalReport.num(results, "/samplesPerSecond")
                        + " times a second") + ", at which the largest distance between a point's LBS and DQS"
                + " positions, over the model's size, is largest (`MethodComparison`, what the difference view"
                + " measures). The camera turns around the model (`--yaw`) until the point the methods move furthest"
                + " apart moves across its view, so the difference shows in the outline. The difference view draws"
                + " the LBS shape coloured by that distance per point: blue"
                + " for none, through cyan, green and yellow, to red for " + EvalReport.num(results,
                        "/differenceFullPercent") + " % of the model's size or more. Measured in the pictures: the"
                + " share of each panel the model covers, and the share of the model's pixels (in either panel)"
                + " whose colour differs by more than " + EvalReport.num(results, "/pixelTolerance") + " levels"
                + " between LBS and DQS, and between DQS and CoR.");
    }

    /** One row per asset drawn; returns the assets skipped, each with why. */
    private static List<String> table(JsonNode results, EvalReport report) {
        report.header("asset", "time (s)", "clip (s)", "max abs(LBS - DQS) %", "yaw (degrees)", "LBS cover %",
                "DQS cover %",
                "CoR cover %", "difference cover %", "LBS vs DQS pixels %", "DQS vs CoR pixels %");
        JsonNode assets = results.get("assets");
        List<String> skipped = new ArrayList<>();
        for (int a = 0; a < assets.size(); a++) {
            JsonNode asset = assets.get(a);
            String p = "/assets/" + a;
            String file = "`" + asset.get("file").asText() + "`";
            if (asset.has("skipped")) {
                skipped.add(file + ": " + quoted(asset.get("skipped").asText()));
            }
            if (!asset.has("time")) {
                continue;
            }
            report.row(file, EvalReport.num(results, p + "/time"), EvalReport.num(results, p + "/clipSeconds"),
                    EvalReport.num(results, p + "/maxLbsDqsPercent"), EvalReport.num(results, p + "/yawDegrees"),
                    EvalReport.numOrDash(results, p + "/coveragePercent/lbs"),
                    EvalReport.numOrDash(results, p + "/coveragePercent/dqs"),
                    EvalReport.numOrDash(results, p + "/coveragePercent/cor"),
                    EvalReport.numOrDash(results, p + "/coveragePercent/difference"),
                    EvalReport.numOrDash(results, p + "/lbsDqsPixelsPercent"),
                    EvalReport.numOrDash(results, p + "/dqsCorPixelsPercent"));
        }
        return skipped;
    }

    /** The control: LBS against DQS at the bind pose, or why it was skipped. */
    private static void controlParagraph(JsonNode control, EvalReport report) {
        if (control.has("lbsDqsPixelsPercent")) {
            report.paragraph("Control: `" + control.get("file").asText() + "` at time " + EvalReport.num(control,
                    "/time") + " (the bind pose), where LBS and DQS lie " + EvalReport.num(control, "/maxLbsDqsPercent")
                    + " % of the model's size apart at most: their pictures differ in " + EvalReport.num(control,
                            "/lbsDqsPixelsPercent") + " % of the model's pixels (the model covers " + EvalReport.num(
                                    control, "/lbsCoveragePercent") + " % of the LBS panel).");
        } else {
            report.paragraph("Control skipped: " + quoted(control.path("skipped").asText("no picture")) + ".");
        }
    }

    /** Each drawn asset's four panels as one figure. */
    private void sheets(JsonNode results, EvalReport report) {
        JsonNode assets = results.get("assets");
        for (int a = 0; a < assets.size(); a++) {
            JsonNode asset = assets.get(a);
            BufferedImage[] panels = pictures.get(asset.get("file").asText());
            if (!asset.has("coveragePercent")) {
                continue;
            }
            String file = asset.get("file").asText();
            String base = file.replaceAll("\\.dae$", "").replaceAll("[^A-Za-z0-9_-]", "_");
            if (panels == null) {
                // Written from results.json alone: the figure the measuring run drew, if it is there.
                report.keep("pictures-" + base + ".png", "LBS, DQS, CoR and the LBS-DQS difference, " + file);
                continue;
            }
            report.image("pictures-" + base + ".png", "LBS, DQS, CoR and the LBS-DQS difference, " + file,
                    sheet(file + " at " + EvalReport.format(asset.get("time")) + " s of "
                            + EvalReport.format(asset.get("clipSeconds")) + " s: LBS and DQS up to "
                            + EvalReport.format(asset.get("maxLbsDqsPercent"))
                            + " % of the model's size apart (seen from yaw "
                            + EvalReport.format(asset.get("yawDegrees"))
                            + " degrees)", panels, labels(results)));
        }
    }

    /**
     * A reason as a code span: a message from the viewer or the system may hold numbers (a display,
     * a status) that are not results, and the report's numbers are results only.
     */
    private static String quoted(String reason) {
        return "`" + reason.replace('`', '\'') + "`";
    }

    private static String[] labels(JsonNode results) {
        String full = EvalReport.format(results.get("differenceFullPercent"));
        return new String[] {"LBS (linear blend)", "DQS (dual quaternions)", "CoR (centres of rotation)",
            "Difference on the LBS shape: LBS to DQS distance,\nblue 0 ... red " + full
                    + " % of the model's size or more"};
    }

    /** The panels in a row under a title, each under its label. */
    static BufferedImage sheet(String title, BufferedImage[] panels, String[] labels) {
        int w = panels[0].getWidth();
        int h = panels[0].getHeight();
        Font label = new Font(Font.SANS_SERIF, Font.BOLD, 16);
        int lines = 1;
        for (String l : labels) {
            lines = Math.max(lines, l.split("\n").length);
        }
        int labelHeight = LABEL_LINE * lines + 6;
        int top = TITLE_HEIGHT + labelHeight;
        BufferedImage sheet = new BufferedImage(panels.length * w + (panels.length - 1) * GAP, top + h,
                BufferedImage.TYPE_INT_RGB);
        Graphics2D g = sheet.createGraphics();
        try {
            g.setRenderingHint(RenderingHints.KEY_TEXT_ANTIALIASING, RenderingHints.VALUE_TEXT_ANTIALIAS_ON);
            g.setColor(Color.WHITE);
            g.fillRect(0, 0, sheet.getWidth(), sheet.getHeight());
            g.setColor(Color.BLACK);
            g.setFont(new Font(Font.SANS_SERIF, Font.BOLD, 18));
            g.drawString(title, 8, 24);
            g.setFont(label);
            for (int i = 0; i < panels.length; i++) {
                int x = i * (w + GAP);
                g.drawImage(panels[i], x, top, null);
                String[] text = labels[i].split("\n");
                for (int l = 0; l < text.length; l++) {
                    g.drawString(text[l], x + 6, TITLE_HEIGHT + LABEL_LINE * (l + 1) - 4);
                }
            }
        } finally {
            g.dispose();
        }
        return sheet;
    }
}
