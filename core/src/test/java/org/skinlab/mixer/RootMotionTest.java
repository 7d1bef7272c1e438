package org.skinlab.mixer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.lang.management.ManagementFactory;
import java.util.Arrays;
import java.util.LinkedHashMap;
import java.util.Map;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.animation.LocalPose;
import org.skinlab.animation.Pose;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.Skeleton;

/**
 * Root motion on {@link MixerRig} (whose armature is moved, turned by 30 degrees and scaled by 2,
 * so the root's parent space is not the model's): loops accumulate with no jump, a turning clip
 * closes its circle, and the placement times the in-place pose is the clip's own motion. Plus:
 * a step with four layers allocates nothing.
 */
class RootMotionTest {
    private final MixerRig rig = new MixerRig();
    private final Skeleton skeleton = Skeleton.of(rig.model);

    private Mixer walking(String clip) {
        Mixer m = new Mixer(rig.model, skeleton);
        m.base().play(clip);
        m.setRootMotion(clip, true);
        return m;
    }

    @Test
    void tenLoopsOfAWalkAdvanceTenLoopsDisplacementWithNoJump() {
        for (double dt : new double[] {1.0 / 60, 1.0 / 7, 0.3}) {
            Mixer m = walking("walk");
            int steps = (int) Math.round(10.0 / dt);
            double[] p = new double[4];
            double[] advances = new double[steps];
            double lastZ = 0;
            for (int i = 0; i < steps; i++) {
                m.advance(i == steps - 1 ? 10.0 - dt * (steps - 1) : dt);
                m.placementPosition(p);
                advances[i] = p[2] - lastZ;
                lastZ = p[2];
            }
            // One loop moves the hips 1.2 m forward in the armature's space.
            double expected = 10 * 1.2;
            double step = dt;
            assertEquals(expected, p[2], 1e-4 * expected, () -> "after 10 loops in steps of " + step + " s");
            assertEquals(0, p[0], 1e-6);
            assertEquals(0, p[3], 1e-6, "the walk's yaw wiggle returns each loop");
            double[] sorted = advances.clone();
            Arrays.sort(sorted, 0, steps - 1);
            double median = sorted[(steps - 1) / 2];
            for (int i = 0; i < steps - 1; i++) {
                int n = i;
                assertTrue(advances[i] > median / 2 && advances[i] < 2 * median,
                        () -> "step " + n + " advanced " + advances[n] + ", the median step " + median);
            }
        }
    }

    @Test
    void aTurningClipClosesItsCircleInFourLoops() {
        Mixer m = walking("turn");
        double[] p = new double[4];
        for (int i = 0; i < 120; i++) {
            m.advance(2.0 / 120);
        }
        m.placementPosition(p);
        assertEquals(2, p[0], 1e-5);
        assertEquals(2, p[2], 1e-5);
        assertEquals(Math.PI / 2, p[3], 1e-5);
        for (int i = 0; i < 3 * 120; i++) {
            m.advance(2.0 / 120);
        }
        m.placementPosition(p);
        assertEquals(0, Math.hypot(p[0], p[2]), 1e-4, "four quarter circles end where they started");
        assertEquals(0, p[3], 1e-5);
    }

    @Test
    void placementTimesTheInPlacePoseIsTheClipsOwnMotion() {
        for (String clip : new String[] {"walk", "turn"}) {
            Mixer inPlace = walking(clip);
            Mixer free = new Mixer(rig.model, skeleton);
            free.base().play(clip);
            LocalPose a = skeleton.newLocalPose();
            LocalPose b = skeleton.newLocalPose();
            Pose pa = skeleton.newPose();
            Pose pb = skeleton.newPose();
            Matrix4f placement = new Matrix4f();
            double duration = rig.clip(clip).duration();
            for (int i = 0; i < 40; i++) {
                double dt = duration / 41;
                inPlace.advance(dt);
                free.advance(dt);
                inPlace.evaluate(RotationInterpolation.SLERP, a);
                free.evaluate(RotationInterpolation.SLERP, b);
                skeleton.evaluate(a, pa);
                skeleton.evaluate(b, pb);
                Matrix4f moved = inPlace.placement(placement).mul(pa.world(MixerRig.LEG, new Matrix4f()));
                Matrix4f original = pb.world(MixerRig.LEG, new Matrix4f());
                Vector3f x = moved.getTranslation(new Vector3f());
                Vector3f y = original.getTranslation(new Vector3f());
                String what = clip + " step " + i;
                assertEquals(0, x.distance(y), 1e-5, what + ": the leg is where the clip puts it");
                for (int c = 0; c < 3; c++) {
                    assertEquals(original.getColumn(c, new Vector3f()).x, moved.getColumn(c, new Vector3f()).x, 1e-5, what);
                    assertEquals(original.getColumn(c, new Vector3f()).z, moved.getColumn(c, new Vector3f()).z, 1e-5, what);
                }
            }
        }
    }

