package org.skinlab.desktop.bench;

import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import java.util.function.IntConsumer;

/**
 * A fixed pool that runs one task over the items {@code 0 .. count-1} of a frame on several
 * threads, the caller's included: each thread takes the next item from a shared counter until none
 * is left, so a thread the machine leaves waiting costs at most the item it holds (a crowd's items
 * are characters, some microseconds each). {@link org.skinlab.skinning.ParallelSkinner} splits one
 * mesh's points and keeps chunks of thousands of points; this splits whole characters.
 *
 * <p>Per frame nothing is allocated and no thread started. One word holds the frame's generation
 * (high half) and the next unclaimed item (low half); a thread claims an item by compare-and-set
 * only while the generation is the one it works on, so a worker still finishing a frame cannot
 * take an item of the next. {@link #run} first bars claims (the new generation with an index no
 * count reaches), then sets the count, then opens the word at item 0: the task's inputs, written
 * by the caller before run, and the count are visible to whoever claims. A frame starts only when
 * every item of the last one is done. Workers spin briefly, then park until the next frame.
 * One caller at a time; {@link #close()} stops the workers.
 */
public final class CrowdThreads implements AutoCloseable {
    /** Spins of a waiting thread before it parks (worker) or yields (caller). */
    private static final int SPIN = 2_000;
    /** The index of a barred word: above any count. */
    private static final int BARRED = Integer.MAX_VALUE;

    private final IntConsumer task;
    private final Thread[] workers;
    private final AtomicLong claim = new AtomicLong((long) BARRED);
    private final AtomicInteger doneByWorkers = new AtomicInteger();
    private final AtomicReference<Throwable> failure = new AtomicReference<>();
    private volatile int count;
    private int generation;
    private volatile boolean closed;
    /** Items the workers have run over every frame so far (the caller's count). */
    private long workerItems;

    /** {@code threads} in all, the caller's included (1: the caller runs every item). */
    CrowdThreads(int threads, IntConsumer task) {
        if (threads < 1) {
            throw new IllegalArgumentException("threads must be at least 1, was " + threads);
        }
        this.task = task;
        workers = new Thread[threads - 1];
        for (int i = 0; i < workers.length; i++) {
            workers[i] = new Thread(this::work, "skinlab-crowd-" + (i + 1));
            workers[i].setDaemon(true);
            workers[i].start();
        }
    }

    int threads() {
        return workers.length + 1;
    }

    /** Items the workers (not the caller) have run over every frame so far. */
    long workerItems() {
        return workerItems;
    }

    /** The ids of every thread that runs items (for counting their allocations). */
    long[] threadIds(Thread caller) {
        long[] ids = new long[workers.length + 1];
        ids[0] = caller.getId();
        for (int i = 0; i < workers.length; i++) {
            ids[i + 1] = workers[i].getId();
        }
        return ids;
    }

    /** Runs the task on items 0 .. count-1 and returns when all are done; rethrows a task's failure. */
    void run(int items) {
        if (closed) {
            throw new IllegalStateException("CrowdThreads is closed");
        }
        int gen = ++generation;
        claim.set((long) gen << 32 | BARRED);
        count = items;
        doneByWorkers.set(0);
        claim.set((long) gen << 32);
        for (Thread w : workers) {
            LockSupport.unpark(w);
        }
        int mine = 0;
        for (int i = next(gen); i >= 0; i = next(gen)) {
            task.accept(i);
            mine++;
        }
        for (int spins = 0; doneByWorkers.get() + mine < items; spins++) {
            if (spins < SPIN) {
                Thread.onSpinWait();
            } else {
                Thread.yield();
            }
        }
        workerItems += items - mine;
        Throwable t = failure.getAndSet(null);
        if (t instanceof RuntimeException) {
            throw (RuntimeException) t;
        }
        if (t instanceof Error) {
            throw (Error) t;
        }
    }

    /** Claims the next item of generation {@code gen}, or -1 when none is left (or that frame is over). */
    private int next(int gen) {
        while (true) {
            long c = claim.get();
            if ((int) (c >>> 32) != gen || (int) c >= count) {
                return -1;
            }
            if (claim.compareAndSet(c, c + 1)) {
                return (int) c;
            }
        }
    }

    private void work() {
        int seen = 0;
        int spins = 0;
        while (!closed) {
            long c = claim.get();
            int gen = (int) (c >>> 32);
            if (gen == seen || (int) c == BARRED) {
                if (spins++ < SPIN) {
                    Thread.onSpinWait();
                } else {
                    // run unparks after opening a frame, so one opened since the read above
                    // leaves a permit and this park returns at once.
                    LockSupport.park(this);
                    spins = 0;
                }
                continue;
            }
            seen = gen;
            spins = 0;
            for (int i = next(gen); i >= 0; i = next(gen)) {
                try {
                    task.accept(i);
                } catch (RuntimeException | Error e) {
                    failure.compareAndSet(null, e);
                }
                doneByWorkers.incrementAndGet();
            }
        }
    }

    /** Stops the workers (waiting up to a second for each). */
    @Override
    public void close() {
        closed = true;
        for (Thread w : workers) {
            LockSupport.unpark(w);
        }
        for (Thread w : workers) {
            try {
                w.join(1000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }
}
