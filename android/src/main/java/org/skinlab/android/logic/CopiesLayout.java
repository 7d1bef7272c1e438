package org.skinlab.android.logic;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.scene.ModelFraming;

/**
 * Where the measurement's copies of a model stand and the camera that sees them all: an about
 * square grid (rows of {@link #columns} copies centred on x, going back along -z,
 * {@link ModelFraming#gridSpacing} apart: the desktop's instance grid), seen from 12 degrees above
 * with a 40-degree vertical field of view, from as far as the grid's bounding sphere needs to fit
 * the narrower side of the view (as the desktop viewer frames a grid).
 */
public final class CopiesLayout {
    private static final float FOV_Y = (float) Math.toRadians(40);
    private static final float PITCH = (float) Math.toRadians(12);

    private CopiesLayout() {
    }

    /** Columns of the grid of {@code copies}. */
    public static int columns(int copies) {
        return Math.max(1, (int) Math.ceil(Math.sqrt(copies)));
    }

    /** Copy {@code i}'s model matrix among {@code copies}: its place in the grid times the model's framing. */
    public static Matrix4f model(ModelFraming framing, int i, int copies, Matrix4f dest) {
        int columns = columns(copies);
        float spacing = framing.gridSpacing();
        float x = (i % columns - 0.5f * (columns - 1)) * spacing;
        float z = -(i / columns) * spacing;
        return dest.translation(x, 0, z).mul(framing.upright());
    }

    /** The view and the projection ({@code width} by {@code height} pixels) that frame the grid of {@code copies}. */
    public static void camera(ModelFraming framing, int copies, int width, int height, Matrix4f view,
            Matrix4f projection) {
        Vector3f target = new Vector3f();
        float radius = Math.max(ModelFraming.MIN_RADIUS, framing.gridSphere(copies, columns(copies), target));
        float aspect = Math.max(1, width) / (float) Math.max(1, height);
        float halfX = (float) Math.atan(Math.tan(FOV_Y / 2) * aspect);
        float distance = radius / (float) Math.sin(Math.min(FOV_Y / 2, halfX)) * 1.1f;
        Vector3f eye = new Vector3f(target.x, target.y + distance * (float) Math.sin(PITCH),
                target.z + distance * (float) Math.cos(PITCH));
        view.setLookAt(eye, target, new Vector3f(0, 1, 0));
        projection.setPerspective(FOV_Y, aspect, Math.max(distance - 2 * radius, distance * 0.01f),
                distance + 2 * radius);
    }
}
