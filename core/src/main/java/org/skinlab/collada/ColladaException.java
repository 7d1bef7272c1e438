package org.skinlab.collada;

import java.util.Locale;

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
public final class ColladaException extends Exception {
    private static final long serialVersionUID = 1L;

    private final String file;
    private final String element;
    private final String problem;

    public ColladaException(String file, String element, String problem) {
        super(file + ": " + oneLine(element) + ": " + oneLine(problem));
        this.file = file;
        this.element = oneLine(element);
        this.problem = oneLine(problem);
    }

    public ColladaException(String file, String element, String problem, Throwable cause) {
        this(file, element, problem);
        initCause(cause);
    }

    /**
     * The text with line breaks and other control characters written as Java escapes (a backslash
     * and n, r, t, or u and four hex digits): problems may quote the file (the XML parser's
     * messages do), and a quoted line break would break the one-line message.
     */
    private static String oneLine(String text) {
        StringBuilder sb = null;
        for (int i = 0; i < text.length(); i++) {
            char c = text.charAt(i);
            boolean control = c < 0x20 || c == 0x7f || c == 0x2028 || c == 0x2029;
            if (control && sb == null) {
                sb = new StringBuilder(text.length() + 16).append(text, 0, i);
            }
            if (!control) {
                if (sb != null) {
                    sb.append(c);
                }
            } else if (c == '\n') {
                sb.append("\\n");
            } else if (c == '\r') {
                sb.append("\\r");
            } else if (c == '\t') {
                sb.append("\\t");
            } else {
                sb.append(String.format(Locale.ROOT, "\\u%04x", (int) c));
            }
        }
        return sb == null ? text : sb.toString();
    }

    /** The file (or stream name) being imported. */
    public String file() {
        return file;
    }

    /** The element the problem was found in, e.g. {@code <skin> in <controller id="c1"> at line 40}. */
    public String element() {
        return element;
    }

    /** What is wrong, without the file and element. */
    public String problem() {
        return problem;
    }
}
