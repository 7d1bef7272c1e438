package org.skinlab.collada;

import org.skinlab.model.ImportException;

/**
 * The one exception type for a COLLADA file that cannot be imported: malformed XML, a refused
 * DOCTYPE or entity, a missing or dangling reference, counts that disagree with the data, an
 * index out of range, a non-finite number or an absurd size.
 *
 * <p>The message always names the file, the element (with its id, or the nearest ancestor that
 * has one, and the line) and the problem, e.g.
 * {@code cube.dae: <float_array id="Cube-pos-array"> at line 12: count="30" but 27 values}.
 * It is meant to be shown to a user as one line.
 */
public final class ColladaException extends ImportException {
    private static final long serialVersionUID = 1L;

    /**
     * An exception whose message is {@code file: element: problem}, on one line.
     *
     * @param file the file (or stream name) being imported
     * @param element the element the problem was found in, with its id or nearest ancestor's and its line
     * @param problem what is wrong, without the file and element
     */
    public ColladaException(String file, String element, String problem) {
        super(file, element, problem);
    }

    /**
     * As {@link #ColladaException(String, String, String)}, with the exception that caused it.
     *
     * @param file the file (or stream name) being imported
     * @param element the element the problem was found in, with its id or nearest ancestor's and its line
     * @param problem what is wrong, without the file and element
     * @param cause the underlying exception (an XML parser's, say), or null
     */
    public ColladaException(String file, String element, String problem, Throwable cause) {
        this(file, element, problem);
        initCause(cause);
    }

    /**
     * The element the problem was found in, e.g. {@code <skin> in <controller id="c1"> at line 40}.
     *
     * @return the element description, the same as {@link #location()}
     */
    public String element() {
        return location();
    }
}
