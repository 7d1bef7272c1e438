package org.skinlab.internal.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.testing.TestPaths;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.PositionSharing;
import org.skinlab.skinning.SkinningMethod;

/**
 * The evaluation's frame timing on a real asset: every method timed in every round, each run a
 * positive median frame, the scalar kernels named; and the bench's frame is the per-frame path's
 * (what it skins is what {@code SkinnedModel} skins). Speed is not judged here.
 */
class FrameTimesTest {
    @Test
    void everyMethodIsTimedInEveryRound() throws Exception {
        Model model = ColladaImporter.read(TestPaths.asset("cylinders/cylinder-twist-low.dae"));
        List<SkinningMethod> methods = List.of(SkinningMethod.LBS, SkinningMethod.DQS, SkinningMethod.COR);
        FrameBench bench = new FrameBench(model, NormalTransform.INVERSE_TRANSPOSE, PositionSharing.AUTO, true, 0,
                methods, Warmup.FOR_TIME);
        List<FrameTimes.Result> results = FrameTimes.measure(bench, methods,
                new FrameTimes.Protocol(Rounds.MIN_RUNS, 0.02, 0.005, 0.01));
        assertEquals(methods.size(), results.size());
        for (int i = 0; i < methods.size(); i++) {
            FrameTimes.Result r = results.get(i);
            assertEquals(methods.get(i), r.method());
            assertEquals("scalar", r.kernel());
            assertEquals(Rounds.MIN_RUNS, r.micros().count());
            assertTrue(r.frames() >= 5 * Rounds.MIN_RUNS, "at least 5 frames a run: " + r.frames());
            for (double run : r.micros().runs()) {
                assertTrue(run > 0 && run < 1e6, r.toString());
            }
        }
        // Two joints, two influences at most (assets/README.md): what one frame skins.
        assertEquals(2, bench.shape().joints());
        assertEquals(2, bench.shape().influences());
    }

    /** The platform's warm-up (the desktop's waits for the JIT) runs once per method; later rounds warm up for the time. */
    @Test
    void theBenchWarmupRunsOncePerMethod() throws Exception {
        Model model = ColladaImporter.read(TestPaths.asset("cylinders/cylinder-twist-low.dae"));
        List<SkinningMethod> methods = List.of(SkinningMethod.LBS, SkinningMethod.DQS);
        int[] calls = {0};
        Warmup counting = (step, seconds) -> {
            calls[0]++;
            return Warmup.FOR_TIME.run(step, seconds);
        };
        FrameBench bench = new FrameBench(model, NormalTransform.INVERSE_TRANSPOSE, PositionSharing.AUTO, true, 0,
                methods, counting);
        FrameTimes.measure(bench, methods, new FrameTimes.Protocol(Rounds.MIN_RUNS, 0.01, 0.005, 0.01));
        assertEquals(methods.size(), calls[0]);
    }

    @Test
    void aProtocolWithoutTimeIsRefused() {
        assertThrows(IllegalArgumentException.class, () -> new FrameTimes.Protocol(5, 1, 0.1, 0));
        assertThrows(IllegalArgumentException.class, () -> new FrameTimes.Protocol(0, 1, 0.1, 1));
    }
}