    @Test
    void blendedClipsMoveByTheirWeights() {
        Mixer m = new Mixer(rig.model, skeleton);
        Map<String, Double> w = new LinkedHashMap<>();
        w.put("walk", 0.5);
        w.put("run", 0.5);
        m.base().setClipWeights(w);
        m.setRootMotion("walk", true);
        m.setRootMotion("run", true);
        ReferenceMixer ref = new ReferenceMixer(rig);
        // The formulas in double: each clip's move in the in-place character's frame, R(psi(0) - psi(a)) (h(b) - h(a)),
        // and its turn, weighted, then applied to the placement in its own frame.
        double px = 0;
        double pz = 0;
        double heading = 0;
        double[] e = {0, 0};
        String[] clips = {"walk", "run"};
        for (int i = 0; i < 60; i++) {
            double dt = 1.0 / 60;
            m.advance(dt);
            double mx = 0;
            double mz = 0;
            double turn = 0;
            for (int k = 0; k < 2; k++) {
                double d = rig.clip(clips[k]).duration();
                double from = e[k];
                double to = from + dt;
                double[] move = {0, 0, 0};
                if (to > d) {
                    segment(ref, clips[k], from, d, move);
                    segment(ref, clips[k], 0, to - d, move);
                    e[k] = to - d;
                } else {
                    segment(ref, clips[k], from, to, move);
                    e[k] = to;
                }
                mx += 0.5 * move[0];
                mz += 0.5 * move[1];
                turn += 0.5 * move[2];
            }
            px += Math.cos(heading) * mx + Math.sin(heading) * mz;
            pz += -Math.sin(heading) * mx + Math.cos(heading) * mz;
            heading += turn;
        }
        double[] p = m.placementPosition(new double[4]);
        assertEquals(px, p[0], 1e-5);
        assertEquals(pz, p[2], 1e-5);
        assertEquals(heading, p[3], 1e-5);
        // Near the two clips' speeds' mean: their yaw wiggles turn the moves a little.
        assertEquals(0.5 * 1.2 + 0.5 * 3.5, p[2], 0.01);
    }

    /** Composes the move of the hips from elapsed a to b of a clip onto {x, z, turn} (Y up). */
    private static void segment(ReferenceMixer ref, String clip, double a, double b, double[] move) {
        double[] start = ref.sample(clip, MixerRig.HIPS, 0);
        double[] pa = ref.sample(clip, MixerRig.HIPS, a);
        double[] pb = ref.sample(clip, MixerRig.HIPS, b);
        double yaw0 = 2 * Math.atan2(start[4], start[6]);
        double ya = 2 * Math.atan2(pa[4], pa[6]);
        double yb = 2 * Math.atan2(pb[4], pb[6]);
        double dx = pb[0] - pa[0];
        double dz = pb[2] - pa[2];
        // Rotation about +Y by angle r maps (x, z) to (x cos r + z sin r, -x sin r + z cos r).
        double r = yaw0 - ya;
        double vx = dx * Math.cos(r) + dz * Math.sin(r);
        double vz = -dx * Math.sin(r) + dz * Math.cos(r);
        double h = move[2];
        move[0] += vx * Math.cos(h) + vz * Math.sin(h);
        move[1] += -vx * Math.sin(h) + vz * Math.cos(h);
        move[2] += yb - ya;
    }

    @Test
    void aStepWithFourLayersAllocatesNothing() {
        Mixer m = walking("walk");
        Map<String, Double> w = new LinkedHashMap<>();
        w.put("walk", 0.5);
        w.put("run", 0.5);
        m.base().setClipWeights(w);
        Layer arm = m.addLayer("arm");
        arm.play("wave");
        arm.setMask(JointMask.subtree(skeleton, "spine"));
        Layer lean = m.addLayer("lean");
        lean.play("lean");
        lean.setAdditive(0);
        Layer space = m.addLayer("space");
        space.setBlendSpace(BlendSpace.linear(Map.of("walk", 1.2, "run", 3.5)), 2, 0);
        space.setWeight(0.3);
        m.base().crossFade("turn", 5, FadeCurve.SMOOTH, true);
        LocalPose local = skeleton.newLocalPose();
        Pose pose = skeleton.newPose();
        Runnable step = () -> {
            m.advance(1.0 / 60);
            m.evaluate(RotationInterpolation.SLERP, local);
            skeleton.evaluate(local, pose);
        };
        for (int i = 0; i < 20_000; i++) {
            step.run();
        }
        m.base().crossFade("walk", 100, FadeCurve.LINEAR, true);
        step.run();
        com.sun.management.ThreadMXBean bean = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        // Five rounds of 1000 steps: a step that allocates shows in every round; the runtime itself
        // (a recompilation switching code in this thread) may allocate a few hundred bytes once.
        long[] rounds = new long[5];
        for (int r = 0; r < rounds.length; r++) {
            long before = bean.getThreadAllocatedBytes(thread);
            for (int i = 0; i < 1000; i++) {
                step.run();
            }
            rounds[r] = bean.getThreadAllocatedBytes(thread) - before;
        }
        Arrays.sort(rounds);
        assertEquals(0, rounds[0], () -> "bytes allocated per 1000 steps of four layers (a fade, a blend space, a mask,"
                + " an additive clip, root motion), by round: " + Arrays.toString(rounds));
        assertTrue(rounds[4] < 1000, () -> "bytes allocated per 1000 steps, by round: " + Arrays.toString(rounds));
    }
}
