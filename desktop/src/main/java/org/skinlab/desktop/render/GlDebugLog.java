package org.skinlab.desktop.render;

import static org.lwjgl.opengl.GL43C.*;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import org.lwjgl.opengl.GLCapabilities;
import org.lwjgl.opengl.GLDebugMessageCallback;
import org.lwjgl.opengl.KHRDebug;

/**
 * The driver's error reports in a debug context (OpenGL 4.3 or KHR_debug): errors and
 * undefined-behaviour reports are counted and the first {@value #KEPT} kept; notifications and
 * performance hints are ignored. {@code skinlab view --gl-debug} prints them and fails when there
 * were any. Without a debug context, {@link #check} asks glGetError at chosen places instead.
 */
public final class GlDebugLog implements AutoCloseable {
    static final int KEPT = 100;

    private final GLDebugMessageCallback callback;
    private final List<String> messages = Collections.synchronizedList(new ArrayList<>());
    private volatile int errors;

    private GlDebugLog(GLDebugMessageCallback callback) {
        this.callback = callback;
    }

    /** Installs the log in the current context; null when the context cannot report (no KHR_debug). */
    public static GlDebugLog install(GLCapabilities caps) {
        if (!caps.OpenGL43 && !caps.GL_KHR_debug) {
            return null;
        }
        GlDebugLog[] self = new GlDebugLog[1];
        GLDebugMessageCallback cb = GLDebugMessageCallback.create((source, type, id, severity, length, message,
                user) -> self[0].report(type, severity, GLDebugMessageCallback.getMessage(length, message)));
        self[0] = new GlDebugLog(cb);
        if (caps.OpenGL43) {
            glDebugMessageCallback(cb, 0L);
            glEnable(GL_DEBUG_OUTPUT);
            glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        } else {
            KHRDebug.glDebugMessageCallback(cb, 0L);
            glEnable(KHRDebug.GL_DEBUG_OUTPUT);
            glEnable(KHRDebug.GL_DEBUG_OUTPUT_SYNCHRONOUS);
        }
        return self[0];
    }

    private void report(int type, int severity, String message) {
        boolean error = type == GL_DEBUG_TYPE_ERROR || type == GL_DEBUG_TYPE_UNDEFINED_BEHAVIOR
                || (severity == GL_DEBUG_SEVERITY_HIGH && type != GL_DEBUG_TYPE_PERFORMANCE);
        if (!error) {
            return;
        }
        errors++;
        if (messages.size() < KEPT) {
            messages.add(message.trim());
        }
    }

    public int errorCount() {
        return errors;
    }

    public List<String> messages() {
        synchronized (messages) {
            return List.copyOf(messages);
        }
    }

    /**
     * Throws when GL has recorded errors since the last call (the way to find them without a debug
     * context). Drains every recorded flag, so the next check starts clean.
     *
     * @param where what was just done, for the message
     * @throws IllegalStateException naming {@code where} and the errors, e.g. "GL_INVALID_ENUM"
     */
    public static void check(String where) {
        int error = glGetError();
        if (error == GL_NO_ERROR) {
            return;
        }
        StringBuilder names = new StringBuilder(errorName(error));
        // An implementation may keep one flag per kind of error; a broken context (lost, or none
        // current) keeps reporting, hence the bound.
        for (int i = 0; i < 8 && (error = glGetError()) != GL_NO_ERROR; i++) {
            names.append(", ").append(errorName(error));
        }
        throw new IllegalStateException("OpenGL error after " + where + ": " + names);
    }

    /** The GL name of a glGetError code. */
    public static String errorName(int error) {
        switch (error) {
            case GL_NO_ERROR:
                return "GL_NO_ERROR";
            case GL_INVALID_ENUM:
                return "GL_INVALID_ENUM";
            case GL_INVALID_VALUE:
                return "GL_INVALID_VALUE";
            case GL_INVALID_OPERATION:
                return "GL_INVALID_OPERATION";
            case GL_INVALID_FRAMEBUFFER_OPERATION:
                return "GL_INVALID_FRAMEBUFFER_OPERATION";
            case GL_OUT_OF_MEMORY:
                return "GL_OUT_OF_MEMORY";
            case GL_STACK_UNDERFLOW:
                return "GL_STACK_UNDERFLOW";
            case GL_STACK_OVERFLOW:
                return "GL_STACK_OVERFLOW";
            default:
                return "GL error 0x" + Integer.toHexString(error);
        }
    }

    @Override
    public void close() {
        glDebugMessageCallback(null, 0L);
        callback.free();
    }
}
