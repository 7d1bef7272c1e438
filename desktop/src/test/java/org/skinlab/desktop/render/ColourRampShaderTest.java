package org.skinlab.desktop.render;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.lwjgl.opengl.GL33C.*;

import java.nio.ByteBuffer;

import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;
import org.skinlab.internal.scene.ColourRamp;

/**
 * The colours the GPU draws for the colour map are the ones {@link ColourRamp#colour(double)} gives
 * Java code (a legend beside a picture): a strip whose columns run through the map from -0.1 to
 * 1.1 (both clamped ends included), drawn by a program built as the viewer builds its own
 * ({@link ShaderProgram}, which puts the generated {@code colour-ramp.glsl} in), is read back and
 * each column compared with the Java colour at the column's centre. Both mix the same stops in
 * single precision; the framebuffer rounds to 8 bits, so one level apart is allowed.
 */
class ColourRampShaderTest {
    private static final int WIDTH = 240;
    private static final int HEIGHT = 4;
    private static final float FROM = -0.1f;
    private static final float TO = 1.1f;

    private static GlWindow window;

    @BeforeAll
    static void open() {
        GlTestDisplay.assume();
        window = GlTestDisplay.window("ColourRampShaderTest", WIDTH, HEIGHT, false);
    }

    @AfterAll
    static void close() {
        if (window != null) {
            window.close();
        }
    }

    @Test
    void everyColumnIsTheJavaColourToOneLevel() {
        int[] size = new int[2];
        window.framebufferSize(size);
        int w = size[0];
        int h = size[1];
        int vao = glGenVertexArrays();
        try (ShaderProgram program = ShaderProgram.load("colour-ramp-strip", "colour-ramp-strip")) {
            glViewport(0, 0, w, h);
            glDisable(GL_DEPTH_TEST);
            glDisable(GL_BLEND);
            glClearColor(0f, 0f, 0f, 1f);
            glClear(GL_COLOR_BUFFER_BIT);
            program.use();
            glUniform1f(program.uniform("uFrom"), FROM);
            glUniform1f(program.uniform("uTo"), TO);
            glBindVertexArray(vao);
            glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
            assertEquals(GL_NO_ERROR, glGetError());
            ByteBuffer rgba = Screenshot.read(0, 0, w, h);
            try {
                int worst = 0;
                String where = "";
                for (int x = 0; x < w; x++) {
                    double fraction = FROM + (TO - FROM) * (x + 0.5) / w;
                    int expected = ColourRamp.colour(fraction);
                    int o = 4 * ((h / 2) * w + x);
                    for (int c = 0; c < 3; c++) {
                        int drawn = rgba.get(o + c) & 0xFF;
                        int want = expected >> (16 - 8 * c) & 0xFF;
                        if (Math.abs(drawn - want) > worst) {
                            worst = Math.abs(drawn - want);
                            where = "column " + x + " (fraction " + fraction + "), channel " + c + ": drawn " + drawn
                                    + ", Java " + want;
                        }
                    }
                }
                assertEquals(0, Math.max(0, worst - 1), "largest difference " + worst + " levels at " + where);
            } finally {
                MemoryUtil.memFree(rgba);
            }
        } finally {
            glBindVertexArray(0);
            glDeleteVertexArrays(vao);
        }
    }
}
