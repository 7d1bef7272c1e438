package org.skinlab.model;

import java.nio.file.Path;

/**
 * An {@code <image>}: the file a texture comes from. The importer never opens it; a renderer
 * loads {@link #file()}.
 *
 * @param id   the image's id
 * @param name its name attribute, or null
 * @param uri  the {@code <init_from>} URI as written (null for an image whose data is embedded)
 * @param file the file the URI names, resolved against the document's folder and normalised
 *             (percent escapes decoded, {@code file://} and Windows separators understood), or
 *             null when the URI is not a file (http:, data:) or the image has none
 */
public record Image(String id, String name, String uri, Path file) {
}
