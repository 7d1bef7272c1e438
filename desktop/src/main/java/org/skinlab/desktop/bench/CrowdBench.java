package org.skinlab.desktop.bench;

import java.lang.management.ManagementFactory;
import java.util.Arrays;
import java.util.List;

import org.skinlab.bench.FrameBench;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.SkinningMethod;

/**
 * A crowd on the CPU, timed for {@code skinlab eval}'s crowds section: copies of one model, each
 * playing its first clip at its own time (phases spread evenly over the clip, so no two copies do
 * the same work), each frame every copy sampled, posed and skinned, positions and exact normals
 * ({@link FrameBench#frame}, the fastest kernels), the copies shared among a fixed pool of threads
 * ({@link CrowdThreads}). The copies share the geometries and skinners
 * ({@link SkinnedModel#newCharacter()}) and own their poses, palettes and outputs, as a crowd of
 * one character would; nothing is allocated per frame.
 */
public final class CrowdBench {
    /** A frame's budget at 60 Hz, in ms: what "characters per frame" divides. */
    public static final double FRAME_MILLIS = 1000.0 / 60;
    /** Most timed frames per measurement. */
    static final int MAX_FRAMES = 1 << 16;
    /** Bytes a frame below which the kernels count as compiled (a frame of an uncompiled one allocates megabytes). */
    public static final int COMPILED_BYTES = 1024;

    /**
     * Frames of a crowd: the median and fastest frame in ms, the bytes the crowd's threads
     * allocated per timed frame (0 once the JIT has compiled the kernels), and the share of the
     * copies the calling thread ran itself (1 on one thread; near 1 / threads when the pool's
     * threads get cores).
     */
    public record Timing(SkinningMethod method, int characters, int threads, int frames, double medianMillis,
            double minMillis, double bytesPerFrame, double callerShare) {
    }

    /**
     * The methods crowds are timed and drawn with (here, in eval's crowds section and in
     * {@code bench-render}): LBS and DQS, the thesis' pair, and CoR. The outlook methods (bulge-free
     * DQS, stretchable and twistable bones, splines) are timed per vertex by {@code bench frame} and
     * eval's time section; in crowds they would more than double the section's run (each method is
     * timed over every thread count and crowd size) without a question the per-vertex figures leave open.
     */
    public static final List<SkinningMethod> METHODS = List.of(SkinningMethod.LBS, SkinningMethod.DQS, SkinningMethod.COR);

    private final SkinnedModel[] characters;
    private final double[] phases;
    /** Per geometry and method, the skinner every copy uses (a skinner keeps no per-frame state). */
    private final Skinner[][] skinners;
    private final float[][][] positions;
    private final float[][][] normals;
    private final int points;
    /** The timed frames' times, in ms (preallocated: the timing loop allocates nothing). */
    private final double[] millis = new double[MAX_FRAMES];

    // The frame being run, written before CrowdThreads.run hands the copies out.
    private SkinningMethod method;
    private long frame;

    /** Up to {@code maxCharacters} copies of the model (the skinners of the {@link #METHODS} made here). */
    public CrowdBench(Model model, int maxCharacters) {
        SkinnedModel first = SkinnedModel.of(model);
        int geometries = first.geometries().size();
        skinners = new Skinner[geometries][SkinningMethod.values().length];
        int p = 0;
        for (int g = 0; g < geometries; g++) {
            for (SkinningMethod m : METHODS) {
                skinners[g][m.ordinal()] = first.skinner(g, m);
            }
            p += first.geometries().get(g).pointCount();
        }
        points = p;
        characters = new SkinnedModel[maxCharacters];
        phases = new double[maxCharacters];
        positions = new float[maxCharacters][geometries][];
        normals = new float[maxCharacters][geometries][];
        double length = first.sampler().end() - first.sampler().start();
        for (int c = 0; c < maxCharacters; c++) {
            characters[c] = c == 0 ? first : first.newCharacter();
            // Spread over the clip by the golden ratio: any first n copies cover it evenly.
            phases[c] = length * ((c * 0.6180339887498949) % 1.0);
            for (int g = 0; g < geometries; g++) {
                SkinnedGeometry geometry = first.geometries().get(g);
                positions[c][g] = new float[3 * geometry.pointCount()];
                normals[c][g] = new float[3 * geometry.pointCount()];
            }
        }
    }

