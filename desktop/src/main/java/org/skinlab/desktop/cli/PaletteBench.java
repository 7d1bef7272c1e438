package org.skinlab.desktop.cli;

import java.io.PrintWriter;
import java.util.Arrays;
import java.util.Locale;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.WrapMode;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.skinning.SkinnedModel;

/** {@code skinlab bench frame --palette-only}: the joint palette of a frame alone, no skinning. */
final class PaletteBench {
    private PaletteBench() {
    }

    /**
     * {@code --palette-only}: per frame, {@link SkinnedModel#pose} (sample, evaluate, skinning
     * matrices) and then every palette's dual quaternions, timed apart. Besides minimum and
     * median it reports the mean, which shows frames that are slow for a reason of their own.
     */
    static int run(SkinnedModel skinned, String name, double warmupSeconds, double seconds, boolean json,
            PrintWriter out) throws JsonProcessingException {
        Samples samples = measure(skinned, warmupSeconds, seconds);
        int joints = samples.joints();
        int n = samples.frames();
        double[][] stats = {stats(samples.total(), n), stats(samples.pose(), n), stats(samples.dualQuaternions(), n)};
        String[] parts = {"palette", "pose", "dualQuaternions"};
        if (json) {
            ObjectMapper mapper = new ObjectMapper();
            ObjectNode root = mapper.createObjectNode();
            root.put("benchmark", "frame-palette");
            root.put("file", name);
            root.put("joints", joints);
            root.put("frames", n);
            for (int p = 0; p < parts.length; p++) {
                ObjectNode part = root.putObject(parts[p]);
                part.put("minMicros", round(stats[p][0]));
                part.put("medianMicros", round(stats[p][1]));
                part.put("meanMicros", round(stats[p][2]));
            }
            out.println(mapper.writeValueAsString(root));
        } else {
            out.printf(Locale.ROOT, "palette of %s: %d joints, %d frames (slerp)%n", name, joints, n);
            for (int p = 0; p < parts.length; p++) {
                out.printf(Locale.ROOT, "%-16s min %.3f µs, median %.3f µs, mean %.3f µs%n", parts[p], stats[p][0],
                        stats[p][1], stats[p][2]);
            }
        }
        out.flush();
        return ExitCodes.OK;
    }

    /** Per frame in µs: the pose (sample, evaluate, skinning matrices), the dual quaternions, both. */
    record Samples(int joints, int frames, double[] pose, double[] dualQuaternions, double[] total) {
        /** The median of the frames' totals. */
        double medianTotal() {
            return stats(total, frames)[1];
        }
    }

    /** Warm-up, then timed frames for {@code seconds} (at least 5), the clip advancing 1/60 s each. */
    static Samples measure(SkinnedModel skinned, double warmupSeconds, double seconds) {
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
                skinned.palette(g).prepareDualQuaternions();
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
                skinned.palette(g).prepareDualQuaternions();
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

    private static double round(double d) {
        return Math.round(d * 1000.0) / 1000.0;
    }
}
