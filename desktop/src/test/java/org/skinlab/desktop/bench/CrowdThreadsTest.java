package org.skinlab.desktop.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.concurrent.atomic.AtomicIntegerArray;

import org.junit.jupiter.api.Test;

/**
 * {@link CrowdThreads}: every item of every frame runs exactly once, and the frame is over when
 * run returns, with the item count changing from frame to frame (a late worker must not take an
 * item of the next frame by the last one's count); a task's failure reaches the caller. Under a
 * second.
 */
class CrowdThreadsTest {
    private static final int MAX_ITEMS = 61;

    @Test
    void everyItemRunsOncePerFrameWhateverTheCount() {
        AtomicIntegerArray runs = new AtomicIntegerArray(MAX_ITEMS + 1);
        try (CrowdThreads pool = new CrowdThreads(3, runs::incrementAndGet)) {
            for (int frame = 0; frame < 3000; frame++) {
                int count = 1 + (frame * 37) % MAX_ITEMS;
                pool.run(count);
                for (int i = 0; i <= MAX_ITEMS; i++) {
                    assertEquals(i < count ? 1 : 0, runs.getAndSet(i, 0), "frame " + frame + ", item " + i
                            + " of " + count);
                }
            }
        }
    }

    @Test
    void aFailureReachesTheCaller() {
        try (CrowdThreads pool = new CrowdThreads(2, i -> {
            if (i == 5) {
                throw new IllegalStateException("item 5");
            }
        })) {
            assertEquals("item 5", assertThrows(IllegalStateException.class, () -> pool.run(20)).getMessage());
            pool.run(3);
        }
    }
}
