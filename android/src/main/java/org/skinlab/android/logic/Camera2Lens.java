package org.skinlab.android.logic;

import java.util.Arrays;
import java.util.Locale;

import org.skinlab.ar.LensDistortion;

/**
 * Camera2's two lens-distortion keys as our {@link LensDistortion} (Brown-Conrady in normalised
 * coordinates, {@code x = X / Z}): the lens, and the factor by which the focal lengths of
 * LENS_INTRINSIC_CALIBRATION must be multiplied for the distorted image.
 *
 * <p>Both keys give, for a point (x_i, y_i) of the corrected (ideal pinhole) image, the point
 * (x_c, y_c) of the camera's raw image to sample there: ideal to distorted, the direction of
 * {@link LensDistortion#distort}.
 *
 * <p><b>LENS_DISTORTION</b> (API 28) {@code [kappa_1 .. kappa_5]}: {@code x_c = x_i (1 + kappa_1 r^2
 * + kappa_2 r^4 + kappa_3 r^6) + kappa_4 (2 x_i y_i) + kappa_5 (r^2 + 2 x_i^2)}, {@code y_c = y_i (..)
 * + kappa_5 (2 x_i y_i) + kappa_4 (r^2 + 2 y_i^2)}, in the coordinates of the intrinsic calibration
 * ({@code x_i = (u - c_x) / f_x}): OpenCV's k1, k2, k3, p1 = kappa_4, p2 = kappa_5 as they are.
 *
 * <p><b>LENS_RADIAL_DISTORTION</b> (API 23, deprecated in 28 as "inconsistently defined in terms
 * of its normalization") {@code [kappa_0 .. kappa_5]}: the same form with {@code kappa_0} in place
 * of the 1, and x and y "normalized to be 1 at the edge further from the optical center", so that
 * both range over [-1, 1]: {@code x_i = (u - c_x) / R_x}, {@code R_x = max(c_x, W - c_x)} (the
 * array's edges at 0 and W), {@code y_i = (v - c_y) / R_y} likewise. With {@code x = (u - c_x) / f_x}
 * that is {@code x_i = a x}, {@code y_i = b y}, {@code a = f_x / R_x}, {@code b = f_y / R_y}, and
 * {@code r_i^2 = a^2 x^2 + b^2 y^2}. Only when {@code a = b} (call it s) is the radial term a
 * function of {@code r^2 = x^2 + y^2}; then, multiplying out {@code u_c - c_x = R_x x_c}:
 * <pre>
 *   u_c - c_x = f_x kappa_0 [x (1 + (kappa_1 s^2 / kappa_0) r^2 + (kappa_2 s^4 / kappa_0) r^4
 *               + (kappa_3 s^6 / kappa_0) r^6) + 2 (kappa_4 s / kappa_0) x y + (kappa_5 s / kappa_0) (r^2 + 2 x^2)]
 * </pre>
 * and the same for v: exactly Brown-Conrady with k1 = kappa_1 s^2 / kappa_0, k2 = kappa_2 s^4 /
 * kappa_0, k3 = kappa_3 s^6 / kappa_0, p1 = kappa_4 s / kappa_0, p2 = kappa_5 s / kappa_0, and focal
 * lengths f kappa_0. When a and b differ (a 4:3 array with its centre on the optical axis: b = 4a/3)
 * the old model's radial distortion is elliptical in normalised coordinates, which Brown-Conrady
 * cannot express: the lens is then not used (a fit would be an approximation of a key whose
 * normalisation devices did not agree on).
 */
public final class Camera2Lens {
    /** a and b equal to float precision (the calibration's floats carry 7 digits). */
    private static final double SAME_SCALE = 1e-5;

    private Camera2Lens() {
    }

    /**
     * A lens read from a key: {@code lens} null when there is none to use, with {@code problem}
     * saying why when the camera reported one (null when it reported nothing or an ideal lens).
     *
     * @param lens       the Brown-Conrady terms, or null
     * @param focalScale what the calibration's focal lengths are multiplied by (1 but for kappa_0)
     * @param problem    why a reported lens is not used, or null
     */
    public record Reading(LensDistortion lens, double focalScale, String problem) {
        static final Reading NONE = new Reading(null, 1, null);

        static Reading unusable(String why) {
            return new Reading(null, 1, why);
        }
    }

    /** LENS_DISTORTION {@code [k1, k2, k3, p1, p2]}, or null. */
    public static Reading fromLensDistortion(float[] k) {
        if (k == null) {
            return Reading.NONE;
        }
        if (k.length != 5 || !finite(k)) {
            return Reading.unusable("LENS_DISTORTION is not 5 finite numbers: " + Arrays.toString(k));
        }
        LensDistortion lens = new LensDistortion(k[0], k[1], k[2], k[3], k[4]);
        return lens.isNone() ? Reading.NONE : new Reading(lens, 1, null);
    }

    /**
     * LENS_RADIAL_DISTORTION {@code [kappa_0 .. kappa_5]}, or null, with the calibration it is
     * normalised by (Camera2's convention: pixel x centred at x + 0.5) and the size of the
     * pre-correction array it covers.
     */
    public static Reading fromRadialDistortion(float[] kappa, double fx, double fy, double cx, double cy, int width,
            int height) {
        if (kappa == null || allZero(kappa)) {
            return Reading.NONE;
        }
        if (kappa.length != 6 || !finite(kappa)) {
            return Reading.unusable("LENS_RADIAL_DISTORTION is not 6 finite numbers: " + Arrays.toString(kappa));
        }
        double k0 = kappa[0];
        if (!(k0 > 0)) {
            return Reading.unusable("LENS_RADIAL_DISTORTION's kappa_0 is not positive: " + k0);
        }
        double rx = Math.max(cx, width - cx);
        double ry = Math.max(cy, height - cy);
        double a = fx / rx;
        double b = fy / ry;
        if (!(Math.abs(a / b - 1) <= SAME_SCALE)) {
            return Reading.unusable(String.format(Locale.ROOT, "LENS_RADIAL_DISTORTION is normalised differently in x"
                    + " and y (f/R %.4f and %.4f): not a Brown-Conrady lens", a, b));
        }
        double s = a;
        double s2 = s * s;
        LensDistortion lens = new LensDistortion(kappa[1] * s2 / k0, kappa[2] * s2 * s2 / k0,
                kappa[3] * s2 * s2 * s2 / k0, kappa[4] * s / k0, kappa[5] * s / k0);
        if (lens.isNone() && k0 == 1) {
            return Reading.NONE;
        }
        return new Reading(lens, k0, null);
    }

    private static boolean finite(float[] values) {
        for (float v : values) {
            if (!Float.isFinite(v)) {
                return false;
            }
        }
        return true;
    }

    private static boolean allZero(float[] values) {
        for (float v : values) {
            if (v != 0) {
                return false;
            }
        }
        return true;
    }
}
