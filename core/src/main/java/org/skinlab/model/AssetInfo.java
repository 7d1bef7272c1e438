package org.skinlab.model;

import org.joml.Matrix4f;

/**
 * What {@code <asset>} says about the document's frame. Recorded as written: the model stays in
 * the document's own frame and units, comparable to other tools that read the same file, and
 * converting to the app's frame is a separate, explicit step ({@link #toYUpMeters}).
 *
 * @param upAxis        the up axis, {@link UpAxis#Y_UP} when not given
 * @param unitMeter     length of one document unit in metres, 1.0 when not given
 * @param unitName      the unit's name, "meter" when not given
 * @param authoringTool the first {@code <authoring_tool>}, or null
 * @param present       false when the file has no {@code <asset>} at all (tolerated, with a warning)
 */
public record AssetInfo(UpAxis upAxis, double unitMeter, String unitName, String authoringTool, boolean present) {
    /**
     * The transform from the document's frame to a right-handed Y-up frame in metres, written
     * into {@code dest}. COLLADA 1.4.1 ({@code up_axis}) names the axes of each convention as
     * (right, up, in): Y_UP (+X, +Y, +Z), Z_UP (+X, +Z, -Y), X_UP (-Y, +X, +Z); the result maps
     * them to (+X, +Y, +Z) and scales by {@link #unitMeter()}. Z_UP is a -90 degree rotation about
     * X, X_UP a +90 degree rotation about Z.
     *
     * @param dest the matrix to overwrite
     * @return {@code dest}, mapping points in document units and axes to Y-up metres
     */
    public Matrix4f toYUpMeters(Matrix4f dest) {
        dest.identity();
        switch (upAxis) {
            case Z_UP:
                dest.rotateX((float) (-Math.PI / 2));
                break;
            case X_UP:
                dest.rotateZ((float) (Math.PI / 2));
                break;
            default:
                break;
        }
        return dest.scaleLocal((float) unitMeter);
    }
}
