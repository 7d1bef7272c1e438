package org.skinlab.internal.bench;

/**
 * How a measurement warms up before it times: runs the step for at least a minimum time and, where
 * the platform can tell, until its compiler has compiled what the step runs. A phone's runtime
 * (ART) compiles ahead of time and in the background and says nothing about it, so there the
 * minimum time is the warm-up ({@link #FOR_TIME}); the desktop waits for HotSpot's JIT
 * ({@code org.skinlab.desktop.bench.JitWarmup}).
 */
@FunctionalInterface
public interface Warmup {
    /** Runs {@code step} for at least {@code minSeconds}; returns how many times it ran. */
    long run(Runnable step, double minSeconds);

    /** The step, over and over, for the minimum time and no longer. */
    Warmup FOR_TIME = (step, minSeconds) -> {
        long runs = 0;
        long end = System.nanoTime() + (long) (minSeconds * 1e9);
        do {
            step.run();
            runs++;
        } while (System.nanoTime() < end);
        return runs;
    };
}
