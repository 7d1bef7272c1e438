package org.skinlab.android;

import static android.opengl.GLES30.*;

/** Compiles and links a shader program; a failure throws with the driver's log. */
final class GlProgram {
    private GlProgram() {
    }

    static int link(String vertex, String fragment) {
        int program = glCreateProgram();
        glAttachShader(program, compile(GL_VERTEX_SHADER, vertex));
        glAttachShader(program, compile(GL_FRAGMENT_SHADER, fragment));
        glLinkProgram(program);
        int[] ok = new int[1];
        glGetProgramiv(program, GL_LINK_STATUS, ok, 0);
        if (ok[0] == 0) {
            throw new IllegalStateException("shader program does not link: " + glGetProgramInfoLog(program));
        }
        return program;
    }

    private static int compile(int type, String source) {
        int shader = glCreateShader(type);
        glShaderSource(shader, source);
        glCompileShader(shader);
        int[] ok = new int[1];
        glGetShaderiv(shader, GL_COMPILE_STATUS, ok, 0);
        if (ok[0] == 0) {
            throw new IllegalStateException("shader does not compile: " + glGetShaderInfoLog(shader));
        }
        return shader;
    }
}
