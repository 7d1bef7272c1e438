package org.skinlab.simulation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.skinlab.model.Model;

/**
 * The frame listener runs after the step lock is released: a listener that blocks must not stall
 * other threads' steps. Each test parks the listener on a latch and has another thread do what
 * needs the step lock; the latch is released only afterwards, so a listener holding the lock
 * would keep that thread waiting until the generous {@link #WAIT_SECONDS} expire (a failure, not
 * a hang). No sleeps decide anything.
 */
@Timeout(value = 30, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class FrameListenerTest {
    private static final Model RIBBON = TwistRibbon.model();
    /** Long enough for any loaded machine; reached only when the lock is (wrongly) held. */
    private static final long WAIT_SECONDS = 10;

    private static SkeletalAnimatedMesh ribbon() {
        return new SkeletalAnimatedMesh(RIBBON, RIBBON.clips().get(0), new AnimationConfig());
    }

    /** A listener whose first call signals {@code entered} and then waits for {@code release}. */
    private static Runnable blockingOnFirstCall(AtomicInteger calls, CountDownLatch entered, CountDownLatch release) {
        return () -> {
            if (calls.incrementAndGet() == 1) {
                entered.countDown();
                try {
                    release.await();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        };
    }

    /** Runs {@code action} on another thread and fails unless it ends within {@link #WAIT_SECONDS}. */
    private static void completesWhileTheListenerBlocks(String what, ThrowingAction action) throws Exception {
        AtomicReference<Throwable> thrown = new AtomicReference<>();
        CountDownLatch done = new CountDownLatch(1);
        Thread t = new Thread(() -> {
            try {
                action.run();
            } catch (Throwable e) {
                thrown.set(e);
            } finally {
                done.countDown();
            }
        }, "test-while-listener-blocks");
        t.setDaemon(true);
        t.start();
        if (!done.await(WAIT_SECONDS, TimeUnit.SECONDS)) {
            fail(what + " did not complete while the frame listener blocked: the step lock is held during it");
        }
        if (thrown.get() != null) {
            throw new AssertionError(what + " failed", thrown.get());
        }
    }

    private interface ThrowingAction {
        void run() throws Exception;
    }

    @Test
    void aBlockedListenerOnTheSimulationThreadHoldsNoLock() throws Exception {
        try (SkeletalAnimatedMesh mesh = ribbon()) {
            AtomicInteger calls = new AtomicInteger();
            CountDownLatch entered = new CountDownLatch(1);
            CountDownLatch release = new CountDownLatch(1);
            mesh.setFrameListener(blockingOnFirstCall(calls, entered, release));
            mesh.setStepRate(1000);
            try {
                mesh.start();
                assertTrue(entered.await(WAIT_SECONDS, TimeUnit.SECONDS), "the listener was never called");
                long published = mesh.latestSequence();
                completesWhileTheListenerBlocks("taking the step lock", () -> {
                    // Both take the step lock; step refuses only once it holds it.
                    mesh.seek(1.5);
                    assertEquals(1.5, mesh.playbackTime(), 1e-12);
                    IllegalStateException e = assertThrows(IllegalStateException.class, () -> mesh.step(0.1));
                    assertTrue(e.getMessage().contains("running"), e.getMessage());
                    try (Frame f = mesh.acquire()) {
                        assertEquals(published, f.sequence());
                    }
                });
                // The thread is still inside the listener: no step since.
                assertEquals(published, mesh.latestSequence());
                assertEquals(1, calls.get());
            } finally {
                release.countDown();
            }
            mesh.stop();
            assertNull(mesh.failure());
        }
    }

    @Test
    void aBlockedListenerOfAHandStepLetsAnotherThreadStep() throws Exception {
        try (SkeletalAnimatedMesh mesh = ribbon()) {
            AtomicInteger calls = new AtomicInteger();
            CountDownLatch entered = new CountDownLatch(1);
            CountDownLatch release = new CountDownLatch(1);
            mesh.setFrameListener(blockingOnFirstCall(calls, entered, release));
            AtomicReference<Throwable> stepperFailure = new AtomicReference<>();
            Thread stepper = new Thread(() -> {
                try {
                    mesh.step(0.1);
                } catch (Throwable t) {
                    stepperFailure.set(t);
                }
            }, "test-stepper");
            try {
                stepper.start();
                assertTrue(entered.await(WAIT_SECONDS, TimeUnit.SECONDS), "the listener was never called");
                assertEquals(1, mesh.latestSequence(), "the listener ran before its frame was published");
                completesWhileTheListenerBlocks("a second hand step", () -> mesh.step(0.1));
                assertEquals(2, mesh.latestSequence());
                assertEquals(2, calls.get(), "the second step's listener call");
                try (Frame f = mesh.acquire()) {
                    assertEquals(0.2f, f.clipTime(), 1e-6f);
                }
            } finally {
                release.countDown();
                stepper.join();
            }
            assertNull(stepperFailure.get());
        }
    }

    @Test
    void whatTheListenerThrowsOnAHandStepReachesTheCallerAfterThePublish() {
        try (SkeletalAnimatedMesh mesh = ribbon()) {
            RuntimeException boom = new RuntimeException("boom from the frame listener");
            mesh.setFrameListener(() -> {
                throw boom;
            });
            assertSame(boom, assertThrows(RuntimeException.class, () -> mesh.step(0.1)));
            assertEquals(1, mesh.latestSequence(), "the frame is published before the listener runs");
            // A hand step's failure is the caller's, not the simulation's: the mesh steps on.
            assertNull(mesh.failure());
            mesh.setFrameListener(null);
            mesh.step(0.1);
            assertEquals(2, mesh.latestSequence());
        }
    }

    @Test
    void noListenerCallForAStepThatPublishesNothing() {
        AnimationConfig config = new AnimationConfig();
        try (SkeletalAnimatedMesh mesh = new SkeletalAnimatedMesh(RIBBON, RIBBON.clips().get(0), config)) {
            AtomicInteger calls = new AtomicInteger();
            mesh.setFrameListener(calls::incrementAndGet);
            mesh.step(0.1);
            config.stopMeshUpdates();
            mesh.step(0.1);
            assertEquals(1, calls.get());
        }
    }
}
