package org.skinlab.gltf;

import org.skinlab.model.ImportException;

/**
 * The one exception type for a glTF file that cannot be imported: malformed JSON, a missing or
 * dangling index, a size that disagrees with the data or exceeds a limit, an unsupported required
 * extension, a URI that leaves the file's folder.
 *
 * <p>The location is the JSON path (an RFC 6901 pointer) of the offending value, e.g.
 * {@code Fox.glb: /accessors/3/count: 12 elements of 12 bytes need 144 bytes but the buffer view
 * has 100}.
 */
public final class GltfException extends ImportException {
    private static final long serialVersionUID = 1L;

    public GltfException(String file, String path, String problem) {
        super(file, path.isEmpty() ? "/" : path, problem);
    }

    public GltfException(String file, String path, String problem, Throwable cause) {
        this(file, path, problem);
        initCause(cause);
    }

    /** The JSON pointer of the value the problem was found in ("/" for the document). */
    public String path() {
        return location();
    }
}
