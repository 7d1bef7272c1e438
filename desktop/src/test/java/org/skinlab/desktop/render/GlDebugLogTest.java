package org.skinlab.desktop.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengl.GL33C.*;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;

/** The debug log hears the driver: a provoked error is counted, a clean draw is not. */
class GlDebugLogTest {
    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    @Test
    void countsErrorsAndNothingElse() {
        try (GlWindow window = new GlWindow("test", 64, 64, false, true)) {
            GlDebugLog log = GlDebugLog.install(window.capabilities());
            assertNotNull(log, "Mesa's llvmpipe has OpenGL 4.5 with KHR_debug");
            try (log) {
                glClear(GL_COLOR_BUFFER_BIT);
                assertEquals(0, log.errorCount(), log.messages().toString());
                glBindTexture(0x1234, 0);
                assertEquals(1, log.errorCount());
                assertTrue(log.messages().get(0).length() > 0);
            }
        }
    }
}
