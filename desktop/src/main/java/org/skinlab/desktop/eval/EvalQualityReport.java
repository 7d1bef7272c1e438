package org.skinlab.desktop.eval;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;

import org.knowm.xchart.BitmapEncoder;
import org.knowm.xchart.XYChart;
import org.skinlab.skinning.SkinningMethod;

/**
 * The quality section's part of the report, from its results alone: the joint measured per
 * asset, the extremes over each clip (as extremes, with the angle they happen at), the values at
 * stated angles, the measures against the angle (0 to 360 degrees where a clip goes that far),
 * every pair of methods apart in the scene and on a phone's screen, and the cost of capping
 * influences.
 */
final class EvalQualityReport {
    private static final SkinningMethod[] METHODS = SkinningMethod.values();
    /** The measures drawn against the angle: results key, label, axis title. */
    private static final String[][] MEASURES = {{"volume", "volume", "volume / rest"},
        {"ringRadius", "ring radius", "joint ring radius / rest"},
        {"ringTurnDegrees", "ring turn", "joint ring's turn (degrees)"},
        {"bulge", "bulge", "bulge (% of the model's size)"}};

    private EvalQualityReport() {
    }

    static void write(JsonNode results, EvalReport report) {
        introduce(results, report);
        for (JsonNode s : results.get("corpusSkipped")) {
            report.paragraph("Skipped: `" + s.asText() + "`.");
        }
        joints(results, report);
        report.heading(3, "The extremes over each clip");
        report.paragraph("Each method's least volume, least joint ring radius and largest bulge over the clip's"
                + " samples, with the joint's angle at that sample in brackets: maxima and minima, not values at a"
                + " stated angle (those follow). A dash: not measured (an open mesh has no volume).");
        extremes(results, "minVolume", "Least volume over rest", report);
        extremes(results, "minRingRadius", "Least joint ring radius over rest", report);
        extremes(results, "maxBulge", "Largest bulge, % of the model's size", report);
        JsonNode assets = results.get("assets");
        for (int a = 0; a < assets.size(); a++) {
            if (assets.get(a).has("atAngles")) {
                angleTables(results, a, report);
            }
        }
        for (int a = 0; a < assets.size(); a++) {
            if (assets.get(a).has("atAngles")) {
                angleFigure(assets.get(a), report);
            }
        }
        for (JsonNode asset : assets) {
            if (!asset.has("atAngles") && !asset.has("skipped")) {
                volumeFigure(asset, report);
            }
        }
        EvalQualityPairs.write(results, report);
        capTable(results, report);
    }

    private static void introduce(JsonNode results, EvalReport report) {
        report.paragraph("Each asset's first clip, sampled " + EvalReport.num(results, "/samplesPerSecond")
                + " times a second, deformed by every method; measured as `skinlab compare` measures"
                + " (docs/skinning.md), at one joint of the largest geometry: the one with the largest joint region"
                + " (points weighted on it and its parent) among those that turn at least "
                + EvalReport.num(results, "/movingDegrees") + " degrees over the clip (else the one that turns"
                + " most): the volume over the rest volume (closed meshes), the joint"
                + " ring's distance from the bones over its rest distance (the candy wrapper collapses it), the"
                + " bulge (how far the joint region stands out beyond its rest distance, in percent of the mesh's"
                + " size), and the joint ring's turn about the joint's axis seen from the parent bone (a smooth"
                + " blend turns it by about half the joint's angle; a method that reads a rotation past a half turn"
                + " the short way round turns it back; left out within " + EvalReport.num(results, "/halfTurnDegrees")
                + " degrees of a half turn, where the rotation has no sign). The joint's angle is its rotation from the bind pose"
                + " relative to its parent, signed about the first axis it turned about and unwrapped from sample"
                + " to sample, so that a full turn reads as one, not as a turn there and back.");
    }

