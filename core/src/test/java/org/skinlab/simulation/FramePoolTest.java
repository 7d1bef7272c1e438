package org.skinlab.simulation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNotSame;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * The snapshot protocol, one interleaving at a time: each test plays the reader's two steps
 * ({@link FramePool#peekLatest()}, {@link FramePool#tryLease}) and the writer's
 * ({@link FramePool#claim()}, {@link FramePool#publish}) in a chosen order on one thread. The
 * stress test ({@link TornFrameTest}) cannot aim at the few nanoseconds between a reader's two
 * steps; these tests can.
 */
@Timeout(5)
class FramePoolTest {
    private static FramePool pool() {
        float[] identities = new float[32];
        identities[0] = identities[5] = identities[10] = identities[15] = 1f;
        identities[16] = identities[21] = identities[26] = identities[31] = 1f;
        SkinnedGeometry geometry = SkinnedGeometry.fromArrays(new float[12], new float[12], 1, new int[4],
                new float[] {1, 1, 1, 1}, identities);
        FramePool pool = new FramePool(List.of(geometry), new boolean[1], SkeletalAnimatedMesh.MAX_BUFFERS);
        pool.publish(pool.claim());
        return pool;
    }

    @Test
    void aWriterNeverClaimsTheLatestFrame() {
        FramePool pool = pool();
        assertNotSame(pool.peekLatest(), pool.claim());
    }

    @Test
    void aFrameLeasedBeforeTheWriterLooksIsNeverClaimed() {
        FramePool pool = pool();
        Frame f = pool.peekLatest();
        assertTrue(pool.tryLease(f));
        Frame g = pool.claim();
        pool.publish(g);
        Frame next = pool.claim();
        assertNotSame(f, next, "the writer claimed a leased frame");
        assertNotSame(g, next);
        f.close();
        assertEquals(0, f.leases.get());
    }

    @Test
    void aReaderWhoseFrameWasClaimedBeforeItsLeaseStepsBackAndRetries() {
        // The race the re-check in tryLease exists for: the reader has read the latest frame f;
        // before it counts itself in, the writer publishes g, claims f (no lease yet, no longer
        // the latest) and starts filling it. The lease must be refused, or the reader would hold
        // a frame being written.
        FramePool pool = pool();
        Frame f = pool.peekLatest();
        Frame g = pool.claim();
        pool.publish(g);
        Frame writing = pool.claim();
        assertSame(f, writing, "setup: with three buffers the writer reuses f once g is out");
        assertFalse(pool.tryLease(f), "a reader leased a frame the writer is filling");
        assertEquals(0, f.leases.get(), "a refused lease must be given back");
        try (Frame acquired = pool.acquire()) {
            assertSame(g, acquired);
        }
    }

    @Test
    void aFrameClaimedFilledAndRepublishedBeforeTheLeaseIsFineToLease() {
        // ABA: f stops being the latest, is refilled and becomes the latest again between the
        // reader's two steps. The reader gets it complete, and from then on the writer skips it.
        FramePool pool = pool();
        Frame f = pool.peekLatest();
        pool.publish(pool.claim());
        assertSame(f, pool.claim());
        pool.publish(f);
        assertTrue(pool.tryLease(f));
        pool.publish(pool.claim());
        assertNotSame(f, pool.claim());
        f.close();
    }

    @Test
    void readersHoldingEveryBufferMakeThePoolGrowThenClaimReturnsNull() {
        FramePool pool = pool();
        List<Frame> held = new ArrayList<>();
        int published = 1;
        // Bounded: a pool that ignored leases would hand out buffers forever.
        for (int i = 0; i < 2 * SkeletalAnimatedMesh.MAX_BUFFERS; i++) {
            held.add(pool.acquire());
            Frame next = pool.claim();
            if (next == null) {
                break;
            }
            pool.publish(next);
            published++;
        }
        // Every buffer was published once and then held: as many distinct frames as buffers.
        Set<Frame> buffers = Collections.newSetFromMap(new IdentityHashMap<>());
        buffers.addAll(held);
        assertEquals(SkeletalAnimatedMesh.MAX_BUFFERS, buffers.size());
        assertEquals(SkeletalAnimatedMesh.MAX_BUFFERS, published);
        held.get(0).close();
        Frame freed = pool.claim();
        assertNotNull(freed);
        assertSame(held.get(0), freed);
        held.subList(1, held.size()).forEach(Frame::close);
    }
}
