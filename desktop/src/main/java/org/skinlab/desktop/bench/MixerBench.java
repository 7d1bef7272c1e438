package org.skinlab.desktop.bench;

import java.lang.management.ManagementFactory;
import java.lang.management.ThreadMXBean;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.Set;

import org.skinlab.animation.LocalPose;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.internal.bench.Spread;
import org.skinlab.internal.bench.Warmup;
import org.skinlab.mixer.Mixer;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.PositionSharing;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

/**
 * {@code skinlab bench frame --blend ...}: one frame of a character that a {@link Mixer} directs,
 * in three parts timed apart on one thread: the mixer ({@link Mixer#advance} by 1/60 s, then
 * {@link Mixer#evaluate}: every layer's clips sampled into local translation, rotation and scale
 * and blended), the pose ({@link SkinnedModel#pose(LocalPose)}: the skeleton's world matrices and
 * the joint palette's matrices) and the skin (the palette's preparation for the method, e.g. DQS's
 * dual quaternions, then every mesh, positions and normals). Warm-up until the JIT has
 * compiled the frame ({@link Warmup}), then {@link #RUNS} runs, each giving the median step of
 * its window; then, untimed, the bytes the thread allocates per step, the mixer alone and the
 * whole frame.
 */
public final class MixerBench {
    /** How many runs a measurement takes; its figures are the median of the runs' medians. */
    public static final int RUNS = 5;
    private static final double STEP_SECONDS = 1.0 / 60;
    /** Steps counted for the bytes allocated per step (not timed). */
    private static final int ALLOCATION_STEPS = 2000;

    /**
     * One method's frames: the kernels, the steps timed in all, each part's median step per run in
     * µs, and the bytes allocated per step (NaN where the JVM cannot count them).
     */
    public record Result(SkinningMethod method, String kernel, int steps, Spread mixerMicros, Spread poseMicros,
            Spread skinMicros, double mixerBytesPerStep, double frameBytesPerStep) {
    }

    private final SkinnedModel skinned;
    private final Mixer mixer;
    private final LocalPose local;
    private final SkinningMethod method;
    private final Skinner[] skinners;
    private final float[][] positions;
    private final float[][] normals;
    private final Warmup warmup;

    /**
     * A bench of {@code mixer}'s frames of {@code skinned} with {@code method}; {@code sharing} as in
     * {@code FrameBench} (auto: the model's own skinners).
     */
    public MixerBench(SkinnedModel skinned, Mixer mixer, SkinningMethod method, NormalTransform rule,
            PositionSharing sharing, Warmup warmup) {
        this.skinned = skinned;
        this.mixer = mixer;
        this.local = skinned.skeleton().newLocalPose();
        this.method = method;
        this.warmup = warmup;
        int n = skinned.geometries().size();
        skinners = new Skinner[n];
        positions = new float[n][];
        normals = new float[n][];
        for (int g = 0; g < n; g++) {
            SkinnedGeometry geometry = skinned.geometries().get(g);
            skinners[g] = sharing == PositionSharing.AUTO ? skinned.skinner(g, method)
                    : Skinners.create(method, geometry, rule, sharing);
            positions[g] = new float[3 * geometry.pointCount()];
            normals[g] = new float[3 * geometry.pointCount()];
        }
    }

    /** The skinners' kernels, each named once, joined by '+' ("none" without meshes). */
    public String kernel() {
        Set<String> names = new LinkedHashSet<>();
        for (Skinner s : skinners) {
            names.add(s.implementation());
        }
        return names.isEmpty() ? "none" : String.join("+", names);
    }

    /**
     * Warms up for at least {@code warmupSeconds} (and on until the JIT has compiled the frame),
     * then times {@link #RUNS} runs of {@code seconds / RUNS} each (at least 5 steps each), then
     * counts the bytes allocated per step.
     */
    public Result measure(double warmupSeconds, double seconds) {
        warmup.run(this::frame, warmupSeconds);
        double[][] medians = new double[3][RUNS];
        int steps = 0;
        long[][] nanos = new long[3][4096];
        for (int r = 0; r < RUNS; r++) {
            int n = 0;
            long end = System.nanoTime() + (long) (seconds / RUNS * 1e9);
            while (n < 5 || System.nanoTime() < end) {
                if (n == nanos[0].length) {
                    for (int p = 0; p < 3; p++) {
                        nanos[p] = Arrays.copyOf(nanos[p], 2 * n);
                    }
                }
                long t0 = System.nanoTime();
                mix();
                long t1 = System.nanoTime();
                skinned.pose(local);
                long t2 = System.nanoTime();
                skin();
                long t3 = System.nanoTime();
                nanos[0][n] = t1 - t0;
                nanos[1][n] = t2 - t1;
                nanos[2][n] = t3 - t2;
                n++;
            }
            for (int p = 0; p < 3; p++) {
                medians[p][r] = median(nanos[p], n) / 1e3;
            }
            steps += n;
        }
        return new Result(method, kernel(), steps, Spread.of(medians[0]), Spread.of(medians[1]),
                Spread.of(medians[2]), bytesPerStep(this::mix), bytesPerStep(this::frame));
    }

    private void mix() {
        mixer.advance(STEP_SECONDS);
        mixer.evaluate(RotationInterpolation.SLERP, local);
    }

    private void skin() {
        for (int g = 0; g < skinners.length; g++) {
            // What the method reads: the dual quaternions (all but LBS), the bone rows (the bone methods).
            skinners[g].skinAll(skinned.palette(g).prepare(method), positions[g], normals[g]);
        }
    }

    private void frame() {
        mix();
        skinned.pose(local);
        skin();
    }

    private static double median(long[] values, int n) {
        long[] sorted = Arrays.copyOf(values, n);
        Arrays.sort(sorted);
        return n % 2 == 1 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2.0;
    }

    /** The bytes this thread allocates per run of {@code step}, from HotSpot's counter; NaN without one. */
    private static double bytesPerStep(Runnable step) {
        ThreadMXBean bean = ManagementFactory.getThreadMXBean();
        if (!(bean instanceof com.sun.management.ThreadMXBean threads) || !threads.isThreadAllocatedMemorySupported()
                || !threads.isThreadAllocatedMemoryEnabled()) {
            return Double.NaN;
        }
        long thread = Thread.currentThread().getId();
        long before = threads.getThreadAllocatedBytes(thread);
        for (int i = 0; i < ALLOCATION_STEPS; i++) {
            step.run();
        }
        return (double) (threads.getThreadAllocatedBytes(thread) - before) / ALLOCATION_STEPS;
    }
}