    private static void joints(JsonNode results, EvalReport report) {
        report.header("asset", "mesh size m", "clip s", "joint", "parent", "region points", "closed",
                "angle range degrees");
        JsonNode assets = results.get("assets");
        for (int a = 0; a < assets.size(); a++) {
            JsonNode asset = assets.get(a);
            String p = "/assets/" + a;
            if (asset.has("skipped")) {
                report.row("`" + asset.get("file").asText() + "`", EvalReport.num(results, p + "/sizeMetres"),
                        EvalReport.num(results, p + "/clipSeconds"), "skipped: " + asset.get("skipped").asText(), "",
                        "", "", "");
                continue;
            }
            int[] range = range(asset.get("angleDegrees"));
            report.row("`" + asset.get("file").asText() + "`", EvalReport.num(results, p + "/sizeMetres"),
                    EvalReport.num(results, p + "/clipSeconds"), "`" + asset.get("joint").asText() + "`",
                    "`" + asset.get("parent").asText() + "`", EvalReport.num(results, p + "/regionPoints"),
                    asset.get("closed").asBoolean() ? "yes" : "no",
                    EvalReport.num(results, p + "/angleDegrees/" + range[0]) + " to "
                            + EvalReport.num(results, p + "/angleDegrees/" + range[1]));
        }
        report.line("");
    }

    /** The indices of the least and the largest angle of a series. */
    private static int[] range(JsonNode angles) {
        int lo = 0;
        int hi = 0;
        for (int i = 0; i < angles.size(); i++) {
            lo = angles.get(i).asDouble() < angles.get(lo).asDouble() ? i : lo;
            hi = angles.get(i).asDouble() > angles.get(hi).asDouble() ? i : hi;
        }
        return new int[] {lo, hi};
    }

    private static void extremes(JsonNode results, String key, String title, EvalReport report) {
        report.paragraph("**" + title + "**");
        List<String> header = new ArrayList<>(List.of("asset"));
        for (SkinningMethod m : METHODS) {
            header.add(upper(m));
        }
        report.header(header.toArray(new String[0]));
        JsonNode assets = results.get("assets");
        for (int a = 0; a < assets.size(); a++) {
            JsonNode asset = assets.get(a);
            if (asset.has("skipped")) {
                continue;
            }
            List<String> row = new ArrayList<>(List.of("`" + asset.get("file").asText() + "`"));
            for (SkinningMethod m : METHODS) {
                String p = "/assets/" + a + "/methods/" + m.key() + "/" + key;
                JsonNode sample = results.at(p + "Sample");
                row.add(sample.isMissingNode() ? "-" : EvalReport.num(results, p) + " ("
                        + EvalReport.num(results, "/assets/" + a + "/angleDegrees/" + sample.asInt()) + "°)");
            }
            report.row(row.toArray(new String[0]));
        }
        report.line("");
    }

    /** An asset's measures at the stated angles it reaches: a table per measure, a column per method. */
    private static void angleTables(JsonNode results, int a, EvalReport report) {
        JsonNode asset = results.at("/assets/" + a);
        report.heading(4, "`" + asset.get("file").asText() + "` at stated angles");
        report.paragraph("Measured at the clip time where the joint's unwrapped angle is the stated angle (bisection,"
                + " within " + EvalReport.num(results, "/angleToleranceDegrees") + " degrees); never at a half turn,"
                + " which has no sign.");
        for (String[] measure : MEASURES) {
            if (measure[0].equals("volume") && !asset.get("closed").asBoolean()) {
                continue;
            }
            List<String> header = new ArrayList<>(List.of("angle degrees", "clip s"));
            for (SkinningMethod m : METHODS) {
                header.add(upper(m) + " " + measure[1]);
            }
            report.header(header.toArray(new String[0]));
            JsonNode at = asset.get("atAngles");
            for (int i = 0; i < at.size(); i++) {
                String p = "/assets/" + a + "/atAngles/" + i;
                List<String> row = new ArrayList<>(List.of(EvalReport.num(results, p + "/angleDegrees"),
                        EvalReport.num(results, p + "/time")));
                for (SkinningMethod m : METHODS) {
                    row.add(EvalReport.numOrDash(results, p + "/methods/" + m.key() + "/" + measure[0] + "/0"));
                }
                report.row(row.toArray(new String[0]));
            }
            report.line("");
        }
    }

    /** The measures against the joint's angle, one panel per measure, a line per method. */
    private static void angleFigure(JsonNode asset, EvalReport report) {
        String file = asset.get("file").asText();
        List<BufferedImage> panels = new ArrayList<>();
        for (String[] measure : MEASURES) {
            XYChart chart = EvalCharts.xy(file + ": " + measure[1] + " against the joint's angle",
                    "joint angle (degrees, unwrapped)", measure[2], 330);
            chart.getStyler().setXAxisMin(0.0);
            int series = 0;
            for (int m = 0; m < METHODS.length; m++) {
                series += line(chart, upper(METHODS[m]), asset.get("angleDegrees"),
                        asset.at("/methods/" + METHODS[m].key() + "/" + measure[0]), m) ? 1 : 0;
            }
            if (series > 0) {
                panels.add(BitmapEncoder.getBufferedImage(chart));
            }
        }
        report.image("quality-angle-" + stem(file) + ".png", "Volume, joint ring, its turn and the bulge against"
                + " the joint's angle, every method, " + file, stack(panels));
    }

