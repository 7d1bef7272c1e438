package org.skinlab.android.logic;

/**
 * What Camera2 reports about a camera's geometry, as {@code CameraSource} reads it: plain values
 * (no android.*), null or NaN where the camera reports nothing or the key is not read at this
 * API level. {@link IntrinsicsEstimate} decides what they mean.
 *
 * @param sdk              the API level the app runs at ({@code Build.VERSION.SDK_INT})
 * @param preCorrection    SENSOR_INFO_PRE_CORRECTION_ACTIVE_ARRAY_SIZE as {left, top, right, bottom}
 *                         in pixel-array coordinates, or null
 * @param active           SENSOR_INFO_ACTIVE_ARRAY_SIZE the same way, or null
 * @param calibration      LENS_INTRINSIC_CALIBRATION as reported: {fx, fy, cx, cy, s} in pixels of
 *                         the pre-correction array, pixel (x, y) centred at (x + 0.5, y + 0.5)
 * @param lensDistortion   LENS_DISTORTION {k1, k2, k3, p1, p2} (API 28 and later), or null
 * @param radialDistortion LENS_RADIAL_DISTORTION {kappa0 .. kappa5} (read below API 28 only), or null
 * @param correctionModes  DISTORTION_CORRECTION_AVAILABLE_MODES (API 28 and later), or null
 * @param focalMm          the first of LENS_INFO_AVAILABLE_FOCAL_LENGTHS, or NaN
 * @param activeWidthMm    the active array's width in mm (SENSOR_INFO_PHYSICAL_SIZE is the whole
 *                         pixel array's: scaled by the active share of SENSOR_INFO_PIXEL_ARRAY_SIZE), or NaN
 */
public record CameraReport(int sdk, int[] preCorrection, int[] active, float[] calibration, float[] lensDistortion,
        float[] radialDistortion, int[] correctionModes, double focalMm, double activeWidthMm) {
    /** DISTORTION_CORRECTION_MODE_OFF (CameraMetadata's value, API 28). */
    public static final int CORRECTION_OFF = 0;
}
