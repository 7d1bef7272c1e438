package org.skinlab.desktop.eval;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.Paths;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;

/**
 * One picture by the viewer's own headless path, {@code skinlab view FILE --screenshot OUT.png
 * --hide-ui}, run in a child JVM: this JVM's {@code java} ({@code java.home}) and class path,
 * so the child runs the same build. A child per picture rather than the window in this JVM, since
 * the evaluation draws many pictures in one run: the window initialises and terminates GLFW, which
 * is process-wide state (on macOS tied to the main thread), so a child leaves the evaluation's JVM
 * (and a test's) untouched; a crash in native driver code costs one picture, not the run; a hung
 * driver is killed after {@value #TIMEOUT_SECONDS} s; and each picture is exactly what a user's
 * {@code skinlab view} command writes. The price is a JVM start per picture (about 2 s here,
 * with Mesa's software renderer).
 */
final class ViewerProcess {
    /** A picture that takes longer is given up (a software renderer draws ours in about a second). */
    static final int TIMEOUT_SECONDS = 120;
    /** Lines of the child's output kept for the message of a failure. */
    private static final int KEPT_LINES = 3;

    /** The class whose {@code main} runs {@code skinlab}'s commands. */
    private final Class<?> skinlabMain;

    ViewerProcess(Class<?> skinlabMain) {
        this.skinlabMain = skinlabMain;
    }

    /** Whether a window can be opened at all: an X or Wayland display is set. */
    static boolean displayAvailable() {
        return System.getenv("DISPLAY") != null || System.getenv("WAYLAND_DISPLAY") != null;
    }

    /**
     * Renders {@code file} with {@code viewArguments} (e.g. "--method", "lbs", "--time", "4")
     * at {@code width x height} into {@code png}; returns null when written, else why not (one line).
     */
    String screenshot(Path file, List<String> viewArguments, int width, int height, Path png) {
        List<String> command = new ArrayList<>();
        command.add(Paths.get(System.getProperty("java.home"), "bin", "java").toString());
        // A short-lived child: a small heap, the quick JIT tier, no parallel collector threads.
        command.addAll(List.of("-Xmx768m", "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", "-cp",
                System.getProperty("java.class.path"), skinlabMain.getName(), "view", file.toString()));
        command.addAll(viewArguments);
        command.addAll(List.of("--size", width + "x" + height, "--hide-ui", "--screenshot", png.toString()));
        Path log = null;
        Process p = null;
        try {
            // A picture left by an earlier call must not pass for this one's.
            Files.deleteIfExists(png);
            log = Files.createTempFile("skinlab-view", ".log");
            p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile()).start();
            if (!p.waitFor(TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
                return "skinlab view did not finish in " + TIMEOUT_SECONDS + " s";
            }
            if (p.exitValue() != 0 || !Files.isRegularFile(png)) {
                return "skinlab view failed (status " + p.exitValue() + "): " + lastLines(log);
            }
            return null;
        } catch (IOException e) {
            return "cannot start skinlab view: " + e.getMessage();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "interrupted";
        } finally {
            if (p != null && p.isAlive()) {
                p.destroyForcibly();
            }
            if (log != null) {
                try {
                    Files.deleteIfExists(log);
                } catch (IOException e) {
                    // a temporary file left behind: nothing to report
                }
            }
        }
    }

    /** The child's last lines, without the JVM's notes (e.g. on incubator modules). */
    private static String lastLines(Path log) throws IOException {
        List<String> lines = new ArrayList<>();
        for (String line : Files.readAllLines(log, StandardCharsets.UTF_8)) {
            if (!line.isBlank() && !line.startsWith("WARNING:")) {
                lines.add(line.trim());
            }
        }
        if (lines.isEmpty()) {
            return "no message";
        }
        return String.join(" / ", lines.subList(Math.max(0, lines.size() - KEPT_LINES), lines.size()));
    }

    /** A time as {@code --time} takes it: plain decimal, no exponent. */
    static String seconds(double t) {
        return String.format(Locale.ROOT, "%.3f", t);
    }
}
