package org.skinlab.ar;

import java.util.List;

import boofcv.abst.shapes.polyline.PointsToPolyline;
import boofcv.alg.shapes.polygon.PolygonHelper;
import georegression.struct.point.Point2D_I32;
import georegression.struct.shapes.Polygon2D_F64;
import org.ddogleg.struct.DogArray_B;

/**
 * In a search near the last markers, passes on to BoofCV's square fitting only the contours about
 * as long as those markers' outlines: the black cells inside a code, specks of texture and the
 * edges of larger things are dropped before a polygon is fitted, refined to the gray edges and
 * read, the costly steps. The whole-frame search keeps every contour ({@link #off}), so that
 * markers of any size are found there.
 */
final class ContourSizeFilter implements PolygonHelper {
    private int min;
    private int max = Integer.MAX_VALUE;

    /** Only contours of {@code min} to {@code max} pixels pass. */
    void set(int min, int max) {
        this.min = min;
        this.max = max;
    }

    void off() {
        set(0, Integer.MAX_VALUE);
    }

    @Override
    public boolean filterContour(List<Point2D_I32> contour, boolean touchesBorder, boolean distorted) {
        return contour.size() >= min && contour.size() <= max;
    }

    @Override
    public void setImageShape(int width, int height) {
    }

    @Override
    public boolean filterPixelPolygon(Polygon2D_F64 undistorted, Polygon2D_F64 distorted, DogArray_B touches,
            boolean touchesBorder) {
        return true;
    }

    @Override
    public void configureBeforePolyline(PointsToPolyline contourToPolyline, boolean touchesBorder) {
    }
}
