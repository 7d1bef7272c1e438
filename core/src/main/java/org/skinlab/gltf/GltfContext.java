package org.skinlab.gltf;

import java.util.ArrayList;
import java.util.List;

import org.skinlab.model.ImportWarning;

/**
 * One import's file name, warnings and allocation budget, shared by its readers.
 *
 * <p>The budget bounds what a document can make the importer allocate in total, whatever the
 * per-accessor limits: an accessor without a buffer view (zeros plus sparse values), or morph
 * targets without data, cost a few bytes of JSON each but arrays the size of a mesh. Every
 * decoded value and every array the readers build is charged before it is allocated, against
 * {@link GltfLimits#budget(long)} of the document's bytes.
 */
final class GltfContext {
    /** Warnings kept; a hostile file could otherwise fill the heap with them (as for COLLADA). */
    static final int MAX_WARNINGS = 200;

    private final String file;
    private final List<ImportWarning> warnings = new ArrayList<>();
    private int droppedWarnings;
    private long budget = GltfLimits.budget(0);

    GltfContext(String file) {
        this.file = file;
    }

    /** Adds the bytes of the document or of a buffer it names to the budget's base. */
    void addDocumentBytes(long bytes) {
        budget += GltfLimits.BUDGET_PER_BYTE * bytes;
    }

    /** Charges {@code values} (4-byte numbers about to be allocated) for what {@code path} names. */
    void charge(long values, String path) throws GltfException {
        if (values > budget) {
            throw error(path, "would need " + values + " more numbers, more than the " + budget
                    + " this document's size allows (" + GltfLimits.BUDGET_PER_BYTE + " per byte of data, plus "
                    + GltfLimits.budget(0) + ")");
        }
        budget -= values;
    }

    String file() {
        return file;
    }

    GltfException error(String path, String problem) {
        return new GltfException(file, path, problem);
    }

    void warn(String path, String message) {
        if (warnings.size() < MAX_WARNINGS) {
            warnings.add(new ImportWarning(path.isEmpty() ? "/" : path, message));
        } else {
            droppedWarnings++;
        }
    }

    /** The warnings, and one line for those beyond {@link #MAX_WARNINGS}. */
    List<ImportWarning> warnings() {
        if (droppedWarnings == 0) {
            return warnings;
        }
        List<ImportWarning> result = new ArrayList<>(warnings);
        result.add(new ImportWarning("/", droppedWarnings + " more warnings not shown"));
        return result;
    }
}
