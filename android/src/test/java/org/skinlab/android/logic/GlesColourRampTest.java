package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.lwjgl.opengles.GLES30.*;

import java.nio.ByteBuffer;

import org.junit.jupiter.api.Test;
import org.lwjgl.system.MemoryUtil;
import org.skinlab.internal.scene.ColourRamp;

/**
 * Core's colour map ({@link ColourRamp}, the desktop viewer's weight and difference views) is
 * shared GLSL that must also compile as GLSL ES 3.00, with the default {@code mediump} float of an
 * app's fragment shader: on a real OpenGL ES 3.0 (Mesa's llvmpipe) a strip whose columns run
 * through the map from -0.1 to 1.1 draws {@link ColourRamp#colour(double)}'s colours to one 8-bit
 * level.
 */
class GlesColourRampTest {
    private static final int W = 240;
    private static final float FROM = -0.1f;
    private static final float TO = 1.1f;

    private static final String VERTEX = """
            #version 300 es
            uniform float uFrom;
            uniform float uTo;
            out float vFraction;
            void main() {
                vec2 corner = vec2(float(gl_VertexID & 1), float(gl_VertexID >> 1));
                vFraction = mix(uFrom, uTo, corner.x);
                gl_Position = vec4(corner * 2.0 - 1.0, 0.0, 1.0);
            }
            """;

    private static final String FRAGMENT = """
            #version 300 es
            precision mediump float;
            in float vFraction;
            out vec4 color;

            #include "colour-ramp.glsl"

            void main() {
                color = vec4(colourRamp(vFraction), 1.0);
            }
            """;

    @Test
    void theStripDrawsTheJavaColours() {
        try (GlesContext context = GlesContext.openOrSkip()) {
            assertTrue(context.capabilities().GLES30, "an OpenGL ES 3.0 context");
            int program = GlesPrograms.link(VERTEX, ColourRamp.expand(FRAGMENT));
            int target = glGenTextures();
            glBindTexture(GL_TEXTURE_2D, target);
            glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, W, 1, 0, GL_RGBA, GL_UNSIGNED_BYTE, (ByteBuffer) null);
            int fbo = glGenFramebuffers();
            glBindFramebuffer(GL_FRAMEBUFFER, fbo);
            glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target, 0);
            assertEquals(GL_FRAMEBUFFER_COMPLETE, glCheckFramebufferStatus(GL_FRAMEBUFFER));
            glViewport(0, 0, W, 1);
            glUseProgram(program);
            glUniform1f(glGetUniformLocation(program, "uFrom"), FROM);
            glUniform1f(glGetUniformLocation(program, "uTo"), TO);
            int vao = glGenVertexArrays();
            glBindVertexArray(vao);
            glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
            ByteBuffer read = MemoryUtil.memAlloc(4 * W);
            try {
                glPixelStorei(GL_PACK_ALIGNMENT, 1);
                glReadPixels(0, 0, W, 1, GL_RGBA, GL_UNSIGNED_BYTE, read);
                assertEquals(GL_NO_ERROR, glGetError());
                int worst = 0;
                for (int x = 0; x < W; x++) {
                    int expected = ColourRamp.colour(FROM + (TO - FROM) * (x + 0.5) / W);
                    for (int c = 0; c < 3; c++) {
                        int drawn = read.get(4 * x + c) & 0xFF;
                        worst = Math.max(worst, Math.abs(drawn - (expected >> (16 - 8 * c) & 0xFF)));
                    }
                }
                assertEquals(0, Math.max(0, worst - 1), "largest difference " + worst + " levels");
            } finally {
                MemoryUtil.memFree(read);
                glDeleteVertexArrays(vao);
                glDeleteFramebuffers(fbo);
                glDeleteTextures(target);
                glDeleteProgram(program);
            }
        }
    }
}
