package org.skinlab.desktop.bench;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.skinlab.internal.bench.FrameBench;
import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.internal.bench.Rounds;
import org.skinlab.internal.bench.Spread;
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
 * one character would; nothing is allocated per frame. Crowds are timed in interleaved runs
 * ({@link #measure}), after a warm-up that waits for the JIT ({@link #warmUp}).
 */
public final class CrowdBench {
    /** A frame's budget at 60 Hz, in ms: what "characters per frame" divides. */
    public static final double FRAME_MILLIS = 1000.0 / 60;
    /** Most timed frames per run. */
    static final int MAX_FRAMES = 1 << 16;
    /** Fewest timed frames per run. */
    public static final int MIN_FRAMES = 5;
    /** Fewest frames of a run's warm-up (the caches, after another crowd's run). */
    public static final int MIN_WARMUP_FRAMES = 2;
    /** Bytes a frame below which the kernels count as compiled (a frame of an uncompiled one allocates megabytes). */
    public static final int COMPILED_BYTES = 1024;

    /** A crowd to time: {@code characters} copies, each skinned with {@code method}, on {@code threads} threads. */
    public record Crowd(SkinningMethod method, int characters, int threads) {
    }

    /**
     * A crowd's frames over several runs: each run's median frame in µs ({@code frameMicros}, in
     * run order), the frames timed in all runs, the bytes the crowd's threads allocated per timed
     * frame (0 once the JIT has compiled the kernels), and the share of the copies the calling
     * thread ran itself (1 on one thread; near 1 / threads when the pool's threads get cores).
     */
    public record Timing(Crowd crowd, Spread frameMicros, int frames, double bytesPerFrame, double callerShare) {
    }

    /** One run's numbers, summed by {@link #measure} over the runs of one crowd. */
    private record Run(double medianMicros, int frames, long bytes, long callerItems) {
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
    /** A run's timed frames' times, in µs (preallocated: the timing loop allocates nothing). */
    private final double[] micros = new double[MAX_FRAMES];

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

    /** The points one copy skins per frame (its render vertices and any unused positions). */
    public int pointsPerCharacter() {
        return points;
    }

    /**
     * Times each crowd in {@code protocol.rounds()} runs, interleaved ({@link Rounds}: each round
     * runs every crowd once, each round starting one further along the list), so that the
     * machine's drift falls on every crowd alike. A run is frames for the protocol's warm-up (its
     * first round's warm-up for round 0; at least {@value #MIN_WARMUP_FRAMES} frames), then timed
     * frames for {@code protocol.seconds()} ({@value #MIN_FRAMES} to {@value #MAX_FRAMES});
     * its value is the median frame. {@code afterRun} runs after each run (progress). Results in the
     * order of {@code crowds}. The JIT is expected warm ({@link #warmUp}).
     */
    public List<Timing> measure(List<Crowd> crowds, FrameTimes.Protocol protocol, Runnable afterRun) {
        for (Crowd c : crowds) {
            check(c.characters());
            crowdMethod(c.method());
        }
        int n = crowds.size();
        int[] frames = new int[n];
        long[] bytes = new long[n];
        long[] callerItems = new long[n];
        long[] items = new long[n];
        Spread[] spreads = Rounds.interleaved(n, protocol.rounds(), (i, round) -> {
            Crowd c = crowds.get(i);
            Run run = run(c, round == 0 ? protocol.firstWarmupSeconds() : protocol.warmupSeconds(), protocol.seconds());
            frames[i] += run.frames();
            bytes[i] += run.bytes();
            callerItems[i] += run.callerItems();
            items[i] += (long) run.frames() * c.characters();
            afterRun.run();
            return run.medianMicros();
        });
        List<Timing> timings = new ArrayList<>(n);
        for (int i = 0; i < n; i++) {
            timings.add(new Timing(crowds.get(i), spreads[i], frames[i], bytes[i] / (double) frames[i],
                    callerItems[i] / (double) items[i]));
        }
        return timings;
    }

    /** One run of a crowd: frames for {@code warmupSeconds}, then timed frames for {@code seconds}. */
    private Run run(Crowd crowd, double warmupSeconds, double seconds) {
        int count = crowd.characters();
        method = crowd.method();
        try (CrowdThreads pool = new CrowdThreads(crowd.threads(), this::character)) {
            long warmupEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
            for (int f = 0; f < MIN_WARMUP_FRAMES || System.nanoTime() < warmupEnd; f++) {
                step(pool, count);
            }
            long[] ids = pool.threadIds(Thread.currentThread());
            long bytesBefore = allocated(ids);
            // What counting costs itself (its result arrays), taken off the frames' bytes.
            long counting = allocated(ids) - bytesBefore;
            long workerItems = pool.workerItems();
            int n = 0;
            long end = System.nanoTime() + (long) (seconds * 1e9);
            while (n < MAX_FRAMES && (n < MIN_FRAMES || System.nanoTime() < end)) {
                long t0 = System.nanoTime();
                step(pool, count);
                micros[n++] = (System.nanoTime() - t0) / 1e3;
            }
            long bytes = Math.max(0, allocated(ids) - bytesBefore - 2 * counting);
            long callerItems = (long) n * count - (pool.workerItems() - workerItems);
            Arrays.sort(micros, 0, n);
            return new Run(micros[n / 2], n, bytes, callerItems);
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
