package org.skinlab.testing;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Optional;

/**
 * Where tests find the repository and the shared folder beside it. The build passes
 * {@code skinlab.root} and {@code skinlab.shared}; run from an IDE, the paths are found by walking
 * up from the working directory to the folder that holds {@code settings.gradle}.
 */
public final class TestPaths {
    private TestPaths() {
    }

    /** The repository root. */
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

    /** The shared folder ({@code ../shared} beside the repository). */
    public static Path shared() {
        String p = System.getProperty("skinlab.shared");
        return p != null ? Path.of(p) : root().resolve("../shared").normalize();
    }

    /** A file of our own assets, e.g. {@code asset("characters/humanoid-walk.dae")}. */
    public static Path asset(String relative) {
        return root().resolve("assets").resolve(relative);
    }

    /**
     * The third-party corpus folder; aborts the calling test (reported as skipped, with the
     * reason) when it is absent.
     */
    public static Path corpusOrSkip() {
        Path corpus = corpus();
        assumeTrue(Files.isDirectory(corpus), () -> "shared corpus not found at " + corpus
                + ": third-party conformance tests skipped");
        return corpus;
    }

    /**
     * One corpus file, or empty when the corpus is absent. Fails when the corpus is there but
     * lacks the file: a broken corpus must not pass for an absent one.
     */
    public static Optional<Path> corpusFile(String name) {
        Path corpus = corpus();
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

    private static Path corpus() {
        return shared().resolve("corpus");
    }
}
