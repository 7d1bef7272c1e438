package org.skinlab.collada;

import java.io.ByteArrayOutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

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
    /** A URI scheme: two or more characters ("C:" is a drive letter). */
    private static final Pattern SCHEME = Pattern.compile("[A-Za-z][A-Za-z0-9+.-]+");
    private static final Pattern ROOTED_DRIVE = Pattern.compile("/[A-Za-z]:/.*");
    private static final Pattern DRIVE = Pattern.compile("[A-Za-z]:/.*");
    /** 3ds Max's relative path to another drive: ../../C:/maps/a.png. */
    private static final Pattern OTHER_DRIVE = Pattern.compile("(?:\\.\\./)+([A-Za-z]:/.*)");

    private final Path document; // normalised, or null when unknown

    DocumentLocation(Path document) {
        this.document = document == null ? null : document.normalize();
    }

    /** The location of a document known only by a name (a path as given, possibly relative). */
    static Path fromName(String name) {
        try {
            return name == null || name.isEmpty() ? null : Paths.get(name); // Path.of is Android 14+
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
            Path p = Paths.get(path);
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
     *
     * <ul>
     * <li>{@code file:///C:/a.png} and {@code file:///home/a.png} are absolute;
     *     {@code file://a.png} and {@code file://..\maps\a.png} (3ds Max, FBX) are relative
     *     paths, not a host name; {@code file://localhost/x} is {@code /x};</li>
     * <li>{@code \..\maps\a.png} (a root cannot be climbed above) is relative;</li>
     * <li>{@code ../../../C:/maps/a.png} (3ds Max's relative path to another drive) is
     *     {@code C:/maps/a.png}.</li>
     * </ul>
     */
    static String filePath(String url) {
        String u = url.trim().replace('\\', '/');
        int colon = u.indexOf(':');
        if (colon > 1 && SCHEME.matcher(u.substring(0, colon)).matches()) {
            if (!u.substring(0, colon).equalsIgnoreCase("file")) {
                return null;
            }
            u = u.substring(colon + 1);
            if (u.startsWith("///")) {
                u = u.substring(2);
            } else if (u.startsWith("//localhost/")) {
                u = u.substring("//localhost".length());
            } else if (u.startsWith("//")) {
                u = u.substring(2);
            }
        }
        u = percentDecode(u);
        if (ROOTED_DRIVE.matcher(u).matches()) {
            u = u.substring(1); // file:///C:/x
        } else if (u.startsWith("/../") || u.startsWith("/./")) {
            u = u.substring(1);
        }
        Matcher drive = OTHER_DRIVE.matcher(u);
        return drive.matches() ? drive.group(1) : u;
    }

    private static boolean isAbsolute(String path) {
        return path.startsWith("/") || DRIVE.matcher(path).matches();
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
