package org.skinlab.desktop.ui;

import java.util.HashMap;
import java.util.Map;
import java.util.function.Consumer;

import org.skinlab.desktop.render.GlWindow;
import org.skinlab.desktop.viewer.ViewerAction;
import org.skinlab.skinning.SkinningMethod;

import imgui.ImGui;
import imgui.ImGuiIO;
import imgui.extension.implot.ImPlot;
import imgui.extension.implot.ImPlotContext;
import imgui.gl3.ImGuiImplGl3;
import imgui.glfw.ImGuiImplGlfw;

/**
 * The Dear ImGui interface (imgui-java): the toolbar with every thesis function, the live numbers
 * and plots, the mixer panel, the help panel and the status line, placed by a {@link PanelLayout}
 * around the scene. It owns the ImGui and ImPlot contexts and their
 * GLFW and OpenGL 3 backends; the GLFW backend chains to the callbacks installed before it, so
 * the scene still gets the keys and the mouse the interface does not use.
 */
public final class ImGuiUi implements UserInterface {
    private final ImGuiImplGlfw glfw = new ImGuiImplGlfw();
    private final ImGuiImplGl3 gl3 = new ImGuiImplGl3();
    private final ImPlotContext plotContext;
    private final Map<String, float[]> itemRects = new HashMap<>();
    private final ToolbarPanel toolbar;
    private final StatsPanel stats;
    private final MixerPanel mixer;
    private final HelpPanel help;
    private final StatusLine status;
    private final PanelLayout layout = new PanelLayout();

    /**
     * @param actions what a button does: the window performs the action (some need the window)
     */
    public ImGuiUi(GlWindow window, Consumer<ViewerAction> actions) {
        ImGui.createContext();
        plotContext = ImPlot.createContext();
        ImGuiIO io = ImGui.getIO();
        io.setIniFilename(null);
        ImGui.styleColorsDark();
        float scale = window.contentScale();
        io.setFontGlobalScale(scale);
        ImGui.getStyle().scaleAllSizes(scale);
        glfw.init(window.handle(), true);
        gl3.init("#version 330 core");
        Widgets widgets = new Widgets(itemRects, actions);
        toolbar = new ToolbarPanel(widgets);
        stats = new StatsPanel();
        mixer = new MixerPanel(widgets);
        help = new HelpPanel();
        status = new StatusLine();
    }

    @Override
    public void layOut(int width, int height, SceneArea area) {
        // Window coordinates are framebuffer pixels divided by the content scale.
        float scale = framebufferScale();
        layout.decide(width / scale, height / scale, ImGui.getFrameHeight());
        int left = Math.round(layout.sceneLeft() * scale);
        int top = Math.round(layout.sceneTop() * scale);
        int right = Math.round(layout.sceneRight() * scale);
        int bottom = Math.round(layout.sceneBottom() * scale);
        area.set(left, height - bottom, right - left, bottom - top);
    }

    @Override
    public void render(SceneReadout scene) {
        gl3.newFrame();
        glfw.newFrame();
        ImGui.newFrame();
        toolbar.draw(scene, layout);
        stats.draw(scene, layout);
        mixer.draw(scene, layout);
        if (scene.viewer().settings().help()) {
            help.draw(scene);
        }
        status.draw(scene, layout);
        labelViews(scene);
        ImGui.render();
        gl3.renderDrawData(ImGui.getDrawData());
    }

    private static float framebufferScale() {
        float scale = ImGui.getIO().getDisplayFramebufferScaleX();
        return scale > 0 ? scale : 1f;
    }

    /** Names the method of each view in the row under it (the split view's two halves), and the bind pose. */
    private static void labelViews(SceneReadout s) {
        if (!s.drewMesh()) {
            return;
        }
        float scale = framebufferScale();
        SceneArea area = s.sceneArea();
        float left = area.x() / scale;
        float bottom = (s.height() - area.y()) / scale;
        float viewWidth = area.width() / scale / s.views();
        for (int v = 0; v < s.views(); v++) {
            boolean bind = s.viewer().config().isBindPose();
            String label = VIEW_LABELS[s.viewMethod(v).ordinal()][(s.viewOnCpu(v) ? 1 : 0) + (bind ? 2 : 0)];
            float x = left + v * viewWidth + (viewWidth - ImGui.calcTextSizeX(label)) / 2;
            float y = bottom + (PanelLayout.labelRow(ImGui.getFrameHeight()) - ImGui.getFontSize()) / 2;
            ImGui.getForegroundDrawList().addText(x, y, 0xFFFFFFFF, label);
        }
    }

    private static final String[][] VIEW_LABELS = labels();

    private static String[][] labels() {
        SkinningMethod[] methods = SkinningMethod.values();
        String[][] labels = new String[methods.length][];
        for (SkinningMethod m : methods) {
            String name = m.key().toUpperCase(java.util.Locale.ROOT);
            labels[m.ordinal()] = new String[] {name + " (GPU)", name + " (CPU)", name + " (GPU), bind pose",
                name + " (CPU), bind pose"};
        }
        return labels;
    }

    @Override
    public boolean wantsMouse() {
        return ImGui.getIO().getWantCaptureMouse();
    }

    @Override
    public boolean wantsKeyboard() {
        return ImGui.getIO().getWantTextInput();
    }

    @Override
    public float[] itemCentre(String label) {
        float[] r = itemRects.get(label);
        if (r == null) {
            ViewerAction a = ViewerAction.byName(label).orElse(null);
            r = a == null ? null : itemRects.get(a.label());
        }
        return r == null ? null : new float[] {(r[0] + r[2]) / 2, (r[1] + r[3]) / 2};
    }

    @Override
    public void close() {
        gl3.shutdown();
        try {
            glfw.shutdown();
        } catch (NullPointerException e) {
            // imgui-java 1.88.0 destroys standard cursors GLFW could not create (0) under Xvfb.
        }
        ImPlot.destroyContext(plotContext);
        ImGui.destroyContext();
    }
}
