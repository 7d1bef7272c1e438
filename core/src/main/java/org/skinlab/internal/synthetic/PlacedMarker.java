package org.skinlab.internal.synthetic;

import org.skinlab.ar.MarkerPattern;

/**
 * A printed marker in the synthetic scene: its pattern, the black square's width, the pose
 * {@code X_cam = R X_marker + t} (the conventions of {@link org.skinlab.ar.MarkerDetection}), and
 * an optional round occluder lying on the marker (a thumb, a pen: part of the marker hidden). Its
 * paper is {@link SyntheticCamera#PAPER_SCALE} times the black square's width.
 *
 * @param pattern        the printed code
 * @param sizeMetres     the black square's width
 * @param rotation       R, 3x3 row-major
 * @param translation    t in metres
 * @param occluderX      the occluder's centre in the marker frame (metres; x right, y up)
 * @param occluderY      see occluderX
 * @param occluderRadius its radius in metres (0: none)
 */
public record PlacedMarker(MarkerPattern pattern, double sizeMetres, double[] rotation, double[] translation,
        double occluderX, double occluderY, double occluderRadius) implements PlacedSheet {

    public PlacedMarker {
        if (rotation.length != 9 || translation.length != 3) {
            throw new IllegalArgumentException("need a 3x3 rotation and a translation");
        }
        rotation = rotation.clone();
        translation = translation.clone();
    }

    /** The marker without an occluder. */
    public static PlacedMarker of(MarkerPattern pattern, double sizeMetres, double[] rotation, double[] translation) {
        return new PlacedMarker(pattern, sizeMetres, rotation, translation, 0, 0, 0);
    }

    /** The same marker with a round occluder of {@code radius} metres centred at (x, y) of its frame. */
    public PlacedMarker occludedBy(double x, double y, double radius) {
        return new PlacedMarker(pattern, sizeMetres, rotation, translation, x, y, radius);
    }

    @Override
    public double[] rotation() {
        return rotation.clone();
    }

    @Override
    public double[] translation() {
        return translation.clone();
    }

    @Override
    public double paperHalfWidth() {
        return sizeMetres / 2 * SyntheticCamera.PAPER_SCALE;
    }

    @Override
    public double paperHalfHeight() {
        return paperHalfWidth();
    }

    @Override
    public int grayAt(double x, double y) {
        if (occluderRadius > 0 && (x - occluderX) * (x - occluderX) + (y - occluderY) * (y - occluderY)
                <= occluderRadius * occluderRadius) {
            return SyntheticCamera.OCCLUDER;
        }
        double half = sizeMetres / 2;
        return pattern.isBlackAt((x + half) / sizeMetres, (half - y) / sizeMetres) ? SyntheticCamera.INK
                : SyntheticCamera.PAPER;
    }

    /**
     * The rotation of a marker that faces the camera (R = diag(1, -1, -1): its top edge up in the
     * image, its face toward the camera) turned by {@code xDeg} about its own x axis (tilting its top
     * away), then {@code yDeg} about its y, then {@code zDeg} about its normal: R = F Rx Ry Rz.
     */
    public static double[] facingCamera(double xDeg, double yDeg, double zDeg) {
        double a = Math.toRadians(xDeg), b = Math.toRadians(yDeg), c = Math.toRadians(zDeg);
        double ca = Math.cos(a), sa = Math.sin(a), cb = Math.cos(b), sb = Math.sin(b), cc = Math.cos(c), sc = Math.sin(c);
        double[] rx = {1, 0, 0, 0, ca, -sa, 0, sa, ca};
        double[] ry = {cb, 0, sb, 0, 1, 0, -sb, 0, cb};
        double[] rz = {cc, -sc, 0, sc, cc, 0, 0, 0, 1};
        double[] f = {1, 0, 0, 0, -1, 0, 0, 0, -1};
        return multiply(multiply(multiply(f, rx), ry), rz);
    }

    static double[] multiply(double[] a, double[] b) {
        double[] m = new double[9];
        for (int i = 0; i < 3; i++) {
            for (int j = 0; j < 3; j++) {
                m[3 * i + j] = a[3 * i] * b[j] + a[3 * i + 1] * b[3 + j] + a[3 * i + 2] * b[6 + j];
            }
        }
        return m;
    }
}
