package org.skinlab.testsummary;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

/**
 * One test run's results, told in a few lines: how many tests ran, each distinct skip reason once
 * with its count, each failure with its first line, the five slowest tests, and where the full log
 * is. {@code gradle test} prints one per module; everything else a run prints goes to that log.
 */
public final class TestSummary {
    /** How many of the slowest tests the summary names. */
    static final int SLOWEST = 5;
    /** How many skip reasons and failures it names at most; the rest are counted, the log has them. */
    static final int REASONS = 5;
    static final int FAILURES = 20;

    /** What became of one test. */
    public enum Outcome { PASSED, SKIPPED, FAILED }

    /**
     * One test's result.
     *
     * @param name    the test as a reader finds it: class, method and invocation
     * @param outcome what became of it
     * @param time    how long it ran (zero when skipped)
     * @param reason  the skip reason or the failure's first line; empty when it passed
     */
    public record Result(String name, Outcome outcome, Duration time, String reason) {
    }

    private final String label;
    private final List<Result> results = new ArrayList<>();

    /** @param label the module (and run, where a module has several), e.g. {@code core} */
    public TestSummary(String label) {
        this.label = label;
    }

    public void add(Result result) {
        results.add(result);
    }

    public int total() {
        return results.size();
    }

    public long count(Outcome outcome) {
        return results.stream().filter(r -> r.outcome() == outcome).count();
    }

    /**
     * The summary's lines.
     *
     * @param elapsed the run's wall-clock time
     * @param log     where the run's full output is, as the reader should type it
     */
    public List<String> lines(Duration elapsed, String log) {
        List<String> lines = new ArrayList<>();
        long failed = count(Outcome.FAILED);
        lines.add(String.format(Locale.ROOT, "%s: %d tests, %d passed, %d skipped, %d failed in %s (full log: %s)",
                label, total(), count(Outcome.PASSED), count(Outcome.SKIPPED), failed, duration(elapsed), log));
        Map<String, Integer> skipped = new LinkedHashMap<>();
        for (Result r : results) {
            if (r.outcome() == Outcome.SKIPPED) {
                skipped.merge(r.reason(), 1, Integer::sum);
            }
        }
        int shown = 0;
        int more = 0;
        for (Map.Entry<String, Integer> reason : skipped.entrySet()) {
            if (shown++ < REASONS) {
                lines.add(String.format(Locale.ROOT, "  skipped %d: %s", reason.getValue(), reason.getKey()));
            } else {
                more += reason.getValue();
            }
        }
        if (more > 0) {
            lines.add(String.format(Locale.ROOT, "  skipped %d more, for %d other reasons (the log names them)",
                    more, skipped.size() - REASONS));
        }
        results.stream().filter(r -> r.outcome() == Outcome.FAILED).limit(FAILURES)
                .forEach(r -> lines.add("  FAILED " + r.name() + ": " + r.reason()));
        if (failed > FAILURES) {
            lines.add(String.format(Locale.ROOT, "  and %d more failures (the log has them)", failed - FAILURES));
        }
        List<Result> slowest = results.stream()
                .filter(r -> r.outcome() != Outcome.SKIPPED)
                .sorted(Comparator.comparing(Result::time).reversed())
                .limit(SLOWEST)
                .toList();
        if (!slowest.isEmpty()) {
            StringBuilder line = new StringBuilder("  slowest:");
            for (int i = 0; i < slowest.size(); i++) {
                line.append(i == 0 ? " " : ", ").append(slowest.get(i).name())
                        .append(' ').append(duration(slowest.get(i).time()));
            }
            lines.add(line.toString());
        }
        return lines;
    }

    /** "0.4 s", "12 s", "3 min 05 s". */
    static String duration(Duration d) {
        long tenths = Math.round(d.toMillis() / 100.0);
        if (tenths < 100) {
            return tenths / 10 + "." + tenths % 10 + " s";
        }
        long whole = Math.round(d.toMillis() / 1000.0);
        if (whole < 60) {
            return whole + " s";
        }
        return String.format(Locale.ROOT, "%d min %02d s", whole / 60, whole % 60);
    }

    /** The first non-blank line of a message, trimmed; the whole text stays in the log. */
    public static String firstLine(String text) {
        if (text != null) {
            for (String line : text.split("\\R")) {
                if (!line.isBlank()) {
                    return line.strip();
                }
            }
        }
        return "";
    }
}
