package org.skinlab.desktop.render;

import static org.lwjgl.opengl.GL33C.*;

import java.nio.FloatBuffer;

import org.joml.Vector4f;
import org.joml.Vector4fc;
import org.lwjgl.system.MemoryUtil;

/**
 * The floor the model stands on: a grid of lines on y = 0 centred under it, fading out towards its
 * rim, so "upright, feet on the floor" is visible at a glance.
 */
public final class FloorGrid implements AutoCloseable {
    /**
     * The lines' colour and opacity at the centre (0-1; fading to 0 at the rim), blended over the
     * background: what tells floor pixels from the model's in a picture.
     */
    public static final Vector4fc COLOR = new Vector4f(0.55f, 0.58f, 0.65f, 0.45f);
    /** Lines per direction. */
    private static final int LINES = 21;

    private final ShaderProgram program;
    private final int vao;
    private final int vbo;
    private final int viewProjection;
    private final int extent;
    private final int centre;
    private final int color;
    private final FloatBuffer matrix = MemoryUtil.memAllocFloat(16);

    public FloorGrid() {
        FloatBuffer lines = MemoryUtil.memAllocFloat(2 * 2 * 2 * LINES);
        try {
            for (int i = 0; i < LINES; i++) {
                float t = -1f + 2f * i / (LINES - 1);
                lines.put(t).put(-1f).put(t).put(1f);
                lines.put(-1f).put(t).put(1f).put(t);
            }
            lines.flip();
            vao = glGenVertexArrays();
            vbo = glGenBuffers();
            glBindVertexArray(vao);
            glBindBuffer(GL_ARRAY_BUFFER, vbo);
            glBufferData(GL_ARRAY_BUFFER, lines, GL_STATIC_DRAW);
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 2, GL_FLOAT, false, 0, 0L);
            glBindVertexArray(0);
            glBindBuffer(GL_ARRAY_BUFFER, 0);
        } finally {
            MemoryUtil.memFree(lines);
        }
        program = ShaderProgram.load("floor", "floor");
        viewProjection = program.uniform("uViewProjection");
        extent = program.uniform("uExtent");
        centre = program.uniform("uCentre");
        color = program.uniform("uColor");
    }

    /**
     * The distance between neighbouring lines of a grid {@code halfExtent} wide each way: a grid
     * that moves by whole multiples of it looks still (a travelling model's floor).
     */
    public static float lineSpacing(float halfExtent) {
        return 2f * halfExtent / (LINES - 1);
    }

    /** Draws the grid, {@code halfExtent} wide each way, under the scene point (x, z). */
    public void draw(DrawSettings s, float x, float z, float halfExtent) {
        program.use();
        glUniformMatrix4fv(viewProjection, false, s.viewProjection.get(matrix));
        glUniform1f(extent, halfExtent);
        glUniform3f(centre, x, 0f, z);
        glUniform4f(color, COLOR.x(), COLOR.y(), COLOR.z(), COLOR.w());
        glBindVertexArray(vao);
        glDrawArrays(GL_LINES, 0, 4 * LINES);
        glBindVertexArray(0);
    }

    @Override
    public void close() {
        glDeleteVertexArrays(vao);
        glDeleteBuffers(vbo);
        program.close();
        MemoryUtil.memFree(matrix);
    }
}
