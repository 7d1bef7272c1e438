package org.skinlab.desktop.app;

import java.util.List;

import org.skinlab.simulation.Frame;
import org.skinlab.skinning.MethodComparison;

/**
 * The numbers beside the difference view: LBS against DQS on the frame shown (core's
 * {@link MethodComparison}, one per geometry), measured at most {@value #PER_SECOND} times a
 * second, since they skin the model twice on the window's thread.
 */
final class DifferenceProbe {
    static final int PER_SECOND = 10;

    private final MethodComparison[] comparisons;
    private final int volumeGeometry;
    private final double size;
    private long measuredAt;
    private boolean measured;
    private double maxRelative = Double.NaN;
    private double lbsVolume = Double.NaN;
    private double dqsVolume = Double.NaN;

    /** @param comparisons one per geometry, made off the window's thread ({@code LoadedModel}) */
    DifferenceProbe(List<MethodComparison> made) {
        comparisons = made.toArray(new MethodComparison[0]);
        double largest = 0;
        int volume = -1;
        for (int g = 0; g < comparisons.length; g++) {
            largest = Math.max(largest, comparisons[g].size());
            // The volume shown is the largest closed mesh's (a character's body, not its eyes).
            if (comparisons[g].closed() && (volume < 0
                    || comparisons[g].geometry().pointCount() > comparisons[volume].geometry().pointCount())) {
                volume = g;
            }
        }
        size = largest;
        volumeGeometry = volume;
    }

    /** The model's size in its own units (the diagonal of its bind-pose bounds), what distances are relative to. */
    double size() {
        return size;
    }

    /** Measures the frame, unless it measured less than 1/{@value #PER_SECOND} s ago. */
    void measure(Frame frame) {
        long now = System.nanoTime();
        if (measured && now - measuredAt < 1_000_000_000L / PER_SECOND) {
            return;
        }
        measured = true;
        measuredAt = now;
        double max = 0;
        for (int g = 0; g < comparisons.length; g++) {
            comparisons[g].compare(frame.skinningMatrices(g));
            max = Math.max(max, comparisons[g].maxDistance());
        }
        maxRelative = size > 0 ? max / size : 0;
        if (volumeGeometry >= 0) {
            lbsVolume = comparisons[volumeGeometry].lbsVolume();
            dqsVolume = comparisons[volumeGeometry].dqsVolume();
        }
    }

    double maxRelative() {
        return maxRelative;
    }

    double lbsVolume() {
        return lbsVolume;
    }

    double dqsVolume() {
        return dqsVolume;
    }
}
