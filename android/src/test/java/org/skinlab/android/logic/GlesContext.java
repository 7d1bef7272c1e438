package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assumptions.assumeTrue;
import static org.lwjgl.glfw.GLFW.*;

import org.lwjgl.opengles.GLES;
import org.lwjgl.opengles.GLESCapabilities;

/**
 * An invisible window with a current OpenGL ES 3.0 context (GLFW over EGL; Mesa's llvmpipe under
 * Xvfb here), for the tests that run the app's shaders. Where none can be had (no display, no
 * ES 3.0) opening it aborts the calling test as skipped, saying why.
 */
final class GlesContext implements AutoCloseable {
    private final long window;
    private final GLESCapabilities capabilities;

    private GlesContext(long window, GLESCapabilities capabilities) {
        this.window = window;
        this.capabilities = capabilities;
    }

    static GlesContext openOrSkip() {
        assumeTrue(System.getenv("DISPLAY") != null, "no display for an OpenGL ES context (install Xvfb)");
        glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_X11);
        assumeTrue(glfwInit(), "GLFW does not start");
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
        glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
        glfwWindowHint(GLFW_CONTEXT_CREATION_API, GLFW_EGL_CONTEXT_API);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
        long window = glfwCreateWindow(64, 64, "gles", 0, 0);
        if (window == 0) {
            glfwTerminate();
        }
        assumeTrue(window != 0, "no OpenGL ES 3.0 context here");
        glfwMakeContextCurrent(window);
        return new GlesContext(window, GLES.createCapabilities());
    }

    GLESCapabilities capabilities() {
        return capabilities;
    }

    @Override
    public void close() {
        GLES.setCapabilities(null);
        glfwDestroyWindow(window);
        glfwTerminate();
    }
}
