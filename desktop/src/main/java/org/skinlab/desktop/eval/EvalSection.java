package org.skinlab.desktop.eval;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * One section of {@code skinlab eval}'s report: it measures into its node of results.json, then
 * writes its part of README.md and its figures from that node alone (so every number the report
 * prints is one results.json holds). A new section is a class listed in {@link Evaluation#SECTIONS}.
 */
interface EvalSection {
    /** The name {@code --only} selects it by, e.g. "load"; also its key in results.json. */
    String key();

    /** The heading of its part of the report. */
    String title();

    /** About how long it measures, in seconds (weights the progress bar's estimate of the time left). */
    double estimatedSeconds(EvalContext context);

    /** Measures, writing every number into {@code results}; reports progress through the context. */
    void measure(EvalContext context, ObjectNode results);

    /**
     * Whether the section sums up the others (measured after them, from their results, and
     * written first in the report).
     */
    default boolean summary() {
        return false;
    }

    /**
     * A summary's results derived again from the other sections' results ({@code sections}: key
     * to results, null when not run), measuring nothing; what {@link #measure} of a summary does.
     */
    default void derive(java.util.function.Function<String, JsonNode> sections, ObjectNode results) {
        throw new UnsupportedOperationException(key() + " measures; only a summary is derived");
    }

    /** Its part of the report and its figures, from its results only. */
    void report(JsonNode results, EvalReport report);
}
