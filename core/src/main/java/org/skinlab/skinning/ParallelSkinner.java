package org.skinlab.skinning;

import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;

/**
 * Runs any {@link Skinner} over several threads: {@link #skin} (and {@link #skinDeformations}) cuts its range into a few chunks
 * per thread, starting at multiples of the kernel's {@link Skinner#rangeAlignment()}, and the
 * calling thread and a small persistent pool take chunks from a shared counter until none is left.
 * Plain Java (Android-safe).
 *
 * <p><b>Why chunks, not one part per thread.</b> On a shared machine a pool thread may not get a
 * core for milliseconds; with fixed parts the frame would wait for it. Here the caller simply
 * takes the chunks nobody took: a late worker costs at most the chunk it holds, and a frame never
 * takes longer than on one thread by more than that.
 *
 * <p><b>Per frame</b> nothing is allocated and no thread started: the call's arguments go into
 * fields, published by the volatile write of a claim word that holds the frame's generation in
 * its high half and the next chunk in its low half. A worker claims chunks by compare-and-set
 * only while the generation is the one it saw, so a worker that wakes late cannot take a chunk of
 * a later frame with the arguments of an earlier one, and the caller closes each frame's claim
 * before it writes the next frame's arguments. Workers spin briefly ({@link
 * Thread#onSpinWait()}: frames are microseconds apart while animating), then park, and are
 * unparked only if they parked. The caller waits until every chunk is done (spin, then yield).
 *
 * <p>Results are identical to the single-thread kernel's when the kernel's results do not depend
 * on how a mesh is cut into ranges at its alignment (true of the kernels in this project).
 *
 * <p>One caller at a time: {@code skin} must not be called concurrently on one instance (the
 * kernels it wraps may be). Workers are daemon threads; {@link #close()} stops them.
 */
public final class ParallelSkinner implements Skinner, AutoCloseable {
    /** Spins before a waiting thread parks (worker) or yields (caller); some tens of µs. */
    private static final int SPIN = 20_000;
    /**
     * {@link Thread#onSpinWait()} where the platform has it, else a handle that does nothing: the
     * method is Java 9 but Android's only from API 33, and core runs on Android 8 (a direct call
     * would fail there). A constant handle is inlined by the JIT as a direct call is.
     */
    private static final MethodHandle SPIN_WAIT = spinWaitHandle();
    /** Chunks per thread: enough to even out a late start, few enough to keep per-call costs small. */
    private static final int CHUNKS_PER_THREAD = 4;
    /** Points below which a chunk is not worth a handoff. */
    private static final int MIN_CHUNK = 2048;

    private final Skinner kernel;
    private final Thread[] workers;
    private final int alignment;

    // The frame being skinned: written by the caller before the claim word is published.
    private JointPalette palette;
    private float[] outPositions;
    private float[] outNormals;
    private float[] outDeformations;
    /** Whether the frame being run is a {@link #skinDeformations} call. */
    private boolean deformationsCall;
    private int from;
    private int to;
    private int chunkSize;
    private int chunkCount;

    /** The chunk index of a finished frame's claim: above every chunk count. */
    private static final long CLOSED = Integer.MAX_VALUE;

