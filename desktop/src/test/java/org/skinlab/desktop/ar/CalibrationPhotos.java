package org.skinlab.desktop.ar;

import java.util.ArrayList;
import java.util.Collections;
import java.util.List;

import org.skinlab.internal.ar.CalibrationTarget;
import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.GrayImage;
import org.skinlab.ar.LensDistortion;
import org.skinlab.internal.synthetic.PlacedMarker;
import org.skinlab.internal.synthetic.PlacedTarget;
import org.skinlab.internal.synthetic.SceneOptions;
import org.skinlab.internal.synthetic.SyntheticCamera;

/**
 * Synthetic photos of the printed calibration target through a known lens, as a user would take
 * them: 14 views at 0.3 to 0.5 m, the target in the middle, near each corner and each edge of the
 * image, turned and tipped up to 45 degrees, with blur (0.8 px), noise (sigma 3) and uneven light
 * ({@link SceneOptions#camera}, with 3x3 samples per pixel). Rendered once per test JVM (about a
 * second each) and shared.
 */
public final class CalibrationPhotos {
    /** The lens: a webcam's barrel distortion, principal point a few pixels off centre. */
    public static final CameraIntrinsics CAMERA = new CameraIntrinsics(640, 480, 520, 521.5, 323.7, 236.2,
            new LensDistortion(-0.30, 0.10, 0, 0.001, -0.0007));
    /** The default printable target: a chessboard of 7 x 10 squares of 20 mm. */
    public static final CalibrationTarget TARGET = CalibrationTarget.chessboard(7, 10, 0.020);

    /** Per view: the target centre's image position (fractions of width and height), distance (m), turns (deg). */
    private static final double[][] VIEWS = {
        {0.50, 0.50, 0.42, 0, 0, 0},
        {0.50, 0.50, 0.27, 12, -10, 5},
        {0.28, 0.30, 0.40, 25, -20, -10},
        {0.72, 0.30, 0.40, 20, 30, 15},
        {0.72, 0.70, 0.40, -30, 20, -8},
        {0.28, 0.70, 0.40, -20, -30, 12},
        {0.50, 0.25, 0.40, 35, 0, 0},
        {0.50, 0.70, 0.44, -35, 5, 90},
        {0.25, 0.50, 0.38, 0, -40, 90},
        {0.75, 0.50, 0.38, 5, 40, -90},
        {0.50, 0.50, 0.33, 45, 10, 30},
        {0.50, 0.50, 0.33, -10, 45, -30},
        {0.45, 0.55, 0.34, 40, -35, 180},
        {0.55, 0.45, 0.33, -25, -25, 60},
    };

    private static List<PlacedTarget> poses;
    private static List<GrayImage> images;

    private CalibrationPhotos() {
    }

    /** The target's poses, one per photo. */
    public static synchronized List<PlacedTarget> poses() {
        if (poses == null) {
            List<PlacedTarget> list = new ArrayList<>();
            double[] ray = new double[2];
            for (double[] v : VIEWS) {
                CAMERA.toNormalized(v[0] * (CAMERA.width() - 1), v[1] * (CAMERA.height() - 1), ray);
                list.add(new PlacedTarget(TARGET, PlacedMarker.facingCamera(v[3], v[4], v[5]),
                        new double[] {ray[0] * v[2], ray[1] * v[2], v[2]}));
            }
            poses = Collections.unmodifiableList(list);
        }
        return poses;
    }

    /** A photo of the same scene without the target. */
    public static GrayImage withoutTarget() {
        return new SyntheticCamera(CAMERA).render(List.of(), new SceneOptions(0.8, 3, 0.3, 0, 3, 99));
    }

    /** The photos, in the order of {@link #poses}. */
    public static synchronized List<GrayImage> images() {
        if (images == null) {
            SyntheticCamera camera = new SyntheticCamera(CAMERA);
            List<GrayImage> list = new ArrayList<>();
            List<PlacedTarget> p = poses();
            for (int i = 0; i < p.size(); i++) {
                list.add(camera.render(List.of(p.get(i)), new SceneOptions(0.8, 3, 0.3, 0, 3, 100 + i)));
            }
            images = Collections.unmodifiableList(list);
        }
        return images;
    }

    /**
     * The smallest distance in pixels from the target's outer edge (pattern plus quiet zone) to the
     * image border in view {@code i}: the photo shows the whole target when it is positive.
     */
    public static double clearance(int i) {
        PlacedTarget t = poses().get(i);
        double m = TARGET.squareMetres();
        double[] cam = new double[3];
        double[] px = new double[2];
        double min = Double.POSITIVE_INFINITY;
        int steps = 20;
        for (int s = 0; s <= steps; s++) {
            double f = (double) s / steps;
            double[][] edge = {{-m + f * (TARGET.width() + 2 * m), -m}, {-m + f * (TARGET.width() + 2 * m),
                TARGET.height() + m}, {-m, -m + f * (TARGET.height() + 2 * m)}, {TARGET.width() + m,
                -m + f * (TARGET.height() + 2 * m)}};
            for (double[] e : edge) {
                toCamera(t, e[0], e[1], cam);
                CAMERA.toPixel(cam[0], cam[1], cam[2], px);
                min = Math.min(min, Math.min(Math.min(px[0] + 0.5, CAMERA.width() - 0.5 - px[0]),
                        Math.min(px[1] + 0.5, CAMERA.height() - 0.5 - px[1])));
            }
        }
        return min;
    }

    /**
     * Where the point (x, y) of {@code placed}'s pattern lies in the camera frame (metres; x right
     * and y down from the pattern's top-left corner, {@link CalibrationTarget#isBlackAt}'s frame).
     */
    public static void toCamera(PlacedTarget placed, double x, double y, double[] out) {
        CalibrationTarget t = placed.target();
        double[] r = placed.rotation();
        double[] tr = placed.translation();
        // The sheet frame: origin at the pattern's centre, y up.
        double sx = x - t.width() / 2;
        double sy = t.height() / 2 - y;
        for (int i = 0; i < 3; i++) {
            out[i] = r[3 * i] * sx + r[3 * i + 1] * sy + tr[i];
        }
    }
}
