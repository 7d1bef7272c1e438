package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;

import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.function.Function;

import org.junit.jupiter.api.Test;
import org.knowm.xchart.XYChart;

/**
 * The category axis' labels by the rules XChart applies to a formatter (EvalCharts.categories):
 * the axis' two ends must format differently or XChart draws no ticks, and the whole positions of
 * a step of 1 (one below the axis to two above) must all differ or it takes a coarser step.
 */
class EvalChartsTest {
    @Test
    void everyCategoryIsLabelledAtAStepOfOne() {
        List<String> labels = List.of("humanoid-walk", "tentacle-wave", "bend", "cowboy", "stormtrooper");
        XYChart chart = EvalCharts.xy("t", "asset", "µs");
        EvalCharts.categories(chart, labels, 90);
        Function<Double, String> format = chart.getStyler().getxAxisTickLabelsFormattingFunction();
        double min = chart.getStyler().getXAxisMin();
        double max = chart.getStyler().getXAxisMax();
        assertEquals(-0.5, min);
        assertEquals(labels.size() - 0.5, max);
        assertNotEquals(format.apply(min), format.apply(max), "the axis' ends alike: XChart would draw no tick");
        Set<String> seen = new HashSet<>();
        for (int k = -1; k <= labels.size() + 1; k++) {
            String label = format.apply((double) k);
            if (k >= 0 && k < labels.size()) {
                assertEquals(labels.get(k), label);
            } else {
                assertEquals("", label.strip(), "beyond the categories: a blank");
            }
            assertEquals(true, seen.add(label), "label " + k + " repeats: " + label);
        }
        // A finer step has two blanks alike between the categories, so XChart passes it over.
        assertEquals(format.apply(0.5), format.apply(1.5));
    }
}
