package org.skinlab.ar;

import boofcv.alg.distort.LensDistortionNarrowFOV;
import boofcv.struct.distort.Point2Transform2_F32;
import boofcv.struct.distort.Point2Transform2_F64;
import georegression.struct.point.Point2D_F32;
import georegression.struct.point.Point2D_F64;

/**
 * A lens for BoofCV's square detector when it looks at a part of the frame. BoofCV applies the
 * lens to the pixel coordinates of the image it is given, and a subimage's pixel (0, 0) is the
 * frame's (x0, y0): given the frame's lens, it would undo the distortion around the wrong centre
 * (measured: corners off by up to 0.63 px, poses by up to 5.2 mm, where the whole-frame search is
 * right). Here every pixel coordinate, distorted or undistorted, is the region's: the frame's lens
 * is applied at the pixel plus (x0, y0), and (x0, y0) is taken off again, so the detector fits the
 * square's sides where they are straight, reads its bits where they are, and its own checks against
 * the image's bounds see coordinates of the image it has. One instance per detector; the transforms
 * read the offset at each call, so moving the region needs no reconfiguration.
 *
 * <p>BoofCV's own per-pixel tables (it calls its pixel transforms at whole pixels: the contour's,
 * and more) assume the image it was configured with and are therefore not used; the same two
 * tables, pixel to pixel undistorted and distorted, are kept here for the whole frame (four floats
 * per pixel) and read at the region's offset.
 */
final class RegionLens implements LensDistortionNarrowFOV {
    private final LensDistortionNarrowFOV frame;
    private final int width;
    private final int height;
    /** Per frame pixel (x, y), at 2 (y width + x): where it is undistorted, in frame pixels. */
    private final float[] undistorted;
    /** Per undistorted frame pixel (x, y), at 2 (y width + x): where it appears, in frame pixels. */
    private final float[] distorted;
    private int x0;
    private int y0;

    /** The lens {@code frame} of a camera of {@code width x height} pixels (BoofCV's pixel convention). */
    RegionLens(LensDistortionNarrowFOV frame, int width, int height) {
        this.frame = frame;
        this.width = width;
        this.height = height;
        undistorted = table(frame.undistort_F32(true, true), width, height);
        distorted = table(frame.distort_F32(true, true), width, height);
    }

    private static float[] table(Point2Transform2_F32 t, int width, int height) {
        float[] table = new float[2 * width * height];
        Point2D_F32 p = new Point2D_F32();
        for (int y = 0; y < height; y++) {
            for (int x = 0; x < width; x++) {
                t.compute(x, y, p);
                table[2 * (y * width + x)] = p.x;
                table[2 * (y * width + x) + 1] = p.y;
            }
        }
        return table;
    }

    /** The region's pixel (0, 0) is the frame's ({@code x0}, {@code y0}); (0, 0) for the whole frame. */
    void moveTo(int x0, int y0) {
        this.x0 = x0;
        this.y0 = y0;
    }

    @Override
    public Point2Transform2_F64 distort_F64(boolean pixelIn, boolean pixelOut) {
        return shifted(frame.distort_F64(pixelIn, pixelOut), pixelIn, pixelOut);
    }

    @Override
    public Point2Transform2_F32 distort_F32(boolean pixelIn, boolean pixelOut) {
        Point2Transform2_F32 exact = shifted(frame.distort_F32(pixelIn, pixelOut), pixelIn, pixelOut);
        return pixelIn && pixelOut ? tabled(exact, distorted) : exact;
    }

    @Override
    public Point2Transform2_F64 undistort_F64(boolean pixelIn, boolean pixelOut) {
        return shifted(frame.undistort_F64(pixelIn, pixelOut), pixelIn, pixelOut);
    }

    @Override
    public Point2Transform2_F32 undistort_F32(boolean pixelIn, boolean pixelOut) {
        Point2Transform2_F32 exact = shifted(frame.undistort_F32(pixelIn, pixelOut), pixelIn, pixelOut);
        return pixelIn && pixelOut ? tabled(exact, undistorted) : exact;
    }

    /** A pixel to pixel transform: whole pixels of the frame from {@code table}, others by {@code exact}. */
    private Point2Transform2_F32 tabled(Point2Transform2_F32 exact, float[] table) {
        return new Point2Transform2_F32() {
            @Override
            public void compute(float x, float y, Point2D_F32 out) {
                int fx = (int) x + x0;
                int fy = (int) y + y0;
                if (x == (int) x && y == (int) y && fx >= 0 && fy >= 0 && fx < width && fy < height) {
                    int i = 2 * (fy * width + fx);
                    out.x = table[i] - x0;
                    out.y = table[i + 1] - y0;
                } else {
                    exact.compute(x, y, out);
                }
            }

            @Override
            public Point2Transform2_F32 copyConcurrent() {
                return tabled(exact.copyConcurrent(), table);
            }
        };
    }

    /** Undistorted pixels to normalised coordinates: pixels in, so shifted in. */
    @Override
    public Point2Transform2_F32 normalized_F32() {
        return shifted(frame.normalized_F32(), true, false);
    }

    @Override
    public Point2Transform2_F64 normalized_F64() {
        return shifted(frame.normalized_F64(), true, false);
    }

    /** {@code t} on region pixels: (x0, y0) added to pixel input, taken off pixel output. */
    private Point2Transform2_F64 shifted(Point2Transform2_F64 t, boolean pixelIn, boolean pixelOut) {
        return new Point2Transform2_F64() {
            @Override
            public void compute(double x, double y, Point2D_F64 out) {
                double dx = pixelIn ? x0 : 0;
                double dy = pixelIn ? y0 : 0;
                t.compute(x + dx, y + dy, out);
                if (pixelOut) {
                    out.x -= x0;
                    out.y -= y0;
                }
            }

            @Override
            public Point2Transform2_F64 copyConcurrent() {
                return shifted(t.copyConcurrent(), pixelIn, pixelOut);
            }
        };
    }

    private Point2Transform2_F32 shifted(Point2Transform2_F32 t, boolean pixelIn, boolean pixelOut) {
        return new Point2Transform2_F32() {
            @Override
            public void compute(float x, float y, Point2D_F32 out) {
                float dx = pixelIn ? (float) x0 : 0;
                float dy = pixelIn ? (float) y0 : 0;
                t.compute(x + dx, y + dy, out);
                if (pixelOut) {
                    out.x -= (float) x0;
                    out.y -= (float) y0;
                }
            }

            @Override
            public Point2Transform2_F32 copyConcurrent() {
                return shifted(t.copyConcurrent(), pixelIn, pixelOut);
            }
        };
    }
}
