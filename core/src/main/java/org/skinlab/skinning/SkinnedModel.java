package org.skinlab.skinning;

import java.util.ArrayList;
import java.util.List;

import org.skinlab.animation.AnimationSampler;
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
 * a {@link SkinnedGeometry}, a {@link JointPalette} and a skinner for each method. The per-frame
 * path is {@link #pose} (sample, evaluate, skinning matrices) then {@link #skin} per geometry;
 * neither allocates.
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
    private final boolean[] dualQuaternionsReady;
    private final boolean[] bonesReady;
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
     * @param clip the clip to play, or null to keep the model at rest
     * @param normals how the skinners move normals
     */
    public SkinnedModel(Model model, AnimationClip clip, NormalTransform normals) {
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
            list.add(morphSampler.animates(g) ? morph(g, instance, SkinnedGeometry.of(instance, model.nodes()))
                    : SkinnedGeometry.of(instance, model.nodes()));
        }
        this.geometries = List.copyOf(list);
        int n = geometries.size();
        palettes = new JointPalette[n];
        dualQuaternionsReady = new boolean[n];
        bonesReady = new boolean[n];
        skinners = new Skinner[n][SkinningMethod.values().length];
        for (int g = 0; g < n; g++) {
            SkinnedGeometry geometry = geometries.get(g);
            palettes[g] = geometry.newPalette();
            // LBS's and DQS's skinners at once; CoR's on first use (its centres take a precomputation).
            for (SkinningMethod m : new SkinningMethod[] {SkinningMethod.LBS, SkinningMethod.DQS}) {
                skinners[g][m.ordinal()] = newSkinner(g, m);
            }
        }
        pose(sampler.start(), RotationInterpolation.SLERP);
    }

    /**
     * Another character of the same model playing the same clip (a crowd): it shares this one's
     * skeleton, sampler and geometries, which are read-only, and starts with its skinners, and owns
     * its pose and palettes, so each copy poses at its own time and on its own thread with the
     * memory of a palette set instead of a whole model (and CoR's centres are computed once per
     * geometry, not per copy). Call it on the thread that drives this model.
     */
    public SkinnedModel newCharacter() {
        return new SkinnedModel(this);
    }

    private SkinnedModel(SkinnedModel template) {
        this.model = template.model;
        this.normals = template.normals;
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
        dualQuaternionsReady = new boolean[n];
        bonesReady = new boolean[n];
        skinners = new Skinner[n][];
        for (int g = 0; g < n; g++) {
            if (template.morphed[g] != null) {
                // A morphing mesh's rest shape follows this character's time: its own geometry.
                list.set(g, morph(g, model.instances().get(g), template.morphed[g].rest()));
                skinners[g] = new Skinner[SkinningMethod.values().length];
            } else {
                skinners[g] = template.skinners[g].clone();
            }
            palettes[g] = list.get(g).newPalette();
        }
        // The same list when nothing morphs: a crowd shares its geometries.
        this.geometries = morphSampler.animatesAny() ? List.copyOf(list) : template.geometries;
        pose(sampler.start(), RotationInterpolation.SLERP);
    }

    private SkinnedGeometry morph(int g, MeshInstance instance, SkinnedGeometry rest) {
        morphed[g] = new MorphedRestShape(instance, model.nodes(), morphSampler.morph(g), rest);
        return morphed[g].geometry();
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

    /** The model with its first clip (or at rest when it has none) and exact normals. */
    public static SkinnedModel of(Model model) {
        return new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0),
                NormalTransform.INVERSE_TRANSPOSE);
    }

    public Model model() {
        return model;
    }

    public Skeleton skeleton() {
        return skeleton;
    }

    public AnimationSampler sampler() {
        return sampler;
    }

    /** The current pose (read-only use). */
    public Pose pose() {
        return pose;
    }

    /** One geometry per placed mesh, in {@link Model#instances()} order. */
    public List<SkinnedGeometry> geometries() {
        return geometries;
    }

    /**
     * Whether geometry {@code g}'s rest positions follow animated morph weights: its
     * {@link SkinnedGeometry#positionArray()} then changes with every {@link #pose} (a renderer
     * that skins on the GPU uploads them per frame).
     */
    public boolean morphs(int g) {
        return morphed[g] != null;
    }

    /** The palette of geometry {@code g}, holding the skinning matrices of the current pose. */
    public JointPalette palette(int g) {
        return palettes[g];
    }

    /**
     * Fills the dual quaternions and scale parts of palette {@code g} for the current pose (once:
     * later calls and DQS skinning reuse them), for a caller that hands the whole palette on.
     */
    public JointPalette preparePalette(int g) {
        if (!dualQuaternionsReady[g]) {
            palettes[g].prepareDualQuaternions();
            dualQuaternionsReady[g] = true;
        }
        return palettes[g];
    }

    /**
     * As {@link #preparePalette(int)}, and fills the palette's bone rows for the current pose
     * ({@link JointPalette#prepareBones()}, once), for the methods that read them.
     */
    public JointPalette prepareBones(int g) {
        preparePalette(g);
        if (!bonesReady[g]) {
            palettes[g].prepareBones();
            bonesReady[g] = true;
        }
        return palettes[g];
    }

    /** The palette of geometry {@code g} prepared for a method: what {@link #skin} hands its skinner. */
    public JointPalette preparePalette(int g, SkinningMethod method) {
        return method.usesBones() ? prepareBones(g) : method.usesDualQuaternions() ? preparePalette(g) : palettes[g];
    }

    /** The skinner geometry {@code g} uses for a method (made on first use). */
    public Skinner skinner(int g, SkinningMethod method) {
        Skinner s = skinners[g][method.ordinal()];
        if (s == null) {
            s = newSkinner(g, method);
            skinners[g][method.ordinal()] = s;
        }
        return s;
    }

    /**
     * Poses the model at clip time {@code clipTime} (seconds; clamped to the keys of each
     * channel): samples the clip, evaluates the skeleton and fills every palette, and morphs the
     * rest shape of every mesh whose weights the clip animates.
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
                    palettes[g].matrices());
            dualQuaternionsReady[g] = false;
            bonesReady[g] = false;
        }
    }

    /**
     * Deforms geometry {@code g} in the current pose: 3 floats per point into each output array
     * (size {@code 3 * pointCount()}). DQS derives the palette's dual quaternions once per pose.
     */
    public void skin(int g, SkinningMethod method, float[] outPositions, float[] outNormals) {
        skinner(g, method).skinAll(preparePalette(g, method), outPositions, outNormals);
    }
}
