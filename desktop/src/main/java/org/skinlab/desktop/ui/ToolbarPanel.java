package org.skinlab.desktop.ui;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.desktop.viewer.DifferenceScale;
import org.skinlab.desktop.viewer.LoadedModel;
import org.skinlab.desktop.viewer.Viewer;
import org.skinlab.desktop.viewer.ViewerAction;
import org.skinlab.desktop.viewer.ViewerSettings;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Model;
import org.skinlab.internal.scene.ColourRamp;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.internal.metrics.LargestDifference;
import org.skinlab.skinning.SkinningMethod;

import imgui.ImDrawList;
import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiSliderFlags;
import imgui.flag.ImGuiWindowFlags;

/**
 * The toolbar beside the scene, as in the thesis: model, animation, skinning and view, each
 * function a button (or box) with its key in the tooltip, plus the timeline and clip choice.
 */
final class ToolbarPanel {
    /** The toolbar's window title; scripts and tests find it by this name. */
    static final String TITLE = "skinlab";

    // values() copies its array on every call; the interface draws every frame.
    private static final RotationInterpolation[] INTERPOLATIONS = RotationInterpolation.values();
    private static final SkinningMethod[] METHODS = SkinningMethod.values();
    /** Radio buttons per row: seven methods in two rows fit the toolbar's width. */
    private static final int METHODS_PER_ROW = 4;
    /** Per method its button's text (the key in capitals) with its enum name as the ImGui id scripts find. */
    private static final String[] METHOD_LABELS = methodLabels();
    /** The difference scale's slider: red at this many percent of the model's size (a logarithmic slider). */
    private static final float SLIDER_MIN_PERCENT = 0.1f;
    private static final float SLIDER_MAX_PERCENT = 50f;
    /** The colour map's stops as ImGui colours (ABGR), for the legend. */
    private static final int[] RAMP_STOPS = rampStops();
    private static final float LEGEND_WIDTH = 200f;
    private static final float LEGEND_HEIGHT = 10f;

    private final Widgets widgets;
    private final float[] timeline = new float[1];
    private final CachedText speed = new CachedText("speed x%.2f");
    private final CachedText instances = new CachedText("%.0f");
    private final CachedText influences = new CachedText("%.0f influences per vertex in the shader");
    private final CachedText capped = new CachedText("%.0f vertices capped (weights renormalised)");
    private final float[] redPercent = {100 * DrawSettings.DIFFERENCE_FULL};
    private final CachedText legendTop = new CachedText("red: %.3g %% of the model's size or more");
    private final CachedText largestAt = new CachedText("the clip's largest, at %.2f s");
    private boolean scrubbing;
    private LoadedModel namedModel;
    private int namedJoint = -1;
    private String modelLine = "";
    private String jointLine = "";

    ToolbarPanel(Widgets widgets) {
        this.widgets = widgets;
    }

    void draw(SceneReadout scene, PanelLayout layout) {
        if (!begin(layout)) {
            layout.toolbarTitleMeasured(ImGui.getWindowWidth());
            ImGui.end();
            return;
        }
        Viewer viewer = scene.viewer();
        LoadedModel model = viewer.current();
        modelSection(viewer, model);
        ImGui.separator();
        animationSection(scene, viewer, model);
        ImGui.separator();
        skinningSection(scene, viewer);
        ImGui.separator();
        viewSection(viewer, model);
        ImGui.separator();
        windowButtons();
        layout.toolbarMeasured(ImGui.getWindowWidth());
        ImGui.end();
    }

    /** Opens the toolbar's window at the top left, no taller than the layout allows; false when collapsed. */
    private static boolean begin(PanelLayout layout) {
        ImGui.setNextWindowPos(PanelLayout.MARGIN, PanelLayout.MARGIN, ImGuiCond.Always);
        ImGui.setNextWindowSizeConstraints(0f, 0f, Float.MAX_VALUE, layout.toolbarMaxHeight());
        if (layout.toolbarChanged()) {
            ImGui.setNextWindowCollapsed(!layout.toolbarOpen(), ImGuiCond.Always);
        }
        ImGui.setNextWindowBgAlpha(0.85f);
        return ImGui.begin(TITLE, ImGuiWindowFlags.AlwaysAutoResize | ImGuiWindowFlags.NoMove);
    }

    private void modelSection(Viewer viewer, LoadedModel model) {
        Widgets.dim("Model");
        ImGui.textUnformatted(modelLine(model));
        widgets.action(ViewerAction.PREVIOUS_MESH);
        ImGui.sameLine();
        widgets.action(ViewerAction.NEXT_MESH);
        ImGui.sameLine();
        widgets.action(ViewerAction.OPEN_FILE);
        clips(viewer, model);
    }

