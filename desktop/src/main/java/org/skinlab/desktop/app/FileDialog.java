package org.skinlab.desktop.app;

import java.nio.file.Path;

import org.lwjgl.PointerBuffer;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.util.tinyfd.TinyFileDialogs;

/** The native "open file" dialog (tinyfd: the desktop's own dialog tool, or a console fallback). */
final class FileDialog {
    private FileDialog() {
    }

    /** The file names the dialog offers, in both cases (the patterns are case-sensitive on Linux). */
    private static final String[] PATTERNS = {"*.dae", "*.gltf", "*.glb", "*.DAE", "*.GLTF", "*.GLB"};

    /** Asks for a model file (COLLADA or glTF); null when cancelled. Blocks the window's thread while open. */
    static Path chooseModel() {
        try (MemoryStack stack = MemoryStack.stackPush()) {
            PointerBuffer patterns = stack.mallocPointer(PATTERNS.length);
            for (String pattern : PATTERNS) {
                patterns.put(stack.UTF8(pattern));
            }
            patterns.flip();
            String chosen = TinyFileDialogs.tinyfd_openFileDialog("Open a model file", "", patterns,
                    "Models (*.dae, *.gltf, *.glb)", false);
            return chosen == null || chosen.isEmpty() ? null : Path.of(chosen);
        }
    }
}