    /** Volume over rest against clip time, a line per method (closed meshes); a line of text otherwise. */
    private static void volumeFigure(JsonNode asset, EvalReport report) {
        String file = asset.get("file").asText();
        XYChart chart = EvalCharts.xy("Volume over rest: " + file, "clip time (s)", "volume / rest");
        int series = 0;
        for (int m = 0; m < METHODS.length; m++) {
            series += line(chart, upper(METHODS[m]), asset.get("times"),
                    asset.at("/methods/" + METHODS[m].key() + "/volume"), m) ? 1 : 0;
        }
        if (series > 0) {
            report.figure("quality-volume-" + stem(file) + ".png", "Volume over rest against clip time, " + file,
                    chart);
        } else {
            report.paragraph("`" + file + "`: not a closed mesh, so no volume.");
        }
    }

    /** Adds the (x, y) pairs whose y is a number as method {@code m}'s line; false when none is. */
    private static boolean line(XYChart chart, String name, JsonNode xs, JsonNode ys, int m) {
        List<Double> x = new ArrayList<>();
        List<Double> y = new ArrayList<>();
        for (int i = 0; i < xs.size() && i < ys.size(); i++) {
            if (ys.get(i).isNumber()) {
                x.add(xs.get(i).asDouble());
                y.add(ys.get(i).asDouble());
            }
        }
        if (x.isEmpty()) {
            return false;
        }
        EvalCharts.methodLine(chart.addSeries(name, x, y), m);
        return true;
    }

    private static BufferedImage stack(List<BufferedImage> panels) {
        int width = panels.stream().mapToInt(BufferedImage::getWidth).max().orElse(1);
        int height = panels.stream().mapToInt(BufferedImage::getHeight).sum();
        BufferedImage out = new BufferedImage(width, Math.max(1, height), BufferedImage.TYPE_INT_RGB);
        Graphics2D g = out.createGraphics();
        try {
            g.setColor(java.awt.Color.WHITE);
            g.fillRect(0, 0, width, height);
            int y = 0;
            for (BufferedImage p : panels) {
                g.drawImage(p, 0, y, null);
                y += p.getHeight();
            }
        } finally {
            g.dispose();
        }
        return out;
    }

    private static void capTable(JsonNode results, EvalReport report) {
        report.heading(3, "Capping influences");
        report.paragraph("The error that capping influences causes (`InfluenceCapReport`, as `skinlab inspect` prints"
                + " it: every clip at " + EvalReport.num(results, "/capSamplesPerSecond") + " samples a second): the"
                + " largest distance a position moves when only its " + EvalReport.num(results, "/cap4") + " or "
                + EvalReport.num(results, "/cap8") + " heaviest influences are kept, in percent of the model's size."
                + " An asset with no more influences than the cap loses nothing.");
        report.header("asset", "influences", "cap", "positions capped", "LBS error %", "DQS error %");
        JsonNode assets = results.get("assets");
        for (int a = 0; a < assets.size(); a++) {
            JsonNode caps = assets.get(a).get("caps");
            if (caps == null) {
                continue;
            }
            for (int c = 0; c < caps.size(); c++) {
                String p = "/assets/" + a + "/caps/" + c;
                report.row("`" + assets.get(a).get("file").asText() + "`", EvalReport.num(results, "/assets/" + a
                        + "/influences"), EvalReport.num(results, p + "/cap"), EvalReport.num(results,
                        p + "/cappedPositions"), EvalReport.num(results, p + "/lbsPercent"),
                        EvalReport.num(results, p + "/dqsPercent"));
            }
        }
        report.line("");
    }

    static String stem(String file) {
        return file.replaceAll("\\.(dae|glb|gltf)$", "").replaceAll("[^A-Za-z0-9_-]", "_");
    }

    static String upper(SkinningMethod m) {
        return m.key().toUpperCase(Locale.ROOT);
    }
}
