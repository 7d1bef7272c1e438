package org.skinlab.mixer;

import org.skinlab.animation.LocalPose;
import org.skinlab.animation.Pose;
import org.skinlab.animation.Skeleton;

/**
 * A clip as one layer plays it: its clock, its weight and the scratch it samples into. Touched by
 * the simulation thread only.
 */
final class ClipState {
    final MixerClip clip;
    /** The transform values sampleLocal works in (persisting, see AnimationSampler.sampleLocal). */
    final Pose values;
    /** The clip's local pose at the last evaluation. */
    final LocalPose local;
    /** An additive layer's reference: the clip's local pose at the reference time, or null. */
    LocalPose reference;
    /** The reference time {@link #reference} was sampled at, NaN when none. */
    double referenceTime = Double.NaN;
    /** Seconds since the clip's start, brought into the clip by the layer's wrap mode. */
    double elapsed;
    double weight;
    /** The weight when the running cross-fade started. */
    double fadeFrom;
    /** Root motion of the last advance, in the root's parent space, in the frame at the step's start. */
    final double[] motion = new double[4];

    ClipState(MixerClip clip, Skeleton skeleton) {
        this.clip = clip;
        this.values = skeleton.newPose();
        this.local = skeleton.newLocalPose();
    }

    float clipTime() {
        return clip.clipTime(elapsed);
    }
}
