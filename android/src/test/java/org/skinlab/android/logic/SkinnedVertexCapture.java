package org.skinlab.android.logic;

import static org.lwjgl.opengles.GLES30.*;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.ShortBuffer;

import org.skinlab.skinning.InfluenceView;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * One geometry fed to the app's skinning program as the app feeds it, and its output read back:
 * the vertex buffers at {@link GlesShaders}' attribute locations with ModelGl's formats (bind-space
 * positions and normals, the {@value GlesShaders#INFLUENCES}-influence view's joints as unsigned
 * shorts and weights, CoR's centres), the palette in an RGBA32F texture of
 * {@link PaletteTexture#TEXELS_PER_JOINT} texels per joint row with nearest filtering; the render
 * vertices drawn as points with transform feedback recording {@code vEye} and {@code vNormal}
 * (with identity model-view and projection: the skinned position and normal). Needs a current
 * OpenGL ES 3.0 context; close it before the context.
 */
final class SkinnedVertexCapture implements AutoCloseable {
    /** The texture unit the palette is bound to (the app's, ModelGl's GL_TEXTURE1). */
    private static final int PALETTE_UNIT = 1;
    /** Interleaved per vertex: vEye (3 floats), vNormal (3 floats). */
    static final String[] VARYINGS = {"vEye", "vNormal"};

    private final int vertices;
    private final int joints;
    private final int vao;
    private final int[] buffers = new int[6];
    private final int palette;
    private final FloatBuffer paletteData;

    SkinnedVertexCapture(SkinnedGeometry g, InfluenceView view) {
        vertices = g.vertexCount();
        joints = g.jointCount();
        int n = vertices;
        int k = view.influencesPerPoint();
        glGenBuffers(buffers);
        vao = glGenVertexArrays();
        glBindVertexArray(vao);
        floats(buffers[0], g.positionArray(), 3 * n, GlesShaders.POSITION);
        floats(buffers[1], g.normalArray(), 3 * n, GlesShaders.NORMAL);
        ShortBuffer j = ByteBuffer.allocateDirect(Math.max(2, 2 * k * n)).order(ByteOrder.nativeOrder()).asShortBuffer();
        view.putJointIndices(j, n);
        j.flip();
        glBindBuffer(GL_ARRAY_BUFFER, buffers[2]);
        glBufferData(GL_ARRAY_BUFFER, j, GL_STATIC_DRAW);
        glEnableVertexAttribArray(GlesShaders.JOINTS);
        glVertexAttribIPointer(GlesShaders.JOINTS, k, GL_UNSIGNED_SHORT, 2 * k, 0);
        FloatBuffer w = ByteBuffer.allocateDirect(Math.max(4, 4 * k * n)).order(ByteOrder.nativeOrder()).asFloatBuffer();
        view.putWeights(w, n);
        w.flip();
        glBindBuffer(GL_ARRAY_BUFFER, buffers[3]);
        glBufferData(GL_ARRAY_BUFFER, w, GL_STATIC_DRAW);
        glEnableVertexAttribArray(GlesShaders.WEIGHTS);
        glVertexAttribPointer(GlesShaders.WEIGHTS, k, GL_FLOAT, false, 4 * k, 0);
        floats(buffers[4], g.centresOfRotation(), 3 * n, GlesShaders.CENTRE);
        glBindVertexArray(0);
        glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffers[5]);
        glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, 24L * Math.max(1, n), GL_STREAM_READ);
        glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);

        paletteData = ByteBuffer.allocateDirect(4 * PaletteTexture.floats(Math.max(1, joints)))
                .order(ByteOrder.nativeOrder()).asFloatBuffer();
        palette = glGenTextures();
        glBindTexture(GL_TEXTURE_2D, palette);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, PaletteTexture.TEXELS_PER_JOINT, Math.max(1, joints), 0, GL_RGBA,
                GL_FLOAT, (FloatBuffer) null);
        glBindTexture(GL_TEXTURE_2D, 0);
    }

    private static void floats(int buffer, float[] data, int count, int attribute) {
        FloatBuffer fb = ByteBuffer.allocateDirect(Math.max(4, 4 * count)).order(ByteOrder.nativeOrder()).asFloatBuffer();
        fb.put(data, 0, count).flip();
        glBindBuffer(GL_ARRAY_BUFFER, buffer);
        glBufferData(GL_ARRAY_BUFFER, fb, GL_STATIC_DRAW);
        glEnableVertexAttribArray(attribute);
        glVertexAttribPointer(attribute, 3, GL_FLOAT, false, 12, 0);
    }

    int vertexCount() {
        return vertices;
    }

    /**
     * Skins the render vertices with {@code program} (linked with {@link #VARYINGS} recorded) from
     * {@code packedPalette} ({@link PaletteTexture#pack}'s layout) and the uniforms the app sets;
     * writes 3 floats per vertex into {@code positions} and {@code normals} (the shader's normal,
     * not renormalised).
     *
     * @param method 1 LBS, 2 DQS, 3 CoR (the shader's uMethod)
     */
    void capture(int program, float[] packedPalette, int method, boolean hasScale, boolean matricesMirror,
            boolean scalesMirror, float[] positions, float[] normals) {
        paletteData.clear();
        paletteData.put(packedPalette, 0, PaletteTexture.floats(joints)).flip();
        glActiveTexture(GL_TEXTURE0 + PALETTE_UNIT);
        glBindTexture(GL_TEXTURE_2D, palette);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, PaletteTexture.TEXELS_PER_JOINT, joints, GL_RGBA, GL_FLOAT, paletteData);
        glUseProgram(program);
        float[] identity = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
        glUniformMatrix4fv(glGetUniformLocation(program, "uProjection"), false, identity);
        glUniformMatrix4fv(glGetUniformLocation(program, "uModelView"), false, identity);
        glUniform1i(glGetUniformLocation(program, "uMethod"), method);
        glUniform1i(glGetUniformLocation(program, "uPalette"), PALETTE_UNIT);
        glUniform1i(glGetUniformLocation(program, "uHasScale"), hasScale ? 1 : 0);
        glUniform1i(glGetUniformLocation(program, "uMatricesMirror"), matricesMirror ? 1 : 0);
        glUniform1i(glGetUniformLocation(program, "uScalesMirror"), scalesMirror ? 1 : 0);
        glBindVertexArray(vao);
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffers[5]);
        int query = glGenQueries();
        glEnable(GL_RASTERIZER_DISCARD);
        glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, query);
        glBeginTransformFeedback(GL_POINTS);
        glDrawArrays(GL_POINTS, 0, vertices);
        glEndTransformFeedback();
        glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
        glDisable(GL_RASTERIZER_DISCARD);
        glBindVertexArray(0);
        int written = glGetQueryObjectui(query, GL_QUERY_RESULT);
        glDeleteQueries(query);
        if (written != vertices) {
            throw new IllegalStateException("transform feedback wrote " + written + " of " + vertices + " vertices");
        }
        glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffers[5]);
        ByteBuffer mapped = glMapBufferRange(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 24L * vertices, GL_MAP_READ_BIT);
        if (mapped == null) {
            throw new IllegalStateException("cannot map the transform feedback buffer: GL error " + glGetError());
        }
        FloatBuffer out = mapped.order(ByteOrder.nativeOrder()).asFloatBuffer();
        for (int i = 0; i < vertices; i++) {
            out.get(positions, 3 * i, 3);
            out.get(normals, 3 * i, 3);
        }
        glUnmapBuffer(GL_TRANSFORM_FEEDBACK_BUFFER);
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
        glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);
    }

    @Override
    public void close() {
        glDeleteBuffers(buffers);
        glDeleteVertexArrays(vao);
        glDeleteTextures(palette);
    }
}
