package org.skinlab.desktop.eval;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import com.fasterxml.jackson.databind.JsonNode;

/**
 * The quality section's comparison of every pair of methods, from its results: how far apart
 * they place the same points over the clip (in percent of the model's size), and the AR answer to
 * "will anyone see the difference?": the largest shift in pixels on a phone's camera image
 * ({@link PhoneView}: a character of a set height on the marker, seen from a set distance).
 */
final class EvalQualityPairs {
    private EvalQualityPairs() {
    }

    static void write(JsonNode results, EvalReport report) {
        report.heading(3, "Every pair of methods");
        report.paragraph("The largest distance between the points two methods place over the clip (every sample,"
                + " every geometry), in percent of the model's size (the diagonal of its bounds at the clip's"
                + " start).");
        table(results, "maxPercent", report);
        report.heading(3, "Visible on a phone's screen?");
        String p = "/phone";
        report.paragraph("The same pairs as a phone sees them in AR: the character scaled to "
                + EvalReport.num(results, p + "/characterMetres") + " m tall on the marker, seen from "
                + EvalReport.num(results, p + "/distanceMetres") + " m (from its centre, level with it) by a camera of "
                + EvalReport.num(results, p + "/width") + " by " + EvalReport.num(results, p + "/height")
                + " pixels with a " + EvalReport.num(results, p + "/fovDegrees") + "-degree horizontal field of view"
                + " (a focal length of " + EvalReport.num(results, p + "/focalPixels") + " pixels), from "
                + EvalReport.num(results, p + "/views") + " directions evenly around it: the largest shift of a point"
                + " between the two methods' pictures, in pixels, over the clip and the directions. A shift under a"
                + " pixel cannot be seen; a few pixels show on a still picture; tens of pixels show at a glance.");
        table(results, "maxPixels", report);
        summary(results, report);
    }

    /** A row per pair of methods, a column per asset: the pair's {@code key} value. */
    private static void table(JsonNode results, String key, EvalReport report) {
        JsonNode assets = results.get("assets");
        List<String> header = new ArrayList<>(List.of("methods"));
        for (JsonNode a : assets) {
            header.add("`" + EvalQualityReport.stem(a.get("file").asText()) + "`");
        }
        report.header(header.toArray(new String[0]));
        int pairs = assets.size() == 0 ? 0 : assets.get(0).get("pairs").size();
        for (int k = 0; k < pairs; k++) {
            JsonNode pair = assets.get(0).get("pairs").get(k);
            List<String> row = new ArrayList<>(List.of(upper(pair.get("a")) + " - " + upper(pair.get("b"))));
            for (int a = 0; a < assets.size(); a++) {
                row.add(EvalReport.num(results, "/assets/" + a + "/pairs/" + k + "/" + key));
            }
            report.row(row.toArray(new String[0]));
        }
        report.line("");
    }

    /** Per asset, the pair that differs most on screen and how many pairs differ by a pixel or more. */
    private static void summary(JsonNode results, EvalReport report) {
        StringBuilder t = new StringBuilder("On screen, per asset, the pair of methods that differ most: ");
        JsonNode assets = results.get("assets");
        for (int a = 0; a < assets.size(); a++) {
            JsonNode pairs = assets.get(a).get("pairs");
            int most = 0;
            for (int k = 0; k < pairs.size(); k++) {
                if (pairs.get(k).get("maxPixels").asDouble() > pairs.get(most).get("maxPixels").asDouble()) {
                    most = k;
                }
            }
            String p = "/assets/" + a + "/pairs/" + most;
            t.append(a == 0 ? "" : "; ").append('`').append(EvalQualityReport.stem(assets.get(a).get("file").asText()))
                    .append("` ").append(upper(pairs.get(most).get("a"))).append(" - ")
                    .append(upper(pairs.get(most).get("b"))).append(", ").append(EvalReport.num(results, p + "/maxPixels"))
                    .append(" px at ").append(EvalReport.num(results, p + "/maxPixelsTime")).append(" s");
        }
        report.paragraph(t.append('.').toString());
    }

    private static String upper(JsonNode key) {
        return key.asText().toUpperCase(Locale.ROOT);
    }
}
