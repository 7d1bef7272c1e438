package org.skinlab.desktop.eval;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.cli.SkinlabMain;

/**
 * One {@code skinlab eval --quick} of every section, run once per test JVM and shared by the
 * tests of each section (each test reads its section from it). Its folder is deleted when the JVM
 * exits.
 *
 * <p>The run is a JVM of its own, as {@code skinlab eval} is: a test JVM that has run the other
 * tests' kernels on other shapes carries their profiles, and C2 then compiled some Vector API
 * kernels without removing their boxes, so {@code JitWarmup} waited its longest on every
 * warm-up and the time section took several times as long as on the command line.
 */
final class EvalQuickRun {
    /** The most the run may take: several times its length on the project's loaded 2-core machine. */
    private static final long LIMIT_MINUTES = 30;

    final Path dir;
    final String output;
    final JsonNode results;
    final String readme;

    private static EvalQuickRun run;

    private EvalQuickRun(Path dir, String output, JsonNode results, String readme) {
        this.dir = dir;
        this.output = output;
        this.results = results;
        this.readme = readme;
    }

    static synchronized EvalQuickRun get() {
        if (run == null) {
            try {
                Path dir = Files.createTempDirectory("skinlab-eval-quick");
                Runtime.getRuntime().addShutdownHook(new Thread(() -> delete(dir)));
                String output = eval(dir);
                run = new EvalQuickRun(dir, output, new ObjectMapper().readTree(dir.resolve("results.json").toFile()),
                        Files.readString(dir.resolve("README.md")));
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new AssertionError("interrupted while eval --quick ran", e);
            }
        }
        return run;
    }

    /** {@code skinlab eval --quick --out dir} in a child JVM of this JVM's java, options and class path; its output. */
    private static String eval(Path dir) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>();
        command.add(Path.of(System.getProperty("java.home"), "bin", "java").toString());
        for (String option : ManagementFactory.getRuntimeMXBean().getInputArguments()) {
            // The build's heap, modules and properties; not a debugger or an agent of the test JVM.
            if (!option.startsWith("-javaagent") && !option.startsWith("-agentlib") && !option.startsWith("-Xrunjdwp")) {
                command.add(option);
            }
        }
        command.addAll(List.of("-cp", System.getProperty("java.class.path"), SkinlabMain.class.getName(), "eval",
                "--quick", "--out", dir.toString()));
        Path log = dir.resolveSibling(dir.getFileName() + ".log");
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile());
        pb.directory(Cli.root().toFile());
        Process p = pb.start();
        try {
            boolean ended = p.waitFor(LIMIT_MINUTES, TimeUnit.MINUTES);
            String output = Files.readString(log);
            assertTrue(ended, "eval --quick did not end within " + LIMIT_MINUTES + " minutes:\n" + output);
            assertEquals(ExitCodes.OK, p.exitValue(), output);
            return output;
        } finally {
            p.destroyForcibly();
            Files.deleteIfExists(log);
        }
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
