package org.skinlab.android.logic;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.lwjgl.opengles.GLES30.*;

/** The GLES tests' one way to build a program from the app's shader texts, failing with GL's log. */
final class GlesPrograms {
    private GlesPrograms() {
    }

    /**
     * Compiles and links {@code vertex} and {@code fragment} in the current context, capturing the
     * given varyings interleaved by transform feedback when there are any.
     */
    static int link(String vertex, String fragment, CharSequence... feedbackVaryings) {
        int p = glCreateProgram();
        int[] shaders = {compile(GL_VERTEX_SHADER, vertex), compile(GL_FRAGMENT_SHADER, fragment)};
        for (int s : shaders) {
            glAttachShader(p, s);
        }
        if (feedbackVaryings.length > 0) {
            glTransformFeedbackVaryings(p, feedbackVaryings, GL_INTERLEAVED_ATTRIBS);
        }
        glLinkProgram(p);
        for (int s : shaders) {
            glDetachShader(p, s);
            glDeleteShader(s);
        }
        assertEquals(GL_TRUE, glGetProgrami(p, GL_LINK_STATUS), () -> "link: " + glGetProgramInfoLog(p));
        return p;
    }

    private static int compile(int type, String source) {
        int s = glCreateShader(type);
        glShaderSource(s, source);
        glCompileShader(s);
        assertEquals(GL_TRUE, glGetShaderi(s, GL_COMPILE_STATUS), () -> "compile: " + glGetShaderInfoLog(s));
        return s;
    }
}
