package org.skinlab.desktop.render;

import org.junit.jupiter.api.Assumptions;

/**
 * Tests that open windows need an X display: the build gives them a private Xvfb when none is set
 * (gradle/test-display.gradle); without one, they skip and say so.
 */
public final class GlTestDisplay {
    private GlTestDisplay() {
    }

    /** Tries to open the display this many times before a test fails. */
    private static final int OPEN_ATTEMPTS = 3;

    public static void assume() {
        Assumptions.assumeTrue(System.getenv("DISPLAY") != null || System.getenv("WAYLAND_DISPLAY") != null,
                "no display for OpenGL tests: install Xvfb (the build then starts one) or set DISPLAY");
    }

    /**
     * A hidden window on the test display. Xvfb on a loaded machine now and then refuses one
     * connection ("Failed to open display") between windows it serves; that refusal, and only
     * it, is tried again, so a test fails on its own problems, not the server's.
     */
    public static GlWindow window(String title, int width, int height, boolean debug) {
        for (int attempt = 1;; attempt++) {
            try {
                return new GlWindow(title, width, height, false, debug);
            } catch (GlWindow.WindowUnavailableException e) {
                if (attempt == OPEN_ATTEMPTS || !String.valueOf(e.getMessage()).contains("Failed to open display")) {
                    throw e;
                }
                pause();
            }
        }
    }

    private static void pause() {
        try {
            Thread.sleep(250);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while waiting for the test display", e);
        }
    }
}
