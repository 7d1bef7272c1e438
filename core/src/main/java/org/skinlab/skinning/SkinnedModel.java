package org.skinlab.skinning;

import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;

import org.skinlab.animation.AnimationSampler;
import org.skinlab.animation.LocalPose;
import org.skinlab.animation.BindPose;
import org.skinlab.animation.MorphWeightSampler;
import org.skinlab.animation.Pose;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.Skeleton;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;

/**
 * A model ready to deform, frame by frame: its skeleton, one clip's sampler, and per placed mesh
 * a {@link SkinnedGeometry}, a {@link JointPalette} and a skinner for each method it was bound
 * for. The per-frame path is {@link #pose} (sample, evaluate, skinning matrices) then
 * {@link #skin} per geometry; neither allocates.
 *
 * <p><b>Bind time and frame time.</b> The constructor does all the bind-time work (each
 * geometry's layout and bones, CoR's centres of rotation, every method's skinner with its
 * bindings): run it where a model is loaded, e.g. on a loader thread. After it nothing is
 * computed on first use: a getter returns what the constructor built, and asking for a method the
 * model was not bound for fails.
 *
 * <p>A placed mesh whose morph weights the clip animates gets its own geometry
 * ({@link MorphedRestShape}) whose rest positions (and normals) {@link #pose} rewrites before
 * skinning, then tells its skinners ({@link Skinner#restShapeChanged}: the SIMD kernels re-pack
 * their copies). Other meshes are untouched.
 *
 * <p>Not thread-safe: one instance per thread that drives it (the simulation thread, a command).
 */
public final class SkinnedModel {
    private final Model model;
    private final Skeleton skeleton;
    private final AnimationSampler sampler;
    private final BindPose bindPose;
    private final Pose pose;
    private final List<SkinnedGeometry> geometries;
    private final JointPalette[] palettes;
    private final Set<SkinningMethod> methods;
    private final Skinner[][] skinners;
    private final NormalTransform normals;
    private final MorphWeightSampler morphSampler;
    /** Per geometry, its morph's weights in the current pose where they animate, else null. */
    private final float[][] morphWeights;
    /** Per geometry, its morph's weights as the file gives them where they animate (the bind pose's), else null. */
    private final float[][] fileMorphWeights;
    /** Per geometry, its per-frame rest shape where its weights animate, else null. */
    private final MorphedRestShape[] morphed;

    /**
     * A model bound for every method that can move its normals as asked: all of them, or for
     * positions only ({@link NormalTransform#NONE}) those with such a kernel
     * ({@link SkinningMethod#skinsPositionsOnly()}).
     *
     * @param model   the model
     * @param clip    the clip to play, or null to keep the model at rest
     * @param normals how the skinners move normals
     */
    public SkinnedModel(Model model, AnimationClip clip, NormalTransform normals) {
        this(model, clip, normals, methodsFor(normals));
    }

    private static Set<SkinningMethod> methodsFor(NormalTransform normals) {
        Set<SkinningMethod> all = EnumSet.allOf(SkinningMethod.class);
        if (normals == NormalTransform.NONE) {
            all.removeIf(m -> !m.skinsPositionsOnly());
        }
        return all;
    }

    /**
     * A model bound for the given methods: their skinners and what they need at bind time (CoR's
     * centres only when {@code methods} holds {@link SkinningMethod#COR}).
     *
     * @param model   the model
     * @param clip    the clip to play, or null to keep the model at rest
     * @param normals how the skinners move normals
     * @param methods the methods {@link #skin} and {@link #skinner} will be asked for (at least one)
     */
    public SkinnedModel(Model model, AnimationClip clip, NormalTransform normals, Set<SkinningMethod> methods) {
        if (methods.isEmpty()) {
            throw new IllegalArgumentException("a skinned model needs at least one method");
        }
        this.methods = Set.copyOf(methods);
        boolean centres = methods.contains(SkinningMethod.COR);
        this.model = model;
        this.normals = normals;
        this.skeleton = Skeleton.of(model);
        this.sampler = clip == null ? AnimationSampler.rest(skeleton) : new AnimationSampler(skeleton, clip);
        this.bindPose = BindPose.of(model);
        this.pose = skeleton.newPose();
        this.morphSampler = new MorphWeightSampler(model, clip);
        this.morphWeights = morphSampler.newWeights();
        this.fileMorphWeights = morphSampler.newWeights();
        this.morphed = new MorphedRestShape[model.instances().size()];
        List<SkinnedGeometry> list = new ArrayList<>();
        for (MeshInstance instance : model.instances()) {
            int g = list.size();
            SkinnedGeometry geometry = SkinnedGeometry.of(instance, model.nodes());
            if (centres) {
                geometry = geometry.withCentresOfRotation();
            }
            list.add(morphSampler.animates(g) ? morph(g, instance, geometry) : geometry);
        }
        this.geometries = List.copyOf(list);
        int n = geometries.size();
        palettes = new JointPalette[n];
        skinners = new Skinner[n][];
        for (int g = 0; g < n; g++) {
            palettes[g] = geometries.get(g).newPalette();
            skinners[g] = newSkinners(g);
        }
        pose(sampler.start(), RotationInterpolation.SLERP);
    }

