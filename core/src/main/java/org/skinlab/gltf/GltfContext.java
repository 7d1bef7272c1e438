package org.skinlab.gltf;

import java.util.ArrayList;
import java.util.List;

import org.skinlab.model.ImportWarning;

/** One import's file name and warnings, shared by its readers. */
final class GltfContext {
    private final String file;
    private final List<ImportWarning> warnings = new ArrayList<>();

    GltfContext(String file) {
        this.file = file;
    }

    String file() {
        return file;
    }

    GltfException error(String path, String problem) {
        return new GltfException(file, path, problem);
    }

    void warn(String path, String message) {
        warnings.add(new ImportWarning(path.isEmpty() ? "/" : path, message));
    }

    List<ImportWarning> warnings() {
        return warnings;
    }
}
