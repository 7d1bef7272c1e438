package org.skinlab.desktop.app;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.app.Pictures.Picture;
import org.skinlab.desktop.render.GlTestDisplay;

/**
 * The checker view ({@code --view checker}) shows what plain shading hides. On the twist cylinder
 * (assets/README.md) DQS keeps the cylinder's shape at 172 degrees of twist (--time 4), so its
 * shaded picture is its bind pose's (--time 0) to a fraction of a percent of the pixels, while the
 * pattern fixed to the rest shape turns with each ring and a quarter of the model's pixels change.
 * Between LBS and DQS at 4 s, where both outlines cover the cylinder, the pattern adds the twist's
 * difference to the shading's (the collapsed joint); at the bind pose both methods place every
 * point alike and the checkered pictures are the same. The pattern comes from the rest position
 * on either skinning path: the CPU-skinned mesh carries it as an extra attribute and draws the
 * same picture as the GPU.
 *
 * <p>Measured on Mesa's llvmpipe at 320x480 per view: DQS 4 s against 0 s differ in 0.2 % of the
 * model's pixels shaded and 26 % checkered; LBS against DQS at 4 s in 7.9 % shaded and 13 %
 * checkered (inside both outlines); the bounds below leave room for another rasteriser.
 */
class CheckerViewTest {
    private static final Path TWIST = Pictures.asset("cylinders/cylinder-twist-high.dae");
    private static final int WIDTH = 640;
    private static final int HEIGHT = 480;

    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    /** The split view of LBS (left) and DQS (right) at {@code time}, shaded or checkered. */
    private static Picture split(Path dir, String time, String view) {
        return Pictures.view(dir, view + "-" + time, TWIST, WIDTH, HEIGHT, "--time", time, "--view", view, "--method",
                "lbs", "--split", "dqs");
    }

    @Test
    void theTwistShowsInThePatternAndNotInTheShading(@TempDir Path dir) {
        Picture shaded4 = split(dir, "4", "shaded");
        Picture shaded0 = split(dir, "0", "shaded");
        Picture checker4 = split(dir, "4", "checker");
        Picture checker0 = split(dir, "0", "checker");
        double dqsShaded = Pictures.differingPercent(shaded4.half(1), shaded0.half(1));
        double dqsChecker = Pictures.differingPercent(checker4.half(1), checker0.half(1));
        double methodsShaded = Pictures.differingInsidePercent(shaded4.half(0), shaded4.half(1));
        double methodsChecker = Pictures.differingInsidePercent(checker4.half(0), checker4.half(1));
        double methodsAtBind = Pictures.differingPercent(checker0.half(0), checker0.half(1));
        String numbers = String.format(java.util.Locale.ROOT, "percent of the model's pixels: DQS 4 s against 0 s "
                + "shaded %.2f, checker %.2f; LBS against DQS at 4 s shaded %.2f, checker %.2f; at 0 s checker %.2f",
                dqsShaded, dqsChecker, methodsShaded, methodsChecker, methodsAtBind);
        assertTrue(dqsShaded < 1, numbers);
        assertTrue(dqsChecker > 15, numbers);
        assertTrue(methodsChecker > 1.4 * methodsShaded, numbers);
        assertTrue(methodsAtBind < 0.5, numbers);
    }

    @Test
    void theCpuSkinnedMeshCarriesTheSamePattern(@TempDir Path dir) {
        Picture gpu = Pictures.view(dir, "gpu", TWIST, WIDTH / 2, HEIGHT, "--time", "3", "--view", "checker",
                "--method", "dqs");
        Picture cpu = Pictures.view(dir, "cpu", TWIST, WIDTH / 2, HEIGHT, "--time", "3", "--view", "checker",
                "--method", "dqs", "--cpu");
        double differing = Pictures.differingPercent(gpu, cpu);
        // The kernels agree with the shader to 3e-7 of the size (check-gpu): at most a few edge pixels flip.
        assertTrue(differing < 1, "GPU against CPU: " + differing + " % of the model's pixels differ");
        assertTrue(Pictures.count(Pictures.model(gpu)) > 0.05 * gpu.rgb().length, "the cylinder is in the picture");
    }
}
