package org.skinlab.desktop.render;

import static org.lwjgl.opengl.GL33C.*;

import java.nio.FloatBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.function.ToIntFunction;

import org.joml.Matrix4f;
import org.lwjgl.system.MemoryUtil;
import org.skinlab.model.Image;
import org.skinlab.model.MeshPart;
import org.skinlab.model.Model;
import org.skinlab.model.Texture;
import org.skinlab.internal.scene.BlendOrder;
import org.skinlab.internal.scene.MaterialGlsl;
import org.skinlab.internal.scene.PartCentres;
import org.skinlab.internal.scene.PartMaterial;
import org.skinlab.simulation.Frame;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinningGlsl;
import org.skinlab.skinning.SkinningMethod;

/**
 * Draws the geometries of one model from {@link Frame}s: uploads a frame once (palette, and the
 * CPU-skinned mesh when it has one) and draws it any number of times (split view, instances) with
 * the skinning shader. Everything it draws comes from the one frame given, so no draw mixes two
 * simulation steps.
 */
public final class ModelRenderer implements AutoCloseable {
    /** One run of triangles with its material and GL textures, resolved once. */
    private record PartDraw(long byteOffset, int indexCount, PartMaterial material, float[] baseColor,
            float[] emission, int baseTexture, float[] baseTransform, int emissionTexture, float[] emissionTransform) {
    }

    private final SkinningShader shader;
    private final Model scene;
    private SkeletonOverlay skeleton;
    private final List<GpuGeometry> geometries = new ArrayList<>();
    private final PartDraw[][] parts;
    private final PartCentres[] centres;
    /** Per geometry, the centres of its parts placed by the frame last uploaded (3 floats each). */
    private final float[][] posedCentres;
    /** Per geometry, whether the frame last uploaded reverses its triangles' winding. */
    private final boolean[] mirrored;
    private final BlendOrder blendOrder;
    /** 16 floats off the heap for matrix uniforms: nothing is allocated per draw, JIT or not. */
    private final FloatBuffer matrix = MemoryUtil.memAllocFloat(16);
    private final Matrix4f clip = new Matrix4f();
    private long uploadedSequence = Long.MIN_VALUE;
    private Frame uploadedFrame;
    /** Per geometry, whether the bone rows of the frame last uploaded are on the GPU (uploaded on first need). */
    private final boolean[] bonesUploaded;

    /**
     * @param shader   the skinning program (shared between models)
     * @param textures the GL texture of an image, 0 when it has none (a texture cache)
     */
    public ModelRenderer(SkinningShader shader, Model scene, List<SkinnedGeometry> geometries,
            ToIntFunction<Image> textures) {
        this.shader = shader;
        this.scene = scene;
        parts = new PartDraw[geometries.size()][];
        centres = new PartCentres[geometries.size()];
        posedCentres = new float[geometries.size()][];
        mirrored = new boolean[geometries.size()];
        bonesUploaded = new boolean[geometries.size()];
        int blended = 0;
        for (int g = 0; g < geometries.size(); g++) {
            GpuGeometry gpu = new GpuGeometry(geometries.get(g));
            this.geometries.add(gpu);
            parts[g] = resolveParts(gpu, textures);
            centres[g] = PartCentres.of(geometries.get(g));
            posedCentres[g] = new float[3 * centres[g].partCount()];
            for (PartDraw p : parts[g]) {
                blended += p.material().blended() ? 1 : 0;
            }
        }
        blendOrder = new BlendOrder(blended);
    }

    private static PartDraw[] resolveParts(GpuGeometry gpu, ToIntFunction<Image> textures) {
        List<MeshPart> meshParts = gpu.parts();
        if (meshParts.isEmpty()) {
            return new PartDraw[] {partDraw(0, gpu.indexCount(), PartMaterial.DEFAULT, gpu, textures)};
        }
        PartDraw[] result = new PartDraw[meshParts.size()];
        for (int i = 0; i < result.length; i++) {
            MeshPart part = meshParts.get(i);
            result[i] = partDraw(12L * part.firstTriangle(), 3 * part.triangleCount(),
                    PartMaterial.of(gpu.instance(), part), gpu, textures);
        }
        return result;
    }

