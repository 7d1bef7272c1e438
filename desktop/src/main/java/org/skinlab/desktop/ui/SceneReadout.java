package org.skinlab.desktop.ui;

import org.skinlab.desktop.viewer.LiveStats;
import org.skinlab.desktop.viewer.Viewer;
import org.skinlab.skinning.SkinningMethod;

/**
 * What the interface shows about the scene just drawn: the viewer (its model, switches, camera and
 * live series), what the renderer drew and the numbers the comparison measured. Refilled every
 * window frame by the render loop and read by the interface on the same thread.
 */
public interface SceneReadout {
    Viewer viewer();

    LiveStats stats();

    /** Framebuffer width and height in pixels. */
    int width();

    int height();

    /** Where the scene was drawn: the window less the docked panels. */
    SceneArea sceneArea();

    /** Views drawn side by side in the scene area: 1, or 2 in the split view. */
    int views();

    /** The method a view shows. */
    SkinningMethod viewMethod(int view);

    /** Whether the CPU skinned what a view shows. */
    boolean viewOnCpu(int view);

    /** Whether a model frame was drawn (false while the first one is being made). */
    boolean drewMesh();

    boolean gpuSkinned();

    /** The clip time of the simulation frame drawn, in seconds. */
    double clipTime();

    /** Vertices drawn per instance. */
    int vertices();

    /** Influences per vertex the shader reads. */
    int shaderInfluences();

    /** Vertices whose influences the shader's cap cut (their weights renormalised). */
    int cappedVertices();

    /** Largest |LBS - DQS| over the model relative to its size; NaN when not measured. */
    double maxDifference();

    /**
     * The value at the top (red) of the difference colour map, relative to the model's size: the
     * viewer's difference scale, fixed or the clip's largest difference.
     */
    double differenceFull();

    /** LBS's volume of the model relative to its rest pose's; NaN when no part counts (see {@link #volumeNote()}). */
    double lbsVolume();

    /** DQS's volume of the model relative to its rest pose's; NaN when no part counts. */
    double dqsVolume();

    /**
     * Which parts the volumes hold, or why there are none ("volume: the mesh is not closed",
     * "volume: 3 of 3 skinned parts open", "volume: no skinned part"); empty when there is
     * nothing to say.
     */
    String volumeNote();
}
