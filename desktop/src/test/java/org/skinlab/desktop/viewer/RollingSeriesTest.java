package org.skinlab.desktop.viewer;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import org.junit.jupiter.api.Test;

class RollingSeriesTest {
    @Test
    void keepsTheNewestSamplesOldestFirst() {
        RollingSeries s = new RollingSeries("x", 3);
        assertEquals(Float.NaN, s.last());
        for (int i = 1; i <= 5; i++) {
            s.add(i, 10 * i);
        }
        s.add(6, Float.NaN);
        float[] xs = new float[3];
        float[] ys = new float[3];
        s.copyTo(xs, ys);
        assertArrayEquals(new float[] {3, 4, 5}, xs);
        assertArrayEquals(new float[] {30, 40, 50}, ys);
        assertEquals(50, s.last());
        assertEquals(40, s.mean(), 1e-6);
        assertEquals(30, s.min());
        assertEquals(50, s.max());
        s.clear();
        assertEquals(0, s.size());
    }
}
