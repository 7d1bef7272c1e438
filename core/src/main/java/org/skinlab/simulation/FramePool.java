package org.skinlab.simulation;

import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;

import org.skinlab.skinning.SkinnedGeometry;

/**
 * The snapshot protocol of {@link SkeletalAnimatedMesh}: reusable {@link Frame} buffers, one of
 * them published as the latest, each with a count of the readers holding it.
 *
 * <p>The writer (one thread at a time) {@link #claim() claims} a buffer that is neither the latest
 * nor leased, fills it, and {@link #publish publishes} it with one atomic store. A reader
 * {@link #acquire() acquires} by {@link #peekLatest() reading the latest} and then
 * {@link #tryLease leasing} it: count itself in, then check the buffer is still the latest (else
 * step back and retry). Why no reader ever holds a buffer the writer is filling: the writer claims
 * only a buffer that has stopped being the latest, and checks its lease count after that; the
 * reader counts itself in before re-checking. All of these are sequentially consistent atomics, so
 * either the writer's check comes after the reader's count (the writer skips the buffer) or the
 * reader's re-check comes after the buffer stopped being the latest (the reader retries). A buffer
 * that became the latest again in between (claimed, filled, republished: ABA) is complete when the
 * re-check sees it, so that case is harmless.
 *
 * <p>Nobody waits: a reader retries only when a frame was published between its two reads; the
 * writer scans a handful of buffers. With one reader three buffers always leave one free; readers
 * holding more make the pool grow up to {@link SkeletalAnimatedMesh#MAX_BUFFERS}, and beyond that
 * {@link #claim()} returns null and the step publishes nothing.
 */
final class FramePool {
    private static final int INITIAL_BUFFERS = 3;

    private final List<SkinnedGeometry> geometries;
    private final boolean[] morphing;
    private final int maxBuffers;
    private final AtomicReference<Frame> latest = new AtomicReference<>();
    /** Writer side only. */
    private Frame[] buffers;

    /**
     * @param geometries the geometries a frame carries
     * @param morphing   per geometry, whether its rest shape morphs ({@link Frame#restPositions})
     */
    FramePool(List<SkinnedGeometry> geometries, boolean[] morphing, int maxBuffers) {
        this.geometries = List.copyOf(geometries);
        this.morphing = morphing.clone();
        this.maxBuffers = maxBuffers;
        buffers = new Frame[Math.min(INITIAL_BUFFERS, maxBuffers)];
        for (int i = 0; i < buffers.length; i++) {
            buffers[i] = new Frame(this.geometries, this.morphing);
        }
    }

    // ------------------------------------------------------------------------------ readers

    /** The latest frame, leased; valid until its {@link Frame#close()}. Call after the first publish. */
    Frame acquire() {
        while (true) {
            Frame f = peekLatest();
            if (tryLease(f)) {
                return f;
            }
        }
    }

    /** Step one of {@link #acquire()}: the latest frame, not yet leased (it may be reclaimed any time). */
    Frame peekLatest() {
        return latest.get();
    }

    /**
     * Step two of {@link #acquire()}: leases {@code f} if it is still the latest frame; otherwise
     * leaves it alone and returns false (the caller starts over).
     */
    boolean tryLease(Frame f) {
        f.leases.incrementAndGet();
        if (latest.get() == f) {
            return true;
        }
        f.leases.decrementAndGet();
        return false;
    }

    // ------------------------------------------------------------------------------ writer

    /** A buffer to fill: neither the latest nor leased. Null when every buffer is held. */
    Frame claim() {
        Frame shown = latest.get();
        for (Frame f : buffers) {
            if (f != shown && f.leases.get() == 0) {
                return f;
            }
        }
        if (buffers.length < maxBuffers) {
            buffers = Arrays.copyOf(buffers, buffers.length + 1);
            Frame f = new Frame(geometries, morphing);
            buffers[buffers.length - 1] = f;
            return f;
        }
        return null;
    }

    /** Makes a filled buffer the latest; the volatile store makes its contents visible to readers. */
    void publish(Frame f) {
        latest.set(f);
    }
}
