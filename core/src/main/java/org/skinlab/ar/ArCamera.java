package org.skinlab.ar;

import org.joml.Matrix4f;

/**
 * OpenGL matrices that register a rendered model with a camera image: the projection of the
 * pinhole camera ({@link CameraIntrinsics}) and the model-view of a marker pose.
 *
 * <p><b>Projection.</b> A point at (X, Y, Z) in the camera's frame (x right, y down, z forward)
 * lands on pixel {@code u = fx X / Z + cx}, {@code v = fy Y / Z + cy}, with pixel (i, j) centred at
 * (i, j), so the image spans [-0.5, width - 0.5] x [-0.5, height - 0.5]. OpenGL's eye frame has y up
 * and looks down -z ({@link #markerModelView}: diag(1, -1, -1) on the left); the projection maps
 * that span onto normalised device coordinates [-1, 1]^2, the image's top row to y = +1:
 * <pre>
 *   ndc_x = (2 fx / w) x_e / (-z_e) + 2 (cx + 0.5) / w - 1
 *   ndc_y = (2 fy / h) y_e / (-z_e) + 1 - 2 (cy + 0.5) / h
 * </pre>
 *
 * <p><b>Viewport.</b> When the image is shown rotated (a phone held upright shows its landscape
 * sensor turned by 90 degrees) or in a viewport of another aspect, {@link #imageToViewport} is the
 * 2-D map of normalised device coordinates that turns and scales the image into the viewport
 * (cropping to fill it, or fitting it whole); the renderer applies it to both the projection
 * ({@link #projection(CameraIntrinsics, float, float, int, int, int, boolean, Matrix4f)}) and the
 * background quad's corners, so the model stays on the marker whatever the layout.
 */
public final class ArCamera {
    private ArCamera() {
    }

    /**
     * The projection that fills normalised device coordinates with the image (viewport of the image's aspect).
     *
     * @param k    the camera's intrinsics; its pinhole only (fx, fy, cx, cy, size): the lens'
     *             distortion cannot be expressed in a matrix and is ignored
     * @param near the distance to the near clipping plane, in the unit of the model-view's
     *             translation (metres for {@link #markerModelView} of a tracked pose); positive
     * @param far  the distance to the far clipping plane, in the same unit; greater than {@code near}
     * @param dest the matrix to overwrite with the projection
     * @return {@code dest}, a column-major OpenGL projection from the eye frame to clip space
     * @throws IllegalArgumentException unless {@code 0 < near < far}
     */
    public static Matrix4f projection(CameraIntrinsics k, float near, float far, Matrix4f dest) {
        if (!(near > 0) || !(far > near)) {
            throw new IllegalArgumentException("need 0 < near < far: " + near + ", " + far);
        }
        float w = k.width();
        float h = k.height();
        float a = (float) (2 * (k.cx() + 0.5) / w - 1);
        float b = (float) (1 - 2 * (k.cy() + 0.5) / h);
        // Column-major: column 2 carries -ndc offset times -z_e, since clip_w = -z_e.
        return dest.set(
                (float) (2 * k.fx() / w), 0, 0, 0,
                0, (float) (2 * k.fy() / h), 0, 0,
                -a, -b, -(far + near) / (far - near), -1,
                0, 0, -2 * far * near / (far - near), 0);
    }

    /**
     * The projection for a viewport of {@code viewportWidth x viewportHeight} pixels showing the image
     * turned by {@code rotationDegrees} (0, 90, 180, 270; counter-clockwise on screen) and scaled to
     * fill the viewport (cropping) or, with {@code fit}, to fit inside it (bars).
     *
     * @param k               the camera's intrinsics (pinhole only, as
     *                        {@link #projection(CameraIntrinsics, float, float, Matrix4f)})
     * @param near            the distance to the near clipping plane, in the model-view's unit; positive
     * @param far             the distance to the far clipping plane, in the same unit; greater than {@code near}
     * @param viewportWidth   the viewport's width in pixels, positive
     * @param viewportHeight  the viewport's height in pixels, positive
     * @param rotationDegrees how far the image is turned on screen, counter-clockwise, in degrees: a
     *                        multiple of 90 (negative and larger values wrap around)
     * @param fit             true to fit the whole image inside the viewport (bars), false to fill
     *                        the viewport with it (cropping)
     * @param dest            the matrix to overwrite with the projection
     * @return {@code dest}: {@link #imageToViewport} times the image's projection, column-major
     * @throws IllegalArgumentException unless {@code 0 < near < far}, or when {@code rotationDegrees}
     *                                  is not a multiple of 90
     */
    public static Matrix4f projection(CameraIntrinsics k, float near, float far, int viewportWidth, int viewportHeight,
            int rotationDegrees, boolean fit, Matrix4f dest) {
        Matrix4f view = imageToViewport(k.width(), k.height(), viewportWidth, viewportHeight, rotationDegrees, fit,
                new Matrix4f());
        return view.mul(projection(k, near, far, dest), dest);
    }

