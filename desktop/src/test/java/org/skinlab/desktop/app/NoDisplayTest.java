package org.skinlab.desktop.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.skinlab.desktop.ExitCodes;

/**
 * Without a display (or without OpenGL 3.3) the viewer says so in one line and exits with status
 * 1: no stack trace, no hang. Run as a separate process, since the display is the environment's.
 */
class NoDisplayTest {
    @Test
    void aClearLineWhenNoWindowCanBeOpened() throws Exception {
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        ProcessBuilder pb = new ProcessBuilder(List.of(java.toString(), "-cp", System.getProperty("java.class.path"),
                "org.skinlab.desktop.cli.SkinlabMain", "--exit-after-frames", "5"));
        pb.environment().remove("DISPLAY");
        pb.environment().remove("WAYLAND_DISPLAY");
        pb.redirectErrorStream(true);
        pb.directory(new File(System.getProperty("skinlab.root", "..")));
        Process p = pb.start();
        assertTrue(p.waitFor(60, TimeUnit.SECONDS), "the viewer did not give up within a minute");
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertEquals(ExitCodes.UNAVAILABLE, p.exitValue(), output);
        List<String> lines = output.lines().filter(l -> l.startsWith("skinlab:")).toList();
        assertEquals(1, lines.size(), output);
        assertTrue(lines.get(0).contains("no DISPLAY is set"), output);
        assertFalse(output.contains("Exception") || output.contains("\tat "), output);
    }
}
