package org.skinlab.desktop.ui;

import java.util.HashMap;
import java.util.Map;

import org.skinlab.desktop.viewer.BlendPad;
import org.skinlab.desktop.viewer.LoadedModel;
import org.skinlab.desktop.viewer.MixerControls;
import org.skinlab.desktop.viewer.MixerControls.LayerChoice;
import org.skinlab.desktop.viewer.Viewer;

import imgui.ImDrawList;
import imgui.ImGui;
import imgui.flag.ImGuiComboFlags;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiSliderFlags;
import imgui.flag.ImGuiWindowFlags;

/**
 * The mixer panel under the numbers, to direct the character shown: a row per layer of its mixer
 * (clip, weight, joint mask, additive, remove) and "Add layer", a cross-fade of the base layer, the
 * blend pad and root motion. The choices go to {@link MixerControls}, which hands them to the
 * simulation thread; what the mixer refuses or warns of shows in the status line. Every item is
 * remembered under a name scripts click ("layer 1 clip", "layer 1 clip: walk", "Cross-fade",
 * "Blend pad"; docs/desktop.md).
 */
final class MixerPanel {
    /** The panel's window title. */
    static final String TITLE = "Mixer";
    private static final float ITEM_WIDTH = 150f;
    /**
     * Combos open on every entry, unscrolled (a skeleton's masks run to dozens): a script clicks an
     * entry where it was drawn, which in a scrolled list may lie outside it.
     */
    private static final int COMBO = ImGuiComboFlags.HeightLargest;
    private static final float PAD_SIZE = 140f;
    private static final float MARK_RADIUS = 3f;
    private static final float DOT_RADIUS = 6f;
    // ImGui's colours are ABGR.
    private static final int PAD_BACKGROUND = 0xFF3A302A;
    private static final int PAD_BORDER = 0xFF8C7F73;
    private static final int MARK = 0xFFC8C8C8;
    private static final int DOT_DRIVING = 0xFF40C0FF;
    private static final int DOT_IDLE = 0xFF707070;

    /** The names one layer row's items are remembered by, made once per row. */
    private static final class RowNames {
        final String clip;
        final String weight;
        final String mask;
        final String additive;
        final String remove;
        final String[] clips;
        final String[] masks;

        RowNames(String layer, MixerControls c) {
            clip = layer + " clip";
            weight = layer + " weight";
            mask = layer + " mask";
            additive = layer + " additive";
            remove = layer + " remove";
            clips = new String[c.clipCount()];
            for (int i = 0; i < clips.length; i++) {
                clips[i] = clip + ": " + c.clip(i);
            }
            masks = new String[c.maskCount()];
            for (int i = 0; i < masks.length; i++) {
                masks[i] = mask + ": " + c.maskLabel(i);
            }
        }
    }

    private final Widgets widgets;
    private final MixerControls controls = new MixerControls();
    private final float[] value = new float[1];
    private final Map<String, RowNames> rowNames = new HashMap<>();
    private String[] fadeNames = new String[0];
    private LoadedModel named;

    MixerPanel(Widgets widgets) {
        this.widgets = widgets;
    }

    void draw(SceneReadout scene, PanelLayout layout) {
        Viewer viewer = scene.viewer();
        follow(viewer.current());
        String message = controls.takeMessage();
        if (message != null) {
            viewer.setStatus(message);
        }
        if (!begin(layout)) {
            layout.mixerTitleMeasured(ImGui.getWindowWidth());
            ImGui.end();
            return;
        }
        if (!controls.hasModel()) {
            Widgets.dim("no model shown");
        } else if (controls.clipCount() == 0) {
            Widgets.dim("the model has no clips to mix");
        } else {
            layers();
            ImGui.separator();
            crossFade();
            if (controls.pad() != null) {
                ImGui.separator();
                pad(controls.pad());
            }
            ImGui.separator();
            rootMotion();
        }
        layout.mixerMeasured(ImGui.getWindowWidth());
        ImGui.end();
    }

    /** A new model: the choices and the items' names start afresh. */
    private void follow(LoadedModel current) {
        controls.show(current);
        if (current != named) {
            named = current;
            rowNames.clear();
            fadeNames = new String[controls.clipCount()];
            for (int i = 0; i < fadeNames.length; i++) {
                fadeNames[i] = "cross-fade to: " + controls.clip(i);
            }
        }
    }

