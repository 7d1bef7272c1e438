package org.skinlab.internal.bench;

/**
 * Repeated measurements of several things that are compared with each other (methods, kernels,
 * our code and a baseline), interleaved: each round measures every one of them once, so that a
 * machine's drift (a neighbour's load, the clock, the JIT still compiling elsewhere) falls on
 * all of them alike rather than on whichever was measured last. Each round starts one further
 * along the list, so that none is always measured first (right after another's warm-up) or last.
 */
public final class Rounds {
    /** The fewest runs a timing that the evaluation reports is taken in. */
    public static final int MIN_RUNS = 5;

    /** One measurement of thing {@code index} in round {@code round}; returns its value. */
    @FunctionalInterface
    public interface Measurement {
        double measure(int index, int round);
    }

    private Rounds() {
    }

    /**
     * Measures {@code things} things in {@code rounds} interleaved rounds; returns each thing's
     * spread over the rounds, its runs in round order.
     */
    public static Spread[] interleaved(int things, int rounds, Measurement measurement) {
        if (things < 1 || rounds < 1) {
            throw new IllegalArgumentException("rounds of " + things + " things, " + rounds + " times");
        }
        double[][] runs = new double[things][rounds];
        for (int r = 0; r < rounds; r++) {
            for (int k = 0; k < things; k++) {
                int index = (r + k) % things;
                runs[index][r] = measurement.measure(index, r);
            }
        }
        Spread[] spreads = new Spread[things];
        for (int i = 0; i < things; i++) {
            spreads[i] = Spread.of(runs[i]);
        }
        return spreads;
    }
}
