package org.skinlab.desktop.cli;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Collectors;

import org.skinlab.animation.AnimationSampler;
import org.skinlab.animation.Skeleton;
import org.skinlab.animation.WrapMode;
import org.skinlab.mixer.Layer;
import org.skinlab.mixer.Mixer;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;

/**
 * What {@code --blend} and {@code --additive} ask for ({@link BlendOptions} reads the text): a
 * weighted set of clips on a {@link Mixer}'s base layer, blended as three.js' {@code AnimationMixer}
 * accumulates its actions (where the weights sum to less than 1 the rest pose fills the remainder),
 * and one additive layer per {@code --additive} clip on top, adding the clip's difference from its
 * own pose at its reference time. Every clip plays at the same time T: T seconds after its own
 * start, looped within it ({@link #setTime}).
 */
final class BlendSpec {
    /** A clip of the base layer and its weight. */
    record Weighted(String clip, double weight) {
    }

    /** An additive layer's clip, its weight and its reference time in seconds after the clip's start. */
    record Additive(String clip, double weight, double referenceTime) {
    }

    private final List<Weighted> base;
    private final List<Additive> additive;

    BlendSpec(List<Weighted> base, List<Additive> additive) {
        this.base = List.copyOf(base);
        this.additive = List.copyOf(additive);
    }

    List<Weighted> base() {
        return base;
    }

    List<Additive> additive() {
        return additive;
    }

    /**
     * This blend with each clip under its name in {@code model} (a COLLADA clip may be given by its
     * id). A clip named twice in the base layer counts once with the sum of its weights: the same
     * pose blended with itself, which is what the two would give.
     *
     * @param file the file as given, for the message
     * @throws IllegalArgumentException naming the option and the clip, and listing the file's clips,
     *     when the model has no such clip
     */
    BlendSpec resolve(Model model, String file) {
        Map<String, Double> weights = new LinkedHashMap<>();
        for (Weighted w : base) {
            weights.merge(clipName(model, file, "--blend", w.clip()), w.weight(), Double::sum);
        }
        List<Weighted> resolved = new ArrayList<>();
        weights.forEach((clip, w) -> resolved.add(new Weighted(clip, w)));
        List<Additive> added = new ArrayList<>();
        for (Additive a : additive) {
            added.add(new Additive(clipName(model, file, "--additive", a.clip()), a.weight(), a.referenceTime()));
        }
        return new BlendSpec(resolved, added);
    }

    /** The name of the clip {@code name} names, as the mixer looks it up: by name, else by id. */
    private static String clipName(Model model, String file, String option, String name) {
        for (AnimationClip c : model.clips()) {
            if (c.name().equals(name)) {
                return c.name();
            }
        }
        for (AnimationClip c : model.clips()) {
            if (name.equals(c.id())) {
                return c.name();
            }
        }
        throw new IllegalArgumentException(option + ": unknown clip '" + name + "' in " + file + "; available clips: "
                + (model.clips().isEmpty() ? "(none)"
                        : model.clips().stream().map(c -> "'" + c.name() + "'").collect(Collectors.joining(", "))));
    }

    /**
     * A mixer of {@code model} playing this blend: the base layer's clips by their weights, in
     * order, then an additive layer per additive clip. Call {@link #setTime} before evaluating.
     */
    Mixer mixer(Model model, Skeleton skeleton) {
        Mixer mixer = new Mixer(model, skeleton);
        Map<String, Double> weights = new LinkedHashMap<>();
        for (Weighted w : base) {
            weights.put(w.clip(), w.weight());
        }
        mixer.base().setClipWeights(weights);
        for (Additive a : additive) {
            Layer layer = mixer.addLayer("additive " + a.clip());
            layer.play(a.clip());
            layer.setAdditive(a.referenceTime());
            layer.setWeight(a.weight());
        }
        return mixer;
    }

    /**
     * Puts every clip of every layer at {@code seconds} after its own start, looped within it
     * ({@link Layer#setTime}: the clips of a weighted set are not synchronised, so each wraps by
     * its own duration).
     */
    static void setTime(Mixer mixer, double seconds) {
        for (Layer layer : mixer.layers()) {
            layer.setTime(seconds);
        }
    }

    /**
     * The clip times (on each clip's keys' timeline) that {@link #setTime} gives at each of
     * {@code times}: per clip, base clips first, then the additive ones.
     */
    float[][] clipTimes(Model model, Skeleton skeleton, float[] times) {
        List<String> clips = clips();
        float[][] clipTimes = new float[clips.size()][times.length];
        for (int c = 0; c < clips.size(); c++) {
            AnimationSampler sampler = new AnimationSampler(skeleton, model.clip(clips.get(c)).orElseThrow());
            for (int t = 0; t < times.length; t++) {
                clipTimes[c][t] = sampler.clipTime(times[t], WrapMode.LOOP);
            }
        }
        return clipTimes;
    }

    /** The clips, base layer first, then one per additive layer. */
    List<String> clips() {
        List<String> clips = new ArrayList<>();
        base.forEach(w -> clips.add(w.clip()));
        additive.forEach(a -> clips.add(a.clip()));
        return clips;
    }

    /**
     * How many clips a step samples: those of weight above 0 (the mixer skips the others, and an
     * additive layer of weight 0 altogether).
     */
    int sampledClips() {
        int n = 0;
        for (Weighted w : base) {
            n += w.weight() > 0 ? 1 : 0;
        }
        for (Additive a : additive) {
            n += a.weight() > 0 ? 1 : 0;
        }
        return n;
    }

    /** Morph weights a blend cannot play: the clips that animate them (a blend poses with the file's weights). */
    List<String> clipsAnimatingMorphWeights(Model model) {
        return clips().stream().distinct()
                .filter(c -> !model.clip(c).orElseThrow().morphWeights().isEmpty())
                .collect(Collectors.toList());
    }

    /** The blend as the options would give it: {@code walk=0.5, run=0.5 + additive lean=0.6@0}. */
    String describe() {
        StringBuilder sb = new StringBuilder();
        for (Weighted w : base) {
            sb.append(sb.length() == 0 ? "" : ", ").append(w.clip()).append('=').append(number(w.weight()));
        }
        for (Additive a : additive) {
            sb.append(" + additive ").append(a.clip()).append('=').append(number(a.weight())).append('@')
                    .append(number(a.referenceTime()));
        }
        return sb.toString();
    }

    /** A number as a user writes it: 1 rather than 1.0. */
    static String number(double d) {
        return d == Math.rint(d) && Math.abs(d) < 1e15 ? Long.toString((long) d) : Double.toString(d);
    }
}
