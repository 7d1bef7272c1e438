package org.skinlab.desktop.ui;

import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.desktop.viewer.LiveStats;
import org.skinlab.desktop.viewer.RollingSeries;

import imgui.ImGui;
import imgui.extension.implot.ImPlot;
import imgui.extension.implot.flag.ImPlotAxis;
import imgui.extension.implot.flag.ImPlotAxisFlags;
import imgui.extension.implot.flag.ImPlotCond;
import imgui.extension.implot.flag.ImPlotFlags;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiWindowFlags;

/**
 * The live numbers beside the scene, each with a small rolling plot of its last
 * {@value LiveStats#SAMPLES} frames: fps and frame time, skinning time, vertices skinned per
 * second, the model's volume under LBS and DQS (or why it has none), and in the difference view
 * the largest LBS-DQS distance.
 */
final class StatsPanel {
    /** The panel's window title. */
    static final String TITLE = "Numbers";
    /** Seconds of history the plots show. */
    private static final float WINDOW_SECONDS = 10f;
    /** The plots' width, which the volume's note wraps at. */
    private static final float PLOT_WIDTH = 300f;

    private final float[] xs = new float[LiveStats.SAMPLES];
    private final float[] ys = new float[LiveStats.SAMPLES];
    private final float[] ys2 = new float[LiveStats.SAMPLES];
    private final CachedText fps = new CachedText("%.0f fps");
    private final CachedText frameMs = new CachedText("frame %.2f ms");
    private final CachedText skinMs = new CachedText("CPU skinning %.3f ms per step");
    private final CachedText vertices = new CachedText("%.3g M vertices skinned per second");
    private final CachedText drawn = new CachedText("%.0f vertices per instance");
    private final CachedText difference = new CachedText("largest |LBS - DQS|: %.2f %% of the model's size");
    private final CachedText full = new CachedText("red: %.3g %% of the size or more");
    private final CachedText lbsVolume = new CachedText("LBS volume %.4f of rest");
    private final CachedText dqsVolume = new CachedText("DQS volume %.4f of rest");
    private long refreshedAt = -1;
    private float meanFps = Float.NaN;
    private float meanFrame = Float.NaN;
    private float meanSkin = Float.NaN;
    private float meanVertices = Float.NaN;

    void draw(SceneReadout scene, PanelLayout layout) {
        LiveStats stats = scene.stats();
        refreshMeans(stats);
        if (!begin(layout)) {
            layout.numbersTitleMeasured(ImGui.getWindowWidth());
            ImGui.end();
            return;
        }
        ImGui.textUnformatted(fps.of(meanFps));
        ImGui.sameLine();
        ImGui.textUnformatted(frameMs.of(meanFrame));
        plot("##fps", stats.fps, null);
        ImGui.textUnformatted(scene.gpuSkinned() ? "skinning on the GPU (vertex shader)" : skinMs.of(meanSkin));
        if (!scene.gpuSkinned()) {
            plot("##skin", stats.skinningMillis, null);
        }
        ImGui.textUnformatted(vertices.of(meanVertices));
        Widgets.dim(drawn.of(scene.vertices()));
        ImGui.separator();
        comparison(scene, stats);
        layout.numbersMeasured(ImGui.getWindowWidth(), ImGui.getWindowHeight());
        ImGui.end();
    }

    /** Numbers that change every frame are read 4 times a second: legible, and no string per frame. */
    private void refreshMeans(LiveStats stats) {
        long now = System.nanoTime();
        if (refreshedAt < 0 || now - refreshedAt > 250_000_000L) {
            refreshedAt = now;
            meanFps = stats.fps.mean();
            meanFrame = stats.frameMillis.mean();
            meanSkin = stats.skinningMillis.mean();
            meanVertices = stats.verticesPerSecond.mean();
        }
    }

    /** Opens the panel's window at the top right; false when collapsed. */
    private static boolean begin(PanelLayout layout) {
        ImGui.setNextWindowPos(ImGui.getIO().getDisplaySizeX() - PanelLayout.MARGIN, PanelLayout.MARGIN,
                ImGuiCond.Always, 1f, 0f);
        if (layout.numbersChanged()) {
            ImGui.setNextWindowCollapsed(!layout.numbersOpen(), ImGuiCond.Always);
        }
        ImGui.setNextWindowBgAlpha(0.85f);
        return ImGui.begin(TITLE, ImGuiWindowFlags.AlwaysAutoResize | ImGuiWindowFlags.NoMove);
    }

    /** The difference view's distance, and both methods' volumes with their plot. */
    private void comparison(SceneReadout scene, LiveStats stats) {
        if (scene.viewer().settings().drawView() == DrawSettings.View.DIFFERENCE) {
            ImGui.textUnformatted(difference.of(100 * scene.maxDifference()));
            Widgets.dim(full.of(100 * scene.differenceFull()));
        }
        if (!Double.isNaN(scene.lbsVolume())) {
            ImGui.textUnformatted(lbsVolume.of(scene.lbsVolume()));
            ImGui.textUnformatted(dqsVolume.of(scene.dqsVolume()));
            plot("##volume", stats.lbsVolume, stats.dqsVolume);
        }
        if (!scene.volumeNote().isEmpty()) {
            ImGui.pushTextWrapPos(ImGui.getCursorPosX() + PLOT_WIDTH);
            Widgets.dim(scene.volumeNote());
            ImGui.popTextWrapPos();
        }
    }

    /** A small line plot of the last seconds of one or two series. */
    private void plot(String id, RollingSeries a, RollingSeries b) {
        int n = a.size();
        if (n < 2) {
            return;
        }
        a.copyTo(xs, ys);
        float last = xs[n - 1];
        ImPlot.setNextAxisLimits(ImPlotAxis.X1, last - WINDOW_SECONDS, last, ImPlotCond.Always);
        if (ImPlot.beginPlot(id, PLOT_WIDTH, 80f, ImPlotFlags.NoLegend | ImPlotFlags.NoMenus | ImPlotFlags.NoBoxSelect
                | ImPlotFlags.NoMouseText)) {
            ImPlot.setupAxes(null, null, ImPlotAxisFlags.NoTickLabels, ImPlotAxisFlags.AutoFit);
            ImPlot.plotLine(a.name(), xs, ys, n);
            if (b != null && b.size() > 1) {
                int m = b.size();
                b.copyTo(xs, ys2);
                ImPlot.plotLine(b.name(), xs, ys2, m);
            }
            ImPlot.endPlot();
        }
    }
}
