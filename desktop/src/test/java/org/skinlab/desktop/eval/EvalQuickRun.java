package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;

/**
 * One {@code skinlab eval --quick} of every section, run once per test JVM and shared by the
 * tests of each section (the run takes one to two minutes on the project's 2-core machine; each
 * test reads its section from it). Its folder is deleted when the JVM exits.
 */
final class EvalQuickRun {
    final Path dir;
    final Cli cli;
    final JsonNode results;
    final String readme;

    private static EvalQuickRun run;

    private EvalQuickRun(Path dir, Cli cli, JsonNode results, String readme) {
        this.dir = dir;
        this.cli = cli;
        this.results = results;
        this.readme = readme;
    }

    static synchronized EvalQuickRun get() {
        if (run == null) {
            try {
                Path dir = Files.createTempDirectory("skinlab-eval-quick");
                Runtime.getRuntime().addShutdownHook(new Thread(() -> delete(dir)));
                Cli cli = Cli.run("eval", "--quick", "--out", dir.toString());
                assertEquals(ExitCodes.OK, cli.status, cli.err);
                run = new EvalQuickRun(dir, cli, new ObjectMapper().readTree(dir.resolve("results.json").toFile()),
                        Files.readString(dir.resolve("README.md")));
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        }
        return run;
    }

    /** The results of section {@code key}. */
    JsonNode section(String key) {
        JsonNode s = results.at("/sections/" + key);
        if (s.isMissingNode()) {
            throw new AssertionError("no section " + key + " in " + results.get("sections").fieldNames());
        }
        return s;
    }

    private static void delete(Path dir) {
        try (Stream<Path> files = Files.walk(dir)) {
            files.sorted(Comparator.reverseOrder()).forEach(f -> f.toFile().delete());
        } catch (IOException e) {
            // A temporary folder left behind is harmless.
        }
    }
}
