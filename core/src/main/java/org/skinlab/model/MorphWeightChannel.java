package org.skinlab.model;

/**
 * Animated morph weights: the track drives weights {@code [weightOffset, weightOffset +
 * track.width())} of the {@link Morph} that mesh instance {@code instance} draws
 * ({@link Model#morphOf}). Weights belong to the instance, not to the morph, because glTF keeps
 * them per node: two nodes drawing one mesh animate their weights apart. A COLLADA channel on a
 * morph controller's weights becomes one such channel per instance of that controller.
 *
 * <p>Examples: glTF {@code /animations/0/channels/0} on a node whose mesh has 2 targets is offset
 * 0, width 2; COLLADA {@code smile-weights(1)} is offset 1, width 1.
 *
 * @param instance     index into {@link Model#instances()}
 * @param weightOffset first weight the channel drives
 * @param track        the keyframe track, one value per driven weight per key
 * @param target       the channel's target as written (JSON path or COLLADA target), for messages
 */
public record MorphWeightChannel(int instance, int weightOffset, KeyframeTrack track, String target) {
    /**
     * Checks that the indices are not negative; the {@link Model} constructor checks them against the model's
     * instances and morphs.
     *
     * @param instance     index into {@link Model#instances()}
     * @param weightOffset first weight the channel drives
     * @param track        the keyframe track, one value per driven weight per key
     * @param target       the channel's target as written (JSON path or COLLADA target), for messages
     * @throws IllegalArgumentException when {@code instance} or {@code weightOffset} is negative
     */
    public MorphWeightChannel {
        if (instance < 0 || weightOffset < 0) {
            throw new IllegalArgumentException("negative instance or weight offset");
        }
    }

    /**
     * Number of weights the channel drives (the track's width).
     *
     * @return the weight count, at least 1
     */
    public int weightCount() {
        return track.width();
    }
}
