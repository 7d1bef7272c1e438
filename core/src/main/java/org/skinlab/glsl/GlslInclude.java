package org.skinlab.glsl;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;

/**
 * One GLSL file in core's resources that shaders pull in with an {@code #include "name"} line
 * alone on its line (GLSL has no includes; the desktop's and the Android app's shader texts are
 * expanded before they are compiled), or one text made in Java under such a name
 * ({@link #generated}: constants whose one home is a Java class). Plain text: no GL here. A leaf
 * package, so that every package holding shader formulas ({@code skinning}, {@code ar}) can use it.
 */
public final class GlslInclude {
    private final String name;
    private final String resource;
    private final String what;
    private final String line;
    /** The text of a {@link #generated} include; null for a resource. */
    private final String generatedText;

    /**
     * @param resource the file's absolute classpath name, e.g. {@code /org/skinlab/ar/lens.glsl};
     *                 its last segment is the name the include line quotes
     * @param what     what the file holds, for error messages, e.g. "the lens shader's formulas"
     */
    public GlslInclude(String resource, String what) {
        this(checkedResource(resource), resource.substring(resource.lastIndexOf('/') + 1), what, null);
    }

    private GlslInclude(String resource, String name, String what, String generatedText) {
        this.resource = resource;
        this.name = name;
        this.what = what;
        this.line = "#include \"" + name + "\"";
        this.generatedText = generatedText;
    }

    private static String checkedResource(String resource) {
        if (!resource.startsWith("/") || resource.endsWith("/")) {
            throw new IllegalArgumentException("not an absolute resource file name: " + resource);
        }
        return resource;
    }

    /**
     * An include whose text is given rather than read: GLSL generated from a Java definition, so
     * that a shader and Java code (a legend, a test) read the same numbers from one place.
     *
     * @param name the name the include line quotes, e.g. {@code colour-ramp.glsl}
     * @param text the GLSL that replaces the include line, returned as is by {@link #text()}
     * @return a new include that never reads a resource
     * @throws IllegalArgumentException when {@code name} is empty or contains a slash or a double quote
     */
    public static GlslInclude generated(String name, String text) {
        if (name.isEmpty() || name.contains("/") || name.contains("\"")) {
            throw new IllegalArgumentException("not an include name: " + name);
        }
        return new GlslInclude(null, name, name, text);
    }

    /**
     * The line of a shader that {@link #expand} replaces with the file's text.
     *
     * @return {@code #include "name"}, without a line break
     */
    public String line() {
        return line;
    }

    /**
     * {@code shader} with its {@link #line} (alone on its line) replaced by the file's text; a
     * shader without that line comes back unchanged.
     *
     * @param shader the GLSL source text
     * @return the expanded source, or {@code shader} itself when it has no include line
     * @throws IllegalStateException when the line occurs more than once (GLSL refuses functions
     *                               defined twice; better said here), or the resource cannot be read
     */
    public String expand(String shader) {
        int at = lineStart(shader, 0);
        if (at < 0) {
            return shader;
        }
        if (lineStart(shader, at + line.length()) >= 0) {
            throw new IllegalStateException("a shader includes " + name + " twice");
        }
        return shader.substring(0, at) + text() + shader.substring(at + line.length());
    }

    /** Where the include line starts at or after {@code from} (alone on its line), or -1. */
    private int lineStart(String shader, int from) {
        for (int at = shader.indexOf(line, from); at >= 0; at = shader.indexOf(line, at + 1)) {
            int end = at + line.length();
            boolean startsLine = at == 0 || shader.charAt(at - 1) == '\n';
            boolean endsLine = end == shader.length() || shader.charAt(end) == '\n' || shader.charAt(end) == '\r';
            if (startsLine && endsLine) {
                return at;
            }
        }
        return -1;
    }

    /**
     * The file's text, read from the resource on each call (once per program a renderer builds),
     * or the generated text.
     *
     * @return the GLSL text, decoded as UTF-8
     * @throws IllegalStateException when the resource is missing from the classpath or cannot be read
     */
    public String text() {
        if (generatedText != null) {
            return generatedText;
        }
        // Read by hand: InputStream.readAllBytes needs Android 13, and the app runs from Android 8.
        try (InputStream in = GlslInclude.class.getResourceAsStream(resource)) {
            if (in == null) {
                throw new IllegalStateException(what + " " + resource
                        + " are missing from the classpath (an APK must carry them at its root)");
            }
            ByteArrayOutputStream out = new ByteArrayOutputStream(8192);
            byte[] buffer = new byte[8192];
            for (int n = in.read(buffer); n >= 0; n = in.read(buffer)) {
                out.write(buffer, 0, n);
            }
            return new String(out.toByteArray(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new IllegalStateException("cannot read " + what + " " + resource, e);
        }
    }
}
