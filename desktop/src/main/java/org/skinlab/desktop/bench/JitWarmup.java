package org.skinlab.desktop.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;

import org.skinlab.internal.bench.Warmup;

/**
 * A warm-up that waits for the JIT: frames for at least the given time, then on, a tenth of a
 * second at a time, until a frame allocates under {@value #COMPILED_BYTES} bytes on the calling
 * thread, or the most time allowed has passed. The Vector API boxes its vectors until C2 has
 * compiled a kernel (then it allocates nothing, like every skinning kernel), and runs tens of times
 * slower meanwhile: a warm-up of fixed length on a busy machine timed those boxes instead of the
 * kernel. Without HotSpot's per-thread allocation counter it is the fixed warm-up.
 */
public final class JitWarmup {
    static final int COMPILED_BYTES = 1024;
    /** The most a warm-up waits for the JIT beyond its minimum, in seconds. */
    static final double MAX_EXTRA_SECONDS = 10;

    private static final com.sun.management.ThreadMXBean THREADS = threads();

    /** This warm-up as core's benches take one. */
    public static final Warmup WARMUP = JitWarmup::run;

    private JitWarmup() {
    }

    /** Runs {@code frame} as described; returns the frames run. */
    static long run(Runnable frame, double minSeconds) {
        long frames = 0;
        long end = System.nanoTime() + (long) (minSeconds * 1e9);
        do {
            frame.run();
            frames++;
        } while (System.nanoTime() < end);
        if (THREADS == null) {
            return frames;
        }
        long thread = Thread.currentThread().getId();
        long limit = System.nanoTime() + (long) (MAX_EXTRA_SECONDS * 1e9);
        while (System.nanoTime() < limit) {
            long bytes = THREADS.getThreadAllocatedBytes(thread);
            long batch = 0;
            long batchEnd = System.nanoTime() + 100_000_000L;
            do {
                frame.run();
                batch++;
            } while (System.nanoTime() < batchEnd);
            frames += batch;
            if (THREADS.getThreadAllocatedBytes(thread) - bytes < COMPILED_BYTES * batch) {
                break;
            }
        }
        return frames;
    }

    private static com.sun.management.ThreadMXBean threads() {
        ThreadMXBean bean = ManagementFactory.getThreadMXBean();
        if (bean instanceof com.sun.management.ThreadMXBean) {
            com.sun.management.ThreadMXBean t = (com.sun.management.ThreadMXBean) bean;
            if (t.isThreadAllocatedMemorySupported() && t.isThreadAllocatedMemoryEnabled()) {
                return t;
            }
        }
        return null;
    }
}
