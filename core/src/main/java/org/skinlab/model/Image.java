package org.skinlab.model;

import java.nio.file.Path;
import java.util.Arrays;
import java.util.Objects;

/**
 * An image a texture comes from: a file ({@code <image>}'s {@code <init_from>}, a glTF image's
 * relative {@code uri}), or bytes embedded in the document (a glTF data URI or buffer view). The
 * importer never decodes it; a renderer loads {@link #bytes()} when present, else {@link #file()}.
 *
 * @param id       the image's id
 * @param name     its name attribute, or null
 * @param uri      the URI as written (null for an image whose data is embedded)
 * @param file     the file the URI names, resolved against the document's folder and normalised
 *                 (percent escapes decoded, {@code file://} and Windows separators understood), or
 *                 null when the URI is not a file (http:, data:) or the image has none
 * @param mimeType the media type the document gives ("image/png", "image/jpeg"), or null
 * @param bytes    the encoded picture (PNG, JPEG) when the document embeds it, else null; copied
 *                 in and out
 */
public record Image(String id, String name, String uri, Path file, String mimeType, byte[] bytes) {
    /**
     * An image; {@code bytes} is copied. The components are described in the class comment.
     *
     * @param id       the image's id
     * @param name     its name attribute, or null
     * @param uri      the URI as written, or null
     * @param file     the resolved file, or null
     * @param mimeType the media type, or null
     * @param bytes    the embedded picture, or null
     */
    public Image {
        bytes = bytes == null ? null : bytes.clone();
    }

    /**
     * An image in a file (or at a URI that is none), with nothing embedded.
     *
     * @param id   the image's id
     * @param name its name attribute, or null
     * @param uri  the URI as written, or null
     * @param file the file the URI names, resolved and normalised, or null when the URI is not a file
     */
    public Image(String id, String name, String uri, Path file) {
        this(id, name, uri, file, null, null);
    }

    /**
     * A copy of the embedded picture, or null.
     *
     * @return a new array of the encoded bytes (PNG, JPEG) the caller may change, or null when not embedded
     */
    @Override
    public byte[] bytes() {
        return bytes == null ? null : bytes.clone();
    }

    /**
     * True when the picture is embedded in the document ({@link #bytes()} is not null).
     *
     * @return whether a renderer loads {@link #bytes()} rather than {@link #file()}
     */
    public boolean isEmbedded() {
        return bytes != null;
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof Image i && Objects.equals(id, i.id) && Objects.equals(name, i.name)
                && Objects.equals(uri, i.uri) && Objects.equals(file, i.file) && Objects.equals(mimeType, i.mimeType)
                && Arrays.equals(bytes, i.bytes);
    }

    @Override
    public int hashCode() {
        return Objects.hash(id, name, uri, file, mimeType) * 31 + Arrays.hashCode(bytes);
    }

    @Override
    public String toString() {
        return "Image[" + id + (file != null ? ", " + file : uri != null ? ", " + uri : "")
                + (bytes != null ? ", " + bytes.length + " bytes " + mimeType : "") + "]";
    }
}
