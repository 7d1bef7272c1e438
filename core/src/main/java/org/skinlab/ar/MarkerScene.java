package org.skinlab.ar;

import org.joml.Matrix4f;
import org.skinlab.scene.ModelFraming;

/**
 * The thesis' scene graph on the marker: marker -> scale -> transform -> mesh. The mesh stands as
 * the viewer stands it ({@link ModelFraming}: upright in Y-up metres, its lowest point on the floor,
 * centred over the origin); a quarter turn about x puts its up axis on the marker's normal (+z, out
 * of the printed face) and its front (the viewer's +z) toward the marker's bottom edge (-y), so a
 * user looking at the marker the right way up faces the model; then it is scaled to a chosen
 * height relative to the marker and turned about the normal by a yaw (follow-the-camera).
 */
public final class MarkerScene {
    /** The model's height over the marker's width unless told otherwise. */
    public static final double DEFAULT_HEIGHT_OVER_MARKER = 1.5;

    private final double markerSizeMetres;
    private final double heightOverMarker;

    /**
     * A scene for a marker of the given size with the model scaled to a multiple of it.
     *
     * @param markerSizeMetres the printed black square's width in metres, positive (as in {@link TrackerConfig})
     * @param heightOverMarker the model's height as a multiple of the marker's width, positive
     * @throws IllegalArgumentException when either is not positive (or NaN)
     */
    public MarkerScene(double markerSizeMetres, double heightOverMarker) {
        if (!(markerSizeMetres > 0) || !(heightOverMarker > 0)) {
            throw new IllegalArgumentException("marker size and model height must be positive: " + markerSizeMetres
                    + ", " + heightOverMarker);
        }
        this.markerSizeMetres = markerSizeMetres;
        this.heightOverMarker = heightOverMarker;
    }

    /**
     * A scene with the model {@link #DEFAULT_HEIGHT_OVER_MARKER} times as tall as the marker is wide.
     *
     * @param markerSizeMetres the printed black square's width in metres, positive
     * @throws IllegalArgumentException when it is not positive (or NaN)
     */
    public MarkerScene(double markerSizeMetres) {
        this(markerSizeMetres, DEFAULT_HEIGHT_OVER_MARKER);
    }

    /**
     * The printed black square's width.
     *
     * @return the marker's width in metres
     */
    public double markerSizeMetres() {
        return markerSizeMetres;
    }

    /**
     * The model's height on the marker, in metres.
     *
     * @return the marker's width times the height over marker
     */
    public double modelHeightMetres() {
        return heightOverMarker * markerSizeMetres;
    }

    /**
     * Document coordinates to the marker frame: {@code Rz(yaw) S Rx(90 degrees) upright}, S the uniform
     * scale that gives the framed model {@link #modelHeightMetres()}.
     *
     * @param framing    how the model stands upright in Y-up metres; its {@code height} (at least
     *                   {@code ModelFraming.MIN_RADIUS}) is scaled to {@link #modelHeightMetres()}
     * @param yawRadians the turn about the marker's normal (+z), counter-clockwise seen from above; 0 faces the
     *                   model toward the marker's bottom edge
     * @param dest       receives the matrix (overwritten)
     * @return {@code dest}: from the model file's coordinates to marker coordinates in metres
     */
    public Matrix4f modelToMarker(ModelFraming framing, double yawRadians, Matrix4f dest) {
        float scale = (float) (modelHeightMetres() / Math.max(framing.height(), ModelFraming.MIN_RADIUS));
        return dest.rotationZ((float) yawRadians).scale(scale).rotateX((float) (Math.PI / 2)).mul(framing.upright());
    }

    /**
     * The model on the marker in one camera frame, for the desktop's and the phone's renderers
     * alike: the marker's OpenGL model-view ({@link ArPose#markerModelView}) into {@code markerView}
     * and {@link #modelToMarker} into {@code model}, turned toward the camera by {@code follow}
     * (which keeps its last yaw when the camera is overhead) when {@code followCamera} is on. The
     * mesh's model-view is {@code markerView * model}.
     *
     * @param pose         the frame's published pose; only its rotation and translation are read
     * @param follow       the presenter's follow state, updated when {@code followCamera} is on, untouched otherwise
     * @param followCamera whether the model turns toward the camera; off, its yaw is 0
     * @param framing      how the model stands upright in Y-up metres ({@link #modelToMarker})
     * @param markerView   receives the marker's OpenGL model-view (overwritten)
     * @param model        receives the model-to-marker matrix (overwritten)
     */
    public void place(ArPose pose, CameraFollow follow, boolean followCamera, ModelFraming framing, Matrix4f markerView,
            Matrix4f model) {
        double yaw = followCamera ? follow.update(pose.rotation(), pose.translation()) : 0;
        pose.markerModelView(markerView);
        modelToMarker(framing, yaw, model);
    }
}
