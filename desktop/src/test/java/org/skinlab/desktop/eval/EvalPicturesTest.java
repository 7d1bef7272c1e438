package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.List;

import javax.imageio.ImageIO;

import com.fasterxml.jackson.databind.JsonNode;

import org.junit.jupiter.api.Test;
import org.skinlab.desktop.render.GlTestDisplay;

/**
 * {@code skinlab eval --quick}'s pictures ({@link EvalQuickRun}): the viewer's pictures of the twist cylinder and the
 * walking character, checked against what the assets are known to do (assets/README.md): the
 * twist reaches 172 degrees at the clip's end (4 s), where LBS collapses the joint (the candy
 * wrapper) and DQS keeps it, so the LBS and DQS pictures differ over much of the cylinder; at the
 * bind pose every method places every point alike, so the pictures are the same; the walk's
 * joints bend little, so its LBS and DQS pictures nearly agree. Each panel shows its model, framed
 * (covering a sane share of the picture).
 */
class EvalPicturesTest {
    @Test
    void picturesShowTheCandyWrapperWhereTheMethodsDifferAndAgreeElsewhere() throws Exception {
        GlTestDisplay.assume();
        EvalQuickRun run = EvalQuickRun.get();
        Path dir = run.dir;
        JsonNode pictures = run.section("pictures");
        assertFalse(pictures.has("skipped"), pictures.toString());
        List<String> linked = EvalReportCheck.linked(run.readme).stream().filter(f -> f.startsWith("pictures-"))
                .collect(java.util.stream.Collectors.toList());
        assertEquals(List.of("pictures-cylinder-twist-high.png", "pictures-humanoid-walk.png"), linked);

        // Each figure: four panels side by side, above the footer.
        BufferedImage sheet = ImageIO.read(dir.resolve(linked.get(0)).toFile());
        int panel = pictures.get("panelWidth").asInt();
        assertTrue(sheet.getWidth() >= 4 * panel && sheet.getHeight() > pictures.get("panelHeight").asInt(),
                sheet.getWidth() + "x" + sheet.getHeight());

        JsonNode twist = asset(pictures, "cylinder-twist-high.dae");
        // The extreme is chosen from the data: the clip's end, 172 degrees (assets/README.md).
        assertEquals(4, twist.get("time").asDouble(), 1e-3, twist.toString());
        // |LBS - DQS| at 172 degrees on the joint ring (weights 1/2 each): DQS keeps the point at the
        // radius r = 0.25, LBS pulls it in to r cos(86 deg), 0.2326 apart; over the bounds' diagonal
        // sqrt(0.5^2 + 0.5^2 + 2^2) = 2.121 that is 10.96 %. 0.3 covers rings not exactly half-weighted.
        assertEquals(10.96, twist.get("maxLbsDqsPercent").asDouble(), 0.3, twist.toString());
        assertTrue(twist.get("lbsDqsPixelsPercent").asDouble() > 8, "the candy wrapper is visible: " + twist);
        // DQS and CoR agree on a two-influence cylinder.
        assertTrue(twist.get("dqsCorPixelsPercent").asDouble() < 1, twist.toString());
        // LBS's collapsed waist covers less of the picture than DQS's full cylinder.
        assertTrue(twist.at("/coveragePercent/lbs").asDouble() < twist.at("/coveragePercent/dqs").asDouble() - 0.5,
                twist.toString());

        JsonNode walk = asset(pictures, "humanoid-walk.dae");
        assertTrue(walk.get("maxLbsDqsPercent").asDouble() < 2, walk.toString());
        assertTrue(walk.get("lbsDqsPixelsPercent").asDouble() < 2, "the walk's methods nearly agree: " + walk);

        JsonNode control = pictures.get("control");
        assertEquals(0, control.get("maxLbsDqsPercent").asDouble(), 1e-3);
        assertTrue(control.get("lbsDqsPixelsPercent").asDouble() < 0.5, "the bind pose is the same: " + control);

        // The model is framed: neither blank (a few percent at least) nor filling the picture.
        for (JsonNode asset : List.of(twist, walk)) {
            for (String p : List.of("lbs", "dqs", "cor", "difference")) {
                double c = asset.at("/coveragePercent/" + p).asDouble();
                assertTrue(c > 2 && c < 60, asset.get("file").asText() + " " + p + " covers " + c + " %");
            }
        }
    }

    private static JsonNode asset(JsonNode pictures, String file) {
        for (JsonNode a : pictures.get("assets")) {
            if (a.get("file").asText().equals(file)) {
                return a;
            }
        }
        throw new AssertionError("no " + file + " in " + pictures);
    }
}
