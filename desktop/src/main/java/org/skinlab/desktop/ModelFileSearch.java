package org.skinlab.desktop;

import java.io.IOException;
import java.nio.file.AccessDeniedException;
import java.nio.file.DirectoryIteratorException;
import java.nio.file.DirectoryStream;
import java.nio.file.FileSystemException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.Deque;
import java.util.List;
import java.util.Locale;
import java.util.function.Predicate;

import org.skinlab.desktop.ExitCodes;
import org.skinlab.importer.ModelImporter;

/**
 * Turns the FILE arguments of a batch command into the files to read, before anything is read:
 * a file argument is taken as it is (whatever its extension), a folder argument is searched
 * recursively for model files ({@code *.dae}, {@code *.gltf}, {@code *.glb}, any case:
 * {@link ModelImporter#isModelFile}), or for COLLADA files only ({@link #COLLADA}) where a
 * report is about our COLLADA assets and their {@code .glb} twins would only repeat them.
 *
 * <p>Arguments keep the order they were given in; the files found in one folder are sorted by
 * their path inside it, name by name (so a folder's files stay together, and the order does not
 * depend on the file system or the locale). Symbolic links named as arguments are followed;
 * links to folders met during the search are not (as {@code find} does), so a link loop cannot
 * make the search endless. A folder that cannot be listed becomes an entry that carries the
 * reason, so the caller reports it in its place and goes on.
 *
 * <p>Only paths are kept, never file contents: a batch of any size reads one file at a time.
 */
public final class ModelFileSearch {
    /** Every file {@link ModelImporter} reads. */
    static final Predicate<String> MODELS = ModelImporter::isModelFile;
    /** COLLADA files only. */
    public static final Predicate<String> COLLADA = name -> name.toLowerCase(Locale.ROOT).endsWith(".dae");

    private ModelFileSearch() {
    }

    /**
     * One file to inspect.
     *
     * @param path where to read it
     * @param shown the argument as the user gave it, joined with the path inside a folder
     *     argument: the name every output line uses
     * @param problem why it cannot even be tried (a folder that cannot be listed), or null
     */
    public record Entry(Path path, String shown, String problem) {
    }

    /** Order of paths inside one folder: name by name, each name by its UTF-16 code units. */
    public static final Comparator<Path> BY_PATH = (a, b) -> {
        int n = Math.min(a.getNameCount(), b.getNameCount());
        for (int i = 0; i < n; i++) {
            int c = a.getName(i).toString().compareTo(b.getName(i).toString());
            if (c != 0) {
                return c;
            }
        }
        return Integer.compare(a.getNameCount(), b.getNameCount());
    };

    /** The files the arguments name, in order, folders searched for every model file. */
    public static List<Entry> expand(List<Path> arguments) {
        return expand(arguments, MODELS);
    }

    /**
     * The files the arguments name, in order, folders searched for the file names {@code wanted}
     * accepts.
     *
     * @throws CommandFailure (status {@link ExitCodes#USAGE}) naming every argument that names
     *     nothing to inspect: a path that does not exist, or a folder with no wanted file
     *     anywhere below it
     */
    public static List<Entry> expand(List<Path> arguments, Predicate<String> wanted) {
        List<Entry> entries = new ArrayList<>();
        List<String> usageProblems = new ArrayList<>();
        for (Path argument : arguments) {
            if (!Files.exists(argument)) {
                usageProblems.add("file not found: " + argument);
            } else if (Files.isDirectory(argument)) {
                List<Entry> found = search(argument, wanted);
                if (found.isEmpty()) {
                    usageProblems.add((wanted == COLLADA ? "no .dae file" : "no model file (.dae, .gltf, .glb)")
                            + " in folder " + argument);
                }
                entries.addAll(found);
            } else {
                entries.add(new Entry(argument, argument.toString(), null));
            }
        }
        if (!usageProblems.isEmpty()) {
            throw new CommandFailure(ExitCodes.USAGE, String.join("; ", usageProblems), null);
        }
        return entries;
    }

    /** Every wanted file below one folder argument (links to folders not followed), sorted. */
    private static List<Entry> search(Path folder, Predicate<String> wanted) {
        // Each found file (or unlisted folder) under its path relative to the argument.
        record Found(Path relative, Path path, String problem) {
        }
        List<Found> found = new ArrayList<>();
        Deque<Path> pending = new ArrayDeque<>();
        pending.push(folder);
        while (!pending.isEmpty()) {
            Path dir = pending.pop();
            try (DirectoryStream<Path> children = Files.newDirectoryStream(dir)) {
                for (Path child : children) {
                    if (Files.isDirectory(child, LinkOption.NOFOLLOW_LINKS)) {
                        pending.push(child);
                    } else if (wanted.test(child.getFileName().toString()) && !Files.isDirectory(child)) {
                        // Links to files are read; a broken link or a device is kept and reported when read.
                        found.add(new Found(folder.relativize(child), child, null));
                    }
                }
            } catch (IOException e) {
                found.add(new Found(folder.relativize(dir), dir, "cannot list folder: " + reason(e)));
            } catch (DirectoryIteratorException e) {
                found.add(new Found(folder.relativize(dir), dir, "cannot list folder: " + reason(e.getCause())));
            }
        }
        found.sort((a, b) -> BY_PATH.compare(a.relative(), b.relative()));
        List<Entry> entries = new ArrayList<>(found.size());
        for (Found f : found) {
            // The folder argument itself relativizes to the empty path: show it as given.
            String shown = f.relative().toString().isEmpty() ? folder.toString() : folder.resolve(f.relative()).toString();
            entries.add(new Entry(f.path(), shown, f.problem()));
        }
        return entries;
    }

    /** A short, human reason for a failed file operation ({@code AccessDeniedException} has only the path). */
    public static String reason(IOException e) {
        if (e instanceof AccessDeniedException) {
            return "permission denied";
        }
        if (e instanceof NoSuchFileException) {
            return "not found";
        }
        if (e instanceof FileSystemException && ((FileSystemException) e).getReason() != null) {
            return ((FileSystemException) e).getReason();
        }
        return e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
    }
}
