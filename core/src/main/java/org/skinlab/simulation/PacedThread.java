package org.skinlab.simulation;

import java.util.concurrent.locks.LockSupport;
import java.util.function.Consumer;
import java.util.function.LongSupplier;

/**
 * One daemon thread that runs a step at a steady rate until it is stopped, interrupted, the step
 * declines to go on, or the step throws: the pacing of {@link SkeletalAnimatedMesh}'s simulation
 * thread, kept apart from what a step does.
 *
 * <p>It waits for absolute deadlines with {@link LockSupport#parkNanos}: each deadline is the
 * previous one plus the period, so oversleeping one step shortens the next wait and the rate does
 * not drift the way sleeping a fixed period after each step would. More than a period behind, it
 * carries on from now rather than catch up in a burst. The period is read before every step, so
 * a rate change applies from the next one. Each step is told the time that actually elapsed
 * since the previous one, so what it advances follows the wall clock even when steps come late.
 *
 * <p>Each instance is one thread with its own stop flag, so a stopped thread that is still
 * finishing can never be mistaken for its successor.
 */
final class PacedThread {
    /** What the thread does at each deadline. */
    interface Step {
        /**
         * One step, {@code dtSeconds} after the previous one (or after the start).
         *
         * @return false to end the thread
         */
        boolean run(PacedThread self, double dtSeconds);
    }

    private final Thread thread;
    private final LongSupplier periodNanos;
    private final Step step;
    private final Consumer<Throwable> onFailure;
    private volatile boolean stopRequested;

    /**
     * @param periodNanos read before each step
     * @param onFailure   given whatever the step throws; the thread then ends
     */
    PacedThread(String name, LongSupplier periodNanos, Step step, Consumer<Throwable> onFailure) {
        this.periodNanos = periodNanos;
        this.step = step;
        this.onFailure = onFailure;
        thread = new Thread(this::run, name);
        thread.setDaemon(true);
    }

    void start() {
        thread.start();
    }

    boolean stopRequested() {
        return stopRequested;
    }

    /** Started, not asked to stop, not ended (by a failure, an interrupt or the step). */
    boolean isRunning() {
        return !stopRequested && thread.isAlive();
    }

    /**
     * Asks the thread to stop and wakes it if it waits for a deadline; does not wait for it.
     *
     * @return true if it was running
     */
    boolean requestStop() {
        boolean running = isRunning();
        stopRequested = true;
        LockSupport.unpark(thread);
        return running;
    }

    /** Waits for the thread to end (keeping an interrupt for later); returns at once on the thread itself. */
    void awaitEnd() {
        if (Thread.currentThread() == thread) {
            return;
        }
        boolean interrupted = false;
        while (true) {
            try {
                thread.join();
                break;
            } catch (InterruptedException e) {
                interrupted = true;
            }
        }
        if (interrupted) {
            Thread.currentThread().interrupt();
        }
    }

    private void run() {
        long last = System.nanoTime();
        long deadline = last;
        try {
            while (!stopRequested && !thread.isInterrupted()) {
                long period = periodNanos.getAsLong();
                deadline += period;
                long now = System.nanoTime();
                while (now - deadline < 0) {
                    LockSupport.parkNanos(this, deadline - now);
                    if (stopRequested || thread.isInterrupted()) {
                        return;
                    }
                    now = System.nanoTime();
                }
                if (now - deadline > period) {
                    deadline = now; // more than a period behind: no burst of steps to catch up
                }
                if (!step.run(this, (now - last) * 1e-9)) {
                    return;
                }
                last = now;
            }
        } catch (Throwable t) {
            onFailure.accept(t);
        }
    }
}
