package org.skinlab.model;

import java.util.Locale;

/**
 * A file that cannot be imported, in any format: the importers' exceptions
 * ({@code ColladaException}, {@code GltfException}) extend it, so callers that load whatever the
 * user chose catch this one type.
 *
 * <p>The message always names the file, where in it the problem was found (an XML element with
 * its line, or a JSON path such as {@code /accessors/3/count}) and the problem, on one line, e.g.
 * {@code cube.dae: <float_array id="Cube-pos-array"> at line 12: count="30" but 27 values}.
 */
public class ImportException extends Exception {
    private static final long serialVersionUID = 1L;

    /** The file (or stream name) being imported, as given. */
    private final String file;
    /** Where in the file, on one line. */
    private final String location;
    /** What is wrong, on one line. */
    private final String problem;

    /**
     * An exception with the message {@code file: location: problem}, line breaks and other control
     * characters in the location and problem written as Java escapes so that the message is one line.
     *
     * @param file     the file (or stream name) being imported, e.g. {@code cube.dae}
     * @param location where in the file: an XML element with its line, or a JSON path; not null
     * @param problem  what is wrong, without the file and location; not null
     */
    public ImportException(String file, String location, String problem) {
        super(file + ": " + oneLine(location) + ": " + oneLine(problem));
        this.file = file;
        this.location = oneLine(location);
        this.problem = oneLine(problem);
    }

    /**
     * As {@link #ImportException(String, String, String)}, with the exception that led to this one.
     *
     * @param file     the file (or stream name) being imported, e.g. {@code cube.dae}
     * @param location where in the file: an XML element with its line, or a JSON path; not null
     * @param problem  what is wrong, without the file and location; not null
     * @param cause    the underlying exception (e.g. the XML or JSON parser's, or an I/O error), or null
     */
    public ImportException(String file, String location, String problem, Throwable cause) {
        this(file, location, problem);
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

    /**
     * The file (or stream name) being imported.
     *
     * @return the file name as given to the constructor
     */
    public String file() {
        return file;
    }

    /**
     * Where in the file: an element with its line, or a JSON path.
     *
     * @return the location, on one line (control characters escaped)
     */
    public String location() {
        return location;
    }

    /**
     * What is wrong, without the file and location.
     *
     * @return the problem, on one line (control characters escaped)
     */
    public String problem() {
        return problem;
    }
}