    /** Under the numbers in their column, no taller than the window leaves; collapsed with the column. */
    private static boolean begin(PanelLayout layout) {
        ImGui.setNextWindowPos(layout.mixerRight(), layout.mixerTop(), ImGuiCond.Always, 1f, 0f);
        ImGui.setNextWindowSizeConstraints(0f, 0f, Float.MAX_VALUE, layout.mixerMaxHeight());
        if (layout.numbersChanged()) {
            ImGui.setNextWindowCollapsed(!layout.numbersOpen(), ImGuiCond.Always);
        }
        ImGui.setNextWindowBgAlpha(0.85f);
        return ImGui.begin(TITLE, ImGuiWindowFlags.AlwaysAutoResize | ImGuiWindowFlags.NoMove);
    }

    // ------------------------------------------------------------------------------ layers

    private void layers() {
        Widgets.dim("Layers, bottom first: clip, weight, mask");
        LayerChoice removed = null;
        for (int i = 0; i < controls.layers().size(); i++) {
            LayerChoice l = controls.layers().get(i);
            if (row(l, names(l))) {
                removed = l;
            }
        }
        if (removed != null) {
            controls.removeLayer(removed);
        }
        if (ImGui.button("Add layer")) {
            controls.addLayer();
        }
        widgets.remember("Add layer");
    }

    private RowNames names(LayerChoice l) {
        RowNames n = rowNames.get(l.name());
        if (n == null) {
            n = new RowNames(l.name(), controls);
            rowNames.put(l.name(), n);
        }
        return n;
    }

    /** One layer's items; true when its remove button was clicked. */
    private boolean row(LayerChoice l, RowNames n) {
        ImGui.pushID(l.name());
        ImGui.setNextItemWidth(ITEM_WIDTH);
        // The layer's name labels its clip.
        if (ImGui.beginCombo(l.name(), preview(l), COMBO)) {
            for (int c = 0; c < controls.clipCount(); c++) {
                if (ImGui.selectable(controls.clip(c), c == l.clip())) {
                    controls.play(l, c);
                }
                widgets.remember(n.clips[c]);
            }
            ImGui.endCombo();
        }
        widgets.remember(n.clip);
        boolean remove = false;
        if (!l.isBase()) {
            ImGui.sameLine();
            remove = ImGui.button("Remove");
            widgets.remember(n.remove);
        }
        value[0] = l.weight();
        ImGui.setNextItemWidth(ITEM_WIDTH);
        if (ImGui.sliderFloat("##weight", value, 0f, 1f, "%.2f", ImGuiSliderFlags.AlwaysClamp)) {
            controls.setWeight(l, value[0]);
        }
        widgets.remember(n.weight);
        label("Weight");
        ImGui.sameLine();
        if (ImGui.checkbox("Additive", l.additive())) {
            controls.setAdditive(l, !l.additive());
        }
        widgets.remember(n.additive);
        if (ImGui.isItemHovered()) {
            ImGui.setTooltip("add the clip's difference from its first pose to the layers below, "
                    + "instead of replacing them");
        }
        ImGui.setNextItemWidth(ITEM_WIDTH);
        if (ImGui.beginCombo("Mask", controls.maskLabel(l.mask()), COMBO)) {
            for (int m = 0; m < controls.maskCount(); m++) {
                if (ImGui.selectable(controls.maskLabel(m), m == l.mask())) {
                    controls.setMask(l, m);
                }
                widgets.remember(n.masks[m]);
            }
            ImGui.endCombo();
        }
        widgets.remember(n.mask);
        ImGui.popID();
        return remove;
    }

    /**
     * A slider's label, drawn beside it as ImGui would: the slider's own rectangle then spans the
     * slider alone, so a script's click on its centre sets the middle of its range.
     */
    private static void label(String text) {
        ImGui.sameLine(0f, ImGui.getStyle().getItemInnerSpacingX());
        ImGui.textUnformatted(text);
    }

    private String preview(LayerChoice l) {
        if (l.isBase() && controls.padDrives()) {
            return "(blend pad)";
        }
        return l.clip() < 0 ? "(none)" : controls.clip(l.clip());
    }

    // ------------------------------------------------------------------------------ cross-fade

