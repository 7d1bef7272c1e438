package org.skinlab.desktop.launch;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;

/** Runs a command with a clean environment (only PATH, HOME and what the test gives) and keeps its output. */
final class Shell {
    final int status;
    final String out;
    final String err;

    private Shell(int status, String out, String err) {
        this.status = status;
        this.out = out;
        this.err = err;
    }

    /** The repository root, which the build passes as {@code skinlab.root}. */
    static Path root() {
        String root = System.getProperty("skinlab.root");
        assertTrue(root != null, "the build passes the repository root as the system property skinlab.root");
        return Path.of(root);
    }

    /** Aborts the calling test (reported as skipped) where there is no POSIX shell. */
    static void assumeShell() {
        assumeTrue(Files.isExecutable(Path.of("/bin/sh")), "no /bin/sh: start-script test skipped");
    }

    static Shell run(List<String> command, Map<String, String> env, Path home) throws IOException,
            InterruptedException {
        ProcessBuilder builder = new ProcessBuilder(command);
        builder.environment().clear();
        builder.environment().put("PATH", System.getenv().getOrDefault("PATH", "/usr/bin:/bin"));
        builder.environment().put("HOME", home.toString());
        builder.environment().putAll(env);
        builder.directory(root().toFile());
        Process p = builder.start();
        p.getOutputStream().close();
        CompletableFuture<String> err = CompletableFuture.supplyAsync(() -> text(p.getErrorStream()));
        String out = text(p.getInputStream());
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), () -> "still running after 60 s: " + command);
        return new Shell(p.exitValue(), out, err.join());
    }

    private static String text(InputStream in) {
        try (in) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    List<String> outLines() {
        return out.lines().toList();
    }

    List<String> errLines() {
        return err.lines().toList();
    }

    @Override
    public String toString() {
        return "status " + status + "\n--- stdout\n" + out + "--- stderr\n" + err;
    }
}
