package org.skinlab.desktop.app;

import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.app.Pictures.Picture;
import org.skinlab.desktop.render.GlTestDisplay;

/**
 * {@code skinlab view --bind-pose} draws the walking character in its A-pose bind pose, not its
 * clip's first key: the same picture at any --time, on the GPU as on the CPU (which core's
 * BindPoseFrameTest checks against the bind shape), and another picture than --time 0's.
 */
class BindPoseViewTest {
    private static final Path WALK = Pictures.asset("characters/humanoid-walk.dae");

    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    @Test
    void theBindPoseIsNeitherTheClipNorItsTime(@TempDir Path dir) {
        Picture gpu = Pictures.view(dir, "gpu", WALK, 320, 400, "--bind-pose", "--time", "0");
        Picture later = Pictures.view(dir, "later", WALK, 320, 400, "--bind-pose", "--time", "0.6");
        Picture cpu = Pictures.view(dir, "cpu", WALK, 320, 400, "--bind-pose", "--cpu", "--method", "dqs");
        Picture keyZero = Pictures.view(dir, "key0", WALK, 320, 400, "--time", "0");
        double time = Pictures.differingPercent(gpu, later);
        double cpuGpu = Pictures.differingPercent(gpu, cpu);
        double clip = Pictures.differingPercent(gpu, keyZero);
        String numbers = "percent of the model's pixels that differ: bind pose at 0 s and 0.6 s " + time
                + ", GPU LBS and CPU DQS " + cpuGpu + ", bind pose and the clip at 0 s " + clip;
        assertTrue(time == 0, numbers);
        // Every joint at its bind frame: all methods give the bind shape (a few outline pixels may flip).
        assertTrue(cpuGpu < 1, numbers);
        // The arms hang in the walk; in the bind pose they are raised.
        assertTrue(clip > 20, numbers);
    }
}
