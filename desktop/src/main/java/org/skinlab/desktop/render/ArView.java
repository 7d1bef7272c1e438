package org.skinlab.desktop.render;

import org.joml.Matrix4f;
import org.skinlab.ar.ArCamera;
import org.skinlab.ar.ArPose;
import org.skinlab.ar.CameraFollow;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.MarkerScene;
import org.skinlab.scene.ModelFraming;

/**
 * One AR view: the camera's colour frame behind the scene ({@link CameraBackground}), and the
 * matrices that stand the model on the marker (marker -> scale -> transform -> mesh,
 * {@link MarkerScene}; turned toward the camera when asked), both mapped into the viewport by
 * {@code ArCamera.imageToViewport}, so the model lands where the marker is in the picture. The
 * window's AR mode and {@code skinlab bench ar-frame} draw through it. GL thread only; nothing
 * allocated per frame.
 */
public final class ArView implements AutoCloseable {
    /** Near and far planes of the AR projection, in metres. */
    private static final float NEAR = 0.01f;
    private static final float FAR = 50f;

    private final CameraIntrinsics intrinsics;
    private final MarkerScene scene;
    private final CameraBackground background = new CameraBackground();
    private final CameraFollow follow = new CameraFollow();
    private final Matrix4f imageToViewport = new Matrix4f();
    private final Matrix4f projection = new Matrix4f();
    private final Matrix4f markerView = new Matrix4f();
    private boolean uploaded;

    /** A view through camera {@code intrinsics} onto a printed marker {@code markerSizeMetres} wide. */
    public ArView(CameraIntrinsics intrinsics, double markerSizeMetres) {
        this.intrinsics = intrinsics;
        this.scene = new MarkerScene(markerSizeMetres);
    }

    /** Uploads a camera frame: {@code w x h} pixels of R, G, B bytes, rows top first. */
    public void upload(int w, int h, byte[] rgb) {
        background.upload(w, h, rgb);
        uploaded = true;
    }

    /** Draws the last uploaded frame across a viewport of this size; false before the first upload. */
    public boolean drawBackground(int viewportWidth, int viewportHeight) {
        if (!uploaded) {
            return false;
        }
        ArCamera.imageToViewport(intrinsics.width(), intrinsics.height(), viewportWidth, viewportHeight, 0, true,
                imageToViewport);
        background.draw(imageToViewport, intrinsics);
        return true;
    }

    /**
     * Sets the draw's view-projection (camera projection times the marker's model-view), model
     * matrix (the model on the marker) and eye for a viewport of this size; false when the pose
     * does not show the marker (model hidden).
     */
    public boolean placeModel(ArPose pose, ModelFraming framing, boolean followCamera, DrawSettings draw,
            int viewportWidth, int viewportHeight) {
        if (!pose.visible()) {
            return false;
        }
        scene.place(pose, follow, followCamera, framing, markerView, draw.model);
        ArCamera.projection(intrinsics, NEAR, FAR, viewportWidth, viewportHeight, 0, true, projection);
        draw.viewProjection.set(projection).mul(markerView);
        // The camera centre in the marker frame (the scene's frame here), for the lighting.
        markerView.originAffine(draw.eye);
        return true;
    }

    @Override
    public void close() {
        background.close();
    }
}
