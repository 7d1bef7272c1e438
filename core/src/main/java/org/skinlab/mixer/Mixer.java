package org.skinlab.mixer;

import java.util.ArrayList;
import java.util.Collections;
import java.util.HashSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.animation.LocalPose;
import org.skinlab.animation.Pose;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.Skeleton;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;

/**
 * Directs a character: {@link Layer}s of clips blended into one {@link LocalPose} per step, and
 * root motion. Layer 0 (made with the mixer, named "base") lies on the rest pose; every further
 * layer lies on the result of the layers below: an override layer replaces it on the joints its
 * clips animate by its weight times its mask (slerp for rotations, linear for translation and
 * scale), an additive layer adds its clips' difference from their reference pose. Blending
 * happens in local translation, rotation and scale, whatever transform stack the file uses
 * ({@link org.skinlab.animation.AnimationSampler#sampleLocal}); the result is evaluated into world
 * matrices by {@link Skeleton#evaluate(LocalPose, Pose)}.
 *
 * <p><b>Root motion</b> ({@link #setRootMotion}, off by default, a switch per clip): the root joint
 * (the first joint of the skeleton) of a base-layer clip with root motion is kept in place, its
 * horizontal movement and yaw go to {@link #placement}, where the scene applies them to the
 * model; several clips move it by their weights.
 *
 * <p>Per step, {@link #advance} then {@link #evaluate}: neither allocates. Not thread-safe: one
 * thread owns a mixer ({@code SkeletalAnimatedMesh.direct} hands changes to its simulation thread).
 */
public final class Mixer {
    private final Model model;
    private final Skeleton skeleton;
    private final Map<String, MixerClip> clips = new LinkedHashMap<>();
    private final List<Layer> layers = new ArrayList<>();
    private final RootMotion rootMotion;
    private final float[] rest;
    private final Blend blend = new Blend();
    private final List<String> warnings = new ArrayList<>();
    private final Set<String> told = new HashSet<>();

    /**
     * A mixer of the model's clips, with a base layer that plays nothing yet (the rest pose). Builds
     * a sampler per clip: bind-time work.
     *
     * @param model the model whose clips ({@link Model#clips()}) the layers play
     * @param skeleton the skeleton of that model the poses are for
     * @throws IllegalArgumentException when the skeleton is not the model's (another node count)
     */
    public Mixer(Model model, Skeleton skeleton) {
        if (skeleton.nodeCount() != model.nodes().size()) {
            throw new IllegalArgumentException("a skeleton of " + skeleton.nodeCount() + " nodes for a model of "
                    + model.nodes().size());
        }
        this.model = model;
        this.skeleton = skeleton;
        int root = -1;
        for (int i = 0; i < skeleton.nodeCount() && root < 0; i++) {
            if (skeleton.node(i).isJoint()) {
                root = i;
            }
        }
        Matrix4f parentWorld = new Matrix4f();
        if (root >= 0 && skeleton.parent(root) >= 0) {
            skeleton.newPose().world(skeleton.parent(root), parentWorld);
        }
        this.rootMotion = new RootMotion(skeleton, root, up(model), parentWorld);
        for (AnimationClip c : model.clips()) {
            clips.putIfAbsent(c.name(), new MixerClip(skeleton, c, root));
        }
        this.rest = skeleton.newLocalPose().array();
        layers.add(new Layer(this, "base"));
    }

    private static Vector3f up(Model model) {
        switch (model.asset().upAxis()) {
            case X_UP:
                return new Vector3f(1, 0, 0);
            case Z_UP:
                return new Vector3f(0, 0, 1);
            default:
                return new Vector3f(0, 1, 0);
        }
    }

    /**
     * The skeleton the poses are for.
     *
     * @return the skeleton given to the constructor
     */
    public Skeleton skeleton() {
        return skeleton;
    }

    /**
     * The names of the clips the layers can play.
     *
     * @return the model's clip names, in file order
     */
    public List<String> clipNames() {
        return List.copyOf(clips.keySet());
    }

