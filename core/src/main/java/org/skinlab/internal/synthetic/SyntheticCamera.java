package org.skinlab.internal.synthetic;

import java.util.List;
import java.util.Random;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;

/**
 * Renders printed markers and calibration targets into gray camera images of known pose: a
 * pinhole camera with its lens
 * ({@link CameraIntrinsics}, pixel (i, j) centred at (i, j); each sample's ray is the pixel
 * undistorted through the lens' model), each pixel the mean of
 * {@code supersampling^2} rays intersected with the sheets' planes, then blur, lighting falloff
 * and noise ({@link SceneOptions}). The ground truth for the tracker's tests and benchmark and for
 * {@code skinlab ar-demo}: plain Java, deterministic for a seed.
 *
 * <p>What a ray sees: the first sheet it hits ({@link PlacedSheet}: a calibration target, or a
 * marker's black square with its code, white paper 1.6 times the square's width around it and an
 * occluder lying on it), else the {@link Background}: a smooth texture with blocky detail and, with
 * {@link SceneOptions#clutter()}, things a detector may mistake for markers, drawn in image space.
 */
public final class SyntheticCamera {
    /** Gray levels of printed black, paper white and an occluder (a thumb in gray). */
    public static final int INK = 25;
    public static final int PAPER = 230;
    public static final int OCCLUDER = 150;
    /** The paper sheet's width over the black square's. */
    public static final double PAPER_SCALE = 1.6;

    private final CameraIntrinsics camera;

    public SyntheticCamera(CameraIntrinsics camera) {
        this.camera = camera;
    }

    public CameraIntrinsics intrinsics() {
        return camera;
    }

    /**
     * One frame of {@code sheets} (printed markers, calibration targets; none: a negative frame)
     * under {@code options}.
     */
    public GrayImage render(List<? extends PlacedSheet> sheets, SceneOptions options) {
        int w = camera.width();
        int h = camera.height();
        Random random = new Random(options.seed());
        Background background = new Background(random, w, h, options.clutter());
        double angle = random.nextDouble() * 2 * Math.PI;
        double gx = Math.cos(angle), gy = Math.sin(angle);
        double span = Math.abs(gx) * w + Math.abs(gy) * h;
        double g0 = Math.min(0, gx * (w - 1)) + Math.min(0, gy * (h - 1));
        Sheet[] planes = new Sheet[sheets.size()];
        for (int i = 0; i < planes.length; i++) {
            planes[i] = new Sheet(sheets.get(i));
        }
        int n = options.supersampling();
        boolean lens = camera.isDistorted();
        float[] image = new float[w * h];
        // Rows in parallel: a frame is millions of rays, and nothing below is shared but read.
        java.util.stream.IntStream.range(0, h).parallel().forEach(y -> {
            double[] ray = new double[2];
            for (int x = 0; x < w; x++) {
                double sum = 0;
                for (int sy = 0; sy < n; sy++) {
                    double py = y + (sy + 0.5) / n - 0.5;
                    for (int sx = 0; sx < n; sx++) {
                        double px = x + (sx + 0.5) / n - 0.5;
                        if (lens && !camera.toNormalized(px, py, ray)) {
                            // Beyond where the lens model inverts: nothing the tracker can use.
                            sum += background.at(px, py);
                            continue;
                        }
                        double dx = lens ? ray[0] : (px - camera.cx()) / camera.fx();
                        double dy = lens ? ray[1] : (py - camera.cy()) / camera.fy();
                        sum += sample(planes, background, px, py, dx, dy);
                    }
                }
                double light = 1 - options.gradient() * ((gx * x + gy * y - g0) / span);
                image[y * w + x] = (float) (sum / (n * n) * light);
            }
        });
        if (options.blurSigma() > 0) {
            blur(image, w, h, options.blurSigma());
        }
        byte[] pixels = new byte[w * h];
        for (int i = 0; i < pixels.length; i++) {
            double v = image[i] + (options.noiseSigma() > 0 ? random.nextGaussian() * options.noiseSigma() : 0);
            pixels[i] = (byte) Math.max(0, Math.min(255, Math.round(v)));
        }
        return new GrayImage(w, h, w, pixels);
    }

