package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.opengles.GLES30.*;

import org.junit.jupiter.api.Test;
import org.lwjgl.opengles.GLES;
import org.lwjgl.opengles.GLESCapabilities;

/**
 * The app's GLSL ES 3.00 shaders compile and link on a real OpenGL ES 3 implementation: Mesa's
 * (llvmpipe, through EGL under Xvfb), the one here; a phone's driver may still differ, but syntax,
 * types and the ES 3.00 rules are checked. The camera background needs
 * GL_OES_EGL_image_external_essl3, which a desktop Mesa may lack: then that pair skips, saying so.
 */
class GlesShadersTest {
    @Test
    void theShadersCompileAndLinkOnOpenGlEs3() {
        assumeTrue(System.getenv("DISPLAY") != null, "no display for an OpenGL ES context (install Xvfb)");
        glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_X11);
        assumeTrue(glfwInit(), "GLFW does not start");
        try {
            glfwDefaultWindowHints();
            glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
            glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
            glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
            glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
            glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
            long window = glfwCreateWindow(64, 64, "gles", 0, 0);
            assumeTrue(window != 0, "no OpenGL ES 3.0 context here");
            try {
                glfwMakeContextCurrent(window);
                GLESCapabilities caps = GLES.createCapabilities();
                assertEquals(0, link(GlesShaders.skinnedVertex(), GlesShaders.SKINNED_FRAGMENT).length(),
                        "skinning program");
                if (caps.GL_OES_EGL_image_external_essl3) {
                    assertEquals(0, link(GlesShaders.BACKGROUND_VERTEX, GlesShaders.BACKGROUND_FRAGMENT).length(),
                            "background program");
                } else {
                    System.out.println("GlesShadersTest: no GL_OES_EGL_image_external_essl3 here: the camera "
                            + "background shader is not compiled (phones have it)");
                }
            } finally {
                GLES.setCapabilities(null);
                glfwDestroyWindow(window);
            }
        } finally {
            glfwTerminate();
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
