package org.skinlab.model;

import java.util.List;

/**
 * A named piece of animation: an {@code <animation_clip>}, or, when the file has none, one clip
 * (named {@value #DEFAULT_NAME}) over every channel of the file. Times are in seconds.
 *
 * @param id    the clip's id, or null
 * @param name  the clip's name, else its id, else "clip-N" (N counting from 1)
 * @param start clip start time (seconds)
 * @param end   clip end time (seconds), never before start
 */
public record AnimationClip(String id, String name, float start, float end, List<AnimationChannel> channels,
        List<MorphWeightChannel> morphWeights) {
    /** Name of the clip made when a file has animations but no {@code <library_animation_clips>}. */
    public static final String DEFAULT_NAME = "default";

    public AnimationClip {
        channels = List.copyOf(channels);
        morphWeights = List.copyOf(morphWeights);
        if (end < start) {
            throw new IllegalArgumentException("clip ends before it starts");
        }
    }

    /** A clip of node channels only. */
    public AnimationClip(String id, String name, float start, float end, List<AnimationChannel> channels) {
        this(id, name, start, end, channels, List.of());
    }

    /** end - start, in seconds. */
    public float duration() {
        return end - start;
    }
}