    private void animationSection(SceneReadout scene, Viewer viewer, LoadedModel model) {
        AnimationConfig config = viewer.config();
        Widgets.dim("Animation");
        widgets.action(ViewerAction.TOGGLE_ANIMATION);
        ImGui.sameLine();
        ImGui.textUnformatted(config.isAnimationRunning() ? "playing" : "paused");
        widgets.toggle(ViewerAction.TOGGLE_MESH_UPDATES, "Mesh updates", config.isMeshUpdatesRunning());
        ImGui.sameLine();
        // The thesis' AR interaction: used by `skinlab ar`; outside AR it changes nothing visible.
        widgets.toggle(ViewerAction.TOGGLE_FOLLOW_CAMERA, "Follow camera", config.isFollowCamera());
        widgets.action(ViewerAction.SLOWER);
        ImGui.sameLine();
        widgets.action(ViewerAction.FASTER);
        ImGui.sameLine();
        ImGui.textUnformatted(speed.of(config.speed()));
        interpolations(config);
        timeline(scene, viewer, model);
        widgets.action(ViewerAction.STEP_BACK);
        ImGui.sameLine();
        widgets.action(ViewerAction.STEP_FORWARD);
        ImGui.sameLine();
        widgets.toggle(ViewerAction.TOGGLE_BIND_POSE, "Bind pose", config.isBindPose());
    }

    private void interpolations(AnimationConfig config) {
        ImGui.textUnformatted("Interpolation");
        for (RotationInterpolation r : INTERPOLATIONS) {
            ImGui.sameLine();
            if (ImGui.radioButton(r.name(), config.interpolation() == r)) {
                config.setInterpolation(r);
            }
            widgets.remember(r.name());
        }
    }

    private void skinningSection(SceneReadout scene, Viewer viewer) {
        AnimationConfig config = viewer.config();
        Widgets.dim("Skinning");
        for (SkinningMethod m : METHODS) {
            if (m.ordinal() % METHODS_PER_ROW != 0) {
                ImGui.sameLine();
            }
            if (ImGui.radioButton(METHOD_LABELS[m.ordinal()], config.method() == m)) {
                config.setMethod(m);
            }
            widgets.remember(m.name());
        }
        widgets.toggle(ViewerAction.TOGGLE_GPU_SKINNING, "GPU skinning", !config.isCpuSkinning());
        Widgets.dim(influences.of(scene.shaderInfluences()));
        if (scene.cappedVertices() > 0) {
            Widgets.dim(capped.of(scene.cappedVertices()));
        }
        widgets.toggle(ViewerAction.TOGGLE_SPLIT, "Split view (the other method beside)", viewer.settings().split());
    }

    private void viewSection(Viewer viewer, LoadedModel model) {
        ViewerSettings s = viewer.settings();
        Widgets.dim("View");
        widgets.radio(ViewerAction.VIEW_SHADED, s.drawView() == DrawSettings.View.SHADED);
        ImGui.sameLine();
        widgets.radio(ViewerAction.VIEW_WEIGHTS, s.drawView() == DrawSettings.View.WEIGHTS);
        ImGui.sameLine();
        widgets.radio(ViewerAction.VIEW_DIFFERENCE, s.drawView() == DrawSettings.View.DIFFERENCE);
        ImGui.sameLine();
        widgets.radio(ViewerAction.VIEW_CHECKER, s.drawView() == DrawSettings.View.CHECKER);
        if (s.drawView() == DrawSettings.View.DIFFERENCE) {
            differenceScale(viewer, s);
        }
        if (s.drawView() == DrawSettings.View.WEIGHTS) {
            widgets.action(ViewerAction.PREVIOUS_JOINT);
            ImGui.sameLine();
            widgets.action(ViewerAction.NEXT_JOINT);
            ImGui.textUnformatted(jointLine(viewer, model, s.selectedJoint()));
        }
        widgets.toggle(ViewerAction.TOGGLE_SKELETON, "Skeleton", s.skeleton());
        ImGui.sameLine();
        widgets.toggle(ViewerAction.TOGGLE_WIREFRAME, "Wireframe", s.wireframe());
        ImGui.textUnformatted("Instances");
        ImGui.sameLine();
        widgets.action(ViewerAction.FEWER_INSTANCES);
        ImGui.sameLine();
        widgets.action(ViewerAction.MORE_INSTANCES);
        ImGui.sameLine();
        ImGui.textUnformatted(instances.of(s.instances()));
    }