    /**
     * Another character of the same model playing the same clip (a crowd): it shares this one's
     * skeleton, sampler and geometries, which are read-only, and starts with its skinners, and owns
     * its pose and palettes, so each copy poses at its own time and on its own thread with the
     * memory of a palette set instead of a whole model (and CoR's centres are computed once per
     * geometry, not per copy). Call it on the thread that drives this model.
     *
     * @return a new character bound for the same methods
     */
    public SkinnedModel newCharacter() {
        return new SkinnedModel(this);
    }

    private SkinnedModel(SkinnedModel template) {
        this.model = template.model;
        this.normals = template.normals;
        this.methods = template.methods;
        this.skeleton = template.skeleton;
        this.sampler = template.sampler;
        this.bindPose = template.bindPose;
        this.pose = skeleton.newPose();
        this.morphSampler = template.morphSampler;
        this.morphWeights = morphSampler.newWeights();
        this.fileMorphWeights = template.fileMorphWeights;
        this.morphed = new MorphedRestShape[template.morphed.length];
        List<SkinnedGeometry> list = new ArrayList<>(template.geometries);
        int n = list.size();
        palettes = new JointPalette[n];
        skinners = new Skinner[n][];
        for (int g = 0; g < n; g++) {
            if (template.morphed[g] != null) {
                // A morphing mesh's rest shape follows this character's time: its own geometry.
                list.set(g, morph(g, model.instances().get(g), template.morphed[g].rest()));
            }
            palettes[g] = list.get(g).newPalette();
        }
        // The same list when nothing morphs: a crowd shares its geometries.
        this.geometries = morphSampler.animatesAny() ? List.copyOf(list) : template.geometries;
        for (int g = 0; g < n; g++) {
            skinners[g] = morphed[g] != null ? newSkinners(g) : template.skinners[g];
        }
        pose(sampler.start(), RotationInterpolation.SLERP);
    }

    private SkinnedGeometry morph(int g, MeshInstance instance, SkinnedGeometry rest) {
        morphed[g] = new MorphedRestShape(instance, model.nodes(), morphSampler.morph(g), rest);
        return morphed[g].geometry();
    }

    /** Geometry {@code g}'s skinner for each bound method, indexed by ordinal (null for the others). */
    private Skinner[] newSkinners(int g) {
        Skinner[] made = new Skinner[SkinningMethod.values().length];
        for (SkinningMethod m : methods) {
            made[m.ordinal()] = newSkinner(g, m);
        }
        return made;
    }

    private Skinner newSkinner(int g, SkinningMethod method) {
        SkinnedGeometry geometry = geometries.get(g);
        if (morphed[g] == null) {
            return Skinners.create(method, geometry, normals);
        }
        // Skinning each shared position once would read the rest normals through a copy made once.
        return Skinners.create(method, geometry, normals,
                morphed[g].morphsNormals() ? PositionSharing.NEVER : PositionSharing.AUTO);
    }

