package org.skinlab.android;

import static android.opengl.GLES30.*;

import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.FloatBuffer;
import java.nio.IntBuffer;
import java.nio.ShortBuffer;
import java.util.List;
import java.util.function.ToIntFunction;

import org.skinlab.android.logic.GlesShaders;
import org.skinlab.android.logic.PaletteTexture;
import org.skinlab.model.Image;
import org.skinlab.model.Mesh;
import org.skinlab.model.MeshPart;
import org.skinlab.model.Texture;
import org.skinlab.internal.scene.PartCentres;
import org.skinlab.internal.scene.PartMaterial;
import org.skinlab.simulation.Frame;
import org.skinlab.skinning.InfluenceView;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * One skinned geometry on the GPU (GL thread only), at the attribute locations of
 * {@link GlesShaders#skinnedVertex()}: bind-pose positions and normals, 4 influences per vertex
 * ({@link InfluenceView}), CoR's centres, texture coordinates and vertex colours, the triangles
 * with each part's material ({@link PartMaterial}), and the palette texture refilled from each
 * frame ({@link PaletteTexture}).
 */
final class ModelGl {
    /** One run of triangles with its material and GL textures, resolved once. */
    record Part(int byteOffset, int indexCount, PartMaterial material, float[] baseColor, float[] emission,
            int baseTexture, float[] baseTransform, int emissionTexture, float[] emissionTransform) {
    }

    private final SkinnedGeometry geometry;
    private final int vao;
    private final int[] buffers = new int[8];
    private final int palette;
    private final int joints;
    private final float[] paletteData;
    private final FloatBuffer paletteBuffer;
    private final Part[] parts;
    private final PartCentres centres;
    private final float[] posedCentres;
    private boolean mirrored;
    private final int vertexCount;
    /** Staging for a morphing rest shape's or a CPU-skinned mesh's positions (3 per vertex), allocated on first use. */
    private FloatBuffer restStaging;
    /** Whether buffers 0 and 1 hold something other than the bind pose (a morphed or CPU-skinned shape). */
    private boolean replacedBindShape;

    /** @param textures the GL texture of an image, 0 when it has none */
    ModelGl(SkinnedGeometry g, ToIntFunction<Image> textures) {
        geometry = g;
        int n = g.vertexCount();
        vertexCount = n;
        InfluenceView view = InfluenceView.of(g, GlesShaders.INFLUENCES);
        Mesh mesh = g.mesh();
        int[] triangles = mesh == null ? new int[0] : mesh.triangles();
        float[] uv = PartMaterial.texCoords(mesh, g.instance());
        parts = parts(g, triangles.length, uv != null ? textures : image -> 0);
        centres = PartCentres.of(g);
        posedCentres = new float[3 * centres.partCount()];
        joints = g.jointCount();
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
        floats(buffers[4], g.centresOfRotation(), 3 * n, GlesShaders.CENTRE, 3);
        if (uv != null) {
            floats(buffers[6], uv, 2 * n, GlesShaders.UV, 2);
        }
        if (mesh != null && mesh.hasColors()) {
            floats(buffers[7], mesh.colors(), 4 * n, GlesShaders.COLOR, 4);
        } else {
            // White: the material's colour as it is (a current attribute value is context state;
            // every geometry without colours wants the same).
            glVertexAttrib4f(GlesShaders.COLOR, 1f, 1f, 1f, 1f);
        }
        IntBuffer idx = ByteBuffer.allocateDirect(Math.max(4, 4 * triangles.length)).order(ByteOrder.nativeOrder())
                .asIntBuffer();
        idx.put(triangles).flip();
        glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffers[5]);
        glBufferData(GL_ELEMENT_ARRAY_BUFFER, 4 * triangles.length, idx, GL_STATIC_DRAW);
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

    private static Part[] parts(SkinnedGeometry g, int indices, ToIntFunction<Image> textures) {
        List<MeshPart> meshParts = g.mesh() == null ? List.of() : g.mesh().parts();
        if (meshParts.isEmpty()) {
            return new Part[] {part(0, indices, PartMaterial.DEFAULT, textures)};
        }
        Part[] result = new Part[meshParts.size()];
        for (int i = 0; i < result.length; i++) {
            MeshPart p = meshParts.get(i);
            result[i] = part(12 * p.firstTriangle(), 3 * p.triangleCount(), PartMaterial.of(g.instance(), p),
                    textures);
        }
        return result;
    }

    private static Part part(int byteOffset, int indexCount, PartMaterial m, ToIntFunction<Image> textures) {
        return new Part(byteOffset, indexCount, m, m.baseColor(), m.emission(), textureOf(m.baseTexture(), textures),
                PartMaterial.uvMatrix(m.baseTexture()), textureOf(m.emissionTexture(), textures),
                PartMaterial.uvMatrix(m.emissionTexture()));
    }

    private static int textureOf(Texture t, ToIntFunction<Image> textures) {
        return t == null ? 0 : textures.applyAsInt(t.image());
    }

    /**
     * Uploads what the shader starts from in place of geometry {@code g}'s bind-pose positions and
     * normals: {@code frame}'s CPU-skinned mesh when it has one (a method without shader code,
     * {@code SkinningGlsl.hasCode}; the shader then leaves the points as they are, method code 0),
     * else its morphed rest shape when the morph weights animate (as the desktop viewer does:
     * docs/skinning.md, "Morphs"), else the bind pose again if an earlier frame replaced it.
     */
    void shape(Frame frame, int g) {
        if (frame.hasSkinnedMesh()) {
            uploadShape(frame.positions(g), frame.normals(g));
        } else if (frame.restPositions(g) != null) {
            uploadShape(frame.restPositions(g), frame.restNormals(g));
        } else if (replacedBindShape) {
            uploadShape(geometry.positionArray(), geometry.normalArray());
            replacedBindShape = false;
            return;
        } else {
            return;
        }
        replacedBindShape = true;
    }

    private void uploadShape(float[] positions, float[] normals) {
        if (restStaging == null) {
            restStaging = ByteBuffer.allocateDirect(Math.max(4, 12 * vertexCount)).order(ByteOrder.nativeOrder())
                    .asFloatBuffer();
        }
        uploadRest(buffers[0], positions);
        uploadRest(buffers[1], normals);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
    }

    private void uploadRest(int buffer, float[] data) {
        restStaging.clear();
        restStaging.put(data, 0, 3 * vertexCount).flip();
        glBindBuffer(GL_ARRAY_BUFFER, buffer);
        glBufferSubData(GL_ARRAY_BUFFER, 0, 12 * vertexCount, restStaging);
    }

    /**
     * Uploads geometry {@code g}'s palette of {@code frame}, binds it to the palette's texture
     * unit and places the parts' centres (for ordering blended parts).
     */
    void palette(Frame frame, int g) {
        PaletteTexture.pack(frame, g, paletteData);
        paletteBuffer.clear();
        paletteBuffer.put(paletteData).flip();
        glActiveTexture(GL_TEXTURE0 + GlesShaders.PALETTE_UNIT);
        glBindTexture(GL_TEXTURE_2D, palette);
        glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, PaletteTexture.TEXELS_PER_JOINT, joints, GL_RGBA, GL_FLOAT,
                paletteBuffer);
        glActiveTexture(GL_TEXTURE0);
        float[] m = frame.palette(g).matrices();
        mirrored = geometry.windingMirrored() ^ PartCentres.firstJointMirrors(m);
        for (int i = 0; i < centres.partCount(); i++) {
            centres.posed(i, m, posedCentres);
        }
    }

    Part[] parts() {
        return parts;
    }

    /** Part {@code i}'s centre as the last palette placed it (3 floats at {@code 3i}), for BlendOrder. */
    float[] posedCentres() {
        return posedCentres;
    }

    /** Parts with a placed centre (all but the one part of a geometry without mesh parts). */
    int centredParts() {
        return centres.partCount();
    }

    /**
     * Draws part {@code p} with {@code uniforms}' program in use: back faces culled unless the
     * material is double-sided ({@code viewMirrors}: the model-view matrix reverses the winding).
     */
    void draw(Part p, MaterialUniforms uniforms, boolean viewMirrors) {
        if (p.material().doubleSided()) {
            glDisable(GL_CULL_FACE);
        } else {
            glEnable(GL_CULL_FACE);
            glCullFace(GL_BACK);
            glFrontFace(mirrored ^ viewMirrors ? GL_CW : GL_CCW);
        }
        uniforms.set(p);
        glBindVertexArray(vao);
        glDrawElements(GL_TRIANGLES, p.indexCount(), GL_UNSIGNED_INT, p.byteOffset());
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
}
