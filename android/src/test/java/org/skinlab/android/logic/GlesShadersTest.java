package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.lwjgl.opengles.GLES30.*;

import org.junit.jupiter.api.Test;

/**
 * The app's GLSL ES 3.00 shaders compile and link on a real OpenGL ES 3 implementation: Mesa's
 * (llvmpipe, through EGL under Xvfb), the one here; a phone's driver may still differ, but syntax,
 * types and the ES 3.00 rules are checked. The camera background needs
 * GL_OES_EGL_image_external_essl3, which a desktop Mesa may lack: then that pair skips, saying so.
 */
class GlesShadersTest {
    @Test
    void theShadersCompileAndLinkOnOpenGlEs3() {
        try (GlesContext context = GlesContext.openOrSkip()) {
            assertEquals(0, link(GlesShaders.skinnedVertex(), GlesShaders.skinnedFragment()).length(), "skinning program");
            if (context.capabilities().GL_OES_EGL_image_external_essl3) {
                assertEquals(0, link(GlesShaders.BACKGROUND_VERTEX, GlesShaders.backgroundFragment()).length(),
                        "background program");
            } else {
                System.out.println("GlesShadersTest: no GL_OES_EGL_image_external_essl3 here: the camera "
                        + "background shader is not compiled (phones have it)");
            }
        }
    }

    /** The compile or link log of a failure ("" when the program links). */
    private static String link(String vertex, String fragment) {
        int program = glCreateProgram();
        String log = compile(program, GL_VERTEX_SHADER, vertex) + compile(program, GL_FRAGMENT_SHADER, fragment);
        if (!log.isEmpty()) {
            return log;
        }
        glLinkProgram(program);
        return glGetProgrami(program, GL_LINK_STATUS) == GL_TRUE ? "" : "link: " + glGetProgramInfoLog(program);
    }

    private static String compile(int program, int type, String source) {
        int shader = glCreateShader(type);
        glShaderSource(shader, source);
        glCompileShader(shader);
        if (glGetShaderi(shader, GL_COMPILE_STATUS) != GL_TRUE) {
            return (type == GL_VERTEX_SHADER ? "vertex: " : "fragment: ") + glGetShaderInfoLog(shader);
        }
        glAttachShader(program, shader);
        return "";
    }
}