    /**
     * The difference view's scale: auto (the clip's largest difference is red) or red at a share of
     * the model's size (a logarithmic slider), and the colour map as a legend from blue (none) to
     * red.
     */
    private void differenceScale(Viewer viewer, ViewerSettings s) {
        DifferenceScale scale = s.differenceScale();
        if (ImGui.checkbox("Auto scale", scale.auto())) {
            s.setDifferenceScale(scale.auto() ? DifferenceScale.percent(redPercent[0]) : DifferenceScale.AUTO);
        }
        widgets.remember("Auto scale");
        if (ImGui.isItemHovered()) {
            ImGui.setTooltip("red at the largest LBS-DQS distance over the clip (measured when chosen)");
        }
        if (scale.auto()) {
            LargestDifference d = viewer.clipLargestDifference();
            ImGui.sameLine();
            Widgets.dim(d == null ? "measuring the clip ..." : largestAt.of(d.clipTime()));
        } else {
            redPercent[0] = (float) (100 * scale.fraction());
            if (ImGui.sliderFloat("Red at", redPercent, SLIDER_MIN_PERCENT, SLIDER_MAX_PERCENT, "%.2f %%",
                    ImGuiSliderFlags.Logarithmic | ImGuiSliderFlags.AlwaysClamp)) {
                s.setDifferenceScale(DifferenceScale.percent(redPercent[0]));
            }
            widgets.remember("Red at");
        }
        legend();
        Widgets.dim(legendTop.of(100 * viewer.differenceFull()));
    }

    /** The colour map from 0 (left) to the scale's top (right), one gradient per pair of stops. */
    private static void legend() {
        ImDrawList draw = ImGui.getWindowDrawList();
        float x = ImGui.getCursorScreenPosX();
        float y = ImGui.getCursorScreenPosY();
        int segments = RAMP_STOPS.length - 1;
        float step = LEGEND_WIDTH / segments;
        for (int i = 0; i < segments; i++) {
            int a = RAMP_STOPS[i];
            int b = RAMP_STOPS[i + 1];
            draw.addRectFilledMultiColor(x + i * step, y, x + (i + 1) * step, y + LEGEND_HEIGHT, a, b, b, a);
        }
        ImGui.dummy(LEGEND_WIDTH, LEGEND_HEIGHT);
    }

    private static int[] rampStops() {
        int[] stops = new int[ColourRamp.stopCount()];
        for (int i = 0; i < stops.length; i++) {
            int rgb = ColourRamp.colour(i / (double) (stops.length - 1));
            // ImGui's colours are ABGR.
            stops[i] = 0xFF000000 | (rgb & 0xFF) << 16 | (rgb & 0xFF00) | (rgb >> 16 & 0xFF);
        }
        return stops;
    }

    /** What the window does: camera, picture, help, quit. */
    private void windowButtons() {
        widgets.action(ViewerAction.CENTRE_CAMERA);
        ImGui.sameLine();
        widgets.action(ViewerAction.SCREENSHOT);
        ImGui.sameLine();
        widgets.action(ViewerAction.TOGGLE_HELP);
        ImGui.sameLine();
        widgets.action(ViewerAction.QUIT);
    }

    private String modelLine(LoadedModel model) {
        if (model != namedModel) {
            namedModel = model;
            namedJoint = -1;
            modelLine = model == null ? "(none)" : model.displayName();
        }
        return modelLine;
    }

    private String jointLine(Viewer viewer, LoadedModel model, int joint) {
        if (joint != namedJoint || model != namedModel) {
            namedJoint = joint;
            int count = viewer.jointCount();
            String name = "-";
            if (model != null && count > 0) {
                int node = model.mesh().geometries().get(0).jointNode(joint);
                Model m = model.model();
                name = node < 0 ? "(bind shape)" : m.node(node).name() != null ? m.node(node).name() : m.node(node).id();
            }
            jointLine = "joint " + joint + " of " + count + ": " + name;
        }
        return jointLine;
    }

    private void clips(Viewer viewer, LoadedModel model) {
        if (model == null) {
            return;
        }
        if (ImGui.beginCombo("Clip", model.clipName())) {
            for (int i = 0; i < model.model().clips().size(); i++) {
                AnimationClip c = model.model().clips().get(i);
                if (ImGui.selectable(c.name(), i == model.clipIndex())) {
                    viewer.playClip(i);
                }
            }
            ImGui.endCombo();
        }
        widgets.remember("Clip");
    }

    private void timeline(SceneReadout scene, Viewer viewer, LoadedModel model) {
        float duration = model == null ? 0f : (float) model.mesh().clipDuration();
        float start = model == null || model.clipIndex() < 0 ? 0f
                : model.model().clips().get(model.clipIndex()).start();
        if (!scrubbing) {
            timeline[0] = (float) scene.clipTime() - start;
        }
        boolean moved = ImGui.sliderFloat("Time", timeline, 0f, Math.max(duration, 1e-3f), "%.2f s");
        scrubbing = ImGui.isItemActive();
        widgets.remember("Time");
        if (moved) {
            // Scrubbing pauses: the frame under the slider is the one to look at.
            viewer.config().stopAnimation();
            viewer.seek(timeline[0]);
        }
    }

    private static String[] methodLabels() {
        String[] labels = new String[METHODS.length];
        for (SkinningMethod m : METHODS) {
            labels[m.ordinal()] = m.key().toUpperCase(java.util.Locale.ROOT) + "##" + m.name();
        }
        return labels;
    }
}
