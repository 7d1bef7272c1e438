package org.skinlab.model;

import java.util.List;

/**
 * A named piece of animation: an {@code <animation_clip>}, or, when the file has none, one clip
 * (named {@value #DEFAULT_NAME}) over every channel of the file. Times are in seconds.
 *
 * @param id           the clip's id, or null
 * @param name         the clip's name, else its id, else "clip-N" (N counting from 1)
 * @param start        clip start time (seconds)
 * @param end          clip end time (seconds), never before start
 * @param channels     the node channels (transform elements the clip animates); read-only
 * @param morphWeights the morph weight channels (weights of mesh instances' morphs); read-only
 */
public record AnimationClip(String id, String name, float start, float end, List<AnimationChannel> channels,
        List<MorphWeightChannel> morphWeights) {
    /** Name of the clip made when a file has animations but no {@code <library_animation_clips>}. */
    public static final String DEFAULT_NAME = "default";

    /**
     * A clip; the channel lists are copied.
     *
     * @param id           the clip's id, or null
     * @param name         the clip's name
     * @param start        start time (seconds)
     * @param end          end time (seconds), at least {@code start}
     * @param channels     the node channels
     * @param morphWeights the morph weight channels
     * @throws IllegalArgumentException when {@code end} is before {@code start}
     * @throws NullPointerException     when a list, or an element of one, is null
     */
    public AnimationClip {
        channels = List.copyOf(channels);
        morphWeights = List.copyOf(morphWeights);
        if (end < start) {
            throw new IllegalArgumentException("clip ends before it starts");
        }
    }

    /**
     * A clip of node channels only.
     *
     * @param id       the clip's id, or null
     * @param name     the clip's name
     * @param start    start time (seconds)
     * @param end      end time (seconds), at least {@code start}
     * @param channels the node channels; copied
     * @throws IllegalArgumentException when {@code end} is before {@code start}
     */
    public AnimationClip(String id, String name, float start, float end, List<AnimationChannel> channels) {
        this(id, name, start, end, channels, List.of());
    }

    /**
     * end - start, in seconds.
     *
     * @return the clip's length in seconds, 0 or more
     */
    public float duration() {
        return end - start;
    }
}
