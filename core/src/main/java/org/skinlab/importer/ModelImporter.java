package org.skinlab.importer;

import java.io.BufferedInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;

import org.skinlab.collada.ColladaImporter;
import org.skinlab.gltf.GltfImporter;
import org.skinlab.model.ImportException;
import org.skinlab.model.Model;

/**
 * Reads a model file in whichever format it is, so callers need not know the formats: a binary
 * glTF by its magic ({@code glTF}), else by content: the first non-blank byte <code>&#123;</code> is glTF
 * JSON, {@code <} COLLADA XML; the name's extension ({@code .gltf}, {@code .glb}, {@code .dae})
 * decides only when the content does not.
 */
public final class ModelImporter {
    private static final int SNIFF_BYTES = 1024;

    private ModelImporter() {
    }

    /**
     * True for a name ending in .dae, .gltf or .glb (any case): the files this class reads.
     *
     * @param name a file name or path; only its ending is looked at, the file is not opened
     * @return whether the name has one of the three extensions
     */
    public static boolean isModelFile(String name) {
        String n = name.toLowerCase(Locale.ROOT);
        return n.endsWith(".dae") || n.endsWith(".gltf") || n.endsWith(".glb");
    }

    /**
     * Imports a file; its external files (glTF buffers, images) are found in its folder.
     *
     * @param file the model file, COLLADA or glTF (told apart by content, see the class comment)
     * @return the imported model, with the file's name as its {@link Model#source()}
     * @throws IOException when the file cannot be opened or read
     * @throws ImportException when its content cannot be imported: a
     *     {@link org.skinlab.collada.ColladaException} or a {@link org.skinlab.gltf.GltfException}
     */
    public static Model read(Path file) throws IOException, ImportException {
        String name = file.getFileName() == null ? file.toString() : file.getFileName().toString();
        try (InputStream in = new BufferedInputStream(Files.newInputStream(file), 1 << 16)) {
            return read(in, name, file.toAbsolutePath());
        }
    }

    /**
     * Imports from a stream (the caller closes it).
     *
     * @param in       the document's bytes, not closed; wrapped in a buffer when it does not support mark
     * @param name     the name used in messages and {@link Model#source()}
     * @param location the document's path for relative URIs, or null: then a glTF URI naming a
     *                 file is refused, and COLLADA takes the name as its location, as
     *                 {@link ColladaImporter#read(InputStream, String)} does (it never opens files)
     * @return the imported model
     * @throws IOException     when reading the stream fails
     * @throws ImportException when the document cannot be imported: a
     *                         {@link org.skinlab.collada.ColladaException} or a {@link org.skinlab.gltf.GltfException}
     */
    public static Model read(InputStream in, String name, Path location) throws IOException, ImportException {
        InputStream buffered = in.markSupported() ? in : new BufferedInputStream(in, 1 << 16);
        if (isGltf(buffered, name)) {
            return GltfImporter.read(buffered, name, location);
        }
        return location == null ? ColladaImporter.read(buffered, name) : ColladaImporter.read(buffered, name, location);
    }

    private static boolean isGltf(InputStream in, String name) throws IOException {
        in.mark(SNIFF_BYTES);
        byte[] head = new byte[SNIFF_BYTES];
        int n = 0;
        for (int r; n < head.length && (r = in.read(head, n, head.length - n)) != -1;) {
            n += r;
        }
        in.reset();
        if (n >= 4 && head[0] == 'g' && head[1] == 'l' && head[2] == 'T' && head[3] == 'F') {
            return true;
        }
        int i = n >= 3 && (head[0] & 0xff) == 0xEF && (head[1] & 0xff) == 0xBB && (head[2] & 0xff) == 0xBF ? 3 : 0;
        while (i < n && (head[i] == ' ' || head[i] == '\t' || head[i] == '\r' || head[i] == '\n')) {
            i++;
        }
        if (i < n && (head[i] == '{' || head[i] == '<')) {
            return head[i] == '{';
        }
        String lower = name.toLowerCase(Locale.ROOT);
        return lower.endsWith(".gltf") || lower.endsWith(".glb");
    }
}
