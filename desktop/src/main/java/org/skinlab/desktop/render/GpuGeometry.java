package org.skinlab.desktop.render;

import static org.lwjgl.opengl.GL33C.*;

import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.nio.ShortBuffer;
import java.util.List;

import org.lwjgl.system.MemoryUtil;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.MeshPart;
import org.skinlab.internal.scene.PartMaterial;
import org.skinlab.simulation.Frame;
import org.skinlab.skinning.InfluenceView;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * One {@link SkinnedGeometry} on the GPU: its render vertices in bind space with normals, texture
 * coordinates, vertex colours (when the mesh has them) and the 4- or 8-influence view (for skinning in the vertex shader), a second pair of
 * position and normal buffers the CPU-skinned frames are streamed into, the triangles, and the
 * palette. Two vertex arrays share everything but positions and normals: one reads the bind pose
 * (GPU skinning), one the streamed pose (CPU skinning); both also read the bind-space positions
 * as the rest position (attribute 9) that the checker view's pattern is fixed to.
 */
final class GpuGeometry implements AutoCloseable {
    /** At most this many influences reach the shader; heavier skins are cut (InfluenceView). */
    static final int MAX_SHADER_INFLUENCES = 8;

    private final SkinnedGeometry geometry;
    private final int vertexCount;
    private final int indexCount;
    private final int influences;
    private final int cappedPoints;
    private final int gpuVao;
    private final int cpuVao;
    private final int[] buffers = new int[9];
    /** CoR's centres, uploaded on first use (0 until then). */
    private int centreBuffer;
    private final PaletteBuffers palette;
    private final List<MeshPart> parts;
    private final MeshInstance instance;
    private final boolean hasUv;
    /** Staging for a morphing rest shape's positions (3 per render vertex), allocated on first use. */
    private FloatBuffer restStaging;

