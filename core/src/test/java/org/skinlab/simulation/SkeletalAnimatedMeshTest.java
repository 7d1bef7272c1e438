package org.skinlab.simulation;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.WrapMode;
import org.skinlab.collada.Fixtures;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningMethod;

/**
 * The simulation step, driven by hand with {@link SkeletalAnimatedMesh#step(double)} so that time
 * is deterministic: playback speed and wrapping, what a paused animation and stopped mesh updates
 * do, and the frame pool's promise that a held frame never changes.
 */
@Timeout(10)
class SkeletalAnimatedMeshTest {
    private static final Model RIBBON = TwistRibbon.model();
    /** Clip times are floats: a time reached by adding doubles, stored as a float. */
    private static final float TIME_TOLERANCE = 1e-6f;

    private static SkeletalAnimatedMesh ribbon(AnimationConfig config) {
        return new SkeletalAnimatedMesh(RIBBON, RIBBON.clips().get(0), config);
    }

    private static float clipTime(SkeletalAnimatedMesh mesh) {
        try (Frame f = mesh.acquire()) {
            return f.clipTime();
        }
    }

    @Test
    void meshPublishesTheClipStartBeforeAnyStep() {
        try (SkeletalAnimatedMesh mesh = ribbon(new AnimationConfig())) {
            try (Frame f = mesh.acquire()) {
                assertEquals(0, f.sequence());
                assertEquals(0f, f.clipTime());
                assertEquals(1, f.geometryCount());
                assertNull(FrameChecker.ribbon(RIBBON).problem(f));
            }
        }
    }