    /**
     * The model with its first clip (or at rest when it has none) and exact normals, bound for
     * every method.
     *
     * @param model the model
     * @return a skinned model posed at the clip's start
     */
    public static SkinnedModel of(Model model) {
        return new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0),
                NormalTransform.INVERSE_TRANSPOSE);
    }

    /**
     * The model this was built from.
     *
     * @return the model
     */
    public Model model() {
        return model;
    }

    /**
     * The model's skeleton.
     *
     * @return the skeleton, shared by the characters of a crowd
     */
    public Skeleton skeleton() {
        return skeleton;
    }

    /**
     * The sampler of the clip played (a rest sampler when there is none).
     *
     * @return the sampler
     */
    public AnimationSampler sampler() {
        return sampler;
    }

    /**
     * The methods this model was bound for: those {@link #skin} and {@link #skinner} accept.
     *
     * @return an immutable set
     */
    public Set<SkinningMethod> methods() {
        return methods;
    }

    /**
     * The current pose.
     *
     * @return the pose (read-only use)
     */
    public Pose pose() {
        return pose;
    }

    /**
     * One geometry per placed mesh, in {@link Model#instances()} order.
     *
     * @return an immutable list
     */
    public List<SkinnedGeometry> geometries() {
        return geometries;
    }

    /**
     * Whether geometry {@code g}'s rest positions follow animated morph weights: its
     * {@link SkinnedGeometry#positionArray()} then changes with every {@link #pose} (a renderer
     * that skins on the GPU uploads them per frame).
     *
     * @param g the geometry
     * @return true when its rest shape morphs
     */
    public boolean morphs(int g) {
        return morphed[g] != null;
    }

    /**
     * The palette of geometry {@code g}, holding the skinning matrices of the current pose; call
     * its {@link JointPalette#prepare} for what a method reads besides them.
     *
     * @param g the geometry
     * @return its palette
     */
    public JointPalette palette(int g) {
        return palettes[g];
    }

    /**
     * The skinner geometry {@code g} uses for a method.
     *
     * @param g      the geometry
     * @param method one of {@link #methods()}
     * @return the skinner, made when this model was built
     * @throws IllegalArgumentException for a method the model was not bound for
     */
    public Skinner skinner(int g, SkinningMethod method) {
        Skinner s = skinners[g][method.ordinal()];
        if (s == null) {
            throw new IllegalArgumentException(method + " was not bound: this model skins with " + methods
                    + " (bind it with the methods it will use: new SkinnedModel(model, clip, normals, methods))");
        }
        return s;
    }

    /**
     * Poses the model at clip time {@code clipTime} (seconds; clamped to the keys of each
     * channel): samples the clip, evaluates the skeleton and fills every palette, and morphs the
     * rest shape of every mesh whose weights the clip animates.
     *
     * @param clipTime  seconds in the clip's time line
     * @param rotations how rotation keys are interpolated
     */
    public void pose(float clipTime, RotationInterpolation rotations) {
        sampler.sample(clipTime, rotations, pose);
        skeleton.evaluate(pose);
        if (morphSampler.animatesAny()) {
            morphSampler.sample(clipTime, morphWeights);
            morphRestShapes(morphWeights);
        }
        fillPalettes();
    }

    /**
     * Poses the model in blended local transforms (a {@code org.skinlab.mixer.Mixer}'s result):
     * evaluates the skeleton from them and fills every palette. Meshes whose morph weights the
     * clip animates take the file's weights: a blend has no single clip time to sample them at.
     *
     * @param local every node's local transform, a local pose of {@link #skeleton()}
     */
    public void pose(LocalPose local) {
        skeleton.evaluate(local, pose);
        if (morphSampler.animatesAny()) {
            morphRestShapes(fileMorphWeights);
        }
        fillPalettes();
    }

    /**
     * Poses the model in its bind pose ({@link BindPose}: every joint at the frame its inverse
     * bind matrix implies, whatever the clip), with the file's morph weights, and fills every
     * palette: each skinned mesh then deforms to its bind shape.
     */
    public void poseBind() {
        bindPose.apply(skeleton, pose);
        if (morphSampler.animatesAny()) {
            morphRestShapes(fileMorphWeights);
        }
        fillPalettes();
    }

    /** Morphs the rest shape of every mesh whose weights the clip animates, to {@code weights}. */
    private void morphRestShapes(float[][] weights) {
        for (int g = 0; g < morphed.length; g++) {
            if (morphed[g] != null) {
                morphed[g].apply(weights[g]);
                for (Skinner s : skinners[g]) {
                    if (s != null) {
                        s.restShapeChanged();
                    }
                }
            }
        }
    }

    /** Every geometry's skinning matrices from the pose just evaluated. */
    private void fillPalettes() {
        for (int g = 0; g < palettes.length; g++) {
            SkinnedGeometry geometry = geometries.get(g);
            skeleton.skinningMatrices(pose, geometry.jointNodeArray(), geometry.bindMatrixArray(),
                    palettes[g].writableMatrices());
        }
    }

    /**
     * Deforms geometry {@code g} in the current pose: 3 floats per point into each output array
     * (size {@code 3 * pointCount()}). The palette derives what the method reads once per pose.
     *
     * @param g            the geometry
     * @param method       one of {@link #methods()}
     * @param outPositions the deformed positions
     * @param outNormals   the deformed normals
     */
    public void skin(int g, SkinningMethod method, float[] outPositions, float[] outNormals) {
        skinner(g, method).skinAll(palettes[g].prepare(method), outPositions, outNormals);
    }
}
