package org.skinlab.simulation;

import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.DoublePredicate;

/**
 * Who takes {@link SkeletalAnimatedMesh}'s steps, and when: the lock that serialises them, the
 * simulation thread's life (start, stop, close, failure, its step rate) and the frame listener
 * that runs after a step that published. What a step does is the mesh's; the thread's pacing is
 * {@link PacedThread}'s.
 *
 * <p><b>Why one lock and one lifecycle monitor.</b> Steps (threaded or by hand) and the mesh's
 * seeks ({@link #exclusively}) hold the step lock, so a thread still finishing its last step
 * after a stop never overlaps a new one. Starting and stopping hold the lifecycle monitor, which is
 * never held while stepping or joining: a {@link #stop()} from another thread (or from the
 * listener, on the simulation thread itself) can therefore never wait for a thread that waits for
 * it. The frame listener runs after the step lock is released, so a slow listener stalls neither
 * hand steps on other threads nor readers.
 *
 * <p><b>Failures.</b> Whatever the simulation thread throws (a step, the listener) is kept as
 * {@link #failure()}; the thread ends, and {@link #start()} and {@link #stepByHand} refuse from
 * then on with the failure as the cause, so it cannot vanish.
 */
final class SimulationThread {
    /** How often a simulation thread waiting for the step lock checks whether it was stopped. */
    private static final long LOCK_POLL_NANOS = TimeUnit.MILLISECONDS.toNanos(5);
    private static final AtomicInteger THREAD_NUMBERS = new AtomicInteger();

    private final String owner;
    /** One step of {@code dt} seconds, the caller holding the step lock; true when it published a frame. */
    private final DoublePredicate step;
    private final ReentrantLock stepLock = new ReentrantLock();
    private final AtomicReference<Throwable> failure = new AtomicReference<>();
    private volatile long periodNanos = Math.round(1e9 / SkeletalAnimatedMesh.DEFAULT_STEP_RATE);
    private volatile Runnable frameListener;

    // Guarded by `lifecycle` (never held while stepping or joining).
    private final Object lifecycle = new Object();
    private volatile PacedThread current;
    private volatile boolean closed;

    /**
     * @param owner what the thread steps, for messages
     * @param step  one step of {@code dt} seconds, run while holding the step lock; returns
     *              whether it published a frame
     */
    SimulationThread(String owner, DoublePredicate step) {
        this.owner = owner;
        this.step = step;
    }

    /** Runs {@code action} holding the step lock: no step runs meanwhile. */
    void exclusively(Runnable action) {
        stepLock.lock();
        try {
            action.run();
        } finally {
            stepLock.unlock();
        }
    }

    // ---------------------------------------------------------------------------- settings

    double stepRate() {
        return 1e9 / periodNanos;
    }

    void setStepRate(double stepsPerSecond) {
        if (!(stepsPerSecond >= SkeletalAnimatedMesh.MIN_STEP_RATE
                && stepsPerSecond <= SkeletalAnimatedMesh.MAX_STEP_RATE)) {
            throw new IllegalArgumentException("step rate " + stepsPerSecond + " outside ["
                    + SkeletalAnimatedMesh.MIN_STEP_RATE + ", " + SkeletalAnimatedMesh.MAX_STEP_RATE
                    + "] steps per second");
        }
        periodNanos = Math.round(1e9 / stepsPerSecond);
    }

    void setFrameListener(Runnable listener) {
        frameListener = listener;
    }

    // ---------------------------------------------------------------------------- failures

    Throwable failure() {
        return failure.get();
    }

    void throwIfFailed() {
        Throwable t = failure.get();
        if (t != null) {
            throw new IllegalStateException(owner + ": simulation thread failed: " + t, t);
        }
    }

    // ---------------------------------------------------------------------------- lifecycle

    /** Starts a thread named {@code skinlab-simulation-N}; false when one already runs. */
    boolean start() {
        synchronized (lifecycle) {
            if (closed) {
                throw new IllegalStateException(owner + ": closed, cannot start again");
            }
            Throwable t = failure.get();
            if (t != null) {
                throw new IllegalStateException(owner + ": the simulation failed earlier: " + t, t);
            }
            PacedThread r = current;
            if (r != null && r.isRunning()) {
                return false;
            }
            PacedThread next = new PacedThread("skinlab-simulation-" + THREAD_NUMBERS.incrementAndGet(),
                    () -> periodNanos, this::threadStep, thrown -> failure.compareAndSet(null, thrown));
            current = next;
            next.start();
            return true;
        }
    }

    boolean isRunning() {
        PacedThread r = current;
        return r != null && r.isRunning();
    }

    /** Asks the thread to stop and waits for it to end (not when called on it); true if it ran. */
    boolean stop() {
        PacedThread r;
        boolean stopped;
        synchronized (lifecycle) {
            r = current;
            if (r == null) {
                return false;
            }
            stopped = r.requestStop();
        }
        r.awaitEnd();
        return stopped;
    }

    /** Stops the thread for good: start and hand steps refuse afterwards. */
    void close() {
        synchronized (lifecycle) {
            closed = true;
        }
        stop();
    }

    boolean isClosed() {
        return closed;
    }

    // ---------------------------------------------------------------------------- steps

    /**
     * One step on the caller's thread, then the listener if it published.
     *
     * @throws IllegalStateException while the thread runs, after close, after a failure
     */
    void stepByHand(double dtSeconds) {
        boolean published;
        stepLock.lock();
        try {
            if (closed) {
                throw new IllegalStateException(owner + ": closed, cannot step");
            }
            throwIfFailed();
            if (isRunning()) {
                throw new IllegalStateException(owner
                        + ": the simulation thread is running; stop() it before stepping by hand");
            }
            published = step.test(dtSeconds);
        } finally {
            stepLock.unlock();
        }
        notifyListener(published);
    }

    /** One step of the simulation thread, {@code elapsedSeconds} capped (see {@link PacedThread} for its pacing). */
    private boolean threadStep(PacedThread r, double elapsedSeconds) {
        if (!lockForStep(r)) {
            return false;
        }
        boolean published;
        try {
            if (r.stopRequested()) {
                return false;
            }
            published = step.test(Math.min(elapsedSeconds, SkeletalAnimatedMesh.MAX_STEP_SECONDS));
        } finally {
            stepLock.unlock();
        }
        notifyListener(published); // what it throws ends the thread as failure()
        return true;
    }

    /**
     * Takes the step lock, polling for a stop while someone else steps, so that a {@link #stop()}
     * does not have to wait for another thread's step to end first.
     */
    private boolean lockForStep(PacedThread r) {
        try {
            while (!stepLock.tryLock(LOCK_POLL_NANOS, TimeUnit.NANOSECONDS)) {
                if (r.stopRequested()) {
                    return false;
                }
            }
            return true;
        } catch (InterruptedException e) {
            return false; // an interrupt stops the simulation thread
        }
    }

    /**
     * Runs the frame listener, if any, after a step that published; the caller must not hold the
     * step lock, so a slow listener stalls neither the next step nor hand steps on other threads.
     */
    private void notifyListener(boolean published) {
        Runnable listener = frameListener;
        if (published && listener != null) {
            listener.run();
        }
    }
}
