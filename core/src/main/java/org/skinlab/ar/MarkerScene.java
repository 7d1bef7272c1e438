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

    public MarkerScene(double markerSizeMetres, double heightOverMarker) {
        if (!(markerSizeMetres > 0) || !(heightOverMarker > 0)) {
            throw new IllegalArgumentException("marker size and model height must be positive: " + markerSizeMetres
                    + ", " + heightOverMarker);
        }
        this.markerSizeMetres = markerSizeMetres;
        this.heightOverMarker = heightOverMarker;
    }

    public MarkerScene(double markerSizeMetres) {
        this(markerSizeMetres, DEFAULT_HEIGHT_OVER_MARKER);
    }

    public double markerSizeMetres() {
        return markerSizeMetres;
    }

    /** The model's height on the marker, in metres. */
    public double modelHeightMetres() {
        return heightOverMarker * markerSizeMetres;
    }

    /**
     * Document coordinates to the marker frame: {@code Rz(yaw) S Rx(90 degrees) upright}, S the uniform
     * scale that gives the framed model {@link #modelHeightMetres()}.
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
     */
    public void place(ArPose pose, CameraFollow follow, boolean followCamera, ModelFraming framing, Matrix4f markerView,
            Matrix4f model) {
        double yaw = followCamera ? follow.update(pose.rotation(), pose.translation()) : 0;
        pose.markerModelView(markerView);
        modelToMarker(framing, yaw, model);
    }
}
