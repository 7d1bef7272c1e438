package org.skinlab.desktop.viewer;

import java.util.ArrayList;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.Consumer;

import org.skinlab.mixer.FadeCurve;
import org.skinlab.mixer.JointMask;
import org.skinlab.mixer.Layer;
import org.skinlab.mixer.Mixer;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.simulation.SkeletalAnimatedMesh;

/**
 * What the user chose in the mixer panel for the model shown, each choice sent to the model's
 * {@link Mixer}: the layers (clip, weight, joint mask, additive), a cross-fade of the base layer,
 * the blend pad and root motion. The mixer belongs to the simulation thread, so every change goes
 * through {@link SkeletalAnimatedMesh#direct} and this class never reads the mixer back: it keeps
 * the choices themselves (what the panel shows), starting from what a freshly loaded mesh plays
 * (its clip alone on the base layer, overriding, every joint). A change the mixer refuses leaves the
 * choice shown and its message for the status line ({@link #takeMessage()}), as does the newest
 * warning the mixer gives about the clips it was asked to blend.
 *
 * <p>Window thread only; a new model ({@link #show}) starts the choices afresh.
 */
public final class MixerControls {
    /** The base layer's name (the mixer's layer 0). */
    public static final String BASE = "base";
    /** The cross-fade's shortest and longest duration in seconds. */
    public static final float MIN_FADE_SECONDS = 0.1f;
    public static final float MAX_FADE_SECONDS = 2f;
    /** The mask list's first entry: no mask. */
    public static final String ALL_JOINTS = "all joints";
    /** Additive layers add their clips' difference from the clips' first pose. */
    private static final double ADDITIVE_REFERENCE_SECONDS = 0;

    /** One layer as the user set it up. */
    public static final class LayerChoice {
        private final String name;
        private int clip;
        private float weight = 1f;
        private int mask;
        private boolean additive;

        LayerChoice(String name, int clip) {
            this.name = name;
            this.clip = clip;
        }

        /** The layer's name in the mixer ({@link #BASE} for layer 0). */
        public String name() {
            return name;
        }

        /** The clip it plays, an index into {@link MixerControls#clip(int)}; -1 when none. */
        public int clip() {
            return clip;
        }

        public float weight() {
            return weight;
        }

        /** Its mask, an index into {@link MixerControls#maskLabel(int)}: 0 for every joint. */
        public int mask() {
            return mask;
        }

        public boolean additive() {
            return additive;
        }

        public boolean isBase() {
            return name.equals(BASE);
        }
    }

    private LoadedModel shown;
    private SkeletalAnimatedMesh mesh;
    private String[] clips = new String[0];
    /** "all joints", then "below JOINT" per joint. */
    private String[] maskLabels = {ALL_JOINTS};
    /** The joint each mask entry names (null for the first). */
    private String[] maskJoints = {null};
    private final List<LayerChoice> layers = new ArrayList<>();
    private final List<LayerChoice> layersView = Collections.unmodifiableList(layers);
    private int layersAdded;
    private int fadeTarget;
    private float fadeSeconds = 0.5f;
    private boolean synchronised = true;
    private BlendPad pad;
    private final float[] padPoint = {0.5f, 0.5f};
    private boolean padDrives;
    private boolean[] rootMotion = new boolean[0];
    /** Where the futures of this model's changes leave a message for the status line. */
    private AtomicReference<String> message = new AtomicReference<>();
    /** The mixer's warnings already passed on; read and written on the simulation thread only. */
    private int[] warningsTold = {0};

    /** Follows the model shown: a model not seen before (or none) starts the choices afresh. */
    public void show(LoadedModel model) {
        if (model == shown) {
            return;
        }
        shown = model;
        mesh = model == null ? null : model.mesh();
        layers.clear();
        layersAdded = 0;
        padDrives = false;
        message = new AtomicReference<>();
        warningsTold = new int[] {0};
        clips = model == null ? new String[0] : clipNames(model.model());
        rootMotion = new boolean[clips.length];
        jointMasks(model == null ? null : model.model());
        pad = BlendPad.of(List.of(clips));
        if (model == null) {
            return;
        }
        int base = model.clipIndex() < 0 ? -1 : indexOf(model.model().clips().get(model.clipIndex()).name());
        layers.add(new LayerChoice(BASE, base));
        fadeTarget = Math.max(0, base);
        padPoint[0] = 0.5f;
        padPoint[1] = 0.5f;
        if (pad != null && base >= 0) {
            pad.place(clips[base], padPoint);
        }
    }

