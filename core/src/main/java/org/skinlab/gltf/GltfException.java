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

    /**
     * An exception whose message is {@code file: path: problem}, on one line.
     *
     * @param file the file (or stream name) being imported
     * @param path the JSON pointer of the offending value, e.g. {@code /accessors/3/count}; empty for the
     *     whole document (stored as "/")
     * @param problem what is wrong, without the file and path
     */
    public GltfException(String file, String path, String problem) {
        super(file, path.isEmpty() ? "/" : path, problem);
    }

    /**
     * As {@link #GltfException(String, String, String)}, with the exception that caused it.
     *
     * @param file the file (or stream name) being imported
     * @param path the JSON pointer of the offending value; empty for the whole document (stored as "/")
     * @param problem what is wrong, without the file and path
     * @param cause the underlying exception (a JSON parser's or an I/O error, say), or null
     */
    public GltfException(String file, String path, String problem, Throwable cause) {
        this(file, path, problem);
        initCause(cause);
    }

    /**
     * The JSON pointer of the value the problem was found in ("/" for the document).
     *
     * @return the pointer, the same as {@link #location()}
     */
    public String path() {
        return location();
    }
}
