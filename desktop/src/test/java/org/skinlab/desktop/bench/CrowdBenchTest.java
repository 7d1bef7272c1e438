package org.skinlab.desktop.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.skinning.SkinningMethod;

/**
 * {@link CrowdBench#measure}: every crowd is timed once in every round (each run's median frame
 * kept, in run order), the results in the crowds' order, every run at least 5 timed frames, and
 * on one thread the caller runs every copy; a method crowds do not run, or more copies than the
 * bench holds, is refused before anything runs. Windows of a few milliseconds: about a second.
 */
class CrowdBenchTest {
    private static final FrameTimes.Protocol SHORT = new FrameTimes.Protocol(3, 0, 0, 0.005);

    @Test
    void everyCrowdIsTimedInEveryRound() {
        CrowdBench bench = new CrowdBench(ModelFiles.load(Cli.defaultAsset()).model, 8);
        List<CrowdBench.Crowd> crowds = List.of(new CrowdBench.Crowd(SkinningMethod.LBS, 8, 1),
                new CrowdBench.Crowd(SkinningMethod.DQS, 2, 2), new CrowdBench.Crowd(SkinningMethod.COR, 1, 1));
        int[] runs = {0};
        List<CrowdBench.Timing> timings = bench.measure(crowds, SHORT, () -> runs[0]++);
        assertEquals(9, runs[0], "3 crowds, 3 rounds");
        assertEquals(crowds.size(), timings.size());
        for (int i = 0; i < crowds.size(); i++) {
            CrowdBench.Timing t = timings.get(i);
            assertEquals(crowds.get(i), t.crowd());
            assertEquals(3, t.frameMicros().count(), t.toString());
            assertTrue(t.frames() >= 3 * 5, t.toString());
            assertTrue(t.frameMicros().min() > 0, t.toString());
            assertTrue(t.callerShare() > 0 && t.callerShare() <= 1, t.toString());
        }
        assertEquals(1.0, timings.get(0).callerShare(), 0.0, "one thread: the caller runs every copy");
        assertEquals(1.0, timings.get(2).callerShare(), 0.0, "one thread: the caller runs every copy");
    }

    @Test
    void refusesWhatItCannotRun() {
        CrowdBench bench = new CrowdBench(ModelFiles.load(Cli.defaultAsset()).model, 4);
        int[] runs = {0};
        assertThrows(IllegalArgumentException.class, () -> bench.measure(List.of(
                new CrowdBench.Crowd(SkinningMethod.LBS, 1, 1), new CrowdBench.Crowd(SkinningMethod.SPLINE, 1, 1)),
                SHORT, () -> runs[0]++));
        assertThrows(IllegalArgumentException.class, () -> bench.measure(List.of(
                new CrowdBench.Crowd(SkinningMethod.LBS, 5, 1)), SHORT, () -> runs[0]++));
        assertEquals(0, runs[0], "nothing ran");
    }
}
