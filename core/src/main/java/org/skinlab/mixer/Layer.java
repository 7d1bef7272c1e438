package org.skinlab.mixer;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import org.skinlab.animation.LocalPose;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.WrapMode;

/**
 * One layer of a {@link Mixer}: the clips it plays with their weights (one clip, a weighted set, a
 * cross-fade between clips or a {@link BlendSpace}), its own clock (speed and wrap mode), its
 * weight, its {@link JointMask} and its {@link LayerMode}.
 *
 * <p><b>Within a layer</b> the clips are blended per joint as three.js' {@code AnimationMixer}
 * blends its actions: the clips that animate the joint accumulate in order, each slerped in by
 * its share of the weight so far ({@code w_i / (w_1 + ... + w_i)}; for two clips the slerp by the
 * second's share of the weight), and where their weights sum to less than one the rest pose fills
 * the remainder. A clip that does not animate a joint has no say there.
 *
 * <p>Not thread-safe: a mixer and its layers belong to one thread (the simulation thread; from
 * other threads change them through {@code SkeletalAnimatedMesh.direct}). Changing a layer
 * allocates (a user action); advancing and evaluating do not.
 */
public final class Layer {
    private final Mixer mixer;
    private final String name;
    /** The clip states this layer has used, by clip name: made once, reused (no allocation per change). */
    private final Map<String, ClipState> states = new HashMap<>();
    /** The clips playing now, in blend order. */
    private final List<ClipState> active = new ArrayList<>();
    private LayerMode mode = LayerMode.OVERRIDE;
    private double referenceTime;
    private double weight = 1;
    private JointMask mask;
    private double speed = 1;
    private WrapMode wrap = WrapMode.LOOP;
    /** The clips advance together by phase (a synchronised fade, a blend space). */
    private boolean synchronised;
    private double phase;
    // The running cross-fade.
    private CrossFade fade;
    // The blend space played, or null.
    private BlendSpace space;
    private double[] spaceWeights;
    private double spaceX;
    private double spaceY;

    Layer(Mixer mixer, String name) {
        this.mixer = mixer;
        this.name = name;
    }

    /**
     * The layer's name.
     *
     * @return the name given when it was added
     */
    public String name() {
        return name;
    }

    // ------------------------------------------------------------------ what plays

    /**
     * Plays one clip alone at weight 1 from its start; ends any cross-fade or blend space.
     *
     * @param clip the clip's name (a glTF animation's name, a COLLADA clip's name or id)
     * @throws IllegalArgumentException when the model has no such clip (the message lists those it has)
     */
    public void play(String clip) {
        ClipState s = state(clip);
        stopFadeAndSpace();
        active.clear();
        s.weight = 1;
        s.elapsed = 0;
        active.add(s);
        synchronised = false;
    }

    /**
     * Plays a weighted set of clips (what {@code skinlab pose --blend} does): each at its own time,
     * kept for a clip already playing, from its start for one that is not. Ends any cross-fade or
     * blend space.
     *
     * @param weights per clip name, a weight: finite and 0 or more; in blend order
     * @throws IllegalArgumentException for an unknown clip or a negative, infinite or NaN weight (naming it)
     */
    public void setClipWeights(Map<String, ? extends Number> weights) {
        List<ClipState> next = new ArrayList<>();
        for (Map.Entry<String, ? extends Number> e : weights.entrySet()) {
            next.add(state(e.getKey()));
            checkWeight("clip \"" + e.getKey() + "\"", e.getValue().doubleValue());
        }
        stopFadeAndSpace();
        for (ClipState s : next) {
            if (!active.contains(s)) {
                s.elapsed = 0;
            }
        }
        active.clear();
        int i = 0;
        for (Number w : weights.values()) {
            ClipState s = next.get(i++);
            s.weight = w.doubleValue();
            active.add(s);
        }
        synchronised = false;
        mixer.checkJointsAnimated(this, active);
    }

