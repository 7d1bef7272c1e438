package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.internal.bench.Rounds;

/** The measurement's protocols: the launch extra's names, at least the evaluation's five rounds, the planned time. */
class MeasureProtocolTest {
    @Test
    void theExtraNamesTheQuickOneAndAnythingElseIsTheFullOne() {
        assertSame(MeasureProtocol.QUICK, MeasureProtocol.named("quick"));
        assertSame(MeasureProtocol.QUICK, MeasureProtocol.named(" Quick "));
        assertSame(MeasureProtocol.FULL, MeasureProtocol.named(null));
        assertSame(MeasureProtocol.FULL, MeasureProtocol.named("full"));
        assertSame(MeasureProtocol.FULL, MeasureProtocol.named("fast"));
    }

    @Test
    void bothTakeTheEvaluationsRoundsAndTheThesisCopies() {
        for (MeasureProtocol p : List.of(MeasureProtocol.FULL, MeasureProtocol.QUICK)) {
            assertTrue(p.times().rounds() >= Rounds.MIN_RUNS, p.toString());
            assertTrue(p.drawRounds() >= Rounds.MIN_RUNS, p.toString());
        }
        assertEquals(List.of(1, 4, 8, 12), MeasureProtocol.COPIES);
        assertThrows(IllegalArgumentException.class, () -> new MeasureProtocol("x", new FrameTimes.Protocol(5, 1, 1, 1),
                0, 5, 1));
    }

    @Test
    void thePlannedTimeAddsTheRunsAndThePoints() {
        MeasureProtocol p = new MeasureProtocol("p", new FrameTimes.Protocol(5, 2, 0.5, 1), 2, 5, 60);
        // Per method: the first run 2 + 1 s, four more 0.5 + 1 s.
        assertEquals(3 * 7 * (3 + 4 * 1.5), p.cpuSeconds(3, 7), 1e-9);
        // 4 copy counts x 3 methods x 5 rounds of 2 s and 60 frames at 60 Hz.
        assertEquals(12 * 5 * 3.0, p.drawnSeconds(60), 1e-9);
        assertTrue(MeasureProtocol.FULL.cpuSeconds(3, 7) + MeasureProtocol.FULL.drawnSeconds(60) < 10 * 60,
                "the full measurement takes minutes, not more");
    }
}
