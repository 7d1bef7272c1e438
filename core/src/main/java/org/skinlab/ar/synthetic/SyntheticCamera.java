package org.skinlab.ar.synthetic;

import java.util.List;
import java.util.Random;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.MarkerPattern;

/**
 * Renders printed markers into gray camera images of known pose: a pinhole camera with its lens
 * ({@link CameraIntrinsics}, pixel (i, j) centred at (i, j); each sample's ray is the pixel
 * undistorted through the lens' model), each pixel the mean of
 * {@code supersampling^2} rays intersected with the markers' planes, then blur, lighting falloff
 * and noise ({@link SceneOptions}). The ground truth for the tracker's tests and benchmark and for
 * {@code skinlab ar-demo}: plain Java, deterministic for a seed.
 *
 * <p>What a ray sees: the first marker sheet it hits (the black square with its code, white paper
 * 1.6 times the square's width around it, an occluder lying on it), else the {@link Background}:
 * a smooth texture with blocky detail and, with {@link SceneOptions#clutter()}, things a detector
 * may mistake for markers, drawn in image space.
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

    /** One frame of {@code markers} (none: a negative frame) under {@code options}. */
    public GrayImage render(List<PlacedMarker> markers, SceneOptions options) {
        int w = camera.width();
        int h = camera.height();
        Random random = new Random(options.seed());
        Background background = new Background(random, w, h, options.clutter());
        double angle = random.nextDouble() * 2 * Math.PI;
        double gx = Math.cos(angle), gy = Math.sin(angle);
        double span = Math.abs(gx) * w + Math.abs(gy) * h;
        double g0 = Math.min(0, gx * (w - 1)) + Math.min(0, gy * (h - 1));
        Sheet[] sheets = new Sheet[markers.size()];
        for (int i = 0; i < sheets.length; i++) {
            sheets[i] = new Sheet(markers.get(i));
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
                        sum += sample(sheets, background, px, py, dx, dy);
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

    /** One marker's plane: where rays meet it, in its frame. Immutable, shared by the rendering threads. */
    private static final class Sheet {
        final MarkerPattern pattern;
        final double[] r;
        final double[] t;
        final double nx, ny, nz, nt;
        final double half, paperHalf;
        final double ox, oy, or2;

        Sheet(PlacedMarker m) {
            pattern = m.pattern();
            r = m.rotation();
            t = m.translation();
            nx = r[2];
            ny = r[5];
            nz = r[8];
            nt = nx * t[0] + ny * t[1] + nz * t[2];
            half = m.sizeMetres() / 2;
            paperHalf = half * PAPER_SCALE;
            ox = m.occluderX();
            oy = m.occluderY();
            or2 = m.occluderRadius() * m.occluderRadius();
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
            return Math.abs(x) > paperHalf || Math.abs(y) > paperHalf ? Double.POSITIVE_INFINITY : lambda;
        }

        /** The gray level where the ray meets the paper at {@code lambda}. */
        double value(double dx, double dy, double lambda) {
            double px = lambda * dx - t[0], py = lambda * dy - t[1], pz = lambda - t[2];
            // X_marker = R^T (X_cam - t)
            double x = r[0] * px + r[3] * py + r[6] * pz;
            double y = r[1] * px + r[4] * py + r[7] * pz;
            if (or2 > 0 && (x - ox) * (x - ox) + (y - oy) * (y - oy) <= or2) {
                return OCCLUDER;
            }
            double u = (x + half) / (2 * half);
            double v = (half - y) / (2 * half);
            return pattern.isBlackAt(u, v) ? INK : PAPER;
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
