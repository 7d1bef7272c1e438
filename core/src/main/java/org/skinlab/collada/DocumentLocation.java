package org.skinlab.collada;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;

/**
 * Where the document being imported lives, and what its relative URLs mean: the document part of
 * a reference ({@code self.dae} in {@code self.dae#cube}) and the file an {@code <image>} names.
 * The importer never opens either; it only compares and resolves paths.
 *
 * <p>A URL's path is read the way exporters write them, not only as RFC 3986 says:
 * {@code file://} prefixes ({@code file:///C:/tex/a.png} is {@code C:/tex/a.png}), percent escapes
 * ({@code my%20skin.png}), Windows separators ({@code textures\skin.png}) and drive letters.
 * Relative paths are resolved against the document's folder.
 */
final class DocumentLocation {
    private final Path document; // normalised, or null when unknown

    DocumentLocation(Path document) {
        this.document = document == null ? null : document.normalize();
    }

    /** The location of a document known only by a name (a path as given, possibly relative). */
    static Path fromName(String name) {
        try {
            return name == null || name.isEmpty() ? null : Path.of(name);
        } catch (InvalidPathException e) {
            return null; // a stream name that is no path: relative URLs cannot be resolved
        }
    }

    /** Whether the document part of a URL (before '#') names this very document. */
    boolean isThisDocument(String documentPart) {
        Path p = resolve(documentPart);
        return p != null && document != null && p.equals(document);
    }

    /**
     * The file a URL names, resolved against the document's folder and normalised; null for
     * URLs with another scheme ({@code http:}, {@code data:}) and for paths this platform cannot
     * represent.
     */
    Path resolve(String url) {
        String path = filePath(url);
        if (path == null) {
            return null;
        }
        try {
            Path p = Path.of(path);
            if (isAbsolute(path) || document == null) {
                return p.normalize();
            }
            Path folder = document.getParent();
            return (folder == null ? p : folder.resolve(p)).normalize();
        } catch (InvalidPathException e) {
            return null;
        }
    }

    /**
     * The path of a URL as written by exporters: percent escapes decoded, backslashes as
     * slashes, a {@code file:} scheme removed; null when the URL has another scheme.
     */
    static String filePath(String url) {
        String u = url.trim().replace('\\', '/');
        int colon = u.indexOf(':');
        // A scheme has two or more characters; "C:" is a drive letter.
        if (colon > 1 && u.substring(0, colon).matches("[A-Za-z][A-Za-z0-9+.-]*")) {
            if (!u.substring(0, colon).equalsIgnoreCase("file")) {
                return null;
            }
            u = u.substring(colon + 1);
            if (u.startsWith("//")) {
                int slash = u.indexOf('/', 2); // file://host/path: the host is dropped
                u = slash < 0 ? "/" : u.substring(slash);
            }
            if (u.matches("/[A-Za-z]:/.*")) {
                u = u.substring(1); // file:///C:/x
            }
        }
        return percentDecode(u);
    }

    private static boolean isAbsolute(String path) {
        return path.startsWith("/") || path.matches("[A-Za-z]:/.*");
    }

    /** Decodes %XX escapes as UTF-8; a malformed escape is kept as written. */
    static String percentDecode(String s) {
        if (s.indexOf('%') < 0) {
            return s;
        }
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(s.length());
        for (int i = 0; i < s.length(); ) {
            int c = s.codePointAt(i);
            if (c == '%' && i + 2 < s.length() && hex(s.charAt(i + 1)) >= 0 && hex(s.charAt(i + 2)) >= 0) {
                bytes.write(hex(s.charAt(i + 1)) * 16 + hex(s.charAt(i + 2)));
                i += 3;
            } else {
                byte[] b = new String(Character.toChars(c)).getBytes(StandardCharsets.UTF_8);
                bytes.write(b, 0, b.length);
                i += Character.charCount(c);
            }
        }
        return new String(bytes.toByteArray(), StandardCharsets.UTF_8);
    }

    private static int hex(char c) {
        return Character.digit(c, 16);
    }
}