    private static PartDraw partDraw(long byteOffset, int indexCount, PartMaterial m, GpuGeometry gpu,
            ToIntFunction<Image> textures) {
        int base = textureOf(m.baseTexture(), gpu, textures);
        int emission = textureOf(m.emissionTexture(), gpu, textures);
        return new PartDraw(byteOffset, indexCount, m, m.baseColor(), m.emission(), base,
                PartMaterial.uvMatrix(m.baseTexture()), emission, PartMaterial.uvMatrix(m.emissionTexture()));
    }

    /** The GL texture of {@code t}, or 0 without one or without texture coordinates to sample it by. */
    private static int textureOf(Texture t, GpuGeometry gpu, ToIntFunction<Image> textures) {
        return t != null && gpu.hasUv() ? textures.applyAsInt(t.image()) : 0;
    }

    /** Uploads {@code frame} unless it is the one uploaded last. */
    public void upload(Frame frame) {
        if (frame == uploadedFrame && frame.sequence() == uploadedSequence) {
            return;
        }
        for (int g = 0; g < geometries.size(); g++) {
            geometries.get(g).upload(frame, g);
            bonesUploaded[g] = false;
            float[] m = frame.palette(g).matrices();
            mirrored[g] = geometries.get(g).geometry().windingMirrored() ^ PartCentres.firstJointMirrors(m);
            for (int i = 0; i < centres[g].partCount(); i++) {
                centres[g].posed(i, m, posedCentres[g]);
            }
        }
        uploadedFrame = frame;
        uploadedSequence = frame.sequence();
    }

    /**
     * Uploads geometry {@code g}'s bone rows of the frame last uploaded, once per frame, for a
     * method that reads them: the other methods leave them in the frame. The frame is still held:
     * drawing happens between its acquire and close.
     */
    private void bonesFor(SkinningMethod method, int g) {
        if (method.usesBones() && !bonesUploaded[g]) {
            geometries.get(g).palette().uploadBones(uploadedFrame, g);
            bonesUploaded[g] = true;
        }
    }

    /**
     * Draws the frame last {@link #upload uploaded}: opaque and masked parts, then blended parts
     * back to front (each part by its centre; depth writes stay on, as three.js draws transparent
     * objects). Single-sided parts cull back faces. With {@code s.gpuSkinning} false, the
     * CPU-skinned positions of that frame are drawn (the caller checks the frame has them); with
     * it true, {@code s.method} must have shader code ({@link SkinningGlsl#hasCode}: the
     * simulation skins the others on the CPU, so their frames have the mesh).
     */
    public void draw(DrawSettings s) {
        shader.use();
        glUniformMatrix4fv(shader.viewProjection, false, s.viewProjection.get(matrix));
        glUniformMatrix4fv(shader.model, false, s.model.get(matrix));
        glUniform3f(shader.eye, s.eye.x, s.eye.y, s.eye.z);
        glUniform1i(shader.skinning, !s.gpuSkinning ? 0 : SkinningGlsl.methodCode(s.method));
        glUniform1i(shader.compare, s.view == DrawSettings.View.DIFFERENCE ? 1 : 0);
        boolean weights = s.view == DrawSettings.View.WEIGHTS;
        glUniform1i(shader.viewMode, s.view.ordinal());
        glUniform1f(shader.scalarFull, s.scalarFull);
        glUniform1f(shader.checkerCell, s.checkerCell);
        glUniform1i(shader.columns, s.columns());
        glUniform1i(shader.firstInstance, s.firstInstance);
        glUniform1f(shader.spacing, s.spacing);
        glUniform1i(shader.flat, 0);
        boolean modelMirrors = s.model.determinant3x3() < 0f;
        for (int g = 0; g < geometries.size(); g++) {
            bindGeometry(s, g, weights);
            for (PartDraw part : parts[g]) {
                if (!part.material().blended()) {
                    drawPart(s, part, mirrored[g] ^ modelMirrors);
                }
            }
        }
        drawBlended(s, weights, modelMirrors);
        glDisable(GL_CULL_FACE);
        if (s.wireframe) {
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            glEnable(GL_POLYGON_OFFSET_LINE);
            glPolygonOffset(-1f, -1f);
            glUniform1i(shader.flat, 1);
            glUniform4f(shader.flatColor, 0.05f, 0.05f, 0.08f, 0.6f);
            for (int g = 0; g < geometries.size(); g++) {
                bindGeometry(s, g, false);
                for (PartDraw part : parts[g]) {
                    drawTriangles(s, part);
                }
            }
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
            glDisable(GL_POLYGON_OFFSET_LINE);
        }
        glFrontFace(GL_CCW);
        glBindVertexArray(0);
    }

