package org.skinlab.internal.bench;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;

/** Interleaved rounds: every thing once per round, the first of each round moving along. */
class RoundsTest {
    @Test
    void eachRoundMeasuresEveryThingOnceStartingOneFurtherAlong() {
        List<String> order = new ArrayList<>();
        Spread[] spreads = Rounds.interleaved(3, 4, (index, round) -> {
            order.add(round + ":" + index);
            return 10 * index + round;
        });
        assertEquals(List.of("0:0", "0:1", "0:2", "1:1", "1:2", "1:0", "2:2", "2:0", "2:1", "3:0", "3:1", "3:2"),
                order);
        assertEquals(3, spreads.length);
        assertArrayEquals(new double[] {0, 1, 2, 3}, spreads[0].runs(), "thing 0's runs in round order");
        assertArrayEquals(new double[] {20, 21, 22, 23}, spreads[2].runs());
        assertEquals(21.5, spreads[2].median());
    }

    @Test
    void aDriftFallsOnEveryThingAlike() {
        // A machine that slows down by 1 per measurement: interleaved, both things see the same drift.
        int[] clock = {0};
        Spread[] spreads = Rounds.interleaved(2, Rounds.MIN_RUNS, (index, round) -> 100 + clock[0]++);
        assertEquals(spreads[0].median(), spreads[1].median(), 1.0);
    }
}