    /** The clip named {@code name} (a clip's name, else its id). */
    MixerClip clip(String name) {
        MixerClip c = clips.get(name);
        if (c != null) {
            return c;
        }
        for (MixerClip m : clips.values()) {
            if (name.equals(m.clip.id())) {
                return m;
            }
        }
        throw new IllegalArgumentException(model.source() + ": no animation clip \"" + name + "\" (clips: "
                + (clips.isEmpty() ? "none" : String.join(", ", clips.keySet())) + ")");
    }

    // ------------------------------------------------------------------ layers

    /**
     * The base layer (layer 0), on the rest pose.
     *
     * @return the first layer
     */
    public Layer base() {
        return layers.get(0);
    }

    /**
     * Adds a layer on top of the others, overriding, at weight 1, playing nothing.
     *
     * @param name a name for messages and panels
     * @return the new layer
     */
    public Layer addLayer(String name) {
        Layer l = new Layer(this, name);
        layers.add(l);
        return l;
    }

    /**
     * Removes a layer other than the base.
     *
     * @param layer one of this mixer's layers
     * @throws IllegalArgumentException for the base layer or a layer of another mixer
     */
    public void removeLayer(Layer layer) {
        if (layer == base() || !layers.remove(layer)) {
            throw new IllegalArgumentException("cannot remove " + layer + " (the base layer, or not this mixer's)");
        }
    }

    /**
     * The layers, bottom (base) first.
     *
     * @return an unmodifiable view
     */
    public List<Layer> layers() {
        return Collections.unmodifiableList(layers);
    }

    // ------------------------------------------------------------------ root motion

    /**
     * Turns root motion on or off for a clip.
     *
     * @param clip the clip's name
     * @param on whether the clip's root movement moves the placement (the clip then plays in place)
     * @throws IllegalArgumentException for an unknown clip
     */
    public void setRootMotion(String clip, boolean on) {
        clip(clip).rootMotion = on;
    }

    /**
     * Whether root motion is on for a clip.
     *
     * @param clip the clip's name
     * @return true when the clip plays in place and moves the placement
     * @throws IllegalArgumentException for an unknown clip
     */
    public boolean rootMotion(String clip) {
        return clip(clip).rootMotion;
    }

    /**
     * Where root motion has taken the model so far, to multiply its model matrix by (on the right).
     *
     * @param dest receives the placement, in the model's space
     * @return {@code dest}
     */
    public Matrix4f placement(Matrix4f dest) {
        return rootMotion.placement(dest);
    }

    /**
     * The last step's root motion, in the placement's frame at the step's start: the placement
     * after the step is the placement before times this.
     *
     * @param dest receives the move, in the model's space
     * @return {@code dest}
     */
    public Matrix4f lastRootMotion(Matrix4f dest) {
        return rootMotion.lastMove(dest);
    }

    /**
     * The placement's position and heading in the root's parent space.
     *
     * @param dest receives x, y, z and the heading in radians (about the up axis, in (-pi, pi])
     * @return {@code dest}
     */
    public double[] placementPosition(double[] dest) {
        rootMotion.position(dest);
        return dest;
    }

    /**
     * Turns the placement where it stands (a scene's steering, e.g. back towards a marker).
     *
     * @param radians the angle about the up axis
     */
    public void turnPlacement(double radians) {
        rootMotion.turn(radians);
    }

    /** Puts the placement back at the model's origin. */
    public void resetPlacement() {
        rootMotion.reset();
    }

    // ------------------------------------------------------------------ per step

    /**
     * Advances every layer's fades and clocks by {@code seconds}, and the placement by the base
     * layer's root motion. Allocation-free.
     *
     * @param seconds animation time, finite (negative plays backwards)
     * @throws IllegalArgumentException for an infinite or NaN time
     */
    public void advance(double seconds) {
        if (!Double.isFinite(seconds)) {
            throw new IllegalArgumentException("advance by " + seconds + " s (need a finite time)");
        }
        for (int i = 0; i < layers.size(); i++) {
            layers.get(i).advance(seconds, i == 0 && rootMotion.root >= 0 ? rootMotion : null);
        }
        Layer base = base();
        List<ClipState> active = base.active();
        double sum = 0;
        for (int i = 0; i < active.size(); i++) {
            sum += active.get(i).weight;
        }
        double scale = base.weight() / Math.max(1, sum);
        double dx = 0;
        double dy = 0;
        double dz = 0;
        double dyaw = 0;
        for (int i = 0; i < active.size(); i++) {
            ClipState s = active.get(i);
            if (s.clip.rootMotion) {
                double w = s.weight * scale;
                dx += w * s.motion[0];
                dy += w * s.motion[1];
                dz += w * s.motion[2];
                dyaw += w * s.motion[3];
            }
        }
        rootMotion.apply(dx, dy, dz, dyaw);
    }

