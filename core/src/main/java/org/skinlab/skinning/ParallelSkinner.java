package org.skinlab.skinning;

import java.util.concurrent.locks.LockSupport;

/**
 * Runs any {@link Skinner} over several threads: {@link #skin} cuts its range into one part per
 * thread, at multiples of the kernel's {@link Skinner#rangeAlignment()}, hands all parts but the
 * first to a small persistent pool and does the first itself, then waits for the others. Plain
 * Java (Android-safe).
 *
 * <p>Per frame it allocates nothing and starts no thread: each worker owns one slot whose fields
 * carry the call's arguments; publishing is a volatile write of a generation counter. A worker
 * spins briefly on that counter ({@link Thread#onSpinWait()}; a frame's handoff is microseconds
 * apart when animating) and then parks, and the caller unparks it only if it parked. The caller
 * waits for the others the same way (spin, then yield). Results are identical to the single-thread
 * kernel's, bit for bit: every point is computed by the same code, only on another thread.
 *
 * <p>One caller at a time: {@code skin} is not reentrant across threads (its slots are shared),
 * unlike the kernels it wraps. The workers are daemon threads; {@link #close()} stops them.
 */
public final class ParallelSkinner implements Skinner, AutoCloseable {
    /** Spins before a waiting thread parks (worker) or yields (caller); about 10-50 µs. */
    private static final int SPIN = 20_000;

    private final Skinner kernel;
    private final Worker[] workers;
    private volatile boolean closed;

    /**
     * @param kernel  the skinner to run; it must accept concurrent calls on disjoint ranges (the
     *                contract of {@link Skinner})
     * @param threads threads in all, the caller's included (1: no pool, calls go straight through)
     */
    public ParallelSkinner(Skinner kernel, int threads) {
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be at least 1, was " + threads);
        }
        this.kernel = kernel;
        this.workers = new Worker[threads - 1];
        for (int i = 0; i < workers.length; i++) {
            workers[i] = new Worker(kernel, "skinlab-skinning-" + (i + 1));
            workers[i].thread.start();
        }
    }

    /** Threads a frame is split over, the caller's included. */
    public int threads() {
        return workers.length + 1;
    }

    @Override
    public SkinningMethod method() {
        return kernel.method();
    }

    @Override
    public NormalTransform normalTransform() {
        return kernel.normalTransform();
    }

    @Override
    public SkinnedGeometry geometry() {
        return kernel.geometry();
    }

    @Override
    public int rangeAlignment() {
        return kernel.rangeAlignment();
    }

    @Override
    public String implementation() {
        return kernel.implementation() + (workers.length == 0 ? "" : ", " + threads() + " threads");
    }

    @Override
    public void skin(JointPalette palette, float[] outPositions, float[] outNormals, int from, int to) {
        if (closed) {
            throw new IllegalStateException("ParallelSkinner is closed");
        }
        int parts = workers.length + 1;
        if (parts == 1 || to - from < 2L * parts * kernel.rangeAlignment()) {
            kernel.skin(palette, outPositions, outNormals, from, to);
            return;
        }
        int firstEnd = boundary(from, to, 1, parts);
        for (int i = 1; i < parts; i++) {
            workers[i - 1].start(palette, outPositions, outNormals, boundary(from, to, i, parts),
                    boundary(from, to, i + 1, parts));
        }
        Throwable failure = null;
        try {
            kernel.skin(palette, outPositions, outNormals, from, firstEnd);
        } catch (RuntimeException | Error e) {
            failure = e;
        }
        for (Worker w : workers) {
            Throwable t = w.await();
            if (failure == null) {
                failure = t;
            }
        }
        if (failure instanceof RuntimeException) {
            throw (RuntimeException) failure;
        }
        if (failure instanceof Error) {
            throw (Error) failure;
        }
    }

    /** Start of part {@code i} of {@code parts}: an even split, rounded up to the kernel's alignment. */
    private int boundary(int from, int to, int i, int parts) {
        if (i >= parts) {
            return to;
        }
        long even = from + (long) (to - from) * i / parts;
        int align = kernel.rangeAlignment();
        long aligned = (even + align - 1) / align * align;
        return (int) Math.max(from, Math.min(to, aligned));
    }

    /** Stops the worker threads (waiting for them); skinning afterwards throws. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true;
        for (Worker w : workers) {
            w.stop();
        }
        for (Worker w : workers) {
            try {
                w.thread.join(1000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    /** One pool thread and its slot: the arguments of the part it runs this frame. */
    private static final class Worker implements Runnable {
        final Thread thread;
        private final Skinner kernel;
        // Written by the caller before the volatile write of 'requested', read by the worker after
        // its volatile read (happens-before through 'requested'); the same for 'failure' and 'done'.
        private JointPalette palette;
        private float[] outPositions;
        private float[] outNormals;
        private int from;
        private int to;
        private Throwable failure;
        private volatile int requested;
        private volatile int done;
        private volatile boolean parked;
        private volatile boolean stop;

        Worker(Skinner kernel, String name) {
            this.kernel = kernel;
            this.thread = new Thread(this, name);
            thread.setDaemon(true);
        }

        void start(JointPalette p, float[] positions, float[] normals, int f, int t) {
            palette = p;
            outPositions = positions;
            outNormals = normals;
            from = f;
            to = t;
            requested = requested + 1;
            if (parked) {
                LockSupport.unpark(thread);
            }
        }

        /** Waits for the part started last; its exception, or null. */
        Throwable await() {
            int target = requested;
            for (int spins = 0; done != target; spins++) {
                if (spins < SPIN) {
                    Thread.onSpinWait();
                } else {
                    Thread.yield();
                }
            }
            Throwable t = failure;
            failure = null;
            palette = null;
            return t;
        }

        void stop() {
            stop = true;
            LockSupport.unpark(thread);
        }

        @Override
        public void run() {
            int seen = 0;
            while (true) {
                int spins = 0;
                while (requested == seen) {
                    if (stop) {
                        return;
                    }
                    if (spins++ < SPIN) {
                        Thread.onSpinWait();
                    } else {
                        parked = true;
                        // Re-check after announcing: a request published before 'parked' was set
                        // would otherwise find no one to unpark (lost wake-up).
                        if (requested == seen && !stop) {
                            LockSupport.park(this);
                        }
                        parked = false;
                    }
                }
                seen = requested;
                try {
                    kernel.skin(palette, outPositions, outNormals, from, to);
                } catch (RuntimeException | Error e) {
                    failure = e;
                }
                done = seen;
            }
        }
    }
}
