package org.skinlab.android.logic;

import java.util.Arrays;

/**
 * Which way the camera preview's texture is read. The tracker and the projection work in the
 * sensor's image (the ImageReader's frames, as the sensor reads them out), and the renderer turns
 * that image upright on screen ({@code ArCamera.imageToViewport}). The preview, though, reaches the
 * GL texture through a SurfaceTexture whose transform (Camera2 sets the buffer transform from
 * {@code SENSOR_ORIENTATION}) already turns it upright for the device's natural orientation. So the
 * background shader maps each point of the sensor's image to the upright image first, then through
 * the SurfaceTexture's transform, and the picture is turned once, as the model is.
 */
public final class PreviewOrientation {
    private PreviewOrientation() {
    }

    /**
     * Writes into {@code out} (column-major 4x4, for {@code glUniformMatrix4fv}) the map from
     * texture coordinates of the sensor's image (u to the right, v up, both in [0, 1]) to those of
     * the image turned upright for the natural orientation: {@code SENSOR_ORIENTATION} is the
     * clockwise angle (0, 90, 180 or 270) through which the sensor's image must be turned to stand
     * upright, so this is a clockwise turn by it about (0.5, 0.5).
     */
    public static float[] sensorToNatural(int sensorOrientationDegrees, float[] out) {
        if (Math.floorMod(sensorOrientationDegrees, 90) != 0) {
            throw new IllegalArgumentException("sensor orientation " + sensorOrientationDegrees + " (need 0, 90, 180 or 270)");
        }
        int quarter = Math.floorMod(sensorOrientationDegrees, 360) / 90;
        // Clockwise by 90 degrees with v up: (u, v) -> (v, 1 - u).
        float[][] turns = {
            {1, 0, 0, 1, 0, 0}, // u' = u, v' = v
            {0, 1, -1, 0, 0, 1}, // u' = v, v' = 1 - u
            {-1, 0, 0, -1, 1, 1}, // u' = 1 - u, v' = 1 - v
            {0, -1, 1, 0, 1, 0}, // u' = 1 - v, v' = u
        };
        float[] t = turns[quarter];
        // u' = t0 u + t1 v + t4, v' = t2 u + t3 v + t5.
        Arrays.fill(out, 0, 16, 0f);
        out[0] = t[0];
        out[4] = t[1];
        out[12] = t[4];
        out[1] = t[2];
        out[5] = t[3];
        out[13] = t[5];
        out[10] = 1;
        out[15] = 1;
        return out;
    }
}
