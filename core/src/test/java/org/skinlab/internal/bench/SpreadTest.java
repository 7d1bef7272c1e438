package org.skinlab.internal.bench;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

/** The spread of repeated runs against values worked out by hand. */
class SpreadTest {
    @Test
    void fiveRunsHaveTheirQuartilesAtTheSecondAndFourthValues() {
        Spread s = Spread.of(9, 1, 5, 3, 7);
        assertEquals(5, s.median());
        assertEquals(1, s.min());
        assertEquals(9, s.max());
        assertEquals(3, s.lowerQuartile());
        assertEquals(7, s.upperQuartile());
        assertEquals(0.8, s.relativeInterquartileRange(), 1e-15);
        assertArrayEquals(new double[] {9, 1, 5, 3, 7}, s.runs(), "the runs in the order they were taken");
    }

    @Test
    void quartilesInterpolateBetweenSortedValues() {
        // Sorted 10 20 30 40: positions 0.75, 1.5, 2.25 of 0..3.
        Spread s = Spread.of(40, 10, 30, 20);
        assertEquals(25, s.median());
        assertEquals(17.5, s.lowerQuartile(), 1e-12);
        assertEquals(32.5, s.upperQuartile(), 1e-12);
        Spread one = Spread.of(4);
        assertEquals(4, one.median());
        assertEquals(0, one.relativeInterquartileRange());
    }

    @Test
    void theRunsCannotBeChangedFromOutside() {
        double[] runs = {1, 2, 3};
        Spread s = Spread.of(runs);
        runs[0] = 100;
        s.runs()[1] = 100;
        assertArrayEquals(new double[] {1, 2, 3}, s.runs());
        assertThrows(IllegalArgumentException.class, Spread::of);
    }
}