    /**
     * Cross-fades from what plays now to {@code clip} over {@code seconds}: the incoming clip's
     * share grows from 0 to 1 along {@code curve} while every other clip's weight shrinks in
     * proportion. A fade started during a fade starts from the weights of that moment, so nothing
     * pops. Synchronised, the incoming clip starts at the phase (the fraction of its duration) of
     * the heaviest clip playing, and all clips advance together by phase until the fade ends, so
     * the feet of two locomotion cycles stay in step; otherwise it starts from its beginning (or
     * goes on from where it is, when already playing). Ends a blend space (its clips fade out at
     * the weights they had).
     *
     * @param clip the incoming clip's name
     * @param seconds the fade's duration in seconds of animation time: finite and 0 or more (0 switches at once)
     * @param curve how the incoming share grows
     * @param synchronised whether to start the incoming clip in step with the outgoing ones
     * @throws IllegalArgumentException for an unknown clip or a negative, infinite or NaN duration
     */
    public void crossFade(String clip, double seconds, FadeCurve curve, boolean synchronised) {
        ClipState target = state(clip);
        if (!(seconds >= 0) || Double.isInfinite(seconds)) {
            throw new IllegalArgumentException("cross-fade to \"" + clip + "\" over " + seconds
                    + " s (need a finite duration >= 0)");
        }
        ClipState heaviest = heaviest();
        double inPhase = heaviest != null && heaviest.clip.duration > 0 ? heaviest.elapsed / heaviest.clip.duration : 0;
        space = null;
        if (!active.contains(target)) {
            target.weight = 0;
            target.elapsed = synchronised ? inPhase * target.clip.duration : 0;
            active.add(target);
        } else if (synchronised) {
            target.elapsed = inPhase * target.clip.duration;
        }
        this.synchronised = synchronised;
        this.phase = inPhase;
        fade = new CrossFade(target, seconds, curve, active);
        if (seconds == 0) {
            finishFade();
        } else {
            mixer.checkJointsAnimated(this, active);
        }
    }

    /**
     * Plays a blend space at the point (x, y) (y ignored in 1-D): every clip of the space at the
     * weight the space gives it, all advancing together by phase, at the weighted mean of their
     * durations, so a walk and a run blended keep their feet in step. Ends any cross-fade.
     *
     * @param blendSpace the blend space; its clips must be the model's
     * @param x the parameter, or the point's x
     * @param y the point's y (2-D)
     * @throws IllegalArgumentException for a clip the model lacks, or a NaN parameter
     */
    public void setBlendSpace(BlendSpace blendSpace, double x, double y) {
        List<ClipState> next = new ArrayList<>();
        for (String c : blendSpace.clips()) {
            next.add(state(c));
        }
        double[] w = new double[next.size()];
        blendSpace.weights(x, y, w);
        ClipState heaviest = heaviest();
        double inPhase = synchronised ? phase
                : heaviest != null && heaviest.clip.duration > 0 ? heaviest.elapsed / heaviest.clip.duration : 0;
        stopFadeAndSpace();
        active.clear();
        active.addAll(next);
        space = blendSpace;
        spaceWeights = w;
        spaceX = x;
        spaceY = y;
        synchronised = true;
        phase = inPhase;
        for (int i = 0; i < next.size(); i++) {
            next.get(i).weight = w[i];
            next.get(i).elapsed = phase * next.get(i).clip.duration;
        }
        mixer.checkJointsAnimated(this, active);
    }

    /**
     * Moves the blend space's point. Allocation-free.
     *
     * @param x the parameter, or the point's x
     * @param y the point's y (2-D)
     * @throws IllegalStateException when the layer plays no blend space
     * @throws IllegalArgumentException for a NaN parameter
     */
    public void setBlendParameter(double x, double y) {
        if (space == null) {
            throw new IllegalStateException("layer \"" + name + "\" plays no blend space");
        }
        space.weights(x, y, spaceWeights);
        spaceX = x;
        spaceY = y;
        for (int i = 0; i < active.size(); i++) {
            active.get(i).weight = spaceWeights[i];
        }
    }

    private void stopFadeAndSpace() {
        fade = null;
        space = null;
    }

    private ClipState state(String clip) {
        MixerClip c = mixer.clip(clip);
        return states.computeIfAbsent(c.name(), k -> new ClipState(c, mixer.skeleton()));
    }

    static void checkWeight(String what, double w) {
        if (!(w >= 0) || Double.isInfinite(w)) {
            throw new IllegalArgumentException("weight of " + what + " is " + w + " (need a finite value >= 0)");
        }
    }

    // ------------------------------------------------------------------ how it plays

