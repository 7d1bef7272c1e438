package org.skinlab.model;

/**
 * Something the importer tolerated instead of refusing the file, e.g. a {@code <lines>}
 * primitive it skipped or weights that do not sum to one.
 *
 * @param element the element concerned, e.g. {@code <lines> in <geometry id="g"> at line 30}
 * @param message what was tolerated and how it was treated
 */
public record ImportWarning(String element, String message) {
    @Override
    public String toString() {
        return element + ": " + message;
    }
}
