package org.skinlab.desktop;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

import org.skinlab.desktop.cli.SkinlabCommand;

/**
 * Runs the command line in this JVM and keeps what it printed; where the repository and the shared
 * fixtures are, for the tests of every package.
 */
public final class Cli {
    public final int status;
    public final String out;
    public final String err;

    private Cli(int status, String out, String err) {
        this.status = status;
        this.out = out;
        this.err = err;
    }

    public static Cli run(String... args) {
        StringWriter out = new StringWriter();
        StringWriter err = new StringWriter();
        int status = SkinlabCommand.run(new PrintWriter(out), new PrintWriter(err), args);
        return new Cli(status, out.toString(), err.toString());
    }

    /** The field names of a JSON object, in order. */
    public static java.util.List<String> keys(com.fasterxml.jackson.databind.JsonNode object) {
        java.util.List<String> keys = new java.util.ArrayList<>();
        object.fieldNames().forEachRemaining(keys::add);
        return keys;
    }

    /** The lines printed on stderr. */
    public String[] errLines() {
        return err.lines().toArray(String[]::new);
    }

    @Override
    public String toString() {
        return "status " + status + "\n--- stdout\n" + out + "--- stderr\n" + err;
    }

    /**
     * The repository root: the build passes {@code skinlab.root}; otherwise the folder above the
     * working directory that holds {@code settings.gradle}.
     */
    public static Path root() {
        String p = System.getProperty("skinlab.root");
        if (p != null) {
            return Path.of(p);
        }
        for (Path d = Path.of("").toAbsolutePath(); d != null; d = d.getParent()) {
            if (Files.exists(d.resolve("settings.gradle"))) {
                return d;
            }
        }
        throw new IllegalStateException("cannot find the repository root from " + Path.of("").toAbsolutePath());
    }

    /** The shared folder beside the repository: the build passes {@code skinlab.shared}. */
    public static Path shared() {
        String p = System.getProperty("skinlab.shared");
        return p != null ? Path.of(p) : root().resolve("../shared").normalize();
    }

    /**
     * The third-party corpus folder; aborts the calling test (reported as skipped, with the
     * reason) when it is absent.
     */
    public static Path corpusOrSkip() {
        Path corpus = shared().resolve("corpus");
        assumeTrue(Files.isDirectory(corpus), () -> "shared corpus not found at " + corpus
                + ": third-party corpus test skipped");
        return corpus;
    }

    /**
     * One corpus file, or empty when the corpus is absent. Fails when the corpus is there but
     * lacks the file: a broken corpus must not pass for an absent one.
     */
    public static Optional<Path> corpusFile(String name) {
        Path corpus = shared().resolve("corpus");
        if (!Files.isDirectory(corpus)) {
            return Optional.empty();
        }
        Path file = corpus.resolve(name);
        assertTrue(Files.isRegularFile(file), () -> "the shared corpus at " + corpus + " has no " + name);
        return Optional.of(file);
    }

    /** One corpus file; skips the calling test when the corpus is absent, fails when it lacks the file. */
    public static Path corpusFileOrSkip(String name) {
        corpusOrSkip();
        return corpusFile(name).orElseThrow();
    }

    /** The default asset, as an absolute path. */
    public static Path defaultAsset() {
        return root().resolve("assets/characters/humanoid-walk.dae");
    }
}
