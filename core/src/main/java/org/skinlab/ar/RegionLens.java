package org.skinlab.ar;

import boofcv.alg.distort.LensDistortionNarrowFOV;
import boofcv.struct.distort.Point2Transform2_F32;
import boofcv.struct.distort.Point2Transform2_F64;
import georegression.struct.point.Point2D_F32;
import georegression.struct.point.Point2D_F64;

/**
 * A camera's lens as seen from a region of its frame, for BoofCV's square detector. The detector
 * works in the pixel coordinates of the image it is given; given a region whose pixel (0, 0) is the
 * frame's (x0, y0), it would undistort the contour as if the region sat at the frame's corner,
 * which bends the square's sides (0.3 px of corner error on a real video with k1 = 0.08). Every
 * pixel coordinate in or out of these transforms is therefore shifted by the {@link #setOffset
 * offset}; a whole-frame search uses offset 0.
 *
 * <p>The pixel-to-pixel float transforms, which the detector applies to every contour pixel, look
 * the frame's whole pixels up in tables made once (what BoofCV's own cache does, which cannot
 * follow an offset); other points are computed.
 */
final class RegionLens implements LensDistortionNarrowFOV {
    private final LensDistortionNarrowFOV lens;
    private final int width;
    private final int height;
    /** Per whole pixel of the frame (x, y), its undistorted pixel (x', y'), interleaved. */
    private final float[] undistorted;
    /** Per whole pixel of the frame (x, y) as an undistorted pixel, its distorted pixel. */
    private final float[] distorted;
    private int offsetX;
    private int offsetY;

    RegionLens(LensDistortionNarrowFOV lens, int width, int height) {
        this.lens = lens;
        this.width = width;
        this.height = height;
        this.undistorted = table(lens.undistort_F32(true, true));
        this.distorted = table(lens.distort_F32(true, true));
    }

    /** The region's pixel (0, 0) is the frame's ({@code x0}, {@code y0}). */
    void setOffset(int x0, int y0) {
        offsetX = x0;
        offsetY = y0;
    }

    private float[] table(Point2Transform2_F32 t) {
        float[] out = new float[2 * width * height];
        Point2D_F32 p = new Point2D_F32();
        for (int y = 0, i = 0; y < height; y++) {
            for (int x = 0; x < width; x++, i += 2) {
                t.compute(x, y, p);
                out[i] = p.x;
                out[i + 1] = p.y;
            }
        }
        return out;
    }

    @Override
    public Point2Transform2_F64 distort_F64(boolean pixelIn, boolean pixelOut) {
        return new Shifted64(lens.distort_F64(pixelIn, pixelOut), pixelIn, pixelOut);
    }

    @Override
    public Point2Transform2_F32 distort_F32(boolean pixelIn, boolean pixelOut) {
        return new Shifted32(lens.distort_F32(pixelIn, pixelOut), pixelIn, pixelOut,
                pixelIn && pixelOut ? distorted : null);
    }

    @Override
    public Point2Transform2_F64 undistort_F64(boolean pixelIn, boolean pixelOut) {
        return new Shifted64(lens.undistort_F64(pixelIn, pixelOut), pixelIn, pixelOut);
    }

    @Override
    public Point2Transform2_F32 undistort_F32(boolean pixelIn, boolean pixelOut) {
        return new Shifted32(lens.undistort_F32(pixelIn, pixelOut), pixelIn, pixelOut,
                pixelIn && pixelOut ? undistorted : null);
    }

    @Override
    public Point2Transform2_F32 normalized_F32() {
        return new Shifted32(lens.normalized_F32(), true, false, null);
    }

    @Override
    public Point2Transform2_F64 normalized_F64() {
        return new Shifted64(lens.normalized_F64(), true, false);
    }

    private final class Shifted32 implements Point2Transform2_F32 {
        private final Point2Transform2_F32 frame;
        private final boolean pixelIn;
        private final boolean pixelOut;
        private final float[] table;

        Shifted32(Point2Transform2_F32 frame, boolean pixelIn, boolean pixelOut, float[] table) {
            this.frame = frame;
            this.pixelIn = pixelIn;
            this.pixelOut = pixelOut;
            this.table = table;
        }

        @Override
        public void compute(float x, float y, Point2D_F32 out) {
            float fx = pixelIn ? x + offsetX : x;
            float fy = pixelIn ? y + offsetY : y;
            int ix = (int) fx;
            int iy = (int) fy;
            if (table != null && ix == fx && iy == fy && ix >= 0 && iy >= 0 && ix < width && iy < height) {
                int i = 2 * (iy * width + ix);
                out.x = table[i];
                out.y = table[i + 1];
            } else {
                frame.compute(fx, fy, out);
            }
            if (pixelOut) {
                out.x -= offsetX;
                out.y -= offsetY;
            }
        }

        @Override
        public Point2Transform2_F32 copyConcurrent() {
            return new Shifted32(frame.copyConcurrent(), pixelIn, pixelOut, table);
        }
    }

    private final class Shifted64 implements Point2Transform2_F64 {
        private final Point2Transform2_F64 frame;
        private final boolean pixelIn;
        private final boolean pixelOut;

        Shifted64(Point2Transform2_F64 frame, boolean pixelIn, boolean pixelOut) {
            this.frame = frame;
            this.pixelIn = pixelIn;
            this.pixelOut = pixelOut;
        }

        @Override
        public void compute(double x, double y, Point2D_F64 out) {
            frame.compute(pixelIn ? x + offsetX : x, pixelIn ? y + offsetY : y, out);
            if (pixelOut) {
                out.x -= offsetX;
                out.y -= offsetY;
            }
        }

        @Override
        public Point2Transform2_F64 copyConcurrent() {
            return new Shifted64(frame.copyConcurrent(), pixelIn, pixelOut);
        }
    }
}
