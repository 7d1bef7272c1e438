package org.skinlab.desktop.ui;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiWindowFlags;

/**
 * The status line at the bottom left: what was loaded, what failed (the importer's message), what
 * was written; wrapped to the width the layout gives it, so it stays under the toolbar.
 */
final class StatusLine {
    void draw(SceneReadout scene, PanelLayout layout) {
        String message = scene.viewer().statusMessage();
        if (message.isEmpty()) {
            layout.statusMeasured(0f);
            return;
        }
        float padding = ImGui.getStyle().getWindowPaddingX();
        // The width is set, not fitted: a fitted window takes the last frame's width, which would
        // clip this frame's text when the layout widens it.
        float width = Math.min(ImGui.calcTextSizeX(message) + 2 * padding, layout.statusWidth());
        ImGui.setNextWindowPos(PanelLayout.MARGIN, ImGui.getIO().getDisplaySizeY() - PanelLayout.MARGIN,
                ImGuiCond.Always, 0f, 1f);
        ImGui.setNextWindowSizeConstraints(width, 0f, width, Float.MAX_VALUE);
        ImGui.setNextWindowBgAlpha(0.7f);
        ImGui.begin("status", ImGuiWindowFlags.NoDecoration | ImGuiWindowFlags.AlwaysAutoResize
                | ImGuiWindowFlags.NoMove | ImGuiWindowFlags.NoFocusOnAppearing | ImGuiWindowFlags.NoNav);
        ImGui.pushTextWrapPos(width - padding);
        ImGui.textUnformatted(message);
        ImGui.popTextWrapPos();
        layout.statusMeasured(ImGui.getWindowHeight());
        ImGui.end();
    }
}