    /**
     * Where the marker's corners (TL, TR, BR, BL of the black square) project, x0, y0, ..., x3, y3 in
     * pixels: the ground truth of a detection's corners.
     */
    public double[] projectCorners(PlacedMarker marker) {
        double r = marker.sizeMetres() / 2;
        double[] mx = {-r, r, r, -r};
        double[] my = {r, r, -r, -r};
        double[] rot = marker.rotation();
        double[] t = marker.translation();
        double[] out = new double[8];
        double[] pixel = new double[2];
        for (int i = 0; i < 4; i++) {
            double x = rot[0] * mx[i] + rot[1] * my[i] + t[0];
            double y = rot[3] * mx[i] + rot[4] * my[i] + t[1];
            double z = rot[6] * mx[i] + rot[7] * my[i] + t[2];
            camera.toPixel(x, y, z, pixel);
            out[2 * i] = pixel[0];
            out[2 * i + 1] = pixel[1];
        }
        return out;
    }

    private static double sample(Sheet[] sheets, Background background, double px, double py, double dx, double dy) {
        double nearest = Double.POSITIVE_INFINITY;
        Sheet hit = null;
        for (Sheet s : sheets) {
            double depth = s.depth(dx, dy);
            if (depth < nearest) {
                nearest = depth;
                hit = s;
            }
        }
        return hit != null ? hit.value(dx, dy, nearest) : background.at(px, py);
    }

    /** One sheet's plane: where rays meet it, in its frame. Immutable, shared by the rendering threads. */
    private static final class Sheet {
        final PlacedSheet print;
        final double[] r;
        final double[] t;
        final double nx, ny, nz, nt;
        final double halfWidth, halfHeight;

        Sheet(PlacedSheet s) {
            print = s;
            r = s.rotation();
            t = s.translation();
            nx = r[2];
            ny = r[5];
            nz = r[8];
            nt = nx * t[0] + ny * t[1] + nz * t[2];
            halfWidth = s.paperHalfWidth();
            halfHeight = s.paperHalfHeight();
        }

        /** The depth at which the ray (dx, dy, 1) meets the paper, or +infinity when it misses. */
        double depth(double dx, double dy) {
            double nd = nx * dx + ny * dy + nz;
            if (Math.abs(nd) < 1e-12) {
                return Double.POSITIVE_INFINITY;
            }
            double lambda = nt / nd;
            if (!(lambda > 0)) {
                return Double.POSITIVE_INFINITY;
            }
            double px = lambda * dx - t[0], py = lambda * dy - t[1], pz = lambda - t[2];
            double x = r[0] * px + r[3] * py + r[6] * pz;
            double y = r[1] * px + r[4] * py + r[7] * pz;
            return Math.abs(x) > halfWidth || Math.abs(y) > halfHeight ? Double.POSITIVE_INFINITY : lambda;
        }

        /** The gray level where the ray meets the paper at {@code lambda}. */
        double value(double dx, double dy, double lambda) {
            double px = lambda * dx - t[0], py = lambda * dy - t[1], pz = lambda - t[2];
            // X_sheet = R^T (X_cam - t)
            double x = r[0] * px + r[3] * py + r[6] * pz;
            double y = r[1] * px + r[4] * py + r[7] * pz;
            return print.grayAt(x, y);
        }
    }

    /** Separable Gaussian blur in place, edges clamped. */
    private static void blur(float[] image, int w, int h, double sigma) {
        int radius = (int) Math.ceil(3 * sigma);
        float[] kernel = new float[2 * radius + 1];
        double sum = 0;
        for (int i = -radius; i <= radius; i++) {
            kernel[i + radius] = (float) Math.exp(-i * i / (2 * sigma * sigma));
            sum += kernel[i + radius];
        }
        for (int i = 0; i < kernel.length; i++) {
            kernel[i] /= (float) sum;
        }
        float[] tmp = new float[image.length];
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                float s = 0;
                for (int k = -radius; k <= radius; k++) {
                    int xx = Math.min(w - 1, Math.max(0, x + k));
                    s += kernel[k + radius] * image[y * w + xx];
                }
                tmp[y * w + x] = s;
            }
        }
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                float s = 0;
                for (int k = -radius; k <= radius; k++) {
                    int yy = Math.min(h - 1, Math.max(0, y + k));
                    s += kernel[k + radius] * tmp[yy * w + x];
                }
                image[y * w + x] = s;
            }
        }
    }
}
