package org.skinlab.animation;

import java.util.ArrayList;
import java.util.List;

import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;
import org.skinlab.model.Morph;
import org.skinlab.model.MorphWeightChannel;

/**
 * Samples the morph weights a clip animates ({@link AnimationClip#morphWeights()}), per mesh
 * instance, into arrays the caller owns: the sibling of {@link AnimationSampler} for weights, with
 * the same rules per weight (STEP holds, LINEAR blends, BEZIER, i.e. glTF's CUBICSPLINE, follows
 * the cubic through the control points; before the first key the first, after the last the last).
 * Weights no channel drives keep the file's ({@link Morph#weights()}). Immutable and
 * thread-safe; sampling allocates nothing.
 */
public final class MorphWeightSampler {
    private final int instanceCount;
    private final Morph[] morphs;
    private final int[] instanceOfChannel;
    private final AnimationSampler.Channel[] channels;

    /**
     * A sampler of {@code clip}'s morph weight channels for the mesh instances of {@code model}.
     *
     * @param model the model the clip belongs to; its {@link Model#instances()} are what the channels name
     * @param clip the clip, or null for none (nothing animated)
     * @throws IllegalArgumentException when a channel animates an instance that draws no morph
     */
    public MorphWeightSampler(Model model, AnimationClip clip) {
        instanceCount = model.instances().size();
        morphs = new Morph[instanceCount];
        List<MorphWeightChannel> list = clip == null ? List.of() : clip.morphWeights();
        instanceOfChannel = new int[list.size()];
        channels = new AnimationSampler.Channel[list.size()];
        List<float[]> timelines = new ArrayList<>();
        for (int i = 0; i < channels.length; i++) {
            MorphWeightChannel c = list.get(i);
            instanceOfChannel[i] = c.instance();
            morphs[c.instance()] = model.morphOf(model.instances().get(c.instance())).orElseThrow(
                    () -> new IllegalArgumentException(c.target() + ": the instance draws no morph"));
            channels[i] = new AnimationSampler.Channel(c.weightOffset(), c.track(),
                    AnimationSampler.sharedTimes(c.track().times(), timelines), false, false);
        }
    }

    /**
     * Whether the clip animates the weights of instance {@code instance}.
     *
     * @param instance an index into the model's {@link Model#instances()}
     * @return true when at least one channel drives a weight of that instance's morph
     */
    public boolean animates(int instance) {
        return morphs[instance] != null;
    }

    /**
     * Whether the clip animates any weights.
     *
     * @return true when the clip has at least one morph weight channel; false also for a null clip
     */
    public boolean animatesAny() {
        return channels.length > 0;
    }

    /**
     * The morph whose weights instance {@code instance} animates, or null.
     *
     * @param instance an index into the model's {@link Model#instances()}
     * @return the instance's morph, or null when the clip animates none of its weights
     */
    public Morph morph(int instance) {
        return morphs[instance];
    }

    /**
     * Per instance, an array of its morph's weights (the file's) where the clip animates them, else
     * null: the state {@link #sample} updates.
     *
     * @return a new array, one entry per mesh instance; each non-null entry is a fresh copy of the morph's
     *     weights in target order, owned by the caller
     */
    public float[][] newWeights() {
        float[][] w = new float[instanceCount][];
        for (int i = 0; i < instanceCount; i++) {
            w[i] = morphs[i] == null ? null : morphs[i].weights();
        }
        return w;
    }

    /**
     * Writes every animated weight at clip time {@code time} into {@code weights} (from {@link #newWeights}).
     *
     * @param time the clip time in seconds, on the keys' timeline as for {@link AnimationSampler#sample}
     * @param weights per instance its weights, as made by {@link #newWeights}; only animated weights are written
     * @throws IllegalArgumentException when {@code time} is NaN
     */
    public void sample(float time, float[][] weights) {
        if (Float.isNaN(time)) {
            throw new IllegalArgumentException("sample time is NaN");
        }
        float[] searched = null;
        int k = 0;
        for (int i = 0; i < channels.length; i++) {
            AnimationSampler.Channel c = channels[i];
            if (c.times != searched) {
                searched = c.times;
                k = AnimationSampler.segment(searched, time);
            }
            c.sample(k, time, RotationInterpolation.SLERP, weights[instanceOfChannel[i]], c.slot, null);
        }
    }
}
