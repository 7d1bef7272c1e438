package org.skinlab.desktop.viewer;

import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.internal.metrics.LargestDifference;

/**
 * The auto difference scale's measure: the clip's largest LBS-DQS difference of the model shown
 * ({@link LargestDifference}: a copy of the model posed 30 times per second of clip), run on the
 * viewer's loader thread, so neither the window's nor the simulation's thread waits for it. One
 * model at a time: asking for another cancels the one under way. Used on the window's thread.
 */
final class ClipMeasure {
    private final ExecutorService loader;
    private Future<LargestDifference> running;
    private LoadedModel measured;
    /** What {@link #running} found, once taken; null before. */
    private LargestDifference result;

    ClipMeasure(ExecutorService loader) {
        this.loader = loader;
    }

    /**
     * Takes a finished measure, and starts measuring {@code model}'s clip (with {@code rotations})
     * unless it is the one measured or being measured. Allocates nothing when there is nothing new.
     */
    void update(LoadedModel model, RotationInterpolation rotations) {
        takeResult();
        if (model == null || model == measured) {
            return;
        }
        cancel();
        measured = model;
        running = loader.submit(() -> LargestDifference.over(model.model(),
                model.clipIndex() < 0 ? null : model.model().clips().get(model.clipIndex()), rotations));
    }

    private void takeResult() {
        if (running == null || result != null || !running.isDone() || running.isCancelled()) {
            return;
        }
        try {
            result = running.get();
        } catch (ExecutionException e) {
            // A model the methods cannot compare: it keeps the default scale.
            running = null;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Stops the measure under way (its loader thread is wanted for a load), and forgets the last. */
    void cancel() {
        if (running != null) {
            running.cancel(true);
        }
        running = null;
        measured = null;
        result = null;
    }

    /** {@code model}'s measure, or null while it is measured or when it is not the model measured. */
    LargestDifference result(LoadedModel model) {
        return model != null && model == measured ? result : null;
    }

    /** Waits at most {@code seconds} for the measure under way, then takes it. */
    void await(long seconds) {
        Future<LargestDifference> f = running;
        if (f != null) {
            try {
                f.get(seconds, TimeUnit.SECONDS);
            } catch (ExecutionException | TimeoutException e) {
                // Drawn at the default scale.
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        takeResult();
    }
}