    GpuGeometry(SkinnedGeometry geometry) {
        this.geometry = geometry;
        this.vertexCount = geometry.vertexCount();
        Mesh mesh = geometry.mesh();
        this.instance = geometry.instance();
        this.parts = mesh == null ? List.of() : mesh.parts();
        int[] triangles = mesh == null ? new int[0] : mesh.triangles();
        this.indexCount = triangles.length;
        this.influences = geometry.influencesPerPoint() <= 4 ? 4 : MAX_SHADER_INFLUENCES;
        InfluenceView view = InfluenceView.of(geometry, influences);
        this.cappedPoints = view.cappedPointCount();
        float[] uv = PartMaterial.texCoords(mesh, instance);
        this.hasUv = uv != null;

        glGenBuffers(buffers);
        int bindPositions = buffers[0];
        int bindNormals = buffers[1];
        int cpuPositions = buffers[2];
        int cpuNormals = buffers[3];
        int uvs = buffers[4];
        int joints = buffers[5];
        int weights = buffers[6];
        int elements = buffers[7];
        int colors = buffers[8];
        float[] vertexColors = mesh != null && mesh.hasColors() ? mesh.colors() : null;
        if (vertexColors != null) {
            upload(colors, vertexColors, 4 * vertexCount, GL_STATIC_DRAW);
        }

        upload(bindPositions, geometry.positionArray(), 3 * vertexCount, GL_STATIC_DRAW);
        upload(bindNormals, geometry.normalArray(), 3 * vertexCount, GL_STATIC_DRAW);
        // The frame holds every point (render vertices, then unused positions): room for all.
        glBindBuffer(GL_ARRAY_BUFFER, cpuPositions);
        glBufferData(GL_ARRAY_BUFFER, 12L * geometry.pointCount(), GL_STREAM_DRAW);
        glBindBuffer(GL_ARRAY_BUFFER, cpuNormals);
        glBufferData(GL_ARRAY_BUFFER, 12L * geometry.pointCount(), GL_STREAM_DRAW);
        upload(uvs, uv == null ? new float[2 * vertexCount] : uv, 2 * vertexCount, GL_STATIC_DRAW);

        ShortBuffer jointData = MemoryUtil.memAllocShort(Math.max(1, influences * vertexCount));
        FloatBuffer weightData = MemoryUtil.memAllocFloat(Math.max(1, influences * vertexCount));
        try {
            view.putJointIndices(jointData, vertexCount);
            view.putWeights(weightData, vertexCount);
            jointData.flip();
            weightData.flip();
            glBindBuffer(GL_ARRAY_BUFFER, joints);
            glBufferData(GL_ARRAY_BUFFER, jointData, GL_STATIC_DRAW);
            glBindBuffer(GL_ARRAY_BUFFER, weights);
            glBufferData(GL_ARRAY_BUFFER, weightData, GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree(jointData);
            MemoryUtil.memFree(weightData);
        }

        gpuVao = glGenVertexArrays();
        cpuVao = glGenVertexArrays();
        for (int vao : new int[] {gpuVao, cpuVao}) {
            glBindVertexArray(vao);
            boolean gpu = vao == gpuVao;
            attribute(0, gpu ? bindPositions : cpuPositions, 3);
            attribute(1, gpu ? bindNormals : cpuNormals, 3);
            attribute(2, uvs, 2);
            glBindBuffer(GL_ARRAY_BUFFER, joints);
            for (int a = 0; a < 2; a++) {
                int size = Math.min(4, influences - 4 * a);
                if (size > 0) {
                    glEnableVertexAttribArray(3 + 2 * a);
                    glVertexAttribIPointer(3 + 2 * a, size, GL_UNSIGNED_SHORT, 2 * influences, 8L * a);
                } else {
                    // No slots 5-8: the shader reads joint 0 with weight 0.
                    glDisableVertexAttribArray(3 + 2 * a);
                    glVertexAttribI4ui(3 + 2 * a, 0, 0, 0, 0);
                }
            }
            glBindBuffer(GL_ARRAY_BUFFER, weights);
            for (int a = 0; a < 2; a++) {
                int size = Math.min(4, influences - 4 * a);
                if (size > 0) {
                    glEnableVertexAttribArray(4 + 2 * a);
                    glVertexAttribPointer(4 + 2 * a, size, GL_FLOAT, false, 4 * influences, 16L * a);
                } else {
                    glDisableVertexAttribArray(4 + 2 * a);
                    glVertexAttrib4f(4 + 2 * a, 0, 0, 0, 0);
                }
            }
            glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, elements);
            // No centres until CoR is drawn: the shader reads (0, 0, 0) and only CoR uses them.
            glDisableVertexAttribArray(7);
            glVertexAttrib3f(7, 0f, 0f, 0f);
            // The rest position for patterns fixed to the rest shape (the checker view), in both
            // arrays: the GPU-skinned one reads it as its position too, the CPU one only here.
            attribute(9, bindPositions, 3);
            if (vertexColors != null) {
                attribute(8, colors, 4);
            } else {
                // White: the material's colour as it is (a current attribute value is context state; every
                // geometry without colours wants the same white).
                glDisableVertexAttribArray(8);
                glVertexAttrib4f(8, 1f, 1f, 1f, 1f);
            }
        }
        IntBuffer indexData = MemoryUtil.memAllocInt(Math.max(1, triangles.length));
        try {
            indexData.put(triangles).flip();
            glBufferData(GL_ELEMENT_ARRAY_BUFFER, indexData, GL_STATIC_DRAW);
        } finally {
            MemoryUtil.memFree(indexData);
        }
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        palette = new PaletteBuffers(geometry.jointCount());
    }

    private static void upload(int buffer, float[] data, int floats, int usage) {
        FloatBuffer fb = MemoryUtil.memAllocFloat(Math.max(1, floats));
        try {
            fb.put(data, 0, floats).flip();
            glBindBuffer(GL_ARRAY_BUFFER, buffer);
            glBufferData(GL_ARRAY_BUFFER, fb, usage);
        } finally {
            MemoryUtil.memFree(fb);
        }
    }

    private static void attribute(int location, int buffer, int size) {
        glBindBuffer(GL_ARRAY_BUFFER, buffer);
        glEnableVertexAttribArray(location);
        glVertexAttribPointer(location, size, GL_FLOAT, false, 0, 0L);
    }

