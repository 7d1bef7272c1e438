package org.skinlab.desktop.ui;

import java.util.Map;
import java.util.function.Consumer;

import org.skinlab.desktop.viewer.ViewerAction;

import imgui.ImGui;
import imgui.flag.ImGuiCol;

/**
 * The interface's clickable items: each remembers where it was drawn (window coordinates, by
 * label) so a script can click it, and action buttons carry the action's key in their tooltip.
 */
final class Widgets {
    private final Map<String, float[]> rects;
    private final Consumer<ViewerAction> actions;

    Widgets(Map<String, float[]> rects, Consumer<ViewerAction> actions) {
        this.rects = rects;
        this.actions = actions;
    }

    /** A button that performs {@code action}; the key is in its tooltip. */
    void action(ViewerAction action) {
        boolean clicked = ImGui.button(action.label());
        remember(action.label());
        if (ImGui.isItemHovered()) {
            ImGui.setTooltip(action.description() + " [" + action.keyName() + "]");
        }
        if (clicked) {
            actions.accept(action);
        }
    }

    /** A radio button that performs {@code action} when chosen. */
    void radio(ViewerAction action, boolean active) {
        boolean clicked = ImGui.radioButton(action.label(), active);
        remember(action.label());
        if (ImGui.isItemHovered()) {
            ImGui.setTooltip(action.description() + " [" + action.keyName() + "]");
        }
        if (clicked && !active) {
            actions.accept(action);
        }
    }

    /** A checkbox showing {@code on} that performs {@code action} when clicked. */
    void toggle(ViewerAction action, String label, boolean on) {
        boolean clicked = ImGui.checkbox(label, on);
        remember(label);
        if (ImGui.isItemHovered()) {
            ImGui.setTooltip(action.description() + " [" + action.keyName() + "]");
        }
        if (clicked) {
            actions.accept(action);
        }
    }

    /**
     * Text in the dimmed colour, drawn as it is (ImGui's own text functions read it as a format,
     * so a '%' in a number's text would be eaten).
     */
    static void dim(String text) {
        ImGui.pushStyleColor(ImGuiCol.Text, 0.6f, 0.6f, 0.65f, 1f);
        ImGui.textUnformatted(text);
        ImGui.popStyleColor();
    }

    /** Records the last item's rectangle under {@code label}. */
    void remember(String label) {
        float[] r = rects.get(label);
        if (r == null) {
            r = new float[4];
            rects.put(label, r);
        }
        r[0] = ImGui.getItemRectMinX();
        r[1] = ImGui.getItemRectMinY();
        r[2] = ImGui.getItemRectMaxX();
        r[3] = ImGui.getItemRectMaxY();
    }
}
