package org.skinlab.desktop.render;

import static org.lwjgl.opengl.GL33C.*;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;

import org.skinlab.ar.LensGlsl;
import org.skinlab.internal.scene.ColourRamp;
import org.skinlab.internal.scene.MaterialGlsl;
import org.skinlab.skinning.SkinningGlsl;

/**
 * A linked GLSL program built from shader resources next to this class
 * ({@code shaders/NAME.vert}, {@code shaders/NAME.frag}), the skinning formulas put in for a line
 * {@code #include "skinning.glsl"} ({@link SkinningGlsl}), the lens' for
 * {@code #include "lens.glsl"} ({@link LensGlsl}), the materials' for
 * {@code #include "material.glsl"} ({@link MaterialGlsl}) and the data views' colour map for
 * {@code #include "colour-ramp.glsl"} ({@link ColourRamp}). Compile and link failures throw with
 * the resource name and the driver's log, so a broken shader says where it broke.
 */
public final class ShaderProgram implements AutoCloseable {
    private final String name;
    private final int program;

    private ShaderProgram(String name, int program) {
        this.name = name;
        this.program = program;
    }

    /** Builds {@code shaders/vertex.vert} and {@code shaders/fragment.frag}. */
    public static ShaderProgram load(String vertex, String fragment) {
        return load(vertex, fragment, new String[0]);
    }

    /**
     * As {@link #load(String, String)}, recording {@code feedbackVaryings} (interleaved) for
     * transform feedback; they must be named before linking.
     */
    public static ShaderProgram load(String vertex, String fragment, String... feedbackVaryings) {
        int vs = compile(GL_VERTEX_SHADER, vertex + ".vert");
        int fs = compile(GL_FRAGMENT_SHADER, fragment + ".frag");
        int program = glCreateProgram();
        glAttachShader(program, vs);
        glAttachShader(program, fs);
        if (feedbackVaryings.length > 0) {
            glTransformFeedbackVaryings(program, feedbackVaryings, GL_INTERLEAVED_ATTRIBS);
        }
        glLinkProgram(program);
        glDetachShader(program, vs);
        glDetachShader(program, fs);
        glDeleteShader(vs);
        glDeleteShader(fs);
        String label = vertex + ".vert + " + fragment + ".frag";
        if (glGetProgrami(program, GL_LINK_STATUS) != GL_TRUE) {
            String log = glGetProgramInfoLog(program);
            glDeleteProgram(program);
            throw new IllegalStateException("shaders " + label + " do not link: " + log.trim());
        }
        return new ShaderProgram(label, program);
    }

    private static int compile(int type, String resource) {
        String source = ColourRamp.expand(MaterialGlsl.expand(LensGlsl.expand(SkinningGlsl.expand(
                read("shaders/" + resource)))));
        int shader = glCreateShader(type);
        glShaderSource(shader, source);
        glCompileShader(shader);
        if (glGetShaderi(shader, GL_COMPILE_STATUS) != GL_TRUE) {
            String log = glGetShaderInfoLog(shader);
            glDeleteShader(shader);
            throw new IllegalStateException("shader " + resource + " does not compile: " + log.trim());
        }
        return shader;
    }

    private static String read(String resource) {
        try (InputStream in = ShaderProgram.class.getResourceAsStream(resource)) {
            if (in == null) {
                throw new IllegalStateException("shader resource " + resource + " is missing from the classpath");
            }
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read shader resource " + resource, e);
        }
    }

    public int id() {
        return program;
    }

    /** The location of uniform {@code uniform}, or -1 when the linker removed it as unused. */
    public int uniform(String uniform) {
        return glGetUniformLocation(program, uniform);
    }

    public void use() {
        glUseProgram(program);
    }

    @Override
    public void close() {
        glDeleteProgram(program);
    }

    @Override
    public String toString() {
        return "ShaderProgram[" + name + "]";
    }
}
