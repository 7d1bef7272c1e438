package org.skinlab.android.logic;

import java.util.Arrays;

import org.skinlab.ar.CameraIntrinsics;
import org.skinlab.ar.LensDistortion;

/**
 * The camera's intrinsics for a stream, from what Camera2 reports ({@link CameraReport}), and
 * whether the capture request must turn the camera's own distortion correction off for them to
 * hold.
 *
 * <p><b>The pinhole</b>, best source first: the calibration ({@code LENS_INTRINSIC_CALIBRATION}),
 * else the focal length and the sensor's physical size (principal point at the centre), else a
 * {@value #FALLBACK_FOV_DEGREES}-degree guess. The calibration's skew is not modelled. A stream of
 * another aspect than the array is a centred crop of it, scaled (Camera2's rule), so the numbers
 * are cropped and scaled the same way, pixel edges to pixel edges; the lens' terms, normalised
 * coordinates, do not change.
 *
 * <p><b>The lens and the device's own correction.</b> The calibration and the lens are given in
 * the pre-correction active array, the raw optics. Camera2 devices that can correct distortion
 * (DISTORTION_CORRECTION_AVAILABLE_MODES lists more than OFF; on by default, and FAST "may be the
 * same as OFF", so from the request alone nobody knows whether a stream is corrected) produce
 * streams of the active array instead, undistorted: there the pinhole is the calibration moved by
 * the offset between the two arrays (both are given in pixel-array coordinates; Camera2's mapping
 * from corrected to output pixels is that translation) and no lens may be applied again. Hence:
 * <ul>
 * <li>A usable lens ({@link Camera2Lens}) and a device that does not correct (API 28: no
 *     correction modes but OFF; below 28, where the control does not exist: both arrays the
 *     same): the raw image, the calibration as it is, with the lens.</li>
 * <li>A usable lens and a device that corrects, API 28 or later, OFF listed: the request sets
 *     DISTORTION_CORRECTION_MODE to OFF ({@link #correctionOff()}) and the stream is the raw image,
 *     as above. We undistort exactly what the calibration describes, not whatever the device's
 *     FAST mode did.</li>
 * <li>A usable lens and a device that may correct but cannot be told not to (below API 28 with the
 *     arrays differing): the lens is not used.</li>
 * <li>No usable lens (no key, an ideal lens, bad values, a lens whose inverse fails inside the
 *     stream), or no calibration: the device's default stands, and the pinhole is the calibration
 *     moved into the active array, without a lens, as before lenses were read.</li>
 * </ul>
 * A lens that was reported but is not used says why in {@link #problem()}.
 *
 * @param intrinsics    the stream's intrinsics
 * @param correctionOff whether the capture request must set DISTORTION_CORRECTION_MODE to OFF
 * @param problem       why a reported lens is not used, or null
 */
public record IntrinsicsEstimate(CameraIntrinsics intrinsics, boolean correctionOff, String problem) {
    /** The horizontal field of view assumed when the camera reports nothing (a typical phone main camera). */
    public static final double FALLBACK_FOV_DEGREES = 65;
    /** Samples along each ray from the principal point in {@link #oneToOneInside}. */
    private static final int RAY_STEPS = 32;

    /** The intrinsics of a {@code streamWidth} x {@code streamHeight} stream of the camera {@code r} describes. */
    public static IntrinsicsEstimate of(CameraReport r, int streamWidth, int streamHeight) {
        int[] active = r.active();
        if (active == null || width(active) <= 0 || height(active) <= 0) {
            return new IntrinsicsEstimate(fallback(streamWidth, streamHeight), false, null);
        }
        int[] pre = r.preCorrection() != null && width(r.preCorrection()) > 0 && height(r.preCorrection()) > 0
                ? r.preCorrection() : active;
        float[] c = r.calibration();
        boolean calibrated = c != null && c.length >= 4 && c[0] > 0 && c[1] > 0 && Float.isFinite(c[0])
                && Float.isFinite(c[1]) && Float.isFinite(c[2]) && Float.isFinite(c[3]);
        if (!calibrated) {
            return new IntrinsicsEstimate(uncalibrated(r, active, streamWidth, streamHeight), false,
                    lensReported(r) ? "lens distortion not used: no LENS_INTRINSIC_CALIBRATION to normalise it" : null);
        }
        // Camera2 centres pixel x at x + 0.5; ours at x.
        double cx = c[2] - 0.5;
        double cy = c[3] - 0.5;
        Camera2Lens.Reading lens = r.sdk() >= 28 ? Camera2Lens.fromLensDistortion(r.lensDistortion())
                : Camera2Lens.fromRadialDistortion(r.radialDistortion(), c[0], c[1], c[2], c[3], width(pre),
                        height(pre));
        // The pinhole of the corrected image in the active array: the fallback of every case below.
        CameraIntrinsics corrected = crop(width(active), height(active), c[0], c[1], cx + pre[0] - active[0],
                cy + pre[1] - active[1], streamWidth, streamHeight);
        if (lens.lens() == null) {
            return new IntrinsicsEstimate(corrected, false, lens.problem() == null ? null
                    : "lens distortion not used: " + lens.problem());
        }
        boolean correcting;
        boolean canTurnOff;
        if (r.sdk() >= 28) {
            int[] modes = r.correctionModes();
            correcting = modes == null ? !Arrays.equals(pre, active) : listsOtherThanOff(modes);
            canTurnOff = modes != null && lists(modes, CameraReport.CORRECTION_OFF);
        } else {
            correcting = !Arrays.equals(pre, active);
            canTurnOff = false;
        }
        if (correcting && !canTurnOff) {
            return new IntrinsicsEstimate(corrected, false, "lens distortion not used: the camera may correct it"
                    + " itself and cannot be told not to");
        }
        double f = lens.focalScale();
        CameraIntrinsics raw = crop(width(pre), height(pre), c[0] * f, c[1] * f, cx, cy, streamWidth, streamHeight)
                .withDistortion(lens.lens());
        String fails = oneToOneInside(raw);
        if (fails != null) {
            return new IntrinsicsEstimate(corrected, false, "lens distortion not used: " + fails);
        }
        return new IntrinsicsEstimate(raw, correcting, null);
    }