    /**
     * Sets the layer's weight: how much it counts over the layers below (for the first layer, over
     * the rest pose).
     *
     * @param w the weight, finite and 0 or more (above 1 an override layer still replaces fully; an
     *     additive one exaggerates)
     * @throws IllegalArgumentException for a negative, infinite or NaN weight
     */
    public void setWeight(double w) {
        checkWeight("layer \"" + name + "\"", w);
        this.weight = w;
    }

    /**
     * The layer's weight.
     *
     * @return the weight set, 1 by default
     */
    public double weight() {
        return weight;
    }

    /**
     * Limits the layer to some joints (null: all).
     *
     * @param jointMask the mask, of the mixer's skeleton, or null
     * @throws IllegalArgumentException when the mask belongs to another skeleton
     */
    public void setMask(JointMask jointMask) {
        if (jointMask != null && jointMask.skeleton() != mixer.skeleton()) {
            throw new IllegalArgumentException("a joint mask of another skeleton");
        }
        this.mask = jointMask;
    }

    /**
     * The layer's mask.
     *
     * @return the mask, or null for all joints
     */
    public JointMask mask() {
        return mask;
    }

    /**
     * Makes the layer additive: its clips' difference from their own pose at {@code referenceTime}
     * (seconds after each clip's start) is added to the layers below.
     *
     * @param referenceTime seconds after the clip's start, finite (clamped to the clip)
     * @throws IllegalArgumentException for an infinite or NaN time
     */
    public void setAdditive(double referenceTime) {
        if (!Double.isFinite(referenceTime)) {
            throw new IllegalArgumentException("additive reference time " + referenceTime + " (need a finite time)");
        }
        this.mode = LayerMode.ADDITIVE;
        this.referenceTime = referenceTime;
    }

    /** Makes the layer override the layers below (the default). */
    public void setOverride() {
        this.mode = LayerMode.OVERRIDE;
    }

    /**
     * The layer's mode.
     *
     * @return override or additive
     */
    public LayerMode mode() {
        return mode;
    }

    /**
     * The additive reference time.
     *
     * @return seconds after each clip's start, as set by {@link #setAdditive}; 0 by default
     */
    public double referenceTime() {
        return referenceTime;
    }

    /**
     * Sets the playback speed of the layer's clips (1 is real time, negative plays backwards).
     *
     * @param speed finite
     * @throws IllegalArgumentException for an infinite or NaN speed
     */
    public void setSpeed(double speed) {
        if (!Double.isFinite(speed)) {
            throw new IllegalArgumentException("layer speed " + speed + " (need a finite value)");
        }
        this.speed = speed;
    }

    /**
     * Sets what happens at the clips' ends.
     *
     * @param mode loop or clamp
     */
    public void setWrapMode(WrapMode mode) {
        this.wrap = java.util.Objects.requireNonNull(mode, "mode");
    }

    /**
     * Moves every clip of the layer to {@code seconds} after its start (wrapped or held as the
     * wrap mode says); synchronised clips to the same phase as the heaviest.
     *
     * @param seconds seconds after the clips' starts, finite
     * @throws IllegalArgumentException for an infinite or NaN time
     */
    public void setTime(double seconds) {
        if (!Double.isFinite(seconds)) {
            throw new IllegalArgumentException("layer time " + seconds + " (need a finite time)");
        }
        for (ClipState s : active) {
            s.elapsed = s.clip.sampler.wrapElapsed(seconds, wrap);
        }
        ClipState h = heaviest();
        if (synchronised && h != null && h.clip.duration > 0) {
            phase = h.elapsed / h.clip.duration;
            for (ClipState s : active) {
                s.elapsed = phase * s.clip.duration;
            }
        }
    }

    /**
     * Seconds since the start of the heaviest clip playing (the first of equals).
     *
     * @return the time, 0 when nothing plays
     */
    public double time() {
        ClipState h = heaviest();
        return h == null ? 0 : h.elapsed;
    }

    /**
     * The clip time (on its keys' timeline) of the heaviest clip playing.
     *
     * @return the clip time in seconds, 0 when nothing plays
     */
    public float clipTime() {
        ClipState h = heaviest();
        return h == null ? 0f : h.clipTime();
    }

    /**
     * The name of the heaviest clip playing.
     *
     * @return the clip's name, or null when nothing plays
     */
    public String heaviestClip() {
        ClipState h = heaviest();
        return h == null ? null : h.clip.name();
    }