    /** Generation (high 32 bits) and next unclaimed chunk (low 32 bits). */
    private final AtomicLong claim = new AtomicLong();
    private final AtomicInteger completed = new AtomicInteger();
    private final AtomicReference<Throwable> failure = new AtomicReference<>();
    private final AtomicInteger parked = new AtomicInteger();
    private int generation;
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
        this.alignment = Math.max(1, kernel.rangeAlignment());
        this.workers = new Thread[threads - 1];
        for (int i = 0; i < workers.length; i++) {
            workers[i] = new Thread(this::work, "skinlab-skinning-" + (i + 1));
            workers[i].setDaemon(true);
            workers[i].start();
        }
    }

    /**
     * Threads a frame is split over, the caller's included.
     *
     * @return the thread count given to the constructor, at least 1
     */
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
    public void skin(JointPalette p, float[] positions, float[] normals, int start, int end) {
        run(p, positions, normals, null, false, start, end);
    }

    @Override
    public void skinDeformations(JointPalette p, float[] deformations, int start, int end) {
        run(p, null, null, deformations, true, start, end);
    }

    private void run(JointPalette p, float[] positions, float[] normals, float[] deformations, boolean isDeformations,
            int start, int end) {
        if (closed) {
            throw new IllegalStateException("ParallelSkinner is closed");
        }
        int n = end - start;
        int chunks = Math.min(threads() * CHUNKS_PER_THREAD, n / MIN_CHUNK);
        if (workers.length == 0 || chunks < 2) {
            runKernel(p, positions, normals, deformations, isDeformations, start, end);
            return;
        }
        int size = (n + chunks - 1) / chunks;
        size = (size + alignment - 1) / alignment * alignment;
        palette = p;
        outPositions = positions;
        outNormals = normals;
        outDeformations = deformations;
        deformationsCall = isDeformations;
        from = start;
        to = end;
        chunkSize = size;
        // Chunk c starts at the first multiple of the alignment at or after from + c * size.
        chunkCount = (int) ((end - firstBoundary(start) + size - 1) / size);
        completed.set(0);
        failure.set(null);
        generation++;
        claim.set((long) generation << 32); // publishes the fields above
        if (parked.get() > 0) {
            for (Thread w : workers) {
                LockSupport.unpark(w);
            }
        }
        int done = runChunks(generation, true);
        for (int spins = 0; completed.get() + done < chunkCount; spins++) {
            if (spins < SPIN) {
                spinWait();
            } else {
                Thread.yield();
            }
        }
        // Close the frame before the next call rewrites the fields: a worker still in runChunks
        // may read the next frame's larger chunk count against this frame's exhausted claim, and
        // its compare-and-set must then fail, or it would run and count a chunk of the next frame.
        claim.set(((long) generation << 32) | CLOSED);
        palette = null;
        outPositions = outNormals = outDeformations = null;
        Throwable t = failure.get();
        if (t instanceof RuntimeException) {
            throw (RuntimeException) t;
        }
        if (t instanceof Error) {
            throw (Error) t;
        }
    }

    /** The first chunk boundary after {@code start}: aligned absolute index (blocks are absolute). */
    private long firstBoundary(int start) {
        return (long) start / alignment * alignment;
    }

    /** Chunk c's range: [bound(c), bound(c + 1)) clipped to [from, to). */
    private int bound(int c) {
        long b = firstBoundary(from) + (long) c * chunkSize;
        return (int) Math.max(from, Math.min(to, b));
    }

    /**
     * Takes and runs chunks of frame {@code gen} until none is left. The caller counts its own
     * chunks (returned); a worker adds each to {@link #completed}, after its outputs are written.
     */
    private int runChunks(int gen, boolean caller) {
        int ran = 0;
        while (true) {
            long c = claim.get();
            if ((int) (c >>> 32) != gen || (int) c >= chunkCount) {
                return ran;
            }
            if (!claim.compareAndSet(c, c + 1)) {
                continue;
            }
            int chunk = (int) c;
            try {
                runKernel(palette, outPositions, outNormals, outDeformations, deformationsCall, bound(chunk),
                        bound(chunk + 1));
            } catch (RuntimeException | Error e) {
                failure.compareAndSet(null, e);
            }
            if (caller) {
                ran++;
            } else {
                completed.incrementAndGet();
            }
        }
    }

    private void runKernel(JointPalette p, float[] positions, float[] normals, float[] deformations,
            boolean isDeformations, int start, int end) {
        if (isDeformations) {
            kernel.skinDeformations(p, deformations, start, end);
        } else {
            kernel.skin(p, positions, normals, start, end);
        }
    }

    private void work() {
        int seen = 0;
        while (!closed) {
            int gen = (int) (claim.get() >>> 32);
            if (gen == seen) {
                waitForFrame(seen);
                continue;
            }
            seen = gen;
            runChunks(gen, false);
        }
    }

    private void waitForFrame(int seen) {
        for (int spins = 0; (int) (claim.get() >>> 32) == seen && !closed; spins++) {
            if (spins < SPIN) {
                spinWait();
            } else {
                parked.incrementAndGet();
                // Re-check after announcing: a frame published before the increment would
                // otherwise find no one to unpark (lost wake-up).
                if ((int) (claim.get() >>> 32) == seen && !closed) {
                    LockSupport.park(this);
                }
                parked.decrementAndGet();
                spins = 0;
            }
        }
    }

    /** Stops the worker threads (waiting up to a second for each); skinning afterwards throws. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
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

    private static MethodHandle spinWaitHandle() {
        MethodType noArguments = MethodType.methodType(void.class);
        try {
            return MethodHandles.publicLookup().findStatic(Thread.class, "onSpinWait", noArguments);
        } catch (NoSuchMethodException | IllegalAccessException e) {
            // A handle returning a constant, its result dropped: does nothing.
            return MethodHandles.constant(Integer.class, 0).asType(noArguments);
        }
    }

    private static void spinWait() {
        try {
            SPIN_WAIT.invokeExact();
        } catch (RuntimeException | Error e) {
            throw e;
        } catch (Throwable e) {
            throw new AssertionError("neither spin-wait handle throws a checked exception", e);
        }
    }
}