    /**
     * Null when the lens maps the ideal image one-to-one onto the whole stream, else why not, at
     * the first border point where it does not. For the rays from the principal point to the
     * corners and the edges' midpoints: the border point must undistort, and distorting the ideal
     * ray from the centre out to that ideal point must move outward all the way. The second test catches a lens
     * whose radius folds back and rises again (a large negative k1 with a positive k2): its border
     * points may undistort, onto the outer branch, while the image between shows some of the world
     * twice.
     */
    private static String oneToOneInside(CameraIntrinsics k) {
        double[] ideal = new double[2];
        double[] pixel = new double[2];
        double right = k.width() - 0.5;
        double bottom = k.height() - 0.5;
        double[][] points = {{-0.5, -0.5}, {right, -0.5}, {right, bottom}, {-0.5, bottom},
            {k.cx(), -0.5}, {right, k.cy()}, {k.cx(), bottom}, {-0.5, k.cy()}};
        for (double[] p : points) {
            double dx = p[0] - k.cx();
            double dy = p[1] - k.cy();
            if (dx == 0 && dy == 0) {
                continue;
            }
            String where = "pixel (" + p[0] + ", " + p[1] + ")";
            if (!k.toNormalized(p[0], p[1], ideal)) {
                return "it cannot be undone at the stream's " + where;
            }
            double along = 0;
            for (int i = 1; i <= RAY_STEPS; i++) {
                double t = (double) i / RAY_STEPS;
                k.toPixel(t * ideal[0], t * ideal[1], 1, pixel);
                double next = (pixel[0] - k.cx()) * dx + (pixel[1] - k.cy()) * dy;
                if (!(next > along)) {
                    return "it folds over inside the stream, toward " + where;
                }
                along = next;
            }
        }
        return null;
    }

    /** Without a calibration: focal length and sensor width, else the field-of-view guess; no lens. */
    private static CameraIntrinsics uncalibrated(CameraReport r, int[] active, int streamWidth, int streamHeight) {
        int w = width(active);
        int h = height(active);
        if (r.focalMm() > 0 && r.activeWidthMm() > 0) {
            double f = r.focalMm() / r.activeWidthMm() * w;
            return crop(w, h, f, f, (w - 1) / 2.0, (h - 1) / 2.0, streamWidth, streamHeight);
        }
        return fallback(streamWidth, streamHeight);
    }

    private static CameraIntrinsics fallback(int streamWidth, int streamHeight) {
        return CameraIntrinsics.fromHorizontalFov(streamWidth, streamHeight, FALLBACK_FOV_DEGREES);
    }

    /**
     * The pinhole (fx, fy, cx, cy: our pixel convention) of an array of {@code arrayWidth} x
     * {@code arrayHeight}, for its centred crop with the stream's aspect scaled to the stream.
     */
    private static CameraIntrinsics crop(int arrayWidth, int arrayHeight, double fx, double fy, double cx, double cy,
            int streamWidth, int streamHeight) {
        double streamAspect = (double) streamWidth / streamHeight;
        double cropW = Math.min(arrayWidth, arrayHeight * streamAspect);
        double cropH = cropW / streamAspect;
        double cropX = (arrayWidth - cropW) / 2;
        double cropY = (arrayHeight - cropH) / 2;
        double s = streamWidth / cropW;
        return new CameraIntrinsics(streamWidth, streamHeight, fx * s, fy * s, (cx + 0.5 - cropX) * s - 0.5,
                (cy + 0.5 - cropY) * s - 0.5, LensDistortion.NONE);
    }

    /** Whether the lens key read at this API level holds anything but zeros. */
    private static boolean lensReported(CameraReport r) {
        float[] k = r.sdk() >= 28 ? r.lensDistortion() : r.radialDistortion();
        if (k != null) {
            for (float v : k) {
                if (v != 0) {
                    return true;
                }
            }
        }
        return false;
    }

    private static boolean listsOtherThanOff(int[] modes) {
        for (int m : modes) {
            if (m != CameraReport.CORRECTION_OFF) {
                return true;
            }
        }
        return false;
    }

    private static boolean lists(int[] modes, int mode) {
        for (int m : modes) {
            if (m == mode) {
                return true;
            }
        }
        return false;
    }

    private static int width(int[] rect) {
        return rect[2] - rect[0];
    }

    private static int height(int[] rect) {
        return rect[3] - rect[1];
    }
}
