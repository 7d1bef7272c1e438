package org.skinlab.desktop.bench;

import java.util.Arrays;
import java.util.List;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.WrapMode;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * {@code skinlab bench frame --palette-only}: the joint palette of a frame alone, no skinning. Per
 * frame, {@link SkinnedModel#pose} (sample, evaluate, skinning matrices) and then every palette's
 * dual quaternions, timed apart. Besides minimum and median it reports the mean, which shows
 * frames that are slow for a reason of their own.
 */
public final class PaletteBench {
    /** The parts timed, in the order of {@link Samples#stats()}. */
    public static final List<String> PARTS = List.of("palette", "pose", "dualQuaternions");

    private PaletteBench() {
    }

    /** Per frame in µs: the pose (sample, evaluate, skinning matrices), the dual quaternions, both. */
    public record Samples(int joints, int frames, double[] pose, double[] dualQuaternions, double[] total) {
        /** Minimum, median and mean in µs of each of {@link #PARTS}: the whole palette, the pose, the dual quaternions. */
        public double[][] stats() {
            return new double[][] {PaletteBench.stats(total, frames), PaletteBench.stats(pose, frames),
                PaletteBench.stats(dualQuaternions, frames)};
        }

        /** The median of the frames' totals. */
        public double medianTotal() {
            return PaletteBench.stats(total, frames)[1];
        }
    }

    /** Warm-up, then timed frames for {@code seconds} (at least 5), the clip advancing 1/60 s each. */
    public static Samples measure(SkinnedModel skinned, double warmupSeconds, double seconds) {
        int geometries = skinned.geometries().size();
        int joints = 0;
        for (int g = 0; g < geometries; g++) {
            joints += skinned.geometries().get(g).jointCount();
        }
        long frame = 0;
        long warmupEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
        do {
            skinned.pose(skinned.sampler().clipTime(frame++ / 60.0, WrapMode.LOOP), RotationInterpolation.SLERP);
            for (int g = 0; g < geometries; g++) {
                skinned.palette(g).prepare(SkinningMethod.DQS);
            }
        } while (System.nanoTime() < warmupEnd);
        double[] pose = new double[1024];
        double[] dq = new double[1024];
        int n = 0;
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (n < 5 || System.nanoTime() < end) {
            float t = skinned.sampler().clipTime(frame++ / 60.0, WrapMode.LOOP);
            long t0 = System.nanoTime();
            skinned.pose(t, RotationInterpolation.SLERP);
            long t1 = System.nanoTime();
            for (int g = 0; g < geometries; g++) {
                skinned.palette(g).prepare(SkinningMethod.DQS);
            }
            long t2 = System.nanoTime();
            if (n == pose.length) {
                pose = Arrays.copyOf(pose, 2 * n);
                dq = Arrays.copyOf(dq, 2 * n);
            }
            pose[n] = (t1 - t0) / 1e3;
            dq[n++] = (t2 - t1) / 1e3;
        }
        double[] total = new double[n];
        for (int i = 0; i < n; i++) {
            total[i] = pose[i] + dq[i];
        }
        return new Samples(joints, n, pose, dq, total);
    }

    /** Minimum, median and mean of the first n values. */
    private static double[] stats(double[] values, int n) {
        double[] sorted = Arrays.copyOf(values, n);
        Arrays.sort(sorted);
        double sum = 0;
        for (double v : sorted) {
            sum += v;
        }
        return new double[] {sorted[0], sorted[n / 2], sum / n};
    }
}
