package org.skinlab.desktop.app;

import org.skinlab.desktop.viewer.LiveStats;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.desktop.viewer.Viewer;

/**
 * What the interface shows about the frame just drawn: the viewer (its model, switches, camera and
 * live series), what the renderer drew and the numbers the comparison measured. One instance,
 * refilled every frame by the render loop; read by {@link AppUi} on the same thread.
 */
public final class AppFrame {
    final LiveStats stats = new LiveStats();
    Viewer viewer;
    int width;
    int height;
    long frameNumber;
    double frameMillis;
    boolean drewMesh;
    boolean gpuSkinned;
    long sequence = -1;
    double clipTime;
    /** The method each view shows (one, or two side by side), and whether the CPU skinned it. */
    final SkinningMethod[] viewMethods = new SkinningMethod[2];
    final boolean[] viewOnCpu = new boolean[2];
    int views;
    int sceneLeft;
    int vertices;
    long skinningNanos;
    int shaderInfluences;
    int cappedVertices;
    /** Largest |LBS - DQS| over the model relative to its size; NaN when not measured. */
    double maxDifference = Double.NaN;
    /** The value at the top of the difference colour map, relative to the model's size. */
    double differenceFull = Double.NaN;
    double lbsVolume = Double.NaN;
    double dqsVolume = Double.NaN;

    public LiveStats stats() {
        return stats;
    }

    /** Framebuffer pixels left of the scene (the toolbar's). */
    public int sceneLeft() {
        return sceneLeft;
    }

    /** Views drawn side by side: 1, or 2 in the split view. */
    public int views() {
        return views;
    }

    public SkinningMethod viewMethod(int view) {
        return viewMethods[view];
    }

    public boolean viewOnCpu(int view) {
        return viewOnCpu[view];
    }

    public Viewer viewer() {
        return viewer;
    }

    public int width() {
        return width;
    }

    public int height() {
        return height;
    }


    public long frameNumber() {
        return frameNumber;
    }

    public double frameMillis() {
        return frameMillis;
    }

    /** Whether a model frame was drawn (false while the first one is being made). */
    public boolean drewMesh() {
        return drewMesh;
    }

    public boolean gpuSkinned() {
        return gpuSkinned;
    }

    public long sequence() {
        return sequence;
    }

    public double clipTime() {
        return clipTime;
    }

    public int vertices() {
        return vertices;
    }

    public int shaderInfluences() {
        return shaderInfluences;
    }

    public int cappedVertices() {
        return cappedVertices;
    }

    public double maxDifference() {
        return maxDifference;
    }

    public double differenceFull() {
        return differenceFull;
    }

    public double lbsVolume() {
        return lbsVolume;
    }

    public double dqsVolume() {
        return dqsVolume;
    }
}
