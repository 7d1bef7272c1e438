package org.skinlab.desktop.app;

import org.skinlab.desktop.ui.SceneArea;
import org.skinlab.desktop.ui.SceneReadout;
import org.skinlab.desktop.viewer.LiveStats;
import org.skinlab.desktop.viewer.Viewer;
import org.skinlab.skinning.SkinningMethod;

/**
 * The {@link SceneReadout} the render loop fills: one instance, written by {@link SkinlabApp} and
 * {@link ScenePainter} while a window frame is drawn, then read by the interface.
 */
final class MutableSceneReadout implements SceneReadout {
    final LiveStats stats = new LiveStats();
    final SceneArea area = new SceneArea();
    Viewer viewer;
    int width;
    int height;
    double frameMillis;
    boolean drewMesh;
    boolean gpuSkinned;
    double clipTime;
    final SkinningMethod[] viewMethods = new SkinningMethod[2];
    final boolean[] viewOnCpu = new boolean[2];
    int views;
    int vertices;
    long skinningNanos;
    int shaderInfluences;
    int cappedVertices;
    double maxDifference = Double.NaN;
    double differenceFull = Double.NaN;
    double lbsVolume = Double.NaN;
    double dqsVolume = Double.NaN;
    String volumeNote = "";

    @Override
    public LiveStats stats() {
        return stats;
    }

    @Override
    public SceneArea sceneArea() {
        return area;
    }

    @Override
    public int views() {
        return views;
    }

    @Override
    public SkinningMethod viewMethod(int view) {
        return viewMethods[view];
    }

    @Override
    public boolean viewOnCpu(int view) {
        return viewOnCpu[view];
    }

    @Override
    public Viewer viewer() {
        return viewer;
    }

    @Override
    public int width() {
        return width;
    }

    @Override
    public int height() {
        return height;
    }

    @Override
    public boolean drewMesh() {
        return drewMesh;
    }

    @Override
    public boolean gpuSkinned() {
        return gpuSkinned;
    }

    @Override
    public double clipTime() {
        return clipTime;
    }

    @Override
    public int vertices() {
        return vertices;
    }

    @Override
    public int shaderInfluences() {
        return shaderInfluences;
    }

    @Override
    public int cappedVertices() {
        return cappedVertices;
    }

    @Override
    public double maxDifference() {
        return maxDifference;
    }

    @Override
    public double differenceFull() {
        return differenceFull;
    }

    @Override
    public double lbsVolume() {
        return lbsVolume;
    }

    @Override
    public double dqsVolume() {
        return dqsVolume;
    }

    @Override
    public String volumeNote() {
        return volumeNote;
    }
}
