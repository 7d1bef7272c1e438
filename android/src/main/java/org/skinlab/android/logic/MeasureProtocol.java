package org.skinlab.android.logic;

import java.util.List;
import java.util.Locale;

import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.internal.bench.Rounds;
import org.skinlab.skinning.SkinningMethod;

/**
 * How long the app's "Measure" runs each part: the CPU timings ({@link FrameTimes.Protocol}, the
 * evaluation's interleaved rounds) and the GPU part, copies drawn for {@code drawSeconds} per point
 * in {@code drawRounds} interleaved rounds after {@code drawWarmupFrames} frames. {@link #FULL} is
 * what a user's tap runs (about five minutes on a phone); {@link #QUICK}, chosen by the launch
 * intent's extra {@value #EXTRA} = "quick", checks that everything runs, in seconds: for CI and
 * the impatient, not figures to quote.
 */
public record MeasureProtocol(String name, FrameTimes.Protocol times, double drawSeconds, int drawRounds,
        int drawWarmupFrames) {
    /** The launch intent's extra that names the protocol ("full" or "quick"). */
    public static final String EXTRA = "org.skinlab.android.extra.MEASURE";
    /** The thesis' figure: 1, 4, 8 and 12 meshes. */
    public static final List<Integer> COPIES = List.of(1, 4, 8, 12);
    /** The methods drawn: the thesis' two and CoR, all skinned in the vertex shader (the app's default path). */
    public static final List<SkinningMethod> DRAWN_METHODS = List.of(SkinningMethod.LBS, SkinningMethod.DQS,
            SkinningMethod.COR);

    public static final MeasureProtocol FULL = new MeasureProtocol("full",
            new FrameTimes.Protocol(Rounds.MIN_RUNS, 2.0, 0.5, 1.0), 2.0, Rounds.MIN_RUNS, 10);
    public static final MeasureProtocol QUICK = new MeasureProtocol("quick",
            new FrameTimes.Protocol(Rounds.MIN_RUNS, 0.05, 0.01, 0.02), 0.25, Rounds.MIN_RUNS, 3);

    public MeasureProtocol {
        if (drawSeconds <= 0 || drawRounds < 1 || drawWarmupFrames < 0) {
            throw new IllegalArgumentException("not a drawing protocol: " + drawSeconds + " s, " + drawRounds
                    + " rounds, " + drawWarmupFrames + " warm-up frames");
        }
    }

    /** The protocol the extra names: {@link #QUICK} for "quick" (any case), else {@link #FULL} (also for null). */
    public static MeasureProtocol named(String extra) {
        return extra != null && extra.trim().toLowerCase(Locale.ROOT).equals(QUICK.name) ? QUICK : FULL;
    }

    /** How long the CPU part's runs take for {@code models} files of {@code methods} methods, in seconds (no setup). */
    public double cpuSeconds(int models, int methods) {
        double perMethod = times.firstWarmupSeconds() + times.seconds()
                + (times.rounds() - 1) * (times.warmupSeconds() + times.seconds());
        return models * methods * perMethod;
    }

    /** How long the GPU part's points take at {@code refreshHz} (warm-up frames included), in seconds. */
    public double drawnSeconds(double refreshHz) {
        return COPIES.size() * DRAWN_METHODS.size() * drawRounds * (drawSeconds + drawWarmupFrames / refreshHz);
    }
}
