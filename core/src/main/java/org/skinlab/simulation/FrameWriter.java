package org.skinlab.simulation;

import org.joml.Matrix4f;
import org.skinlab.animation.LocalPose;
import org.skinlab.mixer.Mixer;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningGlsl;

/**
 * The per-frame work of a step: poses a {@link SkinnedModel} at a playback time and fills a
 * {@link Frame} with every geometry's joint palette and, when the mesh is skinned on the CPU, the
 * skinned mesh. It writes whichever frame it is given; which buffer that may be is
 * {@link FramePool}'s rule. Not thread-safe (the model holds the pose): one step at a time.
 * Allocates nothing.
 */
final class FrameWriter {
    private final SkinnedModel skinned;
    private final Mixer mixer;
    private final LocalPose local;
    private final Matrix4f placement = new Matrix4f();

    FrameWriter(SkinnedModel skinned, Mixer mixer) {
        this.skinned = skinned;
        this.mixer = mixer;
        this.local = skinned.skeleton().newLocalPose();
    }

    /** A pool of frames shaped for this model's geometries. */
    FramePool newPool(int maxBuffers) {
        int n = skinned.geometries().size();
        boolean[] morphing = new boolean[n];
        for (int g = 0; g < n; g++) {
            morphing[g] = skinned.morphs(g);
        }
        return new FramePool(skinned.geometries(), morphing, maxBuffers);
    }

    /**
     * Poses the model as the mixer says (its base layer at {@code playback} seconds since the
     * heaviest clip's start), or in its bind pose when {@code s.bindPose()}, and fills {@code f}
     * as step {@code sequence} under {@code s}. When the mixer plays the model's own clip alone,
     * the clip's sampler poses it directly (the file's values exactly on keys); otherwise the
     * mixer's blend.
     */
    void write(Frame f, double playback, AnimationConfig.Settings s, long sequence) {
        float clipTime = mixer.base().clipTime();
        // A method the shaders cannot skin is skinned here whatever the switch says (SkinningGlsl.hasCode).
        boolean cpuSkinned = s.cpuSkinning() || !SkinningGlsl.hasCode(s.method());
        long t0 = System.nanoTime();
        long meshSkinningNanos = 0;
        if (s.bindPose()) {
            skinned.poseBind();
        } else if (mixer.soleClip() == skinned.sampler().clip() || mixer.playsNothing()) {
            skinned.pose(clipTime, s.interpolation());
        } else {
            mixer.evaluate(s.interpolation(), local);
            skinned.pose(local);
        }
        f.setPlacement(mixer.placement(placement));
        for (int g = 0; g < f.geometryCount(); g++) {
            // Dual quaternions and bone rows whatever the method: a split view may draw two methods from one frame.
            f.copyPalette(g, skinned.palette(g).prepareAll());
            if (f.restPositions(g) != null) {
                SkinnedGeometry geometry = skinned.geometries().get(g);
                f.copyRestShape(g, geometry.positionArray(), geometry.normalArray());
            }
            if (cpuSkinned) {
                long k0 = System.nanoTime();
                skinned.skin(g, s.method(), f.positionsForWriting(g), f.normalsForWriting(g));
                meshSkinningNanos += System.nanoTime() - k0;
            }
        }
        long nanos = System.nanoTime() - t0;
        f.describe(sequence, playback, clipTime, s.method(), s.interpolation(), cpuSkinned, nanos, meshSkinningNanos);
    }
}