    /**
     * The clips playing and their weights now (during a fade, the fade's weights of the last step).
     *
     * @return a new map from clip name to weight, in blend order
     */
    public Map<String, Double> clipWeights() {
        Map<String, Double> m = new LinkedHashMap<>();
        for (ClipState s : active) {
            m.put(s.clip.name(), s.weight);
        }
        return m;
    }

    /**
     * Whether a cross-fade is running.
     *
     * @return true from {@link #crossFade} until its duration has passed
     */
    public boolean isFading() {
        return fade != null;
    }

    /**
     * The blend space played.
     *
     * @return the blend space, or null
     */
    public BlendSpace blendSpace() {
        return space;
    }

    /**
     * The blend space's point.
     *
     * @return {x, y}, as last set
     */
    public double[] blendParameter() {
        return new double[] {spaceX, spaceY};
    }

    ClipState heaviest() {
        ClipState best = null;
        for (int i = 0; i < active.size(); i++) {
            ClipState s = active.get(i);
            if (best == null || s.weight > best.weight) {
                best = s;
            }
        }
        return best;
    }

    List<ClipState> active() {
        return active;
    }

    // ------------------------------------------------------------------ per step

    /** Advances the fade and the clocks by {@code dt} seconds; root motion into each state (null: none). */
    void advance(double dt, RootMotion rootMotion) {
        boolean faded = fade != null && fade.advance(dt, active);
        double step = dt * speed;
        if (synchronised) {
            double sw = 0;
            double swd = 0;
            for (int i = 0; i < active.size(); i++) {
                ClipState s = active.get(i);
                if (s.weight > 0 && s.clip.duration > 0) {
                    sw += s.weight;
                    swd += s.weight * s.clip.duration;
                }
            }
            double dPhase = swd > 0 ? step * sw / swd : 0;
            double next = phase + dPhase;
            phase = wrap == WrapMode.LOOP ? next - Math.floor(next) : Math.max(0, Math.min(1, next));
            for (int i = 0; i < active.size(); i++) {
                ClipState s = active.get(i);
                double e0 = s.elapsed;
                if (rootMotion != null && s.clip.rootMotion) {
                    rootMotion.step(s, e0, dPhase * s.clip.duration, wrap);
                }
                s.elapsed = phase * s.clip.duration;
            }
        } else {
            for (int i = 0; i < active.size(); i++) {
                ClipState s = active.get(i);
                if (rootMotion != null && s.clip.rootMotion) {
                    rootMotion.step(s, s.elapsed, step, wrap);
                }
                s.elapsed = s.clip.sampler.wrapElapsed(s.elapsed + step, wrap);
            }
        }
        if (faded) {
            finishFade();
        }
    }

    private void finishFade() {
        ClipState target = fade.target;
        fade = null;
        active.clear();
        target.weight = 1;
        active.add(target);
        synchronised = false;
    }

    /** Samples every clip playing (in place where root motion takes the root out). */
    void sample(RotationInterpolation rotations, RootMotion rootMotion) {
        for (int i = 0; i < active.size(); i++) {
            ClipState s = active.get(i);
            if (s.weight == 0) {
                continue;
            }
            s.clip.sampler.sampleLocal(s.clipTime(), rotations, s.values, s.local);
            if (rootMotion != null && s.clip.rootMotion) {
                rootMotion.makeInPlace(s.clip, s.local.array());
            }
            if (mode == LayerMode.ADDITIVE && s.referenceTime != referenceTime) {
                referenceOf(s, rotations);
            }
        }
    }

    /**
     * Samples the clip's additive reference, on the first step after the reference time changed
     * (allocating its pose the first time only).
     */
    private void referenceOf(ClipState s, RotationInterpolation rotations) {
        if (s.reference == null) {
            s.reference = mixer.skeleton().newLocalPose();
        }
        float t = s.clip.clipTime(Math.max(0, referenceTime));
        s.clip.sampler.sampleLocal(t, rotations, s.values, s.reference);
        s.referenceTime = referenceTime;
    }

    /** Blends this layer onto {@code dest}, node by node. */
    void blendOnto(float[] dest, float[] rest, Blend blend) {
        blend.layer(active, mode, weight, mask == null ? null : mask.weights(), rest, dest);
    }

    @Override
    public String toString() {
        return "Layer[" + name + ", " + mode + ", weight " + weight + ", " + clipWeights()
                + (space != null ? ", " + space : "") + (fade != null ? ", fading to " + fade.target.clip.name() : "")
                + "]";
    }
}