    /**
     * Blends every layer into {@code dest}: the rest pose, then each layer by its mode, weight and
     * mask. Allocation-free (an additive layer samples its reference once after it changes).
     *
     * @param rotations how rotation keys are interpolated within each clip
     * @param dest receives every node's local transform
     * @throws IllegalArgumentException when {@code dest} belongs to another skeleton
     */
    public void evaluate(RotationInterpolation rotations, LocalPose dest) {
        if (dest.skeleton() != skeleton) {
            throw new IllegalArgumentException("a local pose of another skeleton");
        }
        float[] out = dest.array();
        System.arraycopy(rest, 0, out, 0, rest.length);
        for (int i = 0; i < layers.size(); i++) {
            Layer l = layers.get(i);
            if (l.weight() == 0 || l.active().isEmpty()) {
                continue;
            }
            l.sample(rotations, i == 0 && rootMotion.root >= 0 ? rootMotion : null);
            l.blendOnto(out, rest, blend);
        }
    }

    /**
     * The one clip that makes the whole pose, when it does: the base layer plays it alone at weight
     * 1 with no mask and without root motion, and no other layer counts. A caller may then pose by
     * that clip's sampler alone ({@code SkinnedModel.pose}), which reproduces the file exactly on
     * keys (shear included).
     *
     * @return the clip, or null when the pose is a blend
     */
    public AnimationClip soleClip() {
        Layer base = base();
        List<ClipState> active = base.active();
        if (active.size() != 1 || active.get(0).weight != 1 || base.weight() != 1 || base.mask() != null
                || base.mode() != LayerMode.OVERRIDE || active.get(0).clip.rootMotion) {
            return null;
        }
        for (int i = 1; i < layers.size(); i++) {
            if (layers.get(i).weight() != 0 && !layers.get(i).active().isEmpty()) {
                return null;
            }
        }
        return active.get(0).clip.clip;
    }

    /**
     * Whether no layer counts: the pose is the rest pose.
     *
     * @return true when every layer plays nothing or has weight 0
     */
    public boolean playsNothing() {
        for (Layer l : layers) {
            if (l.weight() != 0 && !l.active().isEmpty()) {
                return false;
            }
        }
        return true;
    }

    // ------------------------------------------------------------------ messages

    /** Tells once per set of clips when the clips of a layer animate different joints. */
    void checkJointsAnimated(Layer layer, List<ClipState> states) {
        if (states.size() < 2) {
            return;
        }
        for (ClipState s : states) {
            List<String> missing = new ArrayList<>();
            for (int j = 0; j < skeleton.nodeCount(); j++) {
                if (!skeleton.node(j).isJoint() || s.clip.sampler.animates(j)) {
                    continue;
                }
                for (ClipState other : states) {
                    if (other.clip.sampler.animates(j)) {
                        missing.add(skeleton.node(j).label());
                        break;
                    }
                }
            }
            if (!missing.isEmpty() && told.add(s.clip.name() + "\u0000" + missing)) {
                warnings.add(model.source() + ": clip \"" + s.clip.name() + "\" does not animate "
                        + missing.size() + " joint" + (missing.size() == 1 ? "" : "s") + " that other clips of layer \""
                        + layer.name() + "\" animate (" + String.join(", ", missing.subList(0, Math.min(8,
                        missing.size()))) + (missing.size() > 8 ? ", ..." : "")
                        + "): there it has no say, and where the weights of the clips that do sum to less than 1"
                        + " the rest pose fills the remainder");
            }
        }
    }

    /**
     * What the mixer has told about the clips it was given to play (each message once), oldest first.
     *
     * @return a copy of the messages so far
     */
    public List<String> warnings() {
        return List.copyOf(warnings);
    }
}
