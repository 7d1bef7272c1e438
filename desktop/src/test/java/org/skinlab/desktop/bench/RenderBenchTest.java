package org.skinlab.desktop.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.render.GlTestDisplay;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinningMethod;

/**
 * {@link RenderBench#measure(Model, List, int, FrameTimes.Protocol, Runnable)}: each series timed
 * once per round, results in the series' order, each run at least 5 drawn frames, and the time
 * per frame positive; and the renderer's name classed as software or not. Needs a display
 * (Xvfb in the build); a small window and windows of a few milliseconds.
 */
class RenderBenchTest {
    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    @Test
    void everySeriesIsDrawnInEveryRound() throws Exception {
        Model model = ModelFiles.load(Cli.defaultAsset()).model;
        List<RenderBench.Series> series = List.of(new RenderBench.Series(false, SkinningMethod.LBS),
                new RenderBench.Series(true, SkinningMethod.DQS));
        int[] runs = {0};
        try (RenderBench bench = RenderBench.open(160, 120)) {
            List<RenderBench.Timing> timings = bench.measure(model, series, 2, new FrameTimes.Protocol(3, 0, 0, 0.01),
                    () -> runs[0]++);
            assertEquals(6, runs[0], "2 series, 3 rounds");
            for (int i = 0; i < series.size(); i++) {
                RenderBench.Timing t = timings.get(i);
                assertEquals(series.get(i), t.series());
                assertEquals(2, t.instances());
                assertEquals(3, t.msPerFrame().count(), t.toString());
                assertTrue(t.frames() >= 3 * 5 && t.msPerFrame().min() > 0, t.toString());
            }
        }
    }

    @Test
    void softwareRasterisersAreNamedSo() {
        assertTrue(RenderBench.isSoftware("llvmpipe (LLVM 15.0.6, 256 bits)"));
        assertTrue(RenderBench.isSoftware("Google SwiftShader"));
        assertTrue(!RenderBench.isSoftware("NVIDIA GeForce RTX 3060/PCIe/SSE2"));
    }
}
