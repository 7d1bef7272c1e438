package org.skinlab.desktop.viewer;

import java.nio.file.Path;

import java.util.List;

import org.skinlab.model.Model;
import org.skinlab.scene.ModelFraming;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.internal.metrics.MethodComparison;
import org.skinlab.internal.metrics.RestPose;

/**
 * A model the viewer shows: the file, the imported {@link Model}, the clip it plays, its
 * simulation and how it stands in the scene. Closing it stops and closes the simulation.
 */
public final class LoadedModel implements AutoCloseable {
    private final Path file;
    private final String displayName;
    private final Model model;
    private final int clip;
    private final SkeletalAnimatedMesh mesh;
    private final ModelFraming framing;
    private final RestPose rest;
    private final List<MethodComparison> comparisons;
    private final double loadMillis;

    LoadedModel(Path file, String displayName, Model model, int clip, SkeletalAnimatedMesh mesh, ModelFraming framing,
            RestPose rest, List<MethodComparison> comparisons, double loadMillis) {
        this.file = file;
        this.displayName = displayName;
        this.model = model;
        this.clip = clip;
        this.mesh = mesh;
        this.framing = framing;
        this.rest = rest;
        this.comparisons = List.copyOf(comparisons);
        this.loadMillis = loadMillis;
    }

    public Path file() {
        return file;
    }

    public String displayName() {
        return displayName;
    }

    public Model model() {
        return model;
    }

    /** Index of the clip playing in {@code model().clips()}, -1 at rest (no clips). */
    public int clipIndex() {
        return clip;
    }

    public String clipName() {
        return clip < 0 ? "none (rest pose)" : model.clips().get(clip).name();
    }

    public SkeletalAnimatedMesh mesh() {
        return mesh;
    }

    public ModelFraming framing() {
        return framing;
    }

    /** The model's parts in its rest pose, what the difference view's numbers are relative to. */
    public RestPose rest() {
        return rest;
    }

    /** LBS against DQS per part (the difference view's numbers), made when the model was loaded. */
    public List<MethodComparison> comparisons() {
        return comparisons;
    }

    public double loadMillis() {
        return loadMillis;
    }

    @Override
    public void close() {
        mesh.close();
    }
}
