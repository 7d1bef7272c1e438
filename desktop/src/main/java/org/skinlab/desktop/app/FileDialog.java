package org.skinlab.desktop.app;

import java.nio.file.Path;

import org.lwjgl.PointerBuffer;
import org.lwjgl.system.MemoryStack;
import org.lwjgl.util.tinyfd.TinyFileDialogs;

/** The native "open file" dialog (tinyfd: the desktop's own dialog tool, or a console fallback). */
final class FileDialog {
    private FileDialog() {
    }

    /** Asks for a COLLADA file; null when cancelled. Blocks the window's thread while open. */
    static Path chooseCollada() {
        try (MemoryStack stack = MemoryStack.stackPush()) {
            PointerBuffer patterns = stack.mallocPointer(2);
            patterns.put(stack.UTF8("*.dae")).put(stack.UTF8("*.DAE")).flip();
            String chosen = TinyFileDialogs.tinyfd_openFileDialog("Open a COLLADA file", "", patterns,
                    "COLLADA files (*.dae)", false);
            return chosen == null || chosen.isEmpty() ? null : Path.of(chosen);
        }
    }
}
