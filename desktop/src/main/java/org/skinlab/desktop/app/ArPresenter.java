package org.skinlab.desktop.app;

import org.joml.Matrix4f;
import org.skinlab.ar.ArCamera;
import org.skinlab.ar.ArPose;
import org.skinlab.ar.CameraFollow;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.MarkerScene;
import org.skinlab.ar.TrackingState;
import org.skinlab.desktop.ar.ArFeed;
import org.skinlab.desktop.render.CameraBackground;
import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.scene.ModelFraming;
import org.skinlab.simulation.AnimationConfig;

/**
 * The window's AR mode ({@code skinlab ar}): per window frame, the newest tracked camera frame as
 * the background, and the matrices that stand the model on the marker (marker -> scale ->
 * transform -> mesh, {@link MarkerScene}; turned toward the camera when "follow camera" is on).
 * The image and the pose come from one {@link ArFeed.Shot}, so they always belong together.
 */
final class ArPresenter implements AutoCloseable {
    /** Near and far planes of the AR projection, in metres. */
    private static final float NEAR = 0.01f;
    private static final float FAR = 50f;

    private final ArFeed feed;
    private final CameraIntrinsics intrinsics;
    private final MarkerScene scene;
    private final CameraBackground background = new CameraBackground();
    private final CameraFollow follow = new CameraFollow();
    private final Matrix4f imageToViewport = new Matrix4f();
    private final Matrix4f projection = new Matrix4f();
    private final Matrix4f markerView = new Matrix4f();
    private long uploaded = -1;
    private ArFeed.Shot shot;
    /** What the status line last said: the pose's state, followed id and markers in view. */
    private TrackingState shownState;
    private int shownId;
    private int shownCount;
    private String shownFailure;

    ArPresenter(ArSetup setup) {
        this.feed = setup.feed();
        this.intrinsics = setup.intrinsics();
        this.scene = new MarkerScene(setup.markerSizeMetres());
    }

    /** Takes the newest tracked frame and draws it across the viewport; false before the first frame. */
    boolean drawBackground(int viewportWidth, int viewportHeight) {
        shot = feed.latest();
        if (shot == null) {
            return false;
        }
        if (shot.number() != uploaded) {
            background.upload(shot.image());
            uploaded = shot.number();
        }
        ArCamera.imageToViewport(intrinsics.width(), intrinsics.height(), viewportWidth, viewportHeight, 0, true,
                imageToViewport);
        background.draw(imageToViewport, intrinsics);
        return true;
    }

    /**
     * Sets the draw's view-projection (camera projection times the marker's model-view) and model
     * matrix (the model on the marker); false when the marker is not shown (model hidden).
     */
    boolean placeModel(ModelFraming framing, AnimationConfig config, DrawSettings draw, int viewportWidth,
            int viewportHeight) {
        if (shot == null || !shot.pose().visible()) {
            return false;
        }
        scene.place(shot.pose(), follow, config.isFollowCamera(), framing, markerView, draw.model);
        ArCamera.projection(intrinsics, NEAR, FAR, viewportWidth, viewportHeight, 0, true, projection);
        draw.viewProjection.set(projection).mul(markerView);
        // The camera centre in the marker frame (the scene's frame here), for the lighting.
        markerView.originAffine(draw.eye);
        return true;
    }

    /**
     * For the status line: what changed since the last call (the tracking state, the followed id,
     * the markers in view: {@link org.skinlab.ar.ArPose#markerLabel()}; a camera failure), or null.
     */
    String statusChange() {
        ArPose pose = shot == null ? ArPose.NONE : shot.pose();
        String failure = feed.failure();
        if (pose.state() == shownState && pose.markerId() == shownId && pose.markers() == shownCount
                && failure == shownFailure) {
            return null;
        }
        shownState = pose.state();
        shownId = pose.markerId();
        shownCount = pose.markers();
        shownFailure = failure;
        return failure != null ? "camera: " + failure : "AR: marker " + pose.markerLabel();
    }

    /** Headless runs: waits for the first tracked frame; null when there is one, else why not. */
    String awaitCameraFrame() {
        try {
            if (feed.awaitFirst(20_000)) {
                return null;
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return "no camera frame" + (feed.failure() != null ? ": " + feed.failure() : " in 20 s");
    }

    @Override
    public void close() {
        feed.close();
        background.close();
    }
}
