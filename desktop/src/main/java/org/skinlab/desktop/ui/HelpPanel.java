package org.skinlab.desktop.ui;

import org.skinlab.desktop.viewer.ViewerAction;

import imgui.ImGui;
import imgui.flag.ImGuiCond;
import imgui.flag.ImGuiTableFlags;
import imgui.flag.ImGuiWindowFlags;

/** Every key and what it does (the list is the actions' own, so it cannot go stale). */
final class HelpPanel {
    private static final ViewerAction[] ALL = ViewerAction.values();

    void draw(SceneReadout scene) {
        ImGui.setNextWindowPos(scene.width() - 8f, scene.height() - 8f, ImGuiCond.Always, 1f, 1f);
        ImGui.setNextWindowBgAlpha(0.85f);
        ImGui.begin("Keys", ImGuiWindowFlags.AlwaysAutoResize | ImGuiWindowFlags.NoMove | ImGuiWindowFlags.NoCollapse);
        Widgets.dim("Mouse: left drag orbits, right or middle drag pans, wheel zooms; drop a .dae, .gltf or .glb "
                + "to open it");
        if (ImGui.beginTable("keys", 4, ImGuiTableFlags.SizingFixedFit)) {
            ViewerAction[] all = ALL;
            int half = (all.length + 1) / 2;
            for (int i = 0; i < half; i++) {
                ImGui.tableNextRow();
                cell(all[i]);
                if (i + half < all.length) {
                    cell(all[i + half]);
                }
            }
            ImGui.endTable();
        }
        ImGui.end();
    }

    private static void cell(ViewerAction a) {
        ImGui.tableNextColumn();
        ImGui.textUnformatted(a.keyName());
        ImGui.tableNextColumn();
        Widgets.dim(a.description());
    }
}