    /**
     * The map of normalised device coordinates from "the image fills the viewport" to the given
     * layout: a turn by {@code rotationDegrees} counter-clockwise, then a scale on x and y so that
     * the turned image, at its own aspect, fills (or with {@code fit}, fits inside) a viewport of
     * {@code viewportWidth x viewportHeight}. Draw the background quad's corners (-1, -1) .. (1, 1)
     * through it as well.
     *
     * @param imageWidth      the camera image's width in pixels, positive (only the aspect counts)
     * @param imageHeight     the camera image's height in pixels, positive
     * @param viewportWidth   the viewport's width in pixels, positive
     * @param viewportHeight  the viewport's height in pixels, positive
     * @param rotationDegrees how far the image is turned on screen, counter-clockwise, in degrees: a
     *                        multiple of 90 (negative and larger values wrap around)
     * @param fit             true to fit the whole image inside the viewport (bars), false to fill
     *                        the viewport with it (cropping)
     * @param dest            the matrix to overwrite with the map
     * @return {@code dest}: a scale of x and y times a turn about z, column-major; z and w pass
     *         through unchanged
     * @throws IllegalArgumentException when {@code rotationDegrees} is not a multiple of 90
     */
    public static Matrix4f imageToViewport(int imageWidth, int imageHeight, int viewportWidth, int viewportHeight,
            int rotationDegrees, boolean fit, Matrix4f dest) {
        if (rotationDegrees % 90 != 0) {
            throw new IllegalArgumentException("display rotation must be a multiple of 90 degrees: " + rotationDegrees);
        }
        int quarter = Math.floorMod(rotationDegrees / 90, 4);
        boolean sideways = quarter % 2 == 1;
        double shownW = sideways ? imageHeight : imageWidth;
        double shownH = sideways ? imageWidth : imageHeight;
        // Scale the shown image's aspect into the viewport: fill covers it, fit stays inside.
        double sx = viewportWidth / shownW;
        double sy = viewportHeight / shownH;
        double s = fit ? Math.min(sx, sy) : Math.max(sx, sy);
        float scaleX = (float) (s * shownW / viewportWidth);
        float scaleY = (float) (s * shownH / viewportHeight);
        dest.identity().scale(scaleX, scaleY, 1);
        // A quarter turn of NDC: an image axis of length 2 goes onto the other axis, also of length 2.
        return dest.rotateZ((float) (quarter * Math.PI / 2));
    }

    /**
     * The OpenGL model-view of a marker pose {@code X_cam = R X_marker + t} (R row-major): the
     * camera frame's y and z flipped into OpenGL's eye frame, {@code diag(1, -1, -1) [R | t]}.
     *
     * @param r    the rotation R from the marker's frame to the camera's, row-major: 9 elements
     *             (only the first 9 are read)
     * @param t    the translation t, the marker's origin in the camera frame (x right, y down, z
     *             forward): 3 elements, in the unit the projection's near and far use (metres for a
     *             tracked {@link ArPose})
     * @param dest the matrix to overwrite with the model-view
     * @return {@code dest}, column-major, from the marker's frame to OpenGL's eye frame
     */
    public static Matrix4f markerModelView(double[] r, double[] t, Matrix4f dest) {
        return dest.set(
                (float) r[0], (float) -r[3], (float) -r[6], 0,
                (float) r[1], (float) -r[4], (float) -r[7], 0,
                (float) r[2], (float) -r[5], (float) -r[8], 0,
                (float) t[0], (float) -t[1], (float) -t[2], 1);
    }
}
