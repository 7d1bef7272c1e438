package org.skinlab.desktop.render;

import static org.lwjgl.opengl.GL33C.*;

import java.nio.FloatBuffer;
import java.util.ArrayList;
import java.util.List;
import java.util.function.ToIntFunction;

import org.lwjgl.system.MemoryUtil;
import org.skinlab.model.Image;
import org.skinlab.model.Material;
import org.skinlab.model.MaterialBinding;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.MeshPart;
import org.skinlab.model.Model;
import org.skinlab.model.Texture;
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
    /** One run of triangles with its material, resolved once. */
    private record PartDraw(long byteOffset, int indexCount, float[] diffuse, int texture) {
    }

    private final SkinningShader shader;
    private final Model scene;
    private SkeletonOverlay skeleton;
    private final List<GpuGeometry> geometries = new ArrayList<>();
    private final PartDraw[][] parts;
    /** 16 floats off the heap for matrix uniforms: nothing is allocated per draw, JIT or not. */
    private final FloatBuffer matrix = MemoryUtil.memAllocFloat(16);
    private long uploadedSequence = Long.MIN_VALUE;
    private Frame uploadedFrame;

    /**
     * @param shader   the skinning program (shared between models)
     * @param textures the GL texture of an image, 0 when it has none (a texture cache)
     */
    public ModelRenderer(SkinningShader shader, Model scene, List<SkinnedGeometry> geometries,
            ToIntFunction<Image> textures) {
        this.shader = shader;
        this.scene = scene;
        parts = new PartDraw[geometries.size()][];
        for (int g = 0; g < geometries.size(); g++) {
            GpuGeometry gpu = new GpuGeometry(geometries.get(g));
            this.geometries.add(gpu);
            parts[g] = resolveParts(gpu, textures);
        }
    }

    private static PartDraw[] resolveParts(GpuGeometry gpu, ToIntFunction<Image> textures) {
        List<MeshPart> meshParts = gpu.parts();
        MeshInstance instance = gpu.instance();
        if (meshParts.isEmpty()) {
            return new PartDraw[] {new PartDraw(0, gpu.indexCount(), Material.DEFAULT.diffuse().clone(), 0)};
        }
        PartDraw[] result = new PartDraw[meshParts.size()];
        for (int i = 0; i < result.length; i++) {
            MeshPart part = meshParts.get(i);
            MaterialBinding binding = instance == null || part.material() == null ? null
                    : instance.material(part.material());
            Material material = binding == null ? Material.DEFAULT : binding.material();
            // A material may have no diffuse colour (a texture, or only emission): white then.
            float[] diffuse = material.diffuse() != null ? material.diffuse().clone() : new float[] {1f, 1f, 1f, 1f};
            diffuse[3] = Math.min(diffuse[3], material.opacity());
            Texture texture = material.baseTexture();
            int id = texture != null && gpu.hasUv() ? textures.applyAsInt(texture.image()) : 0;
            if (id != 0) {
                // A texture modulates white: the file's diffuse colour is then usually a placeholder.
                diffuse[0] = diffuse[1] = diffuse[2] = 1f;
            }
            result[i] = new PartDraw(12L * part.firstTriangle(), 3 * part.triangleCount(), diffuse, id);
        }
        return result;
    }

    /** Uploads {@code frame} unless it is the one uploaded last. */
    public void upload(Frame frame) {
        if (frame == uploadedFrame && frame.sequence() == uploadedSequence) {
            return;
        }
        for (int g = 0; g < geometries.size(); g++) {
            geometries.get(g).upload(frame, g);
        }
        uploadedFrame = frame;
        uploadedSequence = frame.sequence();
    }

    /**
     * Draws the frame last {@link #upload uploaded}. With {@code s.gpuSkinning} false, the
     * CPU-skinned positions of that frame are drawn (the caller checks the frame has them).
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
        glUniform1i(shader.columns, s.columns());
        glUniform1f(shader.spacing, s.spacing);
        glUniform1i(shader.firstInstance, s.firstInstance);
        glUniform1i(shader.flat, 0);
        drawAll(s, false, weights);
        if (s.wireframe) {
            glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
            glEnable(GL_POLYGON_OFFSET_LINE);
            glPolygonOffset(-1f, -1f);
            glUniform1i(shader.flat, 1);
            glUniform4f(shader.flatColor, 0.05f, 0.05f, 0.08f, 0.6f);
            drawAll(s, true, false);
            glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
            glDisable(GL_POLYGON_OFFSET_LINE);
        }
        glBindVertexArray(0);
    }


    private void drawAll(DrawSettings s, boolean flat, boolean weights) {
        for (int g = 0; g < geometries.size(); g++) {
            GpuGeometry gpu = geometries.get(g);
            if (s.gpuSkinning && s.method == SkinningMethod.COR) {
                gpu.ensureCentres();
            }
            // No joint (-1) colours by nothing; a joint outside this palette shows weight 0 (blue).
            glUniform1i(shader.selectedJoint, !weights ? -1 : gpu.paletteIndexOfNode(s.selectedNode));
            gpu.bind(s.gpuSkinning);
            PaletteBuffers p = gpu.palette();
            glUniform1i(shader.influences, gpu.influences());
            glUniform1i(shader.hasScale, p.hasScale() ? 1 : 0);
            glUniform1i(shader.matricesMirror, p.matricesMirror() ? 1 : 0);
            glUniform1i(shader.scalesMirror, p.scalesMirror() ? 1 : 0);
            for (PartDraw part : parts[g]) {
                if (!flat) {
                    float[] c = part.diffuse();
                    glUniform4f(shader.diffuse, c[0], c[1], c[2], c[3]);
                    glUniform1i(shader.hasTexture, part.texture() != 0 ? 1 : 0);
                    glBindTexture(GL_TEXTURE_2D, part.texture());
                }
                glDrawElementsInstanced(GL_TRIANGLES, part.indexCount(), GL_UNSIGNED_INT, part.byteOffset(),
                        Math.max(1, s.instances));
            }
        }
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
