package org.skinlab.android.logic;

/**
 * The camera permission, as a small state machine the Activity follows: ask when it is missing;
 * granted, start the camera; denied, show why the app needs it and a button to ask again (or,
 * when Android will not show the dialog any more, the way to the app's settings). Never a crash,
 * never a camera opened without the permission.
 */
public final class PermissionFlow {
    /** What the Activity shows. */
    public enum Screen {
        /** Waiting for the system dialog. */
        ASKING,
        /** The AR view runs. */
        CAMERA,
        /** An explanation and a retry button. */
        EXPLAIN_AND_RETRY,
        /** An explanation and the hint to allow the camera in the app's settings. */
        EXPLAIN_SETTINGS
    }

    /** The explanation shown when the permission was refused. */
    public static final String EXPLANATION = "skinlab shows the animated character on a printed marker seen through "
            + "the camera, so it needs the camera. Nothing is recorded or sent anywhere.";

    private Screen screen = Screen.ASKING;

    /** On start or resume: whether the permission is held now. Returns whether to request it. */
    public boolean onResume(boolean granted) {
        if (granted) {
            screen = Screen.CAMERA;
            return false;
        }
        if (screen == Screen.EXPLAIN_AND_RETRY || screen == Screen.EXPLAIN_SETTINGS) {
            return false; // the user is reading the explanation: ask only when they tap retry
        }
        screen = Screen.ASKING;
        return true;
    }

    /**
     * The dialog's answer; {@code canAskAgain} is Android's shouldShowRequestPermissionRationale
     * after a refusal (false once the user chose "don't ask again").
     */
    public void onResult(boolean granted, boolean canAskAgain) {
        screen = granted ? Screen.CAMERA : canAskAgain ? Screen.EXPLAIN_AND_RETRY : Screen.EXPLAIN_SETTINGS;
    }

    /** The retry button: returns whether to request the permission again. */
    public boolean onRetry() {
        if (screen == Screen.EXPLAIN_AND_RETRY) {
            screen = Screen.ASKING;
            return true;
        }
        return false;
    }

    public Screen screen() {
        return screen;
    }

    /** Whether the camera may be opened. */
    public boolean cameraAllowed() {
        return screen == Screen.CAMERA;
    }
}
