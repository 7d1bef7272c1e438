package org.skinlab.desktop.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ModelFileSearch;
import org.skinlab.desktop.eval.InfluenceCapReport;
import org.skinlab.model.Mesh;
import org.skinlab.model.ImportException;
import org.skinlab.model.Model;

/**
 * {@code skinlab inspect} over several files (see {@link InspectCommand} for the contract): one
 * file after another, each model dropped before the next is read; a file that is refused, cannot
 * be read, or hits a bug or the memory limit is reported in its place and the batch goes on.
 */
final class InspectBatch {
    /** Reads one file: the importer, or in tests something that fails on purpose. */
    interface Reader {
        Model read(Path file) throws IOException, ImportException;
    }

    static final String OUT_OF_MEMORY = "out of memory; give Java more with SKINLAB_OPTS=-Xmx4g (or JAVA_OPTS)";

    private final boolean json;
    private final boolean influenceCaps;
    private final PrintWriter out;
    private final PrintWriter err;
    private final Reader reader;
    private final ObjectMapper mapper = new ObjectMapper();
    private int loaded;
    private int refused;
    private int internal;
    private int unlisted;

    /** @param influenceCaps whether to measure the influence-cap errors of each file's skinned meshes */
    InspectBatch(boolean json, boolean influenceCaps, PrintWriter out, PrintWriter err, Reader reader) {
        this.json = json;
        this.influenceCaps = influenceCaps;
        this.out = out;
        this.err = err;
        this.reader = reader;
    }

    /**
     * Inspects every entry in order and returns the exit status: 1 if any internal error, else 3
     * if any file was refused or could not be read or any folder could not be listed, else 0.
     */
    int run(List<ModelFileSearch.Entry> entries) {
        for (ModelFileSearch.Entry entry : entries) {
            inspect(entry);
        }
        if (!json) {
            int n = loaded + refused + internal;
            err.println(n + (n == 1 ? " file: " : " files: ") + loaded + " loaded, " + refused + " refused"
                    + (internal == 0 ? "" : ", " + internal + (internal == 1 ? " internal error" : " internal errors"))
                    + (unlisted == 0 ? "" : "; " + unlisted + (unlisted == 1 ? " folder" : " folders") + " could not be listed"));
            err.flush();
        }
        return internal > 0 ? ExitCodes.INTERNAL : refused + unlisted > 0 ? ExitCodes.INVALID_FILE : ExitCodes.OK;
    }

    private void inspect(ModelFileSearch.Entry entry) {
        Path path = entry.path();
        String name = path.getFileName() == null ? path.toString() : path.getFileName().toString();
        try {
            if (entry.problem() != null) {
                // A folder that could not be listed: not a file, so not in the file count.
                unlisted++;
                report(entry, name + ": " + entry.problem(), entry.problem());
                return;
            }
            String unusable = notAFile(path);
            if (unusable != null) {
                refuse(entry, name + ": " + unusable, unusable);
                return;
            }
            Model model;
            double millis;
            long start = System.nanoTime();
            try {
                model = reader.read(path);
                millis = (System.nanoTime() - start) / 1e6;
            } catch (ImportException e) {
                // The message is "name: location: problem"; on stderr the path the user gave replaces the name.
                refuse(entry, SkinlabCommand.oneLine(e.getMessage()),
                        SkinlabCommand.oneLine(e.location() + ": " + e.problem()));
                return;
            } catch (IOException e) {
                String why = "cannot be read: " + SkinlabCommand.oneLine(ModelFileSearch.reason(e));
                refuse(entry, name + ": " + why, why);
                return;
            }
            // The whole line is built before any of it is printed, so a failure cannot leave half a line.
            Map<Mesh, InfluenceCapReport.MeshReport> caps = InspectCommand.capReports(model, influenceCaps);
            if (json) {
                String line = mapper.writeValueAsString(InspectCommand.summary(mapper, entry.shown(), model, millis, caps));
                out.println(line);
            } else {
                out.print(InspectCommand.text(entry.shown(), model, millis, caps));
            }
            out.flush();
            loaded++;
        } catch (OutOfMemoryError e) {
            // This file's model is garbage now; the next file starts with the memory free again.
            fail(entry, name, OUT_OF_MEMORY);
        } catch (Exception | StackOverflowError | AssertionError e) {
            fail(entry, name, "internal error: " + SkinlabCommand.oneLine(String.valueOf(e)));
        }
    }

    /** Why a path cannot be imported before trying (so a pipe or device named .dae is never opened), or null. */
    private static String notAFile(Path path) {
        if (!Files.exists(path)) {
            return Files.isSymbolicLink(path) ? "broken symbolic link" : "file not found";
        }
        if (Files.isDirectory(path)) {
            return "is a folder, not a COLLADA file";
        }
        if (!Files.isRegularFile(path)) {
            return "not a regular file";
        }
        return null;
    }

    private void refuse(ModelFileSearch.Entry entry, String message, String detail) {
        refused++;
        report(entry, message, detail);
    }

    private void fail(ModelFileSearch.Entry entry, String name, String detail) {
        internal++;
        report(entry, name + ": " + detail, detail);
    }

    /** JSON: an error object on stdout, in the file's place. Text: one line on stderr naming the file. */
    private void report(ModelFileSearch.Entry entry, String message, String detail) {
        if (json) {
            ObjectNode error = mapper.createObjectNode();
            error.put("file", entry.shown());
            error.put("error", message);
            out.println(error.toString());
            out.flush();
        } else {
            out.flush();
            err.println("skinlab: " + entry.shown() + ": " + detail);
            err.flush();
        }
    }
}
