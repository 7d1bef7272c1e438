package org.skinlab.desktop.app;

import org.skinlab.ar.ArPose;
import org.skinlab.ar.TrackingState;
import org.skinlab.desktop.ar.ArFeed;
import org.skinlab.desktop.ar.CameraImage;
import org.skinlab.desktop.render.ArView;
import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.scene.ModelFraming;
import org.skinlab.simulation.AnimationConfig;

/**
 * The window's AR mode ({@code skinlab ar}): per window frame, the newest tracked camera frame as
 * the background and the model placed on its marker ({@link ArView}), and the tracking state for
 * the status line. The picture and the pose come from one {@link ArFeed.Shot}, so they always
 * belong together.
 */
final class ArPresenter implements AutoCloseable {
    private final ArFeed feed;
    private final ArView view;
    private long uploaded = -1;
    private ArFeed.Shot shot;
    /** What the status line last said: the pose's state, followed id and markers in view. */
    private TrackingState shownState;
    private int shownId;
    private int shownCount;
    private String shownFailure;

    ArPresenter(ArSetup setup) {
        this.feed = setup.feed();
        this.view = new ArView(setup.intrinsics(), setup.markerSizeMetres());
    }

    /** Takes the newest tracked frame and draws it across the viewport; false before the first frame. */
    boolean drawBackground(int viewportWidth, int viewportHeight) {
        shot = feed.newest();
        if (shot == null) {
            return false;
        }
        if (shot.number() != uploaded) {
            CameraImage image = shot.image();
            view.upload(image.width(), image.height(), image.rgb());
            uploaded = shot.number();
        }
        return view.drawBackground(viewportWidth, viewportHeight);
    }

    /**
     * Sets the draw's view-projection and model matrix for the model on the marker; false when the
     * marker is not shown (model hidden).
     */
    boolean placeModel(ModelFraming framing, AnimationConfig config, DrawSettings draw, int viewportWidth,
            int viewportHeight) {
        return shot != null && view.placeModel(shot.pose(), framing, config.isFollowCamera(), draw, viewportWidth,
                viewportHeight);
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
        view.close();
    }
}
