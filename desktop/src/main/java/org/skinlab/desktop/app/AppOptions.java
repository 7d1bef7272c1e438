package org.skinlab.desktop.app;

import java.nio.file.Path;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.desktop.viewer.DifferenceScale;
import org.skinlab.desktop.viewer.OrbitCamera;
import org.skinlab.skinning.SkinningMethod;

/**
 * How the window starts, from the command line ({@code skinlab view}). Immutable.
 *
 * @param file            the model to open, or null for the bundled default character
 * @param method          the skinning method at start
 * @param interpolation   the rotation interpolation at start
 * @param gpuSkinning     skin in the vertex shader (true) or on the CPU
 * @param view            shaded, weights, difference or checker
 * @param differenceScale the difference view's top (red): a share of the model's size, or auto
 * @param splitMethod     a second method drawn beside the first (split view), or null
 * @param time            a playback time to show, paused; null: play from the start
 * @param bindPose        show the bind pose instead of the clip
 * @param yawDegrees      the angle around the model's vertical axis the camera frames it from
 *                        (0: from the front, +z; 90: from +x)
 * @param pitchDegrees    the camera's elevation over the model's centre when it frames it
 *                        (positive from above)
 * @param screenshot      render one frame, write it to this PNG and exit; null: interactive
 * @param width           window (and screenshot) width in pixels
 * @param height          window (and screenshot) height in pixels
 * @param hideUi          draw the scene only (no toolbar)
 * @param script          UI actions to replay, or null
 * @param exitAfterFrames close after this many frames (0: never); fails when nothing was drawn
 * @param glDebug         a debug context; GL errors are printed and make the exit status non-zero
 */
public record AppOptions(Path file, SkinningMethod method, RotationInterpolation interpolation, boolean gpuSkinning,
        DrawSettings.View view, DifferenceScale differenceScale, SkinningMethod splitMethod, Double time,
        boolean bindPose, double yawDegrees, double pitchDegrees, Path screenshot, int width, int height, boolean hideUi,
        Path script, int exitAfterFrames, boolean glDebug) {

    /** The camera's elevation when {@code --pitch} is not given (degrees). */
    public static final double DEFAULT_PITCH_DEGREES = Math.toDegrees(OrbitCamera.DEFAULT_PITCH);

    public static final int DEFAULT_WIDTH = 1280;
    public static final int DEFAULT_HEIGHT = 800;

    /** The interactive window on the default character. */
    public static AppOptions defaults() {
        return new AppOptions(null, SkinningMethod.LBS, RotationInterpolation.SLERP, true, DrawSettings.View.SHADED,
                DifferenceScale.DEFAULT, null, null, false, 0, DEFAULT_PITCH_DEGREES, null, DEFAULT_WIDTH,
                DEFAULT_HEIGHT, false, null, 0, false);
    }

    /** Whether this run renders one picture and exits. */
    public boolean headless() {
        return screenshot != null;
    }
}
