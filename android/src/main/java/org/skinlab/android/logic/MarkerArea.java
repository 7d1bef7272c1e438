package org.skinlab.android.logic;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.animation.Skeleton;
import org.skinlab.ar.MarkerScene;
import org.skinlab.model.Model;
import org.skinlab.scene.ModelFraming;

/**
 * The part of the printed marker a walking character should stay on, in the space root motion's
 * placement is measured in ({@code Mixer.placementPosition}: the root joint's parent space): a
 * circle about the placement's origin, which {@link ModelFraming} centres on the marker, of a
 * radius given as a fraction of the marker's width, and the up axis it lies across.
 *
 * <p>From the placement's space to the marker: the root's parent's rest world matrix (to the
 * model file's space), the file's unit and up axis ({@code AssetInfo.toYUpMeters}), then
 * {@link MarkerScene}'s uniform scale, which makes the framed model {@link
 * MarkerScene#modelHeightMetres()} tall. That scale grows with the marker, so the radius in the
 * placement's units does not depend on the marker's printed size, only on the model's height and
 * {@code MarkerScene}'s height over marker.
 *
 * <p>The root joint and its parent are found as {@code Mixer} finds them (the first node that is
 * a joint), which keeps them private: the two must agree.
 */
public final class MarkerArea {
    /** The circle's radius over the marker's width: 0.4 keeps it inside the printed square. */
    public static final double RADIUS_OVER_MARKER = 0.4;

    private final double[] up;
    private final double radius;

    /**
     * @param up     the up axis in the placement's space (normalised here); not zero
     * @param radius the circle's radius in the placement's units, positive
     */
    public MarkerArea(double[] up, double radius) {
        double length = Math.sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
        if (!(length > 0) || !(radius > 0) || Double.isInfinite(radius)) {
            throw new IllegalArgumentException("need an up axis and a positive radius: length " + length
                    + ", radius " + radius);
        }
        this.up = new double[] {up[0] / length, up[1] / length, up[2] / length};
        this.radius = radius;
    }

    /**
     * The circle of {@code radiusOverMarker} marker widths for {@code model} as {@code scene}
     * stands it on the marker with {@code framing}.
     */
    public static MarkerArea of(Model model, Skeleton skeleton, ModelFraming framing, MarkerScene scene,
            double radiusOverMarker) {
        Matrix4f parentToScene = model.asset().toYUpMeters(new Matrix4f());
        int root = rootJoint(skeleton);
        if (root >= 0 && skeleton.parent(root) >= 0) {
            parentToScene.mul(skeleton.newPose().world(skeleton.parent(root), new Matrix4f()));
        }
        // The scene's up (+y) back in the placement's space.
        Vector3f up = new Matrix4f(parentToScene).invert().transformDirection(new Vector3f(0, 1, 0)).normalize();
        Vector3f across = Math.abs(up.x) < 0.9f ? new Vector3f(1, 0, 0) : new Vector3f(0, 1, 0);
        across.sub(new Vector3f(up).mul(across.dot(up))).normalize();
        double metresPerUnit = parentToScene.transformDirection(across).length();
        double scale = scene.modelHeightMetres() / Math.max(framing.height(), ModelFraming.MIN_RADIUS);
        double radius = radiusOverMarker * scene.markerSizeMetres() / (scale * metresPerUnit);
        return new MarkerArea(new double[] {up.x, up.y, up.z}, radius);
    }

    private static int rootJoint(Skeleton skeleton) {
        for (int i = 0; i < skeleton.nodeCount(); i++) {
            if (skeleton.node(i).isJoint()) {
                return i;
            }
        }
        return -1;
    }

    /** The up axis in the placement's space, unit length (a copy). */
    public double[] up() {
        return up.clone();
    }

    /** The circle's radius in the placement's units. */
    public double radius() {
        return radius;
    }
}
