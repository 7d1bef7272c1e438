package org.skinlab.android;

import static android.opengl.GLES30.*;

import java.util.ArrayList;
import java.util.List;

import org.joml.Matrix4f;
import org.skinlab.android.logic.CopiesLayout;
import org.skinlab.android.logic.DrawnCopies;
import org.skinlab.model.Model;
import org.skinlab.scene.ModelFraming;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.SkinnedGeometry;

/**
 * The measurement's frames on the GL thread: the copies of a {@link DrawnCopies.Request} in a grid
 * that the camera sees whole ({@link CopiesLayout}), each copy stepped by a 60th of a second, its
 * palette uploaded and its geometries drawn, as a crowd's characters are. The copies share one
 * set of vertex buffers (they are copies of one model); pictures are not drawn (the bundled
 * models have none), each part in its material's colours.
 */
final class CopiesDrawer {
    private static final double STEP_SECONDS = 1.0 / 60;

    private final SkinnedModelDraw draw;
    private final Matrix4f view = new Matrix4f();
    private final Matrix4f projection = new Matrix4f();
    private final Matrix4f model = new Matrix4f();
    private final Matrix4f modelView = new Matrix4f();
    private List<ModelGl> models = new ArrayList<>();
    /** The model whose geometries are on the GPU, or null. */
    private Model uploaded;
    private ModelFraming framing;

    /** Draws with {@code draw}, its own (a blend order sized for the copies' model). */
    CopiesDrawer(SkinnedModelDraw draw) {
        this.draw = draw;
    }

    /** One frame of {@code request}'s copies in a {@code width} by {@code height} view. */
    void draw(DrawnCopies.Request request, int width, int height) {
        List<SkeletalAnimatedMesh> copies = request.copies();
        for (SkeletalAnimatedMesh m : copies) {
            m.step(STEP_SECONDS);
        }
        SkeletalAnimatedMesh first = copies.get(0);
        if (first.model() != uploaded) {
            upload(first);
        }
        glClearColor(0.17f, 0.18f, 0.21f, 1f);
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
        CopiesLayout.camera(framing, copies.size(), width, height, view, projection);
        for (int i = 0; i < copies.size(); i++) {
            try (Frame f = copies.get(i).acquire()) {
                CopiesLayout.model(framing, i, copies.size(), model);
                view.mul(model, modelView);
                draw.draw(models, f, projection, modelView);
            }
        }
    }

    /** The first copy's geometries on the GPU (the others' are the same), and the framing of its first frame. */
    private void upload(SkeletalAnimatedMesh first) {
        release();
        int blended = 0;
        for (SkinnedGeometry g : first.geometries()) {
            ModelGl gl = new ModelGl(g, image -> 0);
            models.add(gl);
            for (ModelGl.Part p : gl.parts()) {
                blended += p.material().blended() ? 1 : 0;
            }
        }
        draw.blendedParts(blended);
        try (Frame f = first.acquire()) {
            framing = ModelFraming.of(first.model().asset(), first.geometries(), f);
        }
        uploaded = first.model();
    }

    /** Deletes the copies' buffers and textures (GL thread; nothing when none are held). */
    void release() {
        for (ModelGl g : models) {
            g.release();
        }
        models = new ArrayList<>();
        uploaded = null;
    }
}
