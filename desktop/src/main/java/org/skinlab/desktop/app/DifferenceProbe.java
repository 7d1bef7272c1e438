package org.skinlab.desktop.app;

import java.util.List;

import org.skinlab.simulation.Frame;
import org.skinlab.internal.metrics.MethodComparison;
import org.skinlab.internal.metrics.RestPose;

/**
 * The numbers beside the difference view: LBS against DQS on the frame shown (core's
 * {@link MethodComparison}, one per part, against the model's {@link RestPose}): the largest
 * distance over every part relative to the placed model's size, and the model's volume (its
 * counted parts summed, each against its own rest), measured at most {@value #PER_SECOND} times a
 * second, since they skin the model twice on the window's thread.
 */
final class DifferenceProbe {
    static final int PER_SECOND = 10;

    private final RestPose rest;
    private final MethodComparison[] comparisons;
    /** Per part, the comparison's LBS and DQS points (the same arrays every measure). */
    private final float[][] lbsPoints;
    private final float[][] dqsPoints;
    private final String volumeNote;
    private long measuredAt;
    private boolean measured;
    private double maxRelative = Double.NaN;
    private double lbsVolume = Double.NaN;
    private double dqsVolume = Double.NaN;

    /** @param made one per part of {@code rest}, in its order, made off the window's thread ({@code LoadedModel}) */
    DifferenceProbe(RestPose rest, List<MethodComparison> made) {
        this.rest = rest;
        comparisons = made.toArray(new MethodComparison[0]);
        lbsPoints = new float[comparisons.length][];
        dqsPoints = new float[comparisons.length][];
        for (int g = 0; g < comparisons.length; g++) {
            lbsPoints[g] = comparisons[g].lbsPositions();
            dqsPoints[g] = comparisons[g].dqsPositions();
        }
        String note = rest.volumeNote();
        volumeNote = note.isEmpty() ? "" : "volume: " + note;
    }

    /** The placed model's size in the document's units (its rest pose's bounds), what distances are relative to. */
    double size() {
        return rest.size();
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
            comparisons[g].compare(frame.palette(g).matrices());
            max = Math.max(max, comparisons[g].maxDistance());
        }
        maxRelative = rest.size() > 0 ? max / rest.size() : 0;
        lbsVolume = rest.relativeVolume(lbsPoints);
        dqsVolume = rest.relativeVolume(dqsPoints);
    }

    double maxRelative() {
        return maxRelative;
    }

    /** LBS's volume of the model over its rest volume; NaN before the first measure or when no part counts. */
    double lbsVolume() {
        return lbsVolume;
    }

    double dqsVolume() {
        return dqsVolume;
    }

    /**
     * Which parts the volume holds or why there is none ("volume: 3 of 3 skinned parts open"),
     * made once; empty for a model of one closed skinned part.
     */
    String volumeNote() {
        return volumeNote;
    }
}
