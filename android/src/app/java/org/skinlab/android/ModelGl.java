package org.skinlab.android;

import static android.opengl.GLES30.*;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.nio.ShortBuffer;

import org.skinlab.android.logic.GlesShaders;
import org.skinlab.android.logic.PaletteTexture;
import org.skinlab.model.MaterialBinding;
import org.skinlab.simulation.Frame;
import org.skinlab.skinning.InfluenceView;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * One skinned geometry on the GPU (GL thread only), at the attribute locations of
 * {@link GlesShaders#skinnedVertex()}: bind-pose positions and normals, 4 influences per vertex
 * ({@link InfluenceView}), CoR's centres, the triangles, and the palette texture
 * refilled from each frame ({@link PaletteTexture}).
 */
final class ModelGl {
    private final int vao;
    private final int[] buffers = new int[6];
    private final int palette;
    private final int indexCount;
    private final int joints;
    private final float[] paletteData;
    private final FloatBuffer paletteBuffer;
    private final int vertexCount;
    /** Staging for a morphing rest shape's positions (3 per vertex), allocated on first use. */
    private FloatBuffer restStaging;
    final float[] color;

    ModelGl(SkinnedGeometry g) {
        int n = g.vertexCount();
        vertexCount = n;
        InfluenceView view = InfluenceView.of(g, GlesShaders.INFLUENCES);
        int[] triangles = g.mesh() == null ? new int[0] : g.mesh().triangles();
        indexCount = triangles.length;
        joints = g.jointCount();
        color = colorOf(g);
        glGenBuffers(buffers.length, buffers, 0);
        vao = genVertexArray();
        glBindVertexArray(vao);
        floats(buffers[0], g.positionArray(), 3 * n, GlesShaders.POSITION, 3);
        floats(buffers[1], g.normalArray(), 3 * n, GlesShaders.NORMAL, 3);
        int k = GlesShaders.INFLUENCES;
        ShortBuffer j = ByteBuffer.allocateDirect(Math.max(2, 2 * k * n)).order(ByteOrder.nativeOrder()).asShortBuffer();
        view.putJointIndices(j, n);
        j.flip();
        glBindBuffer(GL_ARRAY_BUFFER, buffers[2]);
        glBufferData(GL_ARRAY_BUFFER, 2 * k * n, j, GL_STATIC_DRAW);
        glEnableVertexAttribArray(GlesShaders.JOINTS);
        glVertexAttribIPointer(GlesShaders.JOINTS, k, GL_UNSIGNED_SHORT, 2 * k, 0);
        FloatBuffer w = ByteBuffer.allocateDirect(Math.max(4, 4 * k * n)).order(ByteOrder.nativeOrder()).asFloatBuffer();
        view.putWeights(w, n);
        w.flip();
        glBindBuffer(GL_ARRAY_BUFFER, buffers[3]);
        glBufferData(GL_ARRAY_BUFFER, 4 * k * n, w, GL_STATIC_DRAW);
        glEnableVertexAttribArray(GlesShaders.WEIGHTS);
        glVertexAttribPointer(GlesShaders.WEIGHTS, k, GL_FLOAT, false, 4 * k, 0);
        floats(buffers[4], g.centersOfRotation(), 3 * n, GlesShaders.CENTRE, 3);
        IntBuffer idx = ByteBuffer.allocateDirect(Math.max(4, 4 * indexCount)).order(ByteOrder.nativeOrder()).asIntBuffer();
        idx.put(triangles).flip();
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[5]);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, 4 * indexCount, idx, GL_STATIC_DRAW);
        glBindVertexArray(0);

        paletteData = new float[PaletteTexture.floats(joints)];
        paletteBuffer = ByteBuffer.allocateDirect(4 * paletteData.length).order(ByteOrder.nativeOrder()).asFloatBuffer();
        int[] t = new int[1];
        glGenTextures(1, t, 0);
        palette = t[0];
        glBindTexture(GL_TEXTURE_2D, palette);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
        glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, PaletteTexture.TEXELS_PER_JOINT, Math.max(1, joints), 0, GL_RGBA,
                GL_FLOAT, null);
    }

    /**
     * Uploads geometry {@code g}'s morphed rest positions and normals of {@code frame} in place of
     * its bind-pose ones when its morph weights animate (as the desktop viewer does: docs/skinning.md,
     * "Morphs"); nothing otherwise.
     */
    void restShape(Frame frame, int g) {
        if (frame.restPositions(g) == null) {
            return;
        }
        if (restStaging == null) {
            restStaging = ByteBuffer.allocateDirect(Math.max(4, 12 * vertexCount)).order(ByteOrder.nativeOrder())
                    .asFloatBuffer();
        }
        uploadRest(buffers[0], frame.restPositions(g));
        uploadRest(buffers[1], frame.restNormals(g));
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }

    private void uploadRest(int buffer, float[] data) {
        restStaging.clear();
        restStaging.put(data, 0, 3 * vertexCount).flip();
        glBindBuffer(GL_ARRAY_BUFFER, buffer);
        glBufferSubData(GL_ARRAY_BUFFER, 0, 12 * vertexCount, restStaging);
    }

    /** Uploads geometry {@code g}'s palette of {@code frame} and binds it to texture unit 1. */
    void palette(Frame frame, int g) {
        PaletteTexture.pack(frame, g, paletteData);
        paletteBuffer.clear();
        paletteBuffer.put(paletteData).flip();
        glActiveTexture(GL_TEXTURE1);
        glBindTexture(GL_TEXTURE_2D, palette);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, PaletteTexture.TEXELS_PER_JOINT, joints, GL_RGBA, GL_FLOAT,
                paletteBuffer);
    }

    void draw() {
        glBindVertexArray(vao);
        glDrawElements(GL_TRIANGLES, indexCount, GL_UNSIGNED_INT, 0);
        glBindVertexArray(0);
    }

    void release() {
        glDeleteBuffers(buffers.length, buffers, 0);
        glDeleteVertexArrays(1, new int[] {vao}, 0);
        glDeleteTextures(1, new int[] {palette}, 0);
    }

    private static int genVertexArray() {
        int[] a = new int[1];
        glGenVertexArrays(1, a, 0);
        return a[0];
    }

    private static void floats(int buffer, float[] data, int count, int attribute, int size) {
        FloatBuffer fb = ByteBuffer.allocateDirect(Math.max(4, 4 * count)).order(ByteOrder.nativeOrder()).asFloatBuffer();
        fb.put(data, 0, count).flip();
        glBindBuffer(GL_ARRAY_BUFFER, buffer);
        glBufferData(GL_ARRAY_BUFFER, 4 * count, fb, GL_STATIC_DRAW);
        glEnableVertexAttribArray(attribute);
        glVertexAttribPointer(attribute, size, GL_FLOAT, false, 4 * size, 0);
    }

    /** The diffuse colour of the geometry's first bound material, else a neutral clay. */
    private static float[] colorOf(SkinnedGeometry g) {
        if (g.instance() != null) {
            for (MaterialBinding b : g.instance().materials()) {
                if (b.material() != null && b.material().diffuse() != null) {
                    return b.material().diffuse().clone();
                }
            }
        }
        return new float[] {0.8f, 0.72f, 0.62f, 1f};
    }
}
