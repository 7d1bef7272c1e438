package org.skinlab.internal.metrics;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * The largest distance between a point's LBS and its DQS position over a whole clip, relative to
 * the model's size: the top of a difference view's colour scale that holds still while the clip
 * plays, so that a colour means the same distance at every time. Measured as the viewer's
 * difference view measures one frame ({@link MethodComparison} per geometry, the largest distance
 * over all geometries divided by the model's size, {@link RestPose#size}) at the clip's sample times ({@link InfluenceCapError#sampleTimes}: 30 a second, and its
 * end); between samples nothing is looked at.
 *
 * @param relative the largest distance over the model's size (0 at rest, or where the methods agree)
 * @param clipTime the clip time (seconds) it was measured at
 * @param samples  the poses measured
 */
public record LargestDifference(double relative, float clipTime, int samples) {
    /**
     * Samples {@code clip} on a model of its own (the caller's simulation is not touched; any
     * thread may run it, typically a loader). An interrupt ends it early with what was measured.
     *
     * @param clip the clip, or null for the model at rest (one sample)
     */
    public static LargestDifference over(Model model, AnimationClip clip, RotationInterpolation rotations) {
        SkinnedModel skinned = new SkinnedModel(model, clip, NormalTransform.INVERSE_TRANSPOSE,
                EnumSet.of(SkinningMethod.LBS)); // poses and palettes: the comparisons skin
        RestPose rest = RestPose.of(skinned);
        List<MethodComparison> comparisons = new ArrayList<>();
        for (int g = 0; g < skinned.geometries().size(); g++) {
            comparisons.add(new MethodComparison(rest, g));
        }
        double size = rest.size();
        float[] times = InfluenceCapError.sampleTimes(skinned.sampler().start(), skinned.sampler().end());
        double largest = 0;
        float at = times[0];
        int samples = 0;
        for (float t : times) {
            if (Thread.currentThread().isInterrupted()) {
                break;
            }
            skinned.pose(t, rotations);
            double max = 0;
            for (int g = 0; g < comparisons.size(); g++) {
                comparisons.get(g).compare(skinned.palette(g).matrices());
                max = Math.max(max, comparisons.get(g).maxDistance());
            }
            samples++;
            if (max > largest) {
                largest = max;
                at = t;
            }
        }
        return new LargestDifference(size > 0 ? largest / size : 0, at, samples);
    }
}