    private void crossFade() {
        Widgets.dim("Cross-fade the base layer");
        ImGui.setNextItemWidth(ITEM_WIDTH);
        if (ImGui.beginCombo("To", controls.clip(controls.fadeTarget()), COMBO)) {
            for (int c = 0; c < controls.clipCount(); c++) {
                if (ImGui.selectable(controls.clip(c), c == controls.fadeTarget())) {
                    controls.setFadeTarget(c);
                }
                widgets.remember(fadeNames[c]);
            }
            ImGui.endCombo();
        }
        widgets.remember("Cross-fade to");
        value[0] = controls.fadeSeconds();
        ImGui.setNextItemWidth(ITEM_WIDTH);
        if (ImGui.sliderFloat("##duration", value, MixerControls.MIN_FADE_SECONDS, MixerControls.MAX_FADE_SECONDS,
                "%.2f s", ImGuiSliderFlags.AlwaysClamp)) {
            controls.setFadeSeconds(value[0]);
        }
        widgets.remember("Fade duration");
        label("Duration");
        if (ImGui.checkbox("Synchronised", controls.synchronised())) {
            controls.setSynchronised(!controls.synchronised());
        }
        widgets.remember("Synchronised");
        if (ImGui.isItemHovered()) {
            ImGui.setTooltip("start the new clip in step (at the same phase) with the clip playing, "
                    + "as two gaits should");
        }
        ImGui.sameLine();
        if (ImGui.button("Cross-fade")) {
            controls.crossFade();
        }
        widgets.remember("Cross-fade");
    }

    // ------------------------------------------------------------------------------ blend pad

    /** A square the user drags a point on; the base layer plays the pad's blend space at that point. */
    private void pad(BlendPad pad) {
        Widgets.dim("Blend pad (drag on it: the base layer)");
        float x0 = ImGui.getCursorScreenPosX();
        float y0 = ImGui.getCursorScreenPosY();
        ImGui.invisibleButton("##pad", PAD_SIZE, PAD_SIZE);
        widgets.remember("Blend pad");
        if (ImGui.isItemActive()) {
            float u = clamp((ImGui.getMousePosX() - x0) / PAD_SIZE);
            float v = clamp(1f - (ImGui.getMousePosY() - y0) / PAD_SIZE);
            controls.movePad(u, v);
        }
        ImDrawList draw = ImGui.getWindowDrawList();
        draw.addRectFilled(x0, y0, x0 + PAD_SIZE, y0 + PAD_SIZE, PAD_BACKGROUND);
        draw.addRect(x0, y0, x0 + PAD_SIZE, y0 + PAD_SIZE, PAD_BORDER);
        if (!pad.space().isPlanar()) {
            // A 1-D space reads its parameter up the pad: its axis.
            draw.addLine(x0 + PAD_SIZE / 2, y0, x0 + PAD_SIZE / 2, y0 + PAD_SIZE, PAD_BORDER);
        }
        float half = ImGui.getFontSize() / 2f;
        for (int i = 0; i < pad.clipCount(); i++) {
            float x = x0 + pad.u(i) * PAD_SIZE;
            float y = y0 + (1f - pad.v(i)) * PAD_SIZE;
            draw.addCircleFilled(x, y, MARK_RADIUS, MARK);
            String name = pad.clip(i);
            // Names on the right half go left of their mark, so they stay on the pad.
            float tx = pad.u(i) > 0.5f ? x - MARK_RADIUS - 2f - ImGui.calcTextSizeX(name) : x + MARK_RADIUS + 2f;
            float ty = Math.max(y0, Math.min(y0 + PAD_SIZE - 2 * half, y - half));
            draw.addText(tx, ty, MARK, name);
        }
        draw.addCircleFilled(x0 + controls.padU() * PAD_SIZE, y0 + (1f - controls.padV()) * PAD_SIZE, DOT_RADIUS,
                controls.padDrives() ? DOT_DRIVING : DOT_IDLE);
        Widgets.dim(pad.description());
    }

    private static float clamp(float f) {
        return Math.max(0f, Math.min(1f, f));
    }

    // ------------------------------------------------------------------------------ root motion

    private void rootMotion() {
        boolean on = controls.rootMotion();
        if (ImGui.checkbox("Root motion", on)) {
            controls.setRootMotion(!on);
        }
        widgets.remember("Root motion");
        if (ImGui.isItemHovered()) {
            ImGui.setTooltip("the clip plays in place and its root's travel moves the model; the camera follows it");
        }
        ImGui.sameLine();
        Widgets.dim(controls.rootMotionClips());
        if (ImGui.button("Back to the start")) {
            controls.resetPlacement();
        }
        widgets.remember("Back to the start");
    }
}
