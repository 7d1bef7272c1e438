package org.skinlab.mixer;

import java.util.ArrayList;
import java.util.List;

import org.skinlab.animation.AnimationSampler;
import org.skinlab.animation.Skeleton;
import org.skinlab.model.AnimationChannel;
import org.skinlab.model.AnimationClip;

/**
 * One of the model's clips as the mixer knows it: its sampler, the sampler of its root channels
 * alone (for root motion, which samples the root at other times than the pose) and whether root
 * motion is on. Built once per clip; shared by every layer that plays the clip.
 */
final class MixerClip {
    final AnimationClip clip;
    final AnimationSampler sampler;
    /** The clip's channels on the root joint only, or null when it has none (no root motion to take). */
    final AnimationSampler rootSampler;
    final double duration;
    /** Set by the simulation thread only. */
    boolean rootMotion;
    /** The root's horizontal position and heading at the clip's start (RootMotion fills it once). */
    final double[] rootStart = new double[4];
    boolean rootStartKnown;

    MixerClip(Skeleton skeleton, AnimationClip clip, int root) {
        this.clip = clip;
        this.sampler = new AnimationSampler(skeleton, clip);
        this.duration = (double) clip.end() - clip.start();
        List<AnimationChannel> rootChannels = new ArrayList<>();
        for (AnimationChannel c : clip.channels()) {
            if (c.node() == root) {
                rootChannels.add(c);
            }
        }
        this.rootSampler = rootChannels.isEmpty() ? null
                : new AnimationSampler(skeleton, new AnimationClip(clip.id(), clip.name() + " (root)", clip.start(),
                        clip.end(), rootChannels));
    }

    String name() {
        return clip.name();
    }

    /** The clip time {@code elapsed} seconds after its start, as a sampler takes it. */
    float clipTime(double elapsed) {
        return (float) Math.min(clip.start() + elapsed, clip.end());
    }
}
