package org.skinlab.desktop.viewer;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.joml.Vector3fc;

import org.skinlab.scene.ModelFraming;

/**
 * A camera orbiting a target: yaw and pitch around it at a distance, Y up. Dragging orbits,
 * scrolling zooms by a factor per step, and {@link #frame} puts a model's bounding sphere in view
 * (the thesis' "centre camera"). Main-thread only; the matrix methods allocate nothing.
 */
public final class OrbitCamera {
    /** Vertical field of view in radians. */
    public static final float FOV_Y = (float) Math.toRadians(40);
    /** The steepest the camera looks down or up (radians): short of the vertical, where yaw would turn the view. */
    public static final float MAX_PITCH = (float) Math.toRadians(85);
    /** The pitch {@link #frame} looks from unless told otherwise: a little above, the floor in view. */
    public static final float DEFAULT_PITCH = (float) Math.toRadians(12);
    private static final float RADIANS_PER_PIXEL = 0.008f;
    private static final float ZOOM_PER_STEP = 1.15f;

    private final Vector3f target = new Vector3f();
    private final Vector3f eye = new Vector3f();
    private final Vector3f up = new Vector3f(0, 1, 0);
    private final Matrix4f view = new Matrix4f();
    private float yaw;
    /** The yaw {@link #frame} looks from: 0 from the front (+z), positive towards +x. */
    private float homeYaw;
    /** The pitch {@link #frame} looks from: positive from above. */
    private float homePitch = DEFAULT_PITCH;
    private float pitch = DEFAULT_PITCH;
    private float distance = 3f;
    private float radius = 1f;
    /**
     * Whether the distance follows the view's aspect: from {@link #frame} until the user zooms, so
     * the framed sphere stays in a view the interface resizes (its panels settle over the first
     * frames, and a window can be resized).
     */
    private boolean fitting;
    /** How far {@link #follow} has moved the target since it was last framed. */
    private final Vector3f followed = new Vector3f();

    /**
     * Looks at the sphere from the front (or the {@link #setHomeYaw home yaw}), slightly above (or
     * at the {@link #setHomePitch home pitch}), so that it fills the view's height.
     */
    public void frame(Vector3f centre, float sphereRadius) {
        target.set(centre);
        radius = Math.max(ModelFraming.MIN_RADIUS, sphereRadius);
        yaw = homeYaw;
        pitch = homePitch;
        distance = radius / (float) Math.sin(FOV_Y / 2) * 1.1f;
        fitting = true;
        followed.zero();
    }

    /**
     * Keeps a travelling model in view (root motion): moves the target by as much as
     * {@code offset}, how far the model has moved from where it was framed, changed since the last
     * call, so the user's orbit, pan and zoom stay as they are. Allocation-free.
     */
    public void follow(Vector3fc offset) {
        target.add(offset.x() - followed.x, offset.y() - followed.y, offset.z() - followed.z);
        followed.set(offset);
    }

    /** The angle (radians) around the vertical axis that framing looks from: 0 from +z, pi/2 from +x. */
    public void setHomeYaw(float radians) {
        homeYaw = radians;
    }

    /**
     * The angle (radians) above the horizontal that framing looks from: 0 level with the target,
     * positive from above, negative from below; clamped to +-{@link #MAX_PITCH}.
     */
    public void setHomePitch(float radians) {
        homePitch = Math.max(-MAX_PITCH, Math.min(MAX_PITCH, radians));
    }

    public void frame(ModelFraming framing) {
        frame(framing.centre(), framing.radius());
    }

    /** Frames a grid of copies ({@link ModelFraming#gridSphere}). */
    public void frame(ModelFraming framing, int instances, int columns) {
        Vector3f centre = new Vector3f();
        float r = framing.gridSphere(instances, columns, centre);
        frame(centre, r);
    }

    public void orbit(float dxPixels, float dyPixels) {
        yaw -= dxPixels * RADIANS_PER_PIXEL;
        pitch = Math.max(-MAX_PITCH, Math.min(MAX_PITCH, pitch + dyPixels * RADIANS_PER_PIXEL));
    }

    /** Moves the target in the view plane, by pixels of a view {@code viewHeight} pixels high. */
    public void pan(float dxPixels, float dyPixels, int viewHeight) {
        float unitsPerPixel = 2f * distance * (float) Math.tan(FOV_Y / 2) / Math.max(1, viewHeight);
        view(view);
        // The view matrix's rows are the camera's right and up axes in the scene.
        float rx = view.m00();
        float ry = view.m10();
        float rz = view.m20();
        float ux = view.m01();
        float uy = view.m11();
        float uz = view.m21();
        target.add((-dxPixels * rx + dyPixels * ux) * unitsPerPixel, (-dxPixels * ry + dyPixels * uy) * unitsPerPixel,
                (-dxPixels * rz + dyPixels * uz) * unitsPerPixel);
    }

    /** Zooms in (positive steps) or out, between a hundredth and a hundred framing radii. */
    public void zoom(float steps) {
        fitting = false;
        distance = (float) (distance * Math.pow(ZOOM_PER_STEP, -steps));
        distance = Math.max(radius * 0.01f, Math.min(radius * 100f, distance));
    }

    public Vector3f eye(Vector3f dest) {
        float cp = (float) Math.cos(pitch);
        return dest.set(target.x + distance * cp * (float) Math.sin(yaw), target.y + distance * (float) Math.sin(pitch),
                target.z + distance * cp * (float) Math.cos(yaw));
    }

    public Matrix4f view(Matrix4f dest) {
        eye(eye);
        return dest.setLookAt(eye, target, up);
    }

    /** A perspective projection whose near and far planes keep the framed sphere in depth range. */
    public Matrix4f projection(float aspect, Matrix4f dest) {
        if (fitting) {
            // The sphere must fit the narrower of the two fields of view.
            float halfX = (float) Math.atan(Math.tan(FOV_Y / 2) * aspect);
            distance = radius / (float) Math.sin(Math.min(FOV_Y / 2, halfX)) * 1.1f;
        }
        float near = Math.max(distance - 50f * radius, distance * 0.01f);
        float far = distance + 50f * radius;
        return dest.setPerspective(FOV_Y, aspect, near, far);
    }

    /** {@code dest = dest * view}: turns a projection into the view-projection. */
    public Matrix4f viewTimesInto(Matrix4f dest) {
        return dest.mul(view(view));
    }

    public float distance() {
        return distance;
    }

    public Vector3f target() {
        return target;
    }
}
