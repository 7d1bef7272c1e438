package org.skinlab.android;

import static android.opengl.GLES30.*;

import java.util.List;

import org.joml.Matrix4f;
import org.joml.Matrix4fc;
import org.skinlab.android.logic.GlesShaders;
import org.skinlab.internal.scene.BlendOrder;
import org.skinlab.simulation.Frame;
import org.skinlab.skinning.SkinningGlsl;

/**
 * Draws one frame of a skinned model with the app's skinned program (GL thread only): the AR
 * model on the marker ({@link ArRenderer}) and each copy of the measurement ({@link CopiesDrawer}).
 * Opaque and masked parts first, then blended parts farthest first (as the desktop viewer draws
 * them); depth writes stay on.
 */
final class SkinnedModelDraw {
    private final int program;
    private final MaterialUniforms materials;
    private final Matrix4f clip = new Matrix4f();
    private final float[] matrix = new float[16];
    private BlendOrder blendOrder = new BlendOrder(0);

    /** Draws with {@code program} (GlesShaders' skinned shaders) and its material uniforms. */
    SkinnedModelDraw(int program, MaterialUniforms materials) {
        this.program = program;
        this.materials = materials;
    }

    /** Makes room for ordering {@code blendedParts} blended parts (when a new model is uploaded). */
    void blendedParts(int blendedParts) {
        blendOrder = new BlendOrder(blendedParts);
    }

    /** {@code frame} of the geometries in {@code models}, placed by {@code modelView} and {@code projection}. */
    void draw(List<ModelGl> models, Frame frame, Matrix4fc projection, Matrix4fc modelView) {
        glEnable(GL_DEPTH_TEST);
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glUseProgram(program);
        glUniformMatrix4fv(glGetUniformLocation(program, "uProjection"), 1, false, projection.get(matrix), 0);
        glUniformMatrix4fv(glGetUniformLocation(program, "uModelView"), 1, false, modelView.get(matrix), 0);
        // A frame with a CPU-skinned mesh (a method without shader code) is drawn as it is: code 0.
        glUniform1i(glGetUniformLocation(program, "uMethod"),
                frame.hasSkinnedMesh() ? 0 : SkinningGlsl.methodCode(frame.method()));
        glUniform1i(glGetUniformLocation(program, "uPalette"), GlesShaders.PALETTE_UNIT);
        glVertexAttrib4f(GlesShaders.COLOR, 1f, 1f, 1f, 1f); // geometries without vertex colours
        boolean viewMirrors = modelView.determinant3x3() < 0f;
        projection.mul(modelView, clip);
        blendOrder.clear();
        for (int g = 0; g < models.size(); g++) {
            ModelGl model = models.get(g);
            paletteOf(models, frame, g);
            ModelGl.Part[] parts = model.parts();
            for (int i = 0; i < parts.length; i++) {
                if (!parts[i].material().blended()) {
                    model.draw(parts[i], materials, viewMirrors);
                } else {
                    float distance = i < model.centredParts() ? BlendOrder.distance(clip, model.posedCentres(), i) : 0f;
                    blendOrder.add(g, i, distance);
                }
            }
        }
        int bound = -1;
        for (int k = 0; k < blendOrder.size(); k++) {
            int g = blendOrder.geometry(k);
            if (g != bound) {
                paletteOf(models, frame, g);
                bound = g;
            }
            models.get(g).draw(models.get(g).parts()[blendOrder.part(k)], materials, viewMirrors);
        }
        glDisable(GL_CULL_FACE);
        glDisable(GL_BLEND);
    }

    /**
     * Geometry {@code g}'s shape (CPU-skinned, or morphed rest shape when its weights animate),
     * palette and per-geometry uniforms.
     */
    private void paletteOf(List<ModelGl> models, Frame frame, int g) {
        models.get(g).shape(frame, g);
        models.get(g).palette(frame, g);
        glUniform1i(glGetUniformLocation(program, "uHasScale"), frame.palette(g).hasScale() ? 1 : 0);
        glUniform1i(glGetUniformLocation(program, "uMatricesMirror"), frame.palette(g).mirrorsMatrices() ? 1 : 0);
        glUniform1i(glGetUniformLocation(program, "uScalesMirror"), frame.palette(g).mirrorsScales() ? 1 : 0);
    }
}