    /** The blended parts of every geometry, farthest first by their posed centres. */
    private void drawBlended(DrawSettings s, boolean weights, boolean modelMirrors) {
        clip.set(s.viewProjection).mul(s.model);
        blendOrder.clear();
        for (int g = 0; g < geometries.size(); g++) {
            for (int i = 0; i < parts[g].length; i++) {
                if (parts[g][i].material().blended()) {
                    float distance = i < centres[g].partCount() ? BlendOrder.distance(clip, posedCentres[g], i) : 0f;
                    blendOrder.add(g, i, distance);
                }
            }
        }
        int bound = -1;
        for (int k = 0; k < blendOrder.size(); k++) {
            int g = blendOrder.geometry(k);
            if (g != bound) {
                bindGeometry(s, g, weights);
                bound = g;
            }
            drawPart(s, parts[g][blendOrder.part(k)], mirrored[g] ^ modelMirrors);
        }
    }

    /** Binds geometry {@code g} with its palette and the uniforms that are per geometry. */
    private void bindGeometry(DrawSettings s, int g, boolean weights) {
        GpuGeometry gpu = geometries.get(g);
        if (s.gpuSkinning && s.method == SkinningMethod.COR) {
            gpu.ensureCentres();
        }
        if (s.gpuSkinning) {
            bonesFor(s.method, g);
        }
        // No joint (-1) colours by nothing; a joint outside this palette shows weight 0 (blue).
        glUniform1i(shader.selectedJoint, !weights ? -1 : gpu.paletteIndexOfNode(s.selectedNode));
        gpu.bind(s.gpuSkinning);
        PaletteBuffers p = gpu.palette();
        glUniform1i(shader.influences, gpu.influences());
        glUniform1i(shader.hasScale, p.hasScale() ? 1 : 0);
        glUniform1i(shader.matricesMirror, p.matricesMirror() ? 1 : 0);
        glUniform1i(shader.scalesMirror, p.scalesMirror() ? 1 : 0);
    }

    /** One part with its material: culling, colours, textures and their transforms. */
    private void drawPart(DrawSettings s, PartDraw part, boolean mirrored) {
        PartMaterial m = part.material();
        if (m.doubleSided()) {
            glDisable(GL_CULL_FACE);
        } else {
            glEnable(GL_CULL_FACE);
            glCullFace(GL_BACK);
            glFrontFace(mirrored ? GL_CW : GL_CCW);
        }
        float[] c = part.baseColor();
        glUniform4f(shader.baseColor, c[0], c[1], c[2], c[3]);
        float[] e = part.emission();
        glUniform3f(shader.emission, e[0], e[1], e[2]);
        glUniform1i(shader.alphaMode, MaterialGlsl.alphaMode(m));
        glUniform1f(shader.alphaCutoff, m.alphaCutoff());
        glUniform1i(shader.unlit, m.unlit() ? 1 : 0);
        glUniform1i(shader.hasBaseTexture, part.baseTexture() != 0 ? 1 : 0);
        glUniformMatrix3fv(shader.baseTransform, false, part.baseTransform());
        glUniform1i(shader.hasEmissionTexture, part.emissionTexture() != 0 ? 1 : 0);
        glUniformMatrix3fv(shader.emissionTransform, false, part.emissionTransform());
        glActiveTexture(GL_TEXTURE0 + SkinningShader.EMISSION_TEXTURE_UNIT);
        glBindTexture(GL_TEXTURE_2D, part.emissionTexture());
        glActiveTexture(GL_TEXTURE0 + SkinningShader.BASE_TEXTURE_UNIT);
        glBindTexture(GL_TEXTURE_2D, part.baseTexture());
        drawTriangles(s, part);
    }

    private static void drawTriangles(DrawSettings s, PartDraw part) {
        glDrawElementsInstanced(GL_TRIANGLES, part.indexCount(), GL_UNSIGNED_INT, part.byteOffset(),
                Math.max(1, s.instances));
    }

