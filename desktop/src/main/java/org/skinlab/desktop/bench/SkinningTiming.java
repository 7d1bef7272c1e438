package org.skinlab.desktop.bench;

import java.util.Arrays;

/**
 * The timing protocol of the shared C++ skinning reference ({@code ../shared/perf/skin_ref.cpp}),
 * one home for {@code bench skinning} and {@code eval}: one untimed run on zeroed outputs for the
 * checksum, a warm-up (at least the given time and until the JIT has compiled the kernel:
 * {@link JitWarmup}), then timed runs of the whole mesh for a given time (at least 5), each
 * sample in ns per vertex; the minimum and the upper median, as the reference reports them.
 * Normals null: a positions-only frame ({@link org.skinlab.skinning.NormalTransform#NONE}), whose
 * checksum is the positions' sum.
 */
public final class SkinningTiming {
    public final double[] nsPerVertex;
    public final double checksum;

    private SkinningTiming(double[] nsPerVertex, double checksum) {
        this.nsPerVertex = nsPerVertex;
        this.checksum = checksum;
    }

    public static SkinningTiming measure(Runnable frame, float[] positions, float[] normals, int vertices,
            double warmupSeconds, double seconds) {
        Arrays.fill(positions, 0f);
        if (normals != null) {
            Arrays.fill(normals, 0f);
        }
        frame.run();
        double checksum = SyntheticSkinData.checksum(positions, normals);
        JitWarmup.run(frame, warmupSeconds);
        double[] samples = new double[64];
        int n = 0;
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (n < 5 || System.nanoTime() < end) {
            long t0 = System.nanoTime();
            frame.run();
            long t1 = System.nanoTime();
            if (n == samples.length) {
                samples = Arrays.copyOf(samples, 2 * n);
            }
            samples[n++] = (t1 - t0) / (double) vertices;
        }
        return new SkinningTiming(Arrays.copyOf(samples, n), checksum);
    }

    public double min() {
        return Arrays.stream(nsPerVertex).min().orElse(Double.NaN);
    }

    /** The upper median, as the reference ({@code samples[n / 2]} of the sorted samples). */
    public double median() {
        double[] s = nsPerVertex.clone();
        Arrays.sort(s);
        return s[s.length / 2];
    }
}
