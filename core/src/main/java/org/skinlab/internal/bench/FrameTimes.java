package org.skinlab.internal.bench;

import java.util.ArrayList;
import java.util.List;

import org.skinlab.skinning.SkinningMethod;

/**
 * The evaluation's time per frame: one {@link FrameBench} timed with each of several methods in
 * interleaved {@link Rounds}, each run the median frame of a short window. The desktop's
 * {@code skinlab eval} (its time section) and the Android app's measurement run this same
 * protocol, so a phone's numbers sit beside the desktop's.
 */
public final class FrameTimes {
    /**
     * One method's frames: the kernels that ran, the median frame of each run in µs, and how many
     * frames were timed in all.
     */
    public record Result(SkinningMethod method, String kernel, Spread micros, int frames) {
    }

    /** How long each part of a measurement takes, in seconds. */
    public record Protocol(int rounds, double firstWarmupSeconds, double warmupSeconds, double seconds) {
        public Protocol {
            if (rounds < 1 || firstWarmupSeconds < 0 || warmupSeconds < 0 || seconds <= 0) {
                throw new IllegalArgumentException("not a protocol: " + rounds + " rounds, warm-ups "
                        + firstWarmupSeconds + " and " + warmupSeconds + " s, " + seconds + " s each");
            }
        }
    }

    private FrameTimes() {
    }

    /**
     * Times {@code methods} on {@code bench}: a method's first run warms up for
     * {@code firstWarmupSeconds} (the compiler's work), later ones for {@code warmupSeconds}
     * (the caches, after another method's run); results in the order of {@code methods}.
     */
    public static List<Result> measure(FrameBench bench, List<SkinningMethod> methods, Protocol protocol) {
        int[] frames = new int[methods.size()];
        String[] kernels = new String[methods.size()];
        Spread[] spreads = Rounds.interleaved(methods.size(), protocol.rounds(), (i, round) -> {
            double warmup = round == 0 ? protocol.firstWarmupSeconds() : protocol.warmupSeconds();
            FrameBench.Timing t = bench.measure(methods.get(i), warmup, protocol.seconds());
            frames[i] += t.frames();
            kernels[i] = t.kernel();
            return t.medianMicros();
        });
        List<Result> results = new ArrayList<>(methods.size());
        for (int i = 0; i < methods.size(); i++) {
            results.add(new Result(methods.get(i), kernels[i], spreads[i], frames[i]));
        }
        return results;
    }
}
