package org.skinlab.desktop.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
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
        try (GlWindow window = GlTestDisplay.window("test", 64, 64, true)) {
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

    /** Without a debug context: glGetError at a named place, every recorded error drained. */
    @Test
    void checkNamesThePlaceAndTheError() {
        try (GlWindow window = GlTestDisplay.window("test", 64, 64, false)) {
            assertTrue(!window.isDebugContext());
            GlDebugLog.check("a clear");
            glBindTexture(0x1234, 0);
            IllegalStateException e = assertThrows(IllegalStateException.class,
                    () -> GlDebugLog.check("binding a texture"));
            assertEquals("OpenGL error after binding a texture: GL_INVALID_ENUM", e.getMessage());
            GlDebugLog.check("the check before");
            glBindTexture(0x1234, 0);
            glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, -5);
            e = assertThrows(IllegalStateException.class, () -> GlDebugLog.check("two calls"));
            assertTrue(e.getMessage().startsWith("OpenGL error after two calls: GL_INVALID_ENUM"), e.getMessage());
            GlDebugLog.check("the check before");
        }
        assertEquals("GL_INVALID_FRAMEBUFFER_OPERATION", GlDebugLog.errorName(GL_INVALID_FRAMEBUFFER_OPERATION));
        assertEquals("GL error 0x1234", GlDebugLog.errorName(0x1234));
    }
}
