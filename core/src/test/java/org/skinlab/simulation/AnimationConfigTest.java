package org.skinlab.simulation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.concurrent.CountDownLatch;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.WrapMode;
import org.skinlab.skinning.SkinningMethod;

@Timeout(value = 20, threadMode = Timeout.ThreadMode.SEPARATE_THREAD)
class AnimationConfigTest {
    @Test
    void defaultsPlayForwardAtRealTimeWithLbsAndSlerp() {
        AnimationConfig c = new AnimationConfig();
        assertEquals(1.0, c.speed());
        assertEquals(SkinningMethod.LBS, c.method());
        assertEquals(RotationInterpolation.SLERP, c.interpolation());
        assertTrue(c.isAnimationRunning());
        assertTrue(c.isMeshUpdatesRunning());
        assertFalse(c.isFollowCamera());
        assertEquals(WrapMode.LOOP, c.wrapMode());
        assertTrue(c.isCpuSkinning());
    }

    @Test
    void speedIsClampedInMagnitudeAndKeepsItsSign() {
        AnimationConfig c = new AnimationConfig();
        assertEquals(AnimationConfig.MAX_SPEED, c.setSpeed(100));
        assertEquals(AnimationConfig.MIN_SPEED, c.setSpeed(0.001));
        assertEquals(-AnimationConfig.MAX_SPEED, c.setSpeed(Double.NEGATIVE_INFINITY));
        assertEquals(-0.5, c.setSpeed(-0.5));
        assertEquals(-0.5, c.speed());
        assertThrows(IllegalArgumentException.class, () -> c.setSpeed(0));
        assertThrows(IllegalArgumentException.class, () -> c.setSpeed(Double.NaN));
        assertEquals(-0.5, c.speed(), "a refused speed changed the setting");
        assertThrows(IllegalArgumentException.class,
                () -> AnimationConfig.Settings.DEFAULT.withSpeed(21), "the record itself refuses what setters clamp");
    }

    @Test
    void twoPressesOfFasterDoubleTheSpeedAndSlowerUndoesThem() {
        AnimationConfig c = new AnimationConfig();
        c.faster();
        assertEquals(2.0, c.faster(), 1e-12);
        c.slower();
        assertEquals(1.0, c.slower(), 1e-12);
        c.setSpeed(AnimationConfig.MAX_SPEED);
        assertEquals(AnimationConfig.MAX_SPEED, c.faster(), "faster past the top stays at the top");
    }

    @Test
    void everySwitchIsSetAndReadBack() {
        AnimationConfig c = new AnimationConfig();
        c.setMethod(SkinningMethod.DQS);
        c.setInterpolation(RotationInterpolation.LERP);
        c.stopAnimation();
        c.stopMeshUpdates();
        c.setFollowCamera(true);
        c.setWrapMode(WrapMode.CLAMP);
        c.setCpuSkinning(false);
        c.setBindPose(true);
        assertEquals(new AnimationConfig.Settings(1.0, SkinningMethod.DQS, RotationInterpolation.LERP, false, false,
                false, true, WrapMode.CLAMP, true), c.settings());
        assertFalse(c.isCpuSkinning());
        assertTrue(c.isBindPose());
        // Every method in the enum's order, then LBS again.
        SkinningMethod[] all = SkinningMethod.values();
        for (int i = 2; i <= all.length; i++) {
            assertEquals(all[i % all.length], c.nextMethod());
        }
        assertEquals(SkinningMethod.DQS, c.nextMethod());
        assertEquals(RotationInterpolation.SLERP, c.nextInterpolation());
        c.startAnimation();
        c.startMeshUpdates();
        assertTrue(c.isAnimationRunning() && c.isMeshUpdatesRunning());
    }

    @Test
    void concurrentSwitchesLoseNoUpdate() throws Exception {
        // Each nextMethod() steps LBS -> DQS -> CoR -> LBS. 4 threads x 10,001 steps = 40,004:
        // the method ends 40,004 mod 3 = 1 step from LBS only if no step was lost to a race (a
        // read-then-write setter loses some and ends on any method by chance). Concurrent faster()/slower() in
        // equal numbers must likewise cancel out (clamping never reached: at most 2 steps away).
        AnimationConfig c = new AnimationConfig();
        int threads = 4;
        int flips = 10_001;
        CountDownLatch go = new CountDownLatch(1);
        Thread[] workers = new Thread[threads];
        for (int t = 0; t < threads; t++) {
            boolean faster = t % 2 == 0;
            workers[t] = new Thread(() -> {
                try {
                    go.await();
                } catch (InterruptedException e) {
                    return;
                }
                for (int i = 0; i < flips; i++) {
                    c.nextMethod();
                    c.nextInterpolation();
                }
                for (int i = 0; i < flips; i++) {
                    if (faster) {
                        c.faster();
                    } else {
                        c.slower();
                    }
                    if (faster) {
                        c.slower();
                    } else {
                        c.faster();
                    }
                }
            });
            workers[t].start();
        }
        go.countDown();
        for (Thread w : workers) {
            w.join();
        }
        assertEquals(SkinningMethod.values()[(threads * flips) % SkinningMethod.values().length], c.method());
        // 40,004 steps through three interpolations from SLERP (index 1): (1 + 40004) mod 3 = 0.
        assertEquals(RotationInterpolation.values()[(1 + threads * flips) % 3], c.interpolation());
        assertEquals(1.0, c.speed(), 1e-9);
    }

    @Test
    void aReaderNeverSeesHalfOfAnUpdate() throws Exception {
        // One writer changes method and interpolation together (DQS with NLERP, LBS with LERP);
        // a reader must never see a pair that was never written.
        AnimationConfig c = new AnimationConfig();
        c.update(s -> s.withMethod(SkinningMethod.LBS).withInterpolation(RotationInterpolation.LERP));
        AtomicBoolean done = new AtomicBoolean();
        AtomicInteger mixed = new AtomicInteger();
        Thread reader = new Thread(() -> {
            while (!done.get()) {
                AnimationConfig.Settings s = c.settings();
                boolean dqs = s.method() == SkinningMethod.DQS;
                boolean nlerp = s.interpolation() == RotationInterpolation.NLERP;
                if (dqs != nlerp) {
                    mixed.incrementAndGet();
                }
            }
        });
        reader.start();
        for (int i = 0; i < 200_000; i++) {
            boolean dqs = i % 2 == 0;
            c.update(s -> s.withMethod(dqs ? SkinningMethod.DQS : SkinningMethod.LBS)
                    .withInterpolation(dqs ? RotationInterpolation.NLERP : RotationInterpolation.LERP));
        }
        done.set(true);
        reader.join();
        assertEquals(0, mixed.get());
    }
}