    int maxCharacters() {
        return characters.length;
    }

    /** The points one copy skins per frame (its render vertices and any unused positions). */
    public int pointsPerCharacter() {
        return points;
    }

    /**
     * {@code count} copies on {@code threads} threads: frames for {@code warmupSeconds}, then timed
     * frames for {@code seconds} (at least 5, at most {@value #MAX_FRAMES}).
     */
    public Timing measure(SkinningMethod m, int count, int threads, double warmupSeconds, double seconds) {
        check(count);
        method = crowdMethod(m);
        try (CrowdThreads pool = new CrowdThreads(threads, this::character)) {
            long warmupEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
            do {
                step(pool, count);
            } while (System.nanoTime() < warmupEnd);
            long[] ids = pool.threadIds(Thread.currentThread());
            long bytesBefore = allocated(ids);
            // What counting costs itself (its result arrays), taken off the frames' bytes.
            long counting = allocated(ids) - bytesBefore;
            long workerItems = pool.workerItems();
            int n = 0;
            long end = System.nanoTime() + (long) (seconds * 1e9);
            while (n < MAX_FRAMES && (n < 5 || System.nanoTime() < end)) {
                long t0 = System.nanoTime();
                step(pool, count);
                millis[n++] = (System.nanoTime() - t0) / 1e6;
            }
            long bytes = allocated(ids) - bytesBefore - 2 * counting;
            double callerShare = 1 - (double) (pool.workerItems() - workerItems) / ((long) n * count);
            double[] sorted = Arrays.copyOf(millis, n);
            Arrays.sort(sorted);
            return new Timing(m, count, threads, n, sorted[n / 2], sorted[0], Math.max(0, bytes) / (double) n,
                    callerShare);
        }
    }

    /**
     * Runs frames of {@code count} copies on {@code threads} threads for at least {@code minSeconds},
     * then on until a tenth of a second of frames allocates under {@value #COMPILED_BYTES} bytes a
     * frame (the JIT has compiled the kernels: before, the Vector API allocates its vectors and
     * runs many times slower) or {@code maxSeconds} have passed. Returns the seconds it took.
     */
    public double warmUp(SkinningMethod m, int count, int threads, double minSeconds, double maxSeconds) {
        check(count);
        method = crowdMethod(m);
        long start = System.nanoTime();
        try (CrowdThreads pool = new CrowdThreads(threads, this::character)) {
            long[] ids = pool.threadIds(Thread.currentThread());
            long minEnd = start + (long) (minSeconds * 1e9);
            long maxEnd = start + (long) (maxSeconds * 1e9);
            while (true) {
                long bytes = allocated(ids);
                long windowEnd = System.nanoTime() + 100_000_000L;
                int frames = 0;
                do {
                    step(pool, count);
                    frames++;
                } while (System.nanoTime() < windowEnd);
                long now = System.nanoTime();
                boolean compiled = allocated(ids) - bytes < (long) COMPILED_BYTES * frames;
                if (now >= maxEnd || now >= minEnd && compiled) {
                    return (now - start) / 1e9;
                }
            }
        }
    }

    private void check(int count) {
        if (count < 1 || count > characters.length) {
            throw new IllegalArgumentException("characters must be 1 to " + characters.length + ", was " + count);
        }
    }

    private static long allocated(long[] ids) {
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long s = 0;
        for (long v : mx.getThreadAllocatedBytes(ids)) {
            s += Math.max(0, v);
        }
        return s;
    }

    private void step(CrowdThreads pool, int count) {
        frame++;
        pool.run(count);
    }

    /** Copy c's frame: its phase plus this frame's playback time (1/60 s a frame). */
    private void character(int c) {
        FrameBench.frame(characters[c], skinners, method, phases[c] + frame / 60.0, positions[c], normals[c]);
    }


    private static SkinningMethod crowdMethod(SkinningMethod m) {
        if (!METHODS.contains(m)) {
            throw new IllegalArgumentException(m.key() + " is not one of the crowds' methods " + METHODS);
        }
        return m;
    }
}
