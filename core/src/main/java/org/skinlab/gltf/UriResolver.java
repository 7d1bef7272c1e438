package org.skinlab.gltf;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Base64;
import java.util.Locale;

/**
 * What a glTF {@code uri} may name: a {@code data:} URI (base64 or percent-encoded), or a file in the document's own
 * folder (or below it), given relative to the document. Everything else is refused with the
 * URI's JSON path: other schemes ({@code http:}, {@code file:}), absolute paths, drive letters,
 * and {@code ..} segments that climb out of the folder. Without a location (a stream read without
 * its path) no file can be named at all.
 */
final class UriResolver {
    private final GltfContext ctx;
    private final Path folder;

    /** @param location the document's path, or null when unknown */
    UriResolver(GltfContext ctx, Path location) {
        this.ctx = ctx;
        Path parent = location == null ? null : location.toAbsolutePath().getParent();
        this.folder = location == null ? null : parent != null ? parent : location.toAbsolutePath();
    }

    static boolean isDataUri(String uri) {
        return uri.regionMatches(true, 0, "data:", 0, 5);
    }

    /** The media type of a data URI ("" when it gives none). */
    static String dataMediaType(String uri) {
        int comma = uri.indexOf(',');
        int semi = uri.indexOf(';');
        int end = semi >= 0 && (comma < 0 || semi < comma) ? semi : comma;
        return end < 5 ? "" : uri.substring(5, end).trim().toLowerCase(Locale.ROOT);
    }

    /** The bytes of a base64 data URI, refused when larger than {@code maxBytes}. */
    byte[] decodeData(String uri, String path, long maxBytes) throws GltfException {
        int comma = uri.indexOf(',');
        if (comma < 0) {
            throw ctx.error(path, "a data URI without a comma (\"" + abbreviate(uri) + "\")");
        }
        if (!uri.substring(0, comma).toLowerCase(Locale.ROOT).endsWith(";base64")) {
            // RFC 2397's other form: the data percent-encoded (never longer than the text).
            if (uri.length() - comma - 1 > maxBytes) {
                throw ctx.error(path, "the data URI holds more than " + maxBytes + " bytes");
            }
            return percentDecodeBytes(uri.substring(comma + 1), uri, path);
        }
        long decoded = (uri.length() - comma - 1) / 4L * 3;
        if (decoded > maxBytes + 3) {
            throw ctx.error(path, "the data URI holds about " + decoded + " bytes, more than " + maxBytes);
        }
        try {
            return Base64.getDecoder().decode(uri.substring(comma + 1));
        } catch (IllegalArgumentException e) {
            throw new GltfException(ctx.file(), path, "the data URI is not valid base64: " + e.getMessage(), e);
        }
    }

    /** The file a relative URI names inside the document's folder (not checked to exist). */
    Path file(String uri, String path) throws GltfException {
        String decoded = percentDecode(uri, path);
        int colon = decoded.indexOf(':');
        int slash = decoded.indexOf('/');
        if (colon >= 0 && (slash < 0 || colon < slash)) {
            throw ctx.error(path, "the URI \"" + abbreviate(uri) + "\" has a scheme or drive; only data: URIs and"
                    + " relative paths inside the file's folder are read");
        }
        if (decoded.startsWith("/") || decoded.startsWith("\\")) {
            throw ctx.error(path, "the URI \"" + abbreviate(uri) + "\" is an absolute path; only relative paths"
                    + " inside the file's folder are read");
        }
        if (folder == null) {
            throw ctx.error(path, "the URI \"" + abbreviate(uri) + "\" names a file, but the document was read"
                    + " from a stream without a location");
        }
        int depth = 0;
        Path result = folder;
        for (String segment : decoded.split("[/\\\\]")) {
            if (segment.isEmpty() || segment.equals(".")) {
                continue;
            }
            if (segment.equals("..")) {
                if (--depth < 0) {
                    throw ctx.error(path, "the URI \"" + abbreviate(uri) + "\" leaves the file's folder");
                }
                result = result.getParent();
            } else {
                depth++;
                result = result.resolve(segment);
            }
        }
        if (depth == 0) {
            throw ctx.error(path, "the URI \"" + abbreviate(uri) + "\" names the folder, not a file");
        }
        return result;
    }

    /**
     * The file a relative URI names inside the document's folder, refused when it exists but is
     * a link leading out of the folder (a renderer will open it); not opened here.
     */
    Path linkCheckedFile(String uri, String path) throws GltfException {
        Path file = file(uri, path);
        try {
            if (Files.exists(file) && !file.toRealPath().startsWith(folder.toRealPath())) {
                throw ctx.error(path, "\"" + abbreviate(uri) + "\" is a link that leads out of the file's folder");
            }
        } catch (IOException e) {
            throw new GltfException(ctx.file(), path, "cannot check \"" + abbreviate(uri) + "\": " + e, e);
        }
        return file;
    }

    /** The bytes of the file a URI names, refused when larger than {@code maxBytes}. */
    byte[] readFile(String uri, String path, long maxBytes) throws GltfException {
        Path file = linkCheckedFile(uri, path);
        try {
            if (!Files.isRegularFile(file)) {
                throw ctx.error(path, "\"" + abbreviate(uri) + "\": no such file next to the document");
            }
            long size = Files.size(file);
            if (size > maxBytes) {
                throw ctx.error(path, "\"" + abbreviate(uri) + "\" has " + size + " bytes, more than " + maxBytes);
            }
            return Files.readAllBytes(file);
        } catch (IOException e) {
            throw new GltfException(ctx.file(), path, "cannot read \"" + abbreviate(uri) + "\": " + e, e);
        }
    }

    private String percentDecode(String uri, String path) throws GltfException {
        int q = indexOfAny(uri, "?#");
        String s = q >= 0 ? uri.substring(0, q) : uri;
        if (s.indexOf('%') < 0) {
            return s;
        }
        String decoded = new String(percentDecodeBytes(s, uri, path), StandardCharsets.UTF_8);
        if (decoded.indexOf('\0') >= 0) {
            throw ctx.error(path, "the URI \"" + abbreviate(uri) + "\" decodes to a NUL character");
        }
        return decoded;
    }

    /** The bytes of text with %XX escapes (other characters as UTF-8). */
    private byte[] percentDecodeBytes(String s, String uri, String path) throws GltfException {
        ByteArrayOutputStream out = new ByteArrayOutputStream(s.length());
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            if (c == '%') {
                int hi = i + 2 < s.length() ? Character.digit(s.charAt(i + 1), 16) : -1;
                int lo = hi >= 0 ? Character.digit(s.charAt(i + 2), 16) : -1;
                if (lo < 0) {
                    throw ctx.error(path, "the URI \"" + abbreviate(uri) + "\" has a broken percent escape");
                }
                out.write(hi * 16 + lo);
                i += 2;
            } else {
                byte[] b = String.valueOf(c).getBytes(StandardCharsets.UTF_8);
                out.write(b, 0, b.length);
            }
        }
        return out.toByteArray();
    }

    private static int indexOfAny(String s, String chars) {
        for (int i = 0; i < s.length(); i++) {
            if (chars.indexOf(s.charAt(i)) >= 0) {
                return i;
            }
        }
        return -1;
    }

    static String abbreviate(String uri) {
        return uri.length() > 60 ? uri.substring(0, 60) + "..." : uri;
    }
}