    @Test
    void positionsOnlyIsRefusedSinceFramesCarryNormals() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> new SkeletalAnimatedMesh(
                RIBBON, RIBBON.clips().get(0), new AnimationConfig(), NormalTransform.NONE));
        assertTrue(e.getMessage().contains("NormalTransform.NONE"), e.getMessage());
    }

    @Test
    void speedTwoAdvancesClipTimeTwiceAsFast() {
        AnimationConfig normal = new AnimationConfig();
        AnimationConfig fast = new AnimationConfig();
        fast.setSpeed(2);
        try (SkeletalAnimatedMesh a = ribbon(normal); SkeletalAnimatedMesh b = ribbon(fast)) {
            for (int i = 0; i < 5; i++) {
                a.step(0.1);
                b.step(0.1);
            }
            // Expected: steps * dt * speed, from the clip's start at 0.
            assertEquals(0.5, a.playbackTime(), 1e-12);
            assertEquals(1.0, b.playbackTime(), 1e-12);
            assertEquals(0.5f, clipTime(a), TIME_TOLERANCE);
            assertEquals(1.0f, clipTime(b), TIME_TOLERANCE);
        }
    }

    @Test
    void loopWrapsPastTheEndOfTheClip() {
        try (SkeletalAnimatedMesh mesh = ribbon(new AnimationConfig())) {
            mesh.step(3.9);
            mesh.step(0.5);
            // 4.4 s of playback in a 4 s clip: 0.4 s into the second round.
            assertEquals(0.4, mesh.playbackTime(), 1e-9);
            try (Frame f = mesh.acquire()) {
                assertEquals(0.4f, f.clipTime(), TIME_TOLERANCE);
                assertNull(FrameChecker.ribbon(RIBBON).problem(f));
            }
        }
    }

    @Test
    void clampHoldsTheLastPoseAtTheEndOfTheClip() {
        AnimationConfig config = new AnimationConfig();
        config.setWrapMode(WrapMode.CLAMP);
        try (SkeletalAnimatedMesh mesh = ribbon(config)) {
            mesh.step(3.9);
            mesh.step(0.5);
            assertEquals(TwistRibbon.END, clipTime(mesh));
            mesh.step(10);
            try (Frame f = mesh.acquire()) {
                assertEquals(TwistRibbon.END, f.clipTime());
                assertNull(FrameChecker.ribbon(RIBBON).problem(f)); // the axis vertices sit at x = 4
            }
            // Switching to LOOP at the end carries on from the start.
            config.setWrapMode(WrapMode.LOOP);
            mesh.step(0.25);
            assertEquals(0.25f, clipTime(mesh), TIME_TOLERANCE);
        }
    }

    @Test
    void negativeSpeedPlaysBackwardsAndLoopsFromTheEnd() {
        AnimationConfig config = new AnimationConfig();
        config.setSpeed(-1);
        try (SkeletalAnimatedMesh mesh = ribbon(config)) {
            mesh.step(0.3);
            assertEquals(3.7, mesh.playbackTime(), 1e-9);
            config.setWrapMode(WrapMode.CLAMP);
            mesh.step(5);
            assertEquals(0f, clipTime(mesh));
        }
    }

    @Test
    void pausedAnimationStillReskinsWhenTheMethodSwitches() {
        AnimationConfig config = new AnimationConfig();
        try (SkeletalAnimatedMesh mesh = ribbon(config)) {
            mesh.step(1.5);
            config.stopAnimation();
            mesh.step(0.1);
            SkinnedGeometry geometry = mesh.geometries().get(0);
            // At 1.5 s Tip is twisted 180 degrees against Root (SLERP halfway from 120 to 240). The
            // vertices at x = 1 are half Root, half Tip, both turning about the x axis: LBS averages
            // y and -y onto the axis (radius 0), DQS turns them by the half angle (radius 0.5).
            long lbsSequence;
            try (Frame f = mesh.acquire()) {
                assertEquals(SkinningMethod.LBS, f.method());
                assertEquals(1.5f, f.clipTime(), TIME_TOLERANCE);
                assertEquals(0.0, radius(f, geometry, 16), 1e-5);
                lbsSequence = f.sequence();
            }
            config.setMethod(SkinningMethod.DQS);
            mesh.step(0.1);
            try (Frame f = mesh.acquire()) {
                assertEquals(SkinningMethod.DQS, f.method());
                assertEquals(1.5f, f.clipTime(), TIME_TOLERANCE);
                assertTrue(f.sequence() > lbsSequence);
                assertEquals(0.5, radius(f, geometry, 16), 1e-5);
                assertEquals(0.5, radius(f, geometry, 17), 1e-5);
                assertNull(FrameChecker.ribbon(RIBBON).problem(f));
            }
            assertEquals(1.5, mesh.playbackTime(), 1e-12);
        }
    }

    @Test
    void pausedAnimationStillReskinsWhenTheInterpolationSwitches() {
        AnimationConfig config = new AnimationConfig();
        try (SkeletalAnimatedMesh mesh = ribbon(config)) {
            mesh.step(0.5);
            config.stopAnimation();
            SkinnedGeometry geometry = mesh.geometries().get(0);
            // Root turns 0 -> 90 degrees between keys 0 and 1. The vertex at rest (0, -0.5, 0) is
            // rigid on Root: SLERP keeps its radius 0.5; LERP's unnormalised quaternion scales it
            // by cos^2(phi / 4) at the midpoint of keys phi apart (RotationInterpolation.LERP).
            try (Frame f = mesh.acquire()) {
                assertEquals(0.5, radius(f, geometry, 0), 1e-5);
            }
            config.setInterpolation(RotationInterpolation.LERP);
            mesh.step(0.1);
            double shrink = Math.pow(Math.cos(Math.toRadians(90) / 4), 2);
            try (Frame f = mesh.acquire()) {
                assertEquals(RotationInterpolation.LERP, f.interpolation());
                assertEquals(0.5f, f.clipTime(), TIME_TOLERANCE);
                assertEquals(0.5 * shrink, radius(f, geometry, 0), 1e-5);
            }
        }
    }

    @Test
    void stoppedMeshUpdatesKeepTheLastFrameWhileTimeGoesOn() {
        AnimationConfig config = new AnimationConfig();
        try (SkeletalAnimatedMesh mesh = ribbon(config)) {
            mesh.step(1.0);
            long sequence;
            float[] positions;
            try (Frame f = mesh.acquire()) {
                sequence = f.sequence();
                positions = f.positions(0).clone();
            }
            config.stopMeshUpdates();
            config.setMethod(SkinningMethod.DQS);
            for (int i = 0; i < 3; i++) {
                mesh.step(0.5);
            }
            try (Frame f = mesh.acquire()) {
                assertEquals(sequence, f.sequence());
                assertEquals(SkinningMethod.LBS, f.method());
                assertArrayEquals(positions, f.positions(0));
            }
            assertEquals(sequence, mesh.latestSequence());
            // The animation kept running: the clock moved although nothing was skinned.
            assertEquals(2.5, mesh.playbackTime(), 1e-9);
            config.startMeshUpdates();
            mesh.step(0);
            try (Frame f = mesh.acquire()) {
                assertEquals(sequence + 1, f.sequence());
                assertEquals(SkinningMethod.DQS, f.method());
                assertEquals(2.5f, f.clipTime(), TIME_TOLERANCE);
            }
        }
    }

    @Test
    void heldFramesNeverChangeAndAFullPoolDropsStepsInsteadOfBlocking() {
        try (SkeletalAnimatedMesh mesh = ribbon(new AnimationConfig())) {
            FrameChecker checker = FrameChecker.ribbon(RIBBON);
            List<Frame> held = new ArrayList<>();
            List<Long> sequences = new ArrayList<>();
            int rounds = SkeletalAnimatedMesh.MAX_BUFFERS + 4;
            for (int i = 0; i < rounds; i++) {
                Frame f = mesh.acquire();
                held.add(f);
                sequences.add(f.sequence());
                mesh.step(0.05);
            }
            // Each held frame still shows exactly the step it was acquired as.
            for (int i = 0; i < held.size(); i++) {
                assertEquals(sequences.get(i), held.get(i).sequence());
                assertNull(checker.problem(held.get(i)));
            }
            // Holding MAX_BUFFERS - 1 frames leaves the writer only the latest: it must drop, not wait.
            assertTrue(mesh.droppedFrames() > 0, "no step was dropped although every buffer was held");
            // The pool grew to its limit: every buffer was published once and is held.
            Set<Frame> buffers = Collections.newSetFromMap(new IdentityHashMap<>());
            buffers.addAll(held);
            assertEquals(SkeletalAnimatedMesh.MAX_BUFFERS, buffers.size());
            long before = mesh.latestSequence();
            held.forEach(Frame::close);
            mesh.step(0.05);
            assertEquals(before + 1, mesh.latestSequence());
        }
    }

    @Test
    void closingAFrameMoreOftenThanAcquiredFails() {
        try (SkeletalAnimatedMesh mesh = ribbon(new AnimationConfig())) {
            Frame f = mesh.acquire();
            f.close();
            assertThrows(IllegalStateException.class, f::close);
        }
    }

    @Test
    void stepRefusesTimesThatAreNotFiniteAndNonNegative() {
        try (SkeletalAnimatedMesh mesh = ribbon(new AnimationConfig())) {
            assertThrows(IllegalArgumentException.class, () -> mesh.step(-0.1));
            assertThrows(IllegalArgumentException.class, () -> mesh.step(Double.NaN));
            assertThrows(IllegalArgumentException.class, () -> mesh.step(Double.POSITIVE_INFINITY));
            assertEquals(0, mesh.stepCount());
        }
    }

    @Test
    void seekThenStepZeroPublishesTheFrameAtThatTime() {
        try (SkeletalAnimatedMesh sought = ribbon(new AnimationConfig());
                SkeletalAnimatedMesh played = ribbon(new AnimationConfig())) {
            sought.seek(2.5);
            assertEquals(2.5, sought.playbackTime(), 1e-12, "the time is set before any step");
            sought.step(0);
            played.step(2.5);
            try (Frame a = sought.acquire(); Frame b = played.acquire()) {
                assertEquals(2.5f, a.clipTime(), TIME_TOLERANCE);
                // The same time reached two ways poses the same: same code, same inputs.
                assertArrayEquals(b.positions(0), a.positions(0), 0f);
                assertNull(FrameChecker.ribbon(RIBBON).problem(a));
            }
        }
    }

    @Test
    void seekMovesAPausedAnimationWhichThenStaysThere() {
        AnimationConfig config = new AnimationConfig();
        config.stopAnimation();
        try (SkeletalAnimatedMesh mesh = ribbon(config)) {
            mesh.seek(1.25);
            mesh.step(0.5);
            mesh.step(0.5);
            assertEquals(1.25f, clipTime(mesh), TIME_TOLERANCE);
            // Going on from the sought time once playing again.
            config.setAnimationRunning(true);
            mesh.step(0.5);
            assertEquals(1.75f, clipTime(mesh), TIME_TOLERANCE);
        }
    }

    @Test
    void seekWrapsOrClampsAsTheWrapModeSays() {
        AnimationConfig config = new AnimationConfig();
        try (SkeletalAnimatedMesh mesh = ribbon(config)) {
            // LOOP: into [0, 4) as playback wraps.
            mesh.seek(5.5);
            assertEquals(1.5, mesh.playbackTime(), 1e-9);
            mesh.seek(-0.5);
            assertEquals(3.5, mesh.playbackTime(), 1e-9);
            mesh.seek(TwistRibbon.END);
            assertEquals(0.0, mesh.playbackTime(), 1e-9);
            // CLAMP: held at the clip's ends.
            config.setWrapMode(WrapMode.CLAMP);
            mesh.seek(5.5);
            assertEquals(TwistRibbon.END, mesh.playbackTime(), 1e-9);
            mesh.seek(-0.5);
            assertEquals(0.0, mesh.playbackTime(), 1e-9);
        }
    }

    @Test
    void seekRefusesTimesThatAreNotFiniteAndKeepsTheTime() {
        try (SkeletalAnimatedMesh mesh = ribbon(new AnimationConfig())) {
            mesh.seek(1);
            for (double bad : new double[] {Double.NaN, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY}) {
                IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> mesh.seek(bad));
                assertTrue(e.getMessage().contains(String.valueOf(bad)), e.getMessage());
            }
            assertEquals(1.0, mesh.playbackTime(), 1e-12);
        }
    }

    @Test
    void clipDurationIsTheClipsLengthAndZeroAtRest() {
        try (SkeletalAnimatedMesh mesh = ribbon(new AnimationConfig())) {
            assertEquals(TwistRibbon.END, mesh.clipDuration(), 1e-9);
        }
        Model still = Fixtures.resource("geometry/several-primitives.dae");
        assertTrue(still.clips().isEmpty(), "the fixture has a clip: this test needs a model without one");
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(still)) {
            assertEquals(0.0, mesh.clipDuration());
            mesh.seek(3);
            assertEquals(0.0, mesh.playbackTime(), "a model at rest has only time 0");
        }
    }

    @Test
    void anUnknownClipNameIsRefusedNamingTheClipsThereAre() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> SkeletalAnimatedMesh.of(RIBBON, "run", new AnimationConfig()));
        assertTrue(e.getMessage().contains("\"run\"") && e.getMessage().contains("twist"), e.getMessage());
    }

    @Test
    void aModelWithoutClipsStaysAtRestAndStillSteps() {
        Model still = Fixtures.resource("geometry/several-primitives.dae");
        assertTrue(still.clips().isEmpty(), "the fixture has a clip: this test needs a model without one");
        try (SkeletalAnimatedMesh mesh = SkeletalAnimatedMesh.of(still)) {
            mesh.step(1);
            assertEquals(0.0, mesh.playbackTime());
            try (Frame f = mesh.acquire()) {
                assertEquals(1, f.sequence());
                assertEquals(still.instances().size(), f.geometryCount());
                assertNull(new FrameChecker(still, null, false).problem(f));
            }
        }
    }

    @Test
    void stepAllocatesNothingInSteadyState() {
        java.lang.management.ThreadMXBean bean = ManagementFactory.getThreadMXBean();
        assumeTrue(bean instanceof com.sun.management.ThreadMXBean, "no per-thread allocation counter");
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) bean;
        assumeTrue(threads.isThreadAllocatedMemorySupported() && threads.isThreadAllocatedMemoryEnabled(),
                "per-thread allocation counting is off");
        long id = Thread.currentThread().getId();
        AnimationConfig config = new AnimationConfig();
        try (SkeletalAnimatedMesh mesh = ribbon(config)) {
            for (boolean cpuSkinning : new boolean[] {true, false}) {
                config.setCpuSkinning(cpuSkinning);
                for (SkinningMethod method : SkinningMethod.values()) {
                    config.setMethod(method);
                    for (int i = 0; i < 20_000; i++) { // let the JIT settle
                        mesh.step(0.001);
                    }
                    int steps = 10_000;
                    long before = threads.getThreadAllocatedBytes(id);
                    for (int i = 0; i < steps; i++) {
                        mesh.step(0.001);
                        mesh.acquire().close();
                    }
                    long bytes = threads.getThreadAllocatedBytes(id) - before;
                    // The smallest object is 16 bytes: fewer bytes than steps means no step allocated.
                    assertTrue(bytes < steps, method + (cpuSkinning ? "" : " palette only") + ": " + bytes
                            + " bytes allocated in " + steps + " steps");
                }
            }
        }
    }

    /** Distance from the x axis of the point carrying mesh position {@code position}. */
    private static double radius(Frame f, SkinnedGeometry geometry, int position) {
        float[] p = f.positions(0);
        int o = 3 * geometry.pointOfPosition(position);
        return Math.hypot(p[o + 1], p[o + 2]);
    }
}
