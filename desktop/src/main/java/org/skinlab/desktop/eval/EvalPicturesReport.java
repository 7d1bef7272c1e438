package org.skinlab.desktop.eval;

import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * The pictures section's text and strips, from its results: what the pictures show and how they
 * were chosen, the numbers measured in them, the control, each sheet's title and the whole-turn
 * strips.
 */
final class EvalPicturesReport {
    private EvalPicturesReport() {
    }

    static void introduce(JsonNode results, EvalReport report) {
        report.paragraph("Each asset drawn by the viewer (`skinlab view --screenshot --hide-ui`, panels of "
                + EvalReport.num(results, "/panelWidth") + " by " + EvalReport.num(results, "/panelHeight")
                + " pixels): the rest pose (every joint at its bind frame), then every method at the asset's extreme"
                + " pose, all in the checker view (a checker pattern fixed to the rest shape: a twist shows as"
                + " twisted squares), and the difference view (the LBS shape coloured by each point's distance from"
                + " its DQS position). The extreme pose is the time of the first clip, sampled "
                + EvalReport.num(results, "/samplesPerSecond") + " times a second, at which LBS and DQS place a point"
                + " furthest apart (over the model's size: `MethodComparison`, what the difference view measures)."
                + " The camera looks along the moving joint's axis where that axis lies level (a bend: its upward"
                + " part under " + EvalReport.num(results, "/levelAxis") + " of its length), so the fold shows in"
                + " profile; otherwise (a twist about a standing bone) from the side square to the largest"
                + " difference. The difference view's colours run from blue (no distance) through cyan, green and"
                + " yellow to red at the asset's own scale, the pose's largest distance rounded up (the colour bar"
                + " beside it), so no asset is all blue. Measured in the pictures: the share of each panel the model"
                + " covers, and the share of the model's pixels (in either panel) whose colour differs by more than "
                + EvalReport.num(results, "/pixelTolerance") + " levels between LBS and DQS, between DQS and CoR, and"
                + " between the rest pose and DQS.");
    }

    static void table(JsonNode results, EvalReport report) {
        report.header("asset", "time (s)", "clip (s)", "max abs(LBS - DQS) %", "difference scale %", "yaw (degrees)",
                "camera", "LBS cover %", "DQS cover %", "LBS vs DQS pixels %", "DQS vs CoR pixels %",
                "rest vs DQS pixels %");
        JsonNode assets = results.get("assets");
        List<String> skipped = new ArrayList<>();
        for (int a = 0; a < assets.size(); a++) {
            JsonNode asset = assets.get(a);
            String p = "/assets/" + a;
            String file = "`" + asset.get("file").asText() + "`";
            if (asset.has("skipped")) {
                skipped.add(file + ": " + quoted(asset.get("skipped").asText()));
                continue;
            }
            report.row(file, EvalReport.num(results, p + "/time"), EvalReport.num(results, p + "/clipSeconds"),
                    EvalReport.num(results, p + "/maxLbsDqsPercent"),
                    EvalReport.num(results, p + "/differenceScalePercent"), EvalReport.num(results, p + "/yawDegrees"),
                    asset.get("rule").asText(), EvalReport.num(results, p + "/coveragePercent/lbs"),
                    EvalReport.num(results, p + "/coveragePercent/dqs"),
                    EvalReport.num(results, p + "/lbsDqsPixelsPercent"),
                    EvalReport.num(results, p + "/dqsCorPixelsPercent"),
                    EvalReport.num(results, p + "/restDqsPixelsPercent"));
        }
        report.line("");
        for (String s : skipped) {
            report.paragraph("Skipped " + s + ".");
        }
    }

    /** The control: LBS against DQS at the bind pose, or why it was skipped. */
    static void control(JsonNode control, EvalReport report) {
        if (control.has("lbsDqsPixelsPercent")) {
            report.paragraph("Control: `" + control.get("file").asText() + "` in its bind pose, where LBS and DQS lie "
                    + EvalReport.num(control, "/maxLbsDqsPercent") + " % of the model's size apart at most: their"
                    + " pictures differ in " + EvalReport.num(control, "/lbsDqsPixelsPercent") + " % of the model's"
                    + " pixels (the model covers " + EvalReport.num(control, "/lbsCoveragePercent")
                    + " % of the LBS panel).");
        } else {
            report.paragraph("Control skipped: " + quoted(control.path("skipped").asText("no picture")) + ".");
        }
    }

    /** A sheet's title, from its asset's results (numbers as the report prints them). */
    static String title(JsonNode asset) {
        return asset.get("file").asText() + " at " + EvalReport.format(asset.get("time")) + " s of "
                + EvalReport.format(asset.get("clipSeconds")) + " s: LBS and DQS up to "
                + EvalReport.format(asset.get("maxLbsDqsPercent")) + " % of the model's size apart\nseen from yaw "
                + EvalReport.format(asset.get("yawDegrees")) + " degrees, " + asset.get("rule").asText();
    }

    /** A whole-turn strip: LBS above DQS at each angle, or why there is none. */
    static void strip(JsonNode results, int s, List<BufferedImage> panels, EvalReport report) {
        JsonNode strip = results.at("/strips/" + s);
        String file = strip.get("file").asText();
        report.heading(3, "`" + file + "` past a half turn");
        if (strip.has("skipped")) {
            report.paragraph("No strip: " + quoted(strip.get("skipped").asText()) + ".");
            return;
        }
        JsonNode angles = strip.get("angles");
        StringBuilder t = new StringBuilder("LBS (top row) and DQS (bottom row) at ");
        List<String> labels = new ArrayList<>();
        for (int i = 0; i < angles.size(); i++) {
            String p = "/strips/" + s + "/angles/" + i;
            t.append(i == 0 ? "" : ", ").append(EvalReport.num(results, p + "/angleDegrees")).append(" degrees (")
                    .append(EvalReport.num(results, p + "/time")).append(" s)");
            labels.add("LBS, " + EvalReport.format(angles.get(i).get("angleDegrees")) + " degrees");
        }
        for (int i = 0; i < angles.size(); i++) {
            labels.add("DQS, " + EvalReport.format(angles.get(i).get("angleDegrees")) + " degrees");
        }
        report.paragraph(t.append(", the clip times where the quality section measured those angles; seen from yaw ")
                .append(EvalReport.num(results, "/strips/" + s + "/yawDegrees")).append(" degrees (")
                .append(strip.get("rule").asText()).append("); the quality section's ring turn at the same angles gives"
                        + " the numbers.")
                .toString());
        String png = "pictures-" + EvalQualityReport.stem(file) + "-strip.png";
        String caption = "LBS and DQS either side of a half turn and at a full turn, " + file;
        if (panels == null) {
            report.existing(png, caption);
            return;
        }
        report.image(png, caption, PictureSheet.grid(file + ": LBS (top) and DQS (bottom) against the joint's angle",
                panels, labels, angles.size()));
    }

    /**
     * A reason as a code span: a message from the viewer or the system may hold numbers (a display,
     * a status) that are not results, and the report's numbers are results only.
     */
    static String quoted(String reason) {
        return "`" + reason.replace('`', '\'') + "`";
    }
}