    /** The mixer's clip names ({@code Mixer.clipNames()}): each clip's name once, in file order. */
    private static String[] clipNames(Model model) {
        Set<String> names = new LinkedHashSet<>();
        for (AnimationClip c : model.clips()) {
            names.add(c.name());
        }
        return names.toArray(new String[0]);
    }

    /** The masks the panel offers: every joint, or the subtree below one joint (by its name, else id, else sid). */
    private void jointMasks(Model model) {
        List<String> labels = new ArrayList<>(List.of(ALL_JOINTS));
        List<String> joints = new ArrayList<>();
        joints.add(null);
        if (model != null) {
            for (Node n : model.nodes()) {
                String key = n.name() != null ? n.name() : n.id() != null ? n.id() : n.sid();
                if (n.isJoint() && key != null && !joints.contains(key)) {
                    joints.add(key);
                    labels.add("below " + key);
                }
            }
        }
        maskLabels = labels.toArray(new String[0]);
        maskJoints = joints.toArray(new String[0]);
    }

    private int indexOf(String clip) {
        for (int i = 0; i < clips.length; i++) {
            if (clips[i].equals(clip)) {
                return i;
            }
        }
        return -1;
    }

    /** Whether there is a model to direct. */
    public boolean hasModel() {
        return mesh != null;
    }

    public int clipCount() {
        return clips.length;
    }

    public String clip(int i) {
        return clips[i];
    }

    public int maskCount() {
        return maskLabels.length;
    }

    /** "all joints" (0), or "below JOINT". */
    public String maskLabel(int i) {
        return maskLabels[i];
    }

    /** The layers, base first, as the user set them up (the mixer's own, once the changes have run). */
    public List<LayerChoice> layers() {
        return layersView;
    }

    // ------------------------------------------------------------------------------ layers

    /** Adds an overriding layer on top, at weight 1, playing nothing yet. */
    public void addLayer() {
        if (mesh == null) {
            return;
        }
        String name = "layer " + ++layersAdded;
        layers.add(new LayerChoice(name, -1));
        send(m -> m.addLayer(name));
    }

    /** Removes a layer other than the base. */
    public void removeLayer(LayerChoice layer) {
        if (layer.isBase() || !layers.remove(layer)) {
            return;
        }
        send(m -> m.removeLayer(layer(m, layer.name)));
    }

    /** Plays clip {@code clip} alone on the layer, from its start (on the base layer: instead of the pad). */
    public void play(LayerChoice layer, int clip) {
        layer.clip = clip;
        if (layer.isBase()) {
            padDrives = false;
        }
        String name = clips[clip];
        send(m -> layer(m, layer.name).play(name));
    }

    /** The layer's weight, to two decimals (what the slider shows). */
    public void setWeight(LayerChoice layer, float weight) {
        layer.weight = Math.round(weight * 100) / 100f;
        double w = Math.round(weight * 100) / 100.0;
        send(m -> layer(m, layer.name).setWeight(w));
    }

    /** Limits the layer to mask entry {@code mask} (0: every joint). */
    public void setMask(LayerChoice layer, int mask) {
        layer.mask = mask;
        String joint = maskJoints[mask];
        send(m -> layer(m, layer.name).setMask(joint == null ? null : JointMask.subtree(m.skeleton(), joint)));
    }

    /** Makes the layer additive (its clips' difference from their first pose is added) or overriding. */
    public void setAdditive(LayerChoice layer, boolean additive) {
        layer.additive = additive;
        send(m -> {
            Layer l = layer(m, layer.name);
            if (additive) {
                l.setAdditive(ADDITIVE_REFERENCE_SECONDS);
            } else {
                l.setOverride();
            }
        });
    }

    /** The mixer's layer of that name: each choice names its layer, so a refused change cannot shift the rest. */
    private static Layer layer(Mixer m, String name) {
        for (Layer l : m.layers()) {
            if (l.name().equals(name)) {
                return l;
            }
        }
        throw new IllegalStateException("the mixer has no layer \"" + name + "\"");
    }

    // ------------------------------------------------------------------------------ cross-fade

    /** The clip the next cross-fade goes to, an index into {@link #clip(int)}. */
    public int fadeTarget() {
        return fadeTarget;
    }

    public void setFadeTarget(int clip) {
        fadeTarget = clip;
    }

    public float fadeSeconds() {
        return fadeSeconds;
    }

    public void setFadeSeconds(float seconds) {
        fadeSeconds = Math.max(MIN_FADE_SECONDS, Math.min(MAX_FADE_SECONDS, seconds));
    }

