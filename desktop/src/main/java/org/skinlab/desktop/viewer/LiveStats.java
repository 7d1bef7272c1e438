package org.skinlab.desktop.viewer;

/**
 * The live numbers the viewer plots: frames per second, frame time, skinning time, vertices
 * skinned per second and the relative volume under each method, sampled once per drawn frame
 * over the last {@value #SAMPLES} frames.
 */
public final class LiveStats {
    public static final int SAMPLES = 600;

    public final RollingSeries fps = new RollingSeries("fps", SAMPLES);
    public final RollingSeries frameMillis = new RollingSeries("frame ms", SAMPLES);
    public final RollingSeries skinningMillis = new RollingSeries("skinning ms", SAMPLES);
    public final RollingSeries verticesPerSecond = new RollingSeries("Mvertices/s", SAMPLES);
    public final RollingSeries lbsVolume = new RollingSeries("LBS volume", SAMPLES);
    public final RollingSeries dqsVolume = new RollingSeries("DQS volume", SAMPLES);

    public void clear() {
        fps.clear();
        frameMillis.clear();
        skinningMillis.clear();
        verticesPerSecond.clear();
        lbsVolume.clear();
        dqsVolume.clear();
    }
}
