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
 * {@code skinlab eval --quick}'s pictures ({@link EvalQuickRun}): the viewer's pictures of the twist
 * cylinders, checked against what the assets are known to do (assets/README.md): the twist reaches
 * 172 degrees at the clip's end (4 s), where LBS collapses the joint (the candy wrapper) and DQS
 * keeps it, so the LBS and DQS pictures differ over much of the cylinder, and the checker shows the
 * twist against the rest pose; at the bind pose every method places every point alike, so the
 * pictures are the same; the whole-turn twist is never shown at its half turn, and its strip shows
 * the angles either side of it. Each panel shows its model, framed. And the camera's rule, without
 * a window: a bend is seen along its axis.
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
        assertEquals(List.of("pictures-cylinder-twist-high.png", "pictures-cylinder-twist-full.png",
                "pictures-cylinder-twist-full-strip.png"), linked);

        // Each sheet: the rest pose, seven methods and the difference, three to a row, above the footer.
        BufferedImage sheet = ImageIO.read(dir.resolve(linked.get(0)).toFile());
        int panel = pictures.get("panelWidth").asInt();
        assertTrue(sheet.getWidth() >= 3 * panel && sheet.getHeight() > 3 * pictures.get("panelHeight").asInt(),
                sheet.getWidth() + "x" + sheet.getHeight());

        JsonNode twist = asset(pictures, "cylinder-twist-high.dae");
        // The extreme is chosen from the data: the clip's end, 172 degrees (assets/README.md).
        assertEquals(4, twist.get("time").asDouble(), 1e-3, twist.toString());
        // |LBS - DQS| at 172 degrees on the joint ring (weights 1/2 each): DQS keeps the point at the
        // radius r = 0.25, LBS pulls it in to r cos(86 deg), 0.2326 apart; over the bounds' diagonal
        // sqrt(0.5^2 + 0.5^2 + 2^2) = 2.121 that is 10.96 %. 0.3 covers rings not exactly half-weighted.
        assertEquals(10.96, twist.get("maxLbsDqsPercent").asDouble(), 0.3, twist.toString());
        // The difference view's red sits at that distance, rounded up to two digits.
        assertEquals(11, twist.get("differenceScalePercent").asDouble(), 1e-9, twist.toString());
        assertTrue(twist.get("lbsDqsPixelsPercent").asDouble() > 8, "the candy wrapper is visible: " + twist);
        assertTrue(twist.get("restDqsPixelsPercent").asDouble() > 20, "the checker shows the twist: " + twist);
        // DQS and CoR agree on a two-influence cylinder.
        assertTrue(twist.get("dqsCorPixelsPercent").asDouble() < 1, twist.toString());
        // LBS's collapsed waist covers less of the picture than DQS's full cylinder.
        assertTrue(twist.at("/coveragePercent/lbs").asDouble() < twist.at("/coveragePercent/dqs").asDouble() - 0.5,
                twist.toString());
        // A twist about a standing bone is seen from the side square to the difference.
        assertEquals(PicturePose.ACROSS, twist.get("rule").asText());

        JsonNode control = pictures.get("control");
        assertEquals(0, control.get("maxLbsDqsPercent").asDouble(), 1e-3);
        assertTrue(control.get("lbsDqsPixelsPercent").asDouble() < 0.5, "the bind pose is the same: " + control);

        // The model is framed: neither blank (a few percent at least) nor filling the picture.
        JsonNode full = asset(pictures, "cylinder-twist-full.dae");
        for (JsonNode asset : List.of(twist, full)) {
            for (String p : EvalPicturesSection.panels()) {
                double c = asset.at("/coveragePercent/" + p).asDouble();
                assertTrue(c > 2 && c < 60, asset.get("file").asText() + " " + p + " covers " + c + " %");
            }
        }
        // The whole-turn twist (60 t degrees) is never shown within a hair of its half turn.
        assertTrue(Math.abs(60 * full.get("time").asDouble() - 180) > MeasuredJoint.HALF_TURN_DEGREES, full.toString());
        JsonNode strip = pictures.at("/strips/0");
        assertEquals("cylinder-twist-full.dae", strip.get("file").asText());
        for (JsonNode angle : strip.get("angles")) {
            assertEquals(angle.get("angleDegrees").asDouble() / 60, angle.get("time").asDouble(), 1e-3, strip.toString());
        }
    }

    @Test
    void aBendIsSeenAlongItsAxis() throws Exception {
        // The bend cylinder's upper half turns about x (assets/README.md): the camera looks along x,
        // from yaw 90 (or -90, the same profile), so the fold shows in outline.
        PicturePose pose = PicturePose.of(org.skinlab.desktop.ModelFiles.load(org.skinlab.desktop.Cli.root()
                .resolve("assets/cylinders/cylinder-bend.dae")).model, 10);
        assertEquals(PicturePose.ALONG_AXIS, pose.rule());
        assertEquals(90, Math.abs(pose.yawDegrees()), 0.5, pose.toString());
        assertEquals(4, pose.elapsed(), 1e-3, "the extreme is the clip's end, 170 degrees: " + pose);
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