    /**
     * Uploads what the frame holds for this geometry: always the palette, the morphed rest
     * positions and normals when its morph weights animate (the vertex shader skins them: uploading them costs
     * 12 bytes per vertex of the morphing meshes only, and keeps the GPU on exactly the positions
     * the CPU skins; docs/skinning.md, "Morphs"), and the CPU-skinned positions and normals when
     * the frame has them.
     */
    void upload(Frame frame, int g) {
        palette.upload(frame, g);
        if (frame.restPositions(g) != null) {
            if (restStaging == null) {
                restStaging = MemoryUtil.memAllocFloat(Math.max(1, 3 * vertexCount));
            }
            uploadRest(buffers[0], frame.restPositions(g));
            uploadRest(buffers[1], frame.restNormals(g));
        }
        if (frame.hasSkinnedMesh()) {
            glBindBuffer(GL_ARRAY_BUFFER, buffers[2]);
            glBufferSubData(GL_ARRAY_BUFFER, 0, frame.positions(g));
            glBindBuffer(GL_ARRAY_BUFFER, buffers[3]);
            glBufferSubData(GL_ARRAY_BUFFER, 0, frame.normals(g));
            glBindBuffer(GL_ARRAY_BUFFER, 0);
        }
    }

    /** Replaces the render vertices' part of a bind-pose buffer (positions or normals). */
    private void uploadRest(int buffer, float[] data) {
        restStaging.clear();
        restStaging.put(data, 0, 3 * vertexCount).flip();
        glBindBuffer(GL_ARRAY_BUFFER, buffer);
        glBufferSubData(GL_ARRAY_BUFFER, 0, restStaging);
    }

    /**
     * Uploads the centres of rotation for CoR skinning on the GPU, once (computing them, on first
     * use, costs about 0.1 s for a character of 5,000 vertices: docs/skinning.md).
     */
    void ensureCentres() {
        if (centreBuffer != 0) {
            return;
        }
        centreBuffer = glGenBuffers();
        upload(centreBuffer, geometry.centresOfRotation(), 3 * vertexCount, GL_STATIC_DRAW);
        glBindVertexArray(gpuVao);
        attribute(7, centreBuffer, 3);
        glBindVertexArray(0);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }

    /** Binds the vertex array for GPU skinning (bind pose in) or CPU skinning (posed in). */
    void bind(boolean gpuSkinning) {
        glBindVertexArray(gpuSkinning ? gpuVao : cpuVao);
        palette.bind();
    }

    /**
     * The palette index of scene node {@code node} in this geometry, or an index no vertex uses
     * (the joint count) when the node is not one of its joints; -1 for node -1.
     */
    int paletteIndexOfNode(int node) {
        if (node < 0) {
            return -1;
        }
        for (int j = 0; j < geometry.jointCount(); j++) {
            if (geometry.jointNode(j) == node) {
                return j;
            }
        }
        return geometry.jointCount();
    }

    PaletteBuffers palette() {
        return palette;
    }

    SkinnedGeometry geometry() {
        return geometry;
    }

    MeshInstance instance() {
        return instance;
    }

    List<MeshPart> parts() {
        return parts;
    }

    boolean hasUv() {
        return hasUv;
    }

    int vertexCount() {
        return vertexCount;
    }

    int indexCount() {
        return indexCount;
    }

    /** Influences per vertex the shader reads (4 or 8). */
    int influences() {
        return influences;
    }

    /** Vertices that lost influences to the shader's cap (their weights renormalised). */
    int cappedPoints() {
        return cappedPoints;
    }

    @Override
    public void close() {
        glDeleteVertexArrays(gpuVao);
        glDeleteVertexArrays(cpuVao);
        glDeleteBuffers(buffers);
        if (centreBuffer != 0) {
            glDeleteBuffers(centreBuffer);
        }
        palette.close();
        if (restStaging != null) {
            MemoryUtil.memFree(restStaging);
        }
    }
}
