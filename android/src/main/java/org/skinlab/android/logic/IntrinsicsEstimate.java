package org.skinlab.android.logic;

import org.skinlab.ar.CameraIntrinsics;

/**
 * The camera's intrinsics for a preview stream, from what Camera2 reports about the sensor, best
 * source first: the calibration ({@code LENS_INTRINSIC_CALIBRATION}: fx, fy, cx, cy, skew in pixels
 * of the active array), else the focal length and the sensor's physical size, else a field-of-view
 * guess. A stream of another aspect than the sensor is a centred crop of it, scaled (Camera2's
 * rule), so the numbers are cropped and scaled the same way, pixel edges to pixel edges.
 */
public final class IntrinsicsEstimate {
    /** The horizontal field of view assumed when the camera reports nothing (a typical phone main camera). */
    public static final double FALLBACK_FOV_DEGREES = 65;

    private IntrinsicsEstimate() {
    }

    /**
     * @param calibration  LENS_INTRINSIC_CALIBRATION with its principal point moved from the
     *                     pre-correction array into the active array, or null
     * @param activeWidth  SENSOR_INFO_ACTIVE_ARRAY_SIZE width in pixels
     * @param activeHeight its height
     * @param focalMm      the first of LENS_INFO_AVAILABLE_FOCAL_LENGTHS, or NaN
     * @param sensorWidthMm  the active array's width in mm (SENSOR_INFO_PHYSICAL_SIZE is the whole
     *                     pixel array's: scale it by the active share of SENSOR_INFO_PIXEL_ARRAY_SIZE), or NaN
     * @param streamWidth  the analysed stream's width
     * @param streamHeight its height
     */
    public static CameraIntrinsics estimate(float[] calibration, int activeWidth, int activeHeight, double focalMm,
            double sensorWidthMm, int streamWidth, int streamHeight) {
        if (activeWidth <= 0 || activeHeight <= 0) {
            return CameraIntrinsics.fromHorizontalFov(streamWidth, streamHeight, FALLBACK_FOV_DEGREES);
        }
        double fx;
        double fy;
        double cx;
        double cy;
        if (calibration != null && calibration.length >= 4 && calibration[0] > 0 && calibration[1] > 0) {
            fx = calibration[0];
            fy = calibration[1];
            cx = calibration[2];
            cy = calibration[3];
        } else if (focalMm > 0 && sensorWidthMm > 0) {
            fx = fy = focalMm / sensorWidthMm * activeWidth;
            cx = (activeWidth - 1) / 2.0;
            cy = (activeHeight - 1) / 2.0;
        } else {
            return CameraIntrinsics.fromHorizontalFov(streamWidth, streamHeight, FALLBACK_FOV_DEGREES);
        }
        // The centred crop of the active array with the stream's aspect, then the scale to the stream.
        double streamAspect = (double) streamWidth / streamHeight;
        double cropW = Math.min(activeWidth, activeHeight * streamAspect);
        double cropH = cropW / streamAspect;
        double cropX = (activeWidth - cropW) / 2;
        double cropY = (activeHeight - cropH) / 2;
        double s = streamWidth / cropW;
        return new CameraIntrinsics(streamWidth, streamHeight, fx * s, fy * s, (cx + 0.5 - cropX) * s - 0.5,
                (cy + 0.5 - cropY) * s - 0.5);
    }
}
