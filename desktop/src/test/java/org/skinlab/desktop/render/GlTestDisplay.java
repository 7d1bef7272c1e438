package org.skinlab.desktop.render;

import org.junit.jupiter.api.Assumptions;

/**
 * Tests that open windows need an X display: the build gives them a private Xvfb when none is set
 * (gradle/test-display.gradle); without one, they skip and say so.
 */
public final class GlTestDisplay {
    private GlTestDisplay() {
    }

    public static void assume() {
        Assumptions.assumeTrue(System.getenv("DISPLAY") != null || System.getenv("WAYLAND_DISPLAY") != null,
                "no display for OpenGL tests: install Xvfb (the build then starts one) or set DISPLAY");
    }
}