    /** Whether the next cross-fade starts its clip in step (by phase) with what plays. */
    public boolean synchronised() {
        return synchronised;
    }

    public void setSynchronised(boolean on) {
        synchronised = on;
    }

    /** Cross-fades the base layer to the fade's clip, along the smooth curve; the pad stops driving it. */
    public void crossFade() {
        if (mesh == null || clips.length == 0) {
            return;
        }
        String clip = clips[fadeTarget];
        double seconds = fadeSeconds;
        boolean sync = synchronised;
        layers.get(0).clip = fadeTarget;
        padDrives = false;
        send(m -> m.base().crossFade(clip, seconds, FadeCurve.SMOOTH, sync));
    }

    // ------------------------------------------------------------------------------ blend pad

    /** The pad's blend space for this model, or null (fewer than two clips). */
    public BlendPad pad() {
        return pad;
    }

    /** The pad's point, across (0 left, 1 right). */
    public float padU() {
        return padPoint[0];
    }

    /** The pad's point, up (0 bottom, 1 top). */
    public float padV() {
        return padPoint[1];
    }

    /** Whether the base layer plays the pad's blend space (until a clip or a cross-fade replaces it). */
    public boolean padDrives() {
        return padDrives;
    }

    /**
     * Moves the pad's point: the first move puts the base layer on the pad's blend space there,
     * later ones move its parameter. A point where it already is sends nothing.
     */
    public void movePad(float u, float v) {
        if (pad == null || padDrives && u == padPoint[0] && v == padPoint[1]) {
            return;
        }
        padPoint[0] = u;
        padPoint[1] = v;
        double x = pad.x(u, v);
        double y = pad.y(u, v);
        if (padDrives) {
            send(m -> m.base().setBlendParameter(x, y));
        } else {
            padDrives = true;
            BlendPad space = pad;
            send(m -> m.base().setBlendSpace(space.space(), x, y));
        }
    }

    // ------------------------------------------------------------------------------ root motion

    /**
     * Whether root motion is on for the clips the base layer plays as chosen: its clip, or every
     * clip of the pad while the pad drives it.
     */
    public boolean rootMotion() {
        if (padDrives) {
            for (int i = 0; i < pad.clipCount(); i++) {
                if (!rootMotion[indexOf(pad.clip(i))]) {
                    return false;
                }
            }
            return true;
        }
        int c = layers.isEmpty() ? -1 : layers.get(0).clip;
        return c >= 0 && rootMotion[c];
    }

    /** What {@link #rootMotion()} applies to: the base layer's clip, or the pad's clips. */
    public String rootMotionClips() {
        int c = layers.isEmpty() ? -1 : layers.get(0).clip;
        return padDrives ? "the pad's clips" : c < 0 ? "no clip" : clips[c];
    }

    /**
     * Turns root motion on or off for the clips the base layer plays ({@link #rootMotion()}): on, they
     * play in place and their root's travel moves the model.
     */
    public void setRootMotion(boolean on) {
        List<String> affected = new ArrayList<>();
        if (padDrives) {
            affected.addAll(pad.clips());
        } else if (!layers.isEmpty() && layers.get(0).clip >= 0) {
            affected.add(clips[layers.get(0).clip]);
        }
        for (String c : affected) {
            rootMotion[indexOf(c)] = on;
        }
        if (!affected.isEmpty()) {
            send(m -> {
                for (String c : affected) {
                    m.setRootMotion(c, on);
                }
            });
        }
    }

    /** Puts the model back where it was loaded (root motion's travel forgotten). */
    public void resetPlacement() {
        send(Mixer::resetPlacement);
    }

    // ------------------------------------------------------------------------------ messages

    /** The newest message for the status line since the last call (a refused change, a warning), or null. */
    public String takeMessage() {
        return message.getAndSet(null);
    }

    /** Hands a change to the simulation thread; what it refuses or warns of comes back as a message. */
    private void send(Consumer<Mixer> change) {
        if (mesh == null) {
            return;
        }
        AtomicReference<String> to = message;
        int[] told = warningsTold;
        CompletableFuture<Void> done = mesh.direct(m -> {
            change.accept(m);
            List<String> w = m.warnings();
            if (w.size() > told[0]) {
                told[0] = w.size();
                to.set(w.get(w.size() - 1));
            }
        });
        done.whenComplete((v, e) -> {
            if (e != null) {
                to.set("mixer: " + e.getMessage());
            }
        });
    }
}