    /**
     * Draws the skeleton of the first skinned geometry over what is drawn, from the palette of
     * the frame last uploaded.
     */
    public void drawSkeleton(DrawSettings s) {
        GpuGeometry skinned = null;
        for (GpuGeometry g : geometries) {
            if (g.geometry().isSkinned()) {
                skinned = g;
                break;
            }
        }
        if (skinned == null) {
            return;
        }
        if (skeleton == null) {
            skeleton = new SkeletonOverlay(scene, skinned.geometry());
        }
        skinned.bind(true);
        skeleton.draw(s);
    }

    /**
     * Skins geometry {@code g} of the frame last uploaded on the GPU with {@code method} and reads
     * the skinned positions back with transform feedback (the shader's own output, before the
     * model matrix): 3 floats per render vertex, into {@code out} (at least {@code 3 *}
     * {@link #vertexCount(int)} long). For checking the GPU against the CPU kernels.
     */
    public void captureSkinned(int g, SkinningMethod method, float[] out) {
        GpuGeometry gpu = geometries.get(g);
        int n = gpu.vertexCount();
        int buffer = glGenBuffers();
        int query = glGenQueries();
        try {
            glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, buffer);
            glBufferData(GL_TRANSFORM_FEEDBACK_BUFFER, 12L * Math.max(1, n), GL_STREAM_READ);
            shader.use();
            glUniform1i(shader.skinning, SkinningGlsl.methodCode(method));
            if (method == SkinningMethod.COR) {
                gpu.ensureCentres();
            }
            bonesFor(method, g);
            glUniform1i(shader.compare, 0);
            glUniform1i(shader.selectedJoint, -1);
            glUniform1i(shader.columns, 1);
            glUniform1f(shader.spacing, 0f);
            glUniform1i(shader.firstInstance, 0);
            PaletteBuffers p = gpu.palette();
            glUniform1i(shader.influences, gpu.influences());
            glUniform1i(shader.hasScale, p.hasScale() ? 1 : 0);
            glUniform1i(shader.matricesMirror, p.matricesMirror() ? 1 : 0);
            glUniform1i(shader.scalesMirror, p.scalesMirror() ? 1 : 0);
            gpu.bind(true);
            glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, buffer);
            glEnable(GL_RASTERIZER_DISCARD);
            glBeginQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, query);
            glBeginTransformFeedback(GL_POINTS);
            glDrawArrays(GL_POINTS, 0, n);
            glEndTransformFeedback();
            glEndQuery(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN);
            glDisable(GL_RASTERIZER_DISCARD);
            int written = glGetQueryObjecti(query, GL_QUERY_RESULT);
            if (written != n) {
                throw new IllegalStateException("transform feedback wrote " + written + " of " + n + " vertices");
            }
            FloatBuffer read = MemoryUtil.memAllocFloat(3 * Math.max(1, n));
            try {
                glGetBufferSubData(GL_TRANSFORM_FEEDBACK_BUFFER, 0, read);
                read.get(out, 0, 3 * n);
            } finally {
                MemoryUtil.memFree(read);
            }
        } finally {
            glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, 0);
            glBindBuffer(GL_TRANSFORM_FEEDBACK_BUFFER, 0);
            glBindVertexArray(0);
            glDeleteQueries(query);
            glDeleteBuffers(buffer);
        }
    }

    /** Render vertices of geometry {@code g}. */
    public int vertexCount(int g) {
        return geometries.get(g).vertexCount();
    }

    public int geometryCount() {
        return geometries.size();
    }

    /** Vertices drawn per instance. */
    public int vertexCount() {
        int n = 0;
        for (GpuGeometry g : geometries) {
            n += g.vertexCount();
        }
        return n;
    }

    /** The most influences the shader reads for any geometry (4 or 8). */
    public int shaderInfluences() {
        int k = 4;
        for (GpuGeometry g : geometries) {
            k = Math.max(k, g.influences());
        }
        return k;
    }

    /** Vertices whose influences the shader's cap cut (weights renormalised). */
    public int cappedVertices() {
        int n = 0;
        for (GpuGeometry g : geometries) {
            n += g.cappedPoints();
        }
        return n;
    }

    @Override
    public void close() {
        geometries.forEach(GpuGeometry::close);
        geometries.clear();
        if (skeleton != null) {
            skeleton.close();
        }
        MemoryUtil.memFree(matrix);
    }
}
