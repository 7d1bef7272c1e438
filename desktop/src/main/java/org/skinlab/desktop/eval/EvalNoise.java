package org.skinlab.desktop.eval;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * The machine's noise during a run, from the run's own repeated timings: every timing in
 * results.json kept as runs ({@link EvalReport#putSpread}) says how far its runs lay apart; the
 * report states the median and the 90th percentile of that spread over all timings, and the
 * load average at the start and the end, so that a reader can tell a difference from the noise.
 */
final class EvalNoise {
    private EvalNoise() {
    }

    /** Summarises every spread below {@code sections} into {@code out}. */
    static void summarise(JsonNode sections, double loadStart, ObjectNode out) {
        List<Double> iqr = new ArrayList<>();
        List<Double> range = new ArrayList<>();
        collect(sections, iqr, range);
        out.put("timings", iqr.size());
        out.put("minRuns", org.skinlab.internal.bench.Rounds.MIN_RUNS);
        out.put("loadAverageStart", loadStart);
        out.put("loadAverageEnd", EvalMachine.loadAverage());
        if (iqr.isEmpty()) {
            return;
        }
        Collections.sort(iqr);
        Collections.sort(range);
        out.put("medianInterquartilePercent", EvalReport.round(100 * quantile(iqr, 0.5)));
        out.put("p90InterquartilePercent", EvalReport.round(100 * quantile(iqr, 0.9)));
        out.put("medianRangePercent", EvalReport.round(100 * quantile(range, 0.5)));
        out.put("p90RangePercent", EvalReport.round(100 * quantile(range, 0.9)));
    }

    /** Each timing's interquartile range and full range, over its median. */
    private static void collect(JsonNode node, List<Double> iqr, List<Double> range) {
        if (node.isObject() && node.has("runs") && node.has("median") && node.has("q1") && node.has("q3")) {
            double median = node.get("median").asDouble();
            if (median > 0) {
                iqr.add((node.get("q3").asDouble() - node.get("q1").asDouble()) / median);
                range.add((node.get("max").asDouble() - node.get("min").asDouble()) / median);
            }
            return;
        }
        for (JsonNode child : node) {
            collect(child, iqr, range);
        }
    }

    private static double quantile(List<Double> sorted, double q) {
        double position = q * (sorted.size() - 1);
        int below = (int) Math.floor(position);
        int above = Math.min(sorted.size() - 1, below + 1);
        return sorted.get(below) + (position - below) * (sorted.get(above) - sorted.get(below));
    }

    /** The report's paragraph on the noise (from {@code noise}, the node {@link #summarise} wrote). */
    static String paragraph(JsonNode results) {
        JsonNode n = results.get("noise");
        if (n.get("timings").asInt() == 0) {
            return "No timing was taken in this run, so there is no noise to state.";
        }
        return "**The machine's noise.** Every timing below was taken in at least " + EvalReport.num(results,
                "/noise/minRuns") + " runs, interleaved across what it is compared with; over the " + EvalReport.num(results, "/noise/timings") + " timings of this run"
                + " the runs' interquartile range is a median " + EvalReport.num(results,
                        "/noise/medianInterquartilePercent") + " % of the timing (" + EvalReport.num(results,
                        "/noise/p90InterquartilePercent") + " % or less for nine timings in ten), the whole range from the"
                + " fastest run to the slowest a median " + EvalReport.num(results, "/noise/medianRangePercent")
                + " % (" + EvalReport.num(results, "/noise/p90RangePercent") + " % for nine in ten). The load average"
                + " was " + EvalReport.num(results, "/noise/loadAverageStart") + " at the start and "
                + EvalReport.num(results, "/noise/loadAverageEnd") + " at the end. Differences smaller than the"
                + " spread of the timings compared are not differences.";
    }
}
