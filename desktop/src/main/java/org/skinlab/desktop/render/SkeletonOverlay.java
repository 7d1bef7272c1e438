package org.skinlab.desktop.render;

import static org.lwjgl.opengl.GL33C.*;

import java.nio.ByteBuffer;
import java.nio.FloatBuffer;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.lwjgl.system.MemoryUtil;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * The skeleton drawn over the mesh: a point per joint and a line from each joint to its nearest
 * ancestor in the palette, placed on the GPU from the same palette the mesh is skinned with (so
 * the bones can never lag the skin). Drawn without depth test, so it shows through the mesh.
 */
final class SkeletonOverlay implements AutoCloseable {
    private final ShaderProgram program;
    private final int vao;
    private final int vbo;
    private final int pointCount;
    private final int lineVertexCount;
    private final int viewProjection;
    private final int model;
    private final int columns;
    private final int spacing;
    private final int pointSize;
    private final int color;
    private final FloatBuffer matrix = MemoryUtil.memAllocFloat(16);

    SkeletonOverlay(Model scene, SkinnedGeometry geometry) {
        int joints = geometry.jointCount();
        float[] bind = geometry.bindMatrixArray();
        Vector3f[] origins = new Vector3f[joints];
        Matrix4f inverse = new Matrix4f();
        int[] paletteOfNode = new int[scene.nodes().size()];
        java.util.Arrays.fill(paletteOfNode, -1);
        for (int j = 0; j < joints; j++) {
            inverse.set(bind, 16 * j).invert();
            origins[j] = inverse.getTranslation(new Vector3f());
            int node = geometry.jointNode(j);
            if (node >= 0) {
                paletteOfNode[node] = j;
            }
        }
        // Lines: joint -> nearest ancestor node that is in the palette.
        int lines = 0;
        int[] parentOf = new int[joints];
        for (int j = 0; j < joints; j++) {
            parentOf[j] = -1;
            int node = geometry.jointNode(j);
            if (node < 0) {
                continue;
            }
            for (int p = scene.node(node).parent(); p >= 0; p = scene.node(p).parent()) {
                if (paletteOfNode[p] >= 0) {
                    parentOf[j] = paletteOfNode[p];
                    lines++;
                    break;
                }
            }
        }
        pointCount = joints;
        lineVertexCount = 2 * lines;
        int vertices = pointCount + lineVertexCount;
        // 3 floats origin + 1 uint joint per vertex.
        ByteBuffer data = MemoryUtil.memAlloc(16 * Math.max(1, vertices));
        try {
            for (int j = 0; j < joints; j++) {
                put(data, origins[j], j);
            }
            for (int j = 0; j < joints; j++) {
                if (parentOf[j] >= 0) {
                    put(data, origins[parentOf[j]], parentOf[j]);
                    put(data, origins[j], j);
                }
            }
            data.flip();
            vao = glGenVertexArrays();
            vbo = glGenBuffers();
            glBindVertexArray(vao);
            glBindBuffer(GL_ARRAY_BUFFER, vbo);
            glBufferData(GL_ARRAY_BUFFER, data, GL_STATIC_DRAW);
            glEnableVertexAttribArray(0);
            glVertexAttribPointer(0, 3, GL_FLOAT, false, 16, 0L);
            glEnableVertexAttribArray(1);
            glVertexAttribIPointer(1, 1, GL_UNSIGNED_INT, 16, 12L);
            glBindVertexArray(0);
            glBindBuffer(GL_ARRAY_BUFFER, 0);
        } finally {
            MemoryUtil.memFree(data);
        }
        program = ShaderProgram.load("skeleton", "skeleton");
        viewProjection = program.uniform("uViewProjection");
        model = program.uniform("uModel");
        columns = program.uniform("uColumns");
        spacing = program.uniform("uSpacing");
        pointSize = program.uniform("uPointSize");
        color = program.uniform("uColor");
        program.use();
        glUniform1i(program.uniform("uMatrices"), PaletteBuffers.MATRIX_UNIT);
        glUseProgram(0);
    }

    private static void put(ByteBuffer b, Vector3f p, int joint) {
        b.putFloat(p.x).putFloat(p.y).putFloat(p.z).putInt(joint);
    }

    /** Draws with the palette that is bound (the first geometry's). */
    void draw(DrawSettings s) {
        program.use();
        glUniformMatrix4fv(viewProjection, false, s.viewProjection.get(matrix));
        glUniformMatrix4fv(model, false, s.model.get(matrix));
        glUniform1i(columns, s.columns());
        glUniform1f(spacing, s.spacing);
        glDisable(GL_DEPTH_TEST);
        glEnable(GL_PROGRAM_POINT_SIZE);
        glBindVertexArray(vao);
        glUniform4f(color, 1f, 0.85f, 0.2f, 1f);
        glDrawArraysInstanced(GL_LINES, pointCount, lineVertexCount, Math.max(1, s.instances));
        glUniform1f(pointSize, 6f);
        glUniform4f(color, 1f, 0.35f, 0.2f, 1f);
        glDrawArraysInstanced(GL_POINTS, 0, pointCount, Math.max(1, s.instances));
        glBindVertexArray(0);
        glDisable(GL_PROGRAM_POINT_SIZE);
        glEnable(GL_DEPTH_TEST);
    }

    @Override
    public void close() {
        glDeleteVertexArrays(vao);
        glDeleteBuffers(vbo);
        program.close();
        MemoryUtil.memFree(matrix);
    }
}
