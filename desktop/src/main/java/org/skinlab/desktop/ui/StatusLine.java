package org.skinlab.desktop.ui;

import org.skinlab.desktop.app.AppFrame;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiWindowFlags;

/** The status line at the bottom: what was loaded, what failed (the importer's message), what was written. */
final class StatusLine {
    void draw(AppFrame f) {
        String message = f.viewer().statusMessage();
        if (message.isEmpty()) {
            return;
        }
        ImGui.setNextWindowPos(8, f.height() - 8f, ImGuiCond.Always, 0f, 1f);
        ImGui.setNextWindowBgAlpha(0.7f);
        ImGui.begin("status", ImGuiWindowFlags.NoDecoration | ImGuiWindowFlags.AlwaysAutoResize
                | ImGuiWindowFlags.NoMove | ImGuiWindowFlags.NoFocusOnAppearing | ImGuiWindowFlags.NoNav);
        ImGui.textUnformatted(message);
        ImGui.end();
    }
}
