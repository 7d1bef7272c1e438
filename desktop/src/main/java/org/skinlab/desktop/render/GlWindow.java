package org.skinlab.desktop.render;

import static org.lwjgl.glfw.GLFW.*;
import static org.lwjgl.system.MemoryUtil.NULL;


import org.lwjgl.glfw.GLFWErrorCallback;
import org.lwjgl.opengl.GL;
import org.lwjgl.opengl.GLCapabilities;
import org.lwjgl.system.MemoryStack;

/**
 * The GLFW window with an OpenGL 3.3 core, forward-compatible context (what macOS needs too),
 * current on the creating thread. A context that cannot be made throws
 * {@link WindowUnavailableException} with one line for the user (the GLFW error, and what to try),
 * not a stack trace.
 */
public final class GlWindow implements AutoCloseable {
    private final long handle;
    private final GLCapabilities capabilities;
    private final GLFWErrorCallback errorCallback;
    private final boolean debugContext;
    private final int[] width = new int[1];
    private final int[] height = new int[1];

    /** Raised when no window or no OpenGL 3.3 core context can be had. */
    public static final class WindowUnavailableException extends RuntimeException {
        private static final long serialVersionUID = 1L;

        WindowUnavailableException(String message) {
            super(message);
        }
    }

    /**
     * @param visible false for an off-screen window (headless screenshots, benchmarks)
     * @param debug   ask for a debug context (GL errors reported by the driver)
     */
    public GlWindow(String title, int width, int height, boolean visible, boolean debug) {
        StringBuilder lastError = new StringBuilder();
        errorCallback = GLFWErrorCallback.create((code, description) -> {
            lastError.setLength(0);
            lastError.append(GLFWErrorCallback.getDescription(description));
        });
        glfwSetErrorCallback(errorCallback);
        // X11 first: GLFW 3.4+ probes Wayland otherwise and complains without XDG_RUNTIME_DIR.
        if (glfwPlatformSupported(GLFW_PLATFORM_X11) && System.getenv("WAYLAND_DISPLAY") == null) {
            glfwInitHint(GLFW_PLATFORM, GLFW_PLATFORM_X11);
        }
        if (!glfwInit()) {
            glfwSetErrorCallback(null);
            errorCallback.free();
            throw new WindowUnavailableException("cannot start GLFW: " + orUnknown(lastError)
                    + display() + ". Without a screen, run it under xvfb-run (e.g. xvfb-run -a skinlab view --screenshot"
                    + " OUT.png)");
        }
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_VISIBLE, visible ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, debug ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
        glfwWindowHint(GLFW_SAMPLES, 4);
        long window = glfwCreateWindow(width, height, title, NULL, NULL);
        if (window == NULL) {
            glfwTerminate();
            glfwSetErrorCallback(null);
            errorCallback.free();
            throw new WindowUnavailableException("cannot open an OpenGL 3.3 core window: " + orUnknown(lastError)
                    + display() + ". skinlab needs OpenGL 3.3; for headless use run it under xvfb-run"
                    + " (Mesa's llvmpipe has OpenGL 4.5)");
        }
        handle = window;
        debugContext = debug;
        glfwMakeContextCurrent(window);
        capabilities = GL.createCapabilities();
    }

    private static String orUnknown(CharSequence s) {
        return s.length() == 0 ? "no reason given" : s.toString();
    }

    private static String display() {
        String d = System.getenv("DISPLAY");
        String w = System.getenv("WAYLAND_DISPLAY");
        return d == null && w == null ? " (no DISPLAY is set)" : "";
    }

    public long handle() {
        return handle;
    }

    public GLCapabilities capabilities() {
        return capabilities;
    }

    public boolean isDebugContext() {
        return debugContext;
    }

    /** Framebuffer size in pixels (differs from the window size on HiDPI screens). */
    public void framebufferSize(int[] widthHeight) {
        glfwGetFramebufferSize(handle, width, height);
        widthHeight[0] = width[0];
        widthHeight[1] = height[0];
    }

    /** The monitor's content scale (UI scale on HiDPI screens), at least 1. */
    public float contentScale() {
        try (MemoryStack stack = MemoryStack.stackPush()) {
            java.nio.FloatBuffer x = stack.mallocFloat(1);
            java.nio.FloatBuffer y = stack.mallocFloat(1);
            glfwGetWindowContentScale(handle, x, y);
            float s = Math.max(x.get(0), y.get(0));
            return s >= 1f && s < 8f ? s : 1f;
        }
    }

    public boolean shouldClose() {
        return glfwWindowShouldClose(handle);
    }

    public void requestClose() {
        glfwSetWindowShouldClose(handle, true);
    }

    public void swapBuffers() {
        glfwSwapBuffers(handle);
    }

    public void setTitle(String title) {
        glfwSetWindowTitle(handle, title);
    }

    @Override
    public void close() {
        GL.setCapabilities(null);
        glfwDestroyWindow(handle);
        glfwTerminate();
        GLFWErrorCallback cb = glfwSetErrorCallback(null);
        if (cb != null) {
            cb.free();
        }
    }
}
