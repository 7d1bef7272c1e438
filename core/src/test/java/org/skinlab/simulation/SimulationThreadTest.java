package org.skinlab.simulation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertSame;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.SplittableRandom;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import java.util.concurrent.locks.LockSupport;
import java.util.function.BooleanSupplier;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.testing.TestPaths;

/**
 * The simulation thread's life: start, stop, close from any thread and in any order, failures that
 * must not vanish, interrupts, its pace, and a real asset playing on it. Timeouts run in a
 * separate thread, so a deadlock fails the test instead of hanging the build.
 */
@Timeout(value = 30, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class SimulationThreadTest {
    private static final Model RIBBON = TwistRibbon.model();
    private static final String THREAD_PREFIX = "skinlab-simulation-";

    private static SkeletalAnimatedMesh ribbon(AnimationConfig config) {
        return new SkeletalAnimatedMesh(RIBBON, RIBBON.clips().get(0), config);
    }

    /** Polls until the condition holds; fails after {@code seconds}. */
    private static void await(String what, double seconds, BooleanSupplier condition) throws InterruptedException {
        long deadline = System.nanoTime() + (long) (seconds * 1e9);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() - deadline > 0) {
                fail("timed out after " + seconds + " s waiting for " + what);
            }
            Thread.sleep(2);
        }
    }

    private static boolean liveThreadNamed(String name) {
        return Thread.getAllStackTraces().keySet().stream().anyMatch(t -> t.isAlive() && t.getName().equals(name));
    }

    /**
     * A frame listener that notes the threads it runs on and then runs {@code then}. The listener
     * runs on the thread that stepped, so after {@link SkeletalAnimatedMesh#start()} it meets the
     * simulation thread: the tests watch that thread without the mesh handing it out.
     */
    private static final class ThreadWitness implements Runnable {
        private final Runnable then;
        private final Set<Thread> seen = ConcurrentHashMap.newKeySet();
        private volatile Thread last;

        ThreadWitness(Runnable then) {
            this.then = then;
        }

        @Override
        public void run() {
            Thread t = Thread.currentThread();
            seen.add(t);
            last = t;
            then.run();
        }

        /** Every thread the listener ran on so far. */
        Set<Thread> seen() {
            return Set.copyOf(seen);
        }

        /** Waits for a frame published by a simulation thread other than {@code previous}; returns that thread. */
        Thread awaitSimulationThread(Thread previous) throws InterruptedException {
            AtomicReference<Thread> found = new AtomicReference<>();
            await("a frame from a new simulation thread", 5, () -> {
                Thread t = last;
                if (t != null && t != previous && t.getName().startsWith(THREAD_PREFIX)) {
                    found.set(t);
                }
                return found.get() != null;
            });
            return found.get();
        }
    }

    @Test
    void closeStopsTheThreadAndStartAfterCloseFailsClearly() throws Exception {
        SkeletalAnimatedMesh mesh = ribbon(new AnimationConfig());
        ThreadWitness witness = new ThreadWitness(() -> { });
        mesh.setFrameListener(witness);
        assertTrue(mesh.start());
        Thread thread = witness.awaitSimulationThread(null);
        assertTrue(thread.isDaemon());
        assertTrue(thread.getName().startsWith(THREAD_PREFIX), thread.getName());
        assertTrue(liveThreadNamed(thread.getName()));
        await("a few steps", 5, () -> mesh.latestSequence() >= 3);

        mesh.close();
        assertFalse(thread.isAlive(), "close() returned before the thread ended");
        assertFalse(liveThreadNamed(thread.getName()));
        assertFalse(mesh.isRunning());
        IllegalStateException e = assertThrows(IllegalStateException.class, mesh::start);
        assertTrue(e.getMessage().contains("closed"), e.getMessage());
        assertThrows(IllegalStateException.class, () -> mesh.step(0.1));
        mesh.close(); // twice is fine
        assertFalse(mesh.stop());
        // The last frame stays readable after close.
        try (Frame f = mesh.acquire()) {
            assertNull(FrameChecker.ribbon(RIBBON).problem(f));
        }
    }

    @Test
    void startTwiceRunsOneThreadAndStopBeforeStartIsHarmless() throws Exception {
        try (SkeletalAnimatedMesh mesh = ribbon(new AnimationConfig())) {
            ThreadWitness witness = new ThreadWitness(() -> { });
            mesh.setFrameListener(witness);
            assertFalse(mesh.stop());
            assertTrue(mesh.start());
            Thread first = witness.awaitSimulationThread(null);
            assertFalse(mesh.start());
            long seen = mesh.latestSequence();
            await("more steps", 5, () -> mesh.latestSequence() >= seen + 3);
            assertEquals(Set.of(first), witness.seen(), "a second start began another thread");
            assertThrows(IllegalStateException.class, () -> mesh.step(0.1), "hand steps while the thread runs");
            assertTrue(mesh.stop());
            assertFalse(first.isAlive());
            assertFalse(mesh.stop());
            mesh.step(0.1); // allowed again once stopped
            assertTrue(mesh.start()); // and a stopped mesh restarts on a new thread
            assertTrue(witness.awaitSimulationThread(first) != first && mesh.isRunning());
        }
    }

    @Test
    void startStopPauseAndSwitchSpamFromManyThreadsEndsWithoutDeadlock() throws Exception {
        AnimationConfig config = new AnimationConfig();
        SkeletalAnimatedMesh mesh = ribbon(config);
        mesh.setStepRate(2000);
        // A listener that now and then works a little, then stops the thread from the thread
        // itself ("stop after N frames"), racing the spammers' own stops and starts. The work
        // widens the window in which a spammer's stop() waits for this thread while this thread
        // calls stop(): a stop() that held its lock while joining would deadlock here.
        AtomicInteger published = new AtomicInteger();
        ThreadWitness witness = new ThreadWitness(() -> {
            if (published.incrementAndGet() % 8 == 0) {
                LockSupport.parkNanos(200_000);
                mesh.stop();
            }
        });
        mesh.setFrameListener(witness);
        int threads = 6;
        int operations = 3000;
        ConcurrentLinkedQueue<Throwable> unexpected = new ConcurrentLinkedQueue<>();
        AtomicInteger tornFrames = new AtomicInteger();
        CountDownLatch go = new CountDownLatch(1);
        CountDownLatch finished = new CountDownLatch(threads);
        List<Thread> workers = new ArrayList<>();
        for (int w = 0; w < threads; w++) {
            long seed = w;
            Thread t = new Thread(() -> {
                SplittableRandom random = new SplittableRandom(seed);
                FrameChecker checker = FrameChecker.ribbon(RIBBON);
                try {
                    go.await();
                    for (int i = 0; i < operations; i++) {
                        switch (random.nextInt(10)) {
                            case 0 -> mesh.start();
                            case 1 -> mesh.stop();
                            case 2 -> {
                                try {
                                    mesh.step(0.01);
                                } catch (IllegalStateException running) {
                                    // expected while the thread runs
                                }
                            }
                            case 3 -> config.setAnimationRunning(random.nextBoolean());
                            case 4 -> config.setMeshUpdatesRunning(random.nextInt(4) > 0);
                            case 5 -> config.nextMethod();
                            case 6 -> {
                                config.nextInterpolation();
                                config.setCpuSkinning(random.nextInt(4) > 0);
                            }
                            case 7 -> {
                                if (random.nextBoolean()) {
                                    config.faster();
                                } else {
                                    config.slower();
                                }
                            }
                            case 8 -> mesh.setStepRate(random.nextDouble(50, 5000));
                            default -> {
                                try (Frame f = mesh.acquire()) {
                                    if (checker.problem(f) != null) {
                                        tornFrames.incrementAndGet();
                                    }
                                }
                            }
                        }
                        // Let the thread live a little between operations, as a user's clicks would.
                        LockSupport.parkNanos(random.nextInt(100_000));
                    }
                } catch (Throwable e) {
                    unexpected.add(e);
                } finally {
                    finished.countDown();
                }
            }, "test-spam-" + w);
            t.start();
            workers.add(t);
        }
        go.countDown();
        if (!finished.await(10, TimeUnit.SECONDS)) {
            StringBuilder dump = new StringBuilder();
            Thread.getAllStackTraces().forEach((t, stack) -> {
                dump.append(t.getName()).append(' ').append(t.getState()).append('\n');
                for (StackTraceElement e : stack) {
                    dump.append("    at ").append(e).append('\n');
                }
            });
            fail("spam did not finish within 10 s (deadlock?)\n" + dump);
        }
        for (Thread t : workers) {
            t.join();
        }
        assertTrue(unexpected.isEmpty(), () -> "unexpected: " + unexpected);
        assertEquals(0, tornFrames.get());
        assertNull(mesh.failure());
        mesh.close();
        // Every thread that published (simulation threads, and the spammers' hand steps) has ended.
        assertTrue(witness.seen().stream().noneMatch(Thread::isAlive), () -> "still alive: " + witness.seen());
        // Every thread any spammer started has ended: each was stopped (and joined) by a stop()
        // that returned, or by the close() above.
        assertFalse(Thread.getAllStackTraces().keySet().stream()
                .anyMatch(t -> t.isAlive() && t.getName().startsWith(THREAD_PREFIX)),
                "a simulation thread outlived close()");
    }

    @Test
    void aFailureOnTheSimulationThreadIsKeptStopsItAndIsReported() throws Exception {
        try (SkeletalAnimatedMesh mesh = ribbon(new AnimationConfig())) {
            mesh.setStepRate(1000);
            RuntimeException boom = new RuntimeException("boom from the frame listener");
            AtomicInteger calls = new AtomicInteger();
            ThreadWitness witness = new ThreadWitness(() -> {
                if (calls.incrementAndGet() == 5) {
                    throw boom;
                }
            });
            mesh.setFrameListener(witness);
            mesh.start();
            Thread thread = witness.awaitSimulationThread(null);
            await("the thread to end", 5, () -> !thread.isAlive());
            assertSame(boom, mesh.failure());
            assertFalse(mesh.isRunning());
            IllegalStateException reported = assertThrows(IllegalStateException.class, mesh::throwIfFailed);
            assertSame(boom, reported.getCause());
            assertSame(boom, assertThrows(IllegalStateException.class, mesh::start).getCause());
            assertSame(boom, assertThrows(IllegalStateException.class, () -> mesh.step(0.1)).getCause());
            // Readers keep the frame the failing step published, whole.
            try (Frame f = mesh.acquire()) {
                assertEquals(5, f.sequence());
                assertNull(FrameChecker.ribbon(RIBBON).problem(f));
            }
        }
    }

    @Test
    void interruptingTheSimulationThreadStopsItAndItCanStartAgain() throws Exception {
        try (SkeletalAnimatedMesh mesh = ribbon(new AnimationConfig())) {
            ThreadWitness witness = new ThreadWitness(() -> { });
            mesh.setFrameListener(witness);
            mesh.start();
            Thread thread = witness.awaitSimulationThread(null);
            thread.interrupt();
            await("the interrupted thread to end", 5, () -> !thread.isAlive());
            assertFalse(mesh.isRunning());
            assertNull(mesh.failure());
            assertTrue(mesh.start());
            long seen = mesh.latestSequence();
            await("frames from the new thread", 5, () -> mesh.latestSequence() > seen);
        }
    }

    @Test
    void methodSwitchShowsOnThePausedThread() throws Exception {
        AnimationConfig config = new AnimationConfig();
        try (SkeletalAnimatedMesh mesh = ribbon(config)) {
            mesh.step(1.5);
            config.stopAnimation();
            mesh.setStepRate(200);
            mesh.start();
            long before = mesh.latestSequence();
            await("steps on the thread", 5, () -> mesh.latestSequence() >= before + 3);
            config.setMethod(SkinningMethod.DQS);
            await("a DQS frame", 5, () -> {
                try (Frame f = mesh.acquire()) {
                    return f.method() == SkinningMethod.DQS;
                }
            });
            try (Frame f = mesh.acquire()) {
                assertEquals(1.5f, f.clipTime(), 1e-6f, "the paused clock moved");
                assertNull(FrameChecker.ribbon(RIBBON).problem(f));
            }
        }
    }

    @Test
    void seekWhileThePausedThreadRunsShowsTheNewTime() throws Exception {
        AnimationConfig config = new AnimationConfig();
        config.stopAnimation();
        try (SkeletalAnimatedMesh mesh = ribbon(config)) {
            mesh.setStepRate(200);
            mesh.start();
            // A scrubber dragged over a paused animation: each position shows without playing.
            for (double t : new double[] {0.5, 3.0, 1.75}) {
                mesh.seek(t);
                await("the frame at " + t + " s", 5, () -> {
                    try (Frame f = mesh.acquire()) {
                        return Math.abs(f.clipTime() - t) < 1e-6;
                    }
                });
            }
            assertTrue(mesh.isRunning());
            try (Frame f = mesh.acquire()) {
                assertNull(FrameChecker.ribbon(RIBBON).problem(f));
            }
        }
    }

    @Test
    void threadKeepsItsPaceWithoutBurstsAndPlaybackFollowsTheWallClock() throws Exception {
        try (SkeletalAnimatedMesh mesh = ribbon(new AnimationConfig())) {
            double rate = 100;
            mesh.setStepRate(rate);
            long start = System.nanoTime();
            mesh.start();
            Thread.sleep(1000);
            mesh.stop();
            double elapsed = (System.nanoTime() - start) * 1e-9;
            long steps = mesh.stepCount();
            // Absolute deadlines never run ahead of the clock: at most one step per period (plus
            // the one at the end of the first period being counted early).
            assertTrue(steps <= rate * elapsed + 1, () -> steps + " steps in " + elapsed + " s at " + rate + " Hz");
            // A loaded machine may be late, but not by half (generous: CI shares two cores).
            assertTrue(steps >= rate * elapsed * 0.5, () -> "only " + steps + " steps in " + elapsed + " s");
            // dt is the measured time between steps, so playback ends within a step of wall time
            // since the first step (one period after start).
            double playback = mesh.playbackTime();
            assertTrue(playback <= elapsed && playback >= elapsed - 3 / rate - 0.1,
                    () -> "playback " + playback + " s after " + elapsed + " s");
        }
    }

    @Test
    void humanoidWalkPlaysOnTheThreadAndItsFramesAdvance() throws Exception {
        Model model = ColladaImporter.read(TestPaths.asset("characters/humanoid-walk.dae"));
        AnimationConfig config = new AnimationConfig();
        config.setInterpolation(RotationInterpolation.NLERP);
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(model, model.clips().get(0).name(), config)) {
            FrameChecker checker = new FrameChecker(model, mesh.clip(), false);
            ThreadWitness witness = new ThreadWitness(() -> { });
            mesh.setFrameListener(witness);
            long first;
            float firstTime;
            float[] firstPositions;
            try (Frame f = mesh.acquire()) {
                first = f.sequence();
                firstTime = f.clipTime();
                firstPositions = f.positions(0).clone();
            }
            mesh.start();
            Thread.sleep(300);
            await("ten frames", 5, () -> mesh.latestSequence() >= first + 10);
            config.setMethod(SkinningMethod.DQS);
            await("a DQS frame", 5, () -> {
                try (Frame f = mesh.acquire()) {
                    return f.method() == SkinningMethod.DQS;
                }
            });
            try (Frame f = mesh.acquire()) {
                assertTrue(f.sequence() >= first + 10);
                assertTrue(f.clipTime() != firstTime, "clip time did not advance");
                float[] p = f.positions(0);
                double moved = 0;
                for (int i = 0; i < p.length; i++) {
                    moved = Math.max(moved, Math.abs(p[i] - firstPositions[i]));
                }
                assertTrue(moved > 1e-3, "no vertex moved: " + moved);
                assertNull(checker.problem(f));
                assertTrue(f.skinningNanos() > 0);
            }
            assertNull(mesh.failure());
            assertTrue(witness.seen().stream().anyMatch(t -> t.getName().startsWith(THREAD_PREFIX)),
                    () -> "no frame came from a simulation thread: " + witness.seen());
        }
    }
}
