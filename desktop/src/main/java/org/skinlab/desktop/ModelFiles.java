package org.skinlab.desktop;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;

import org.skinlab.desktop.ExitCodes;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.ImportException;
import org.skinlab.model.Model;

/** Loads the file a command names, turning failures into {@link CommandFailure}s. */
public final class ModelFiles {
    private ModelFiles() {
    }

    /** A model and how long the import took. */
    public static final class Loaded {
        public final Model model;
        public final double millis;

        Loaded(Model model, double millis) {
            this.model = model;
            this.millis = millis;
        }
    }

    public static Loaded load(Path file) {
        if (!Files.exists(file)) {
            throw new CommandFailure(ExitCodes.USAGE, "file not found: " + file, null);
        }
        if (Files.isDirectory(file)) {
            throw new CommandFailure(ExitCodes.USAGE, file + " is a directory, not a model file", null);
        }
        long start = System.nanoTime();
        try {
            Model model = ModelImporter.read(file);
            return new Loaded(model, (System.nanoTime() - start) / 1e6);
        } catch (ImportException e) {
            throw new CommandFailure(ExitCodes.INVALID_FILE, e.getMessage(), e);
        } catch (NoSuchFileException e) {
            throw new CommandFailure(ExitCodes.USAGE, "file not found: " + file, e);
        } catch (IOException e) {
            throw new CommandFailure(ExitCodes.INVALID_FILE, file.getFileName() + ": cannot be read: " + e.getMessage(), e);
        }
    }
}
