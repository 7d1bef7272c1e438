package org.skinlab.android.logic;

/**
 * The camera permission, as a small state machine the Activity follows: ask when it is missing;
 * granted, start the camera; denied, show why the app needs it and a button to ask again (or,
 * when Android will not show the dialog any more, the way to the app's settings). Never a crash,
 * never a camera opened without the permission.
 *
 * <p>Android shows its dialog in another activity, so ours pauses and resumes around it: a request
 * is remembered as pending until its answer arrives, and a resume meanwhile does not ask again
 * (a second request while one is open is cancelled by Android). An empty answer is a cancelled
 * request (the dialog was dismissed by something other than the user, for example the activity
 * being recreated): asked again once, not taken as a refusal.
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

    /** The answer to a request, as onRequestPermissionsResult gives it. */
    public enum Answer {
        GRANTED,
        DENIED,
        /** No result at all: the request was cancelled. */
        CANCELLED;

        /**
         * The answer in Android's terms: the results array of the request, and whether the
         * permission is held now (checkSelfPermission). What is held decides, since that is what
         * opening the camera checks: a cancelled request says nothing about a permission granted
         * meanwhile, and a result that claims a grant the system does not hold opens nothing.
         */
        public static Answer of(int[] results, boolean heldNow) {
            return heldNow ? GRANTED : results.length == 0 ? CANCELLED : DENIED;
        }
    }

    /** The explanation shown when the permission was refused. */
    public static final String EXPLANATION = "skinlab shows the animated character on a printed marker seen through "
            + "the camera, so it needs the camera. Nothing is recorded or sent anywhere.";

    private Screen screen = Screen.ASKING;
    private boolean pending;
    private boolean cancelledOnce;

    /** A flow restored from {@link #savedState()} (the Activity's saved instance state), or a new one for null. */
    public static PermissionFlow restore(String saved) {
        PermissionFlow flow = new PermissionFlow();
        if (saved != null) {
            String[] parts = saved.split(",", -1);
            if (parts.length == 3) {
                try {
                    flow.screen = Screen.valueOf(parts[0]);
                    flow.pending = Boolean.parseBoolean(parts[1]);
                    flow.cancelledOnce = Boolean.parseBoolean(parts[2]);
                } catch (IllegalArgumentException e) {
                    return new PermissionFlow(); // a state from another version of the app: start over
                }
            }
        }
        return flow;
    }

    /** The state to keep across the Activity being recreated. */
    public String savedState() {
        return screen + "," + pending + "," + cancelledOnce;
    }

    /** On start or resume: whether the permission is held now. Returns whether to request it. */
    public boolean onResume(boolean granted) {
        if (granted) {
            screen = Screen.CAMERA;
            pending = false;
            return false;
        }
        if (pending) {
            screen = Screen.ASKING;
            return false; // the dialog is still up (or its answer is on its way)
        }
        if (screen == Screen.EXPLAIN_AND_RETRY || screen == Screen.EXPLAIN_SETTINGS) {
            return false; // the user is reading the explanation: ask only when they tap retry
        }
        return request();
    }

    /**
     * The dialog's answer; {@code canAskAgain} is Android's shouldShowRequestPermissionRationale
     * after a refusal (false once the user chose "don't ask again"). Returns whether to request
     * again (a first cancelled request).
     */
    public boolean onResult(Answer answer, boolean canAskAgain) {
        pending = false;
        switch (answer) {
            case GRANTED:
                screen = Screen.CAMERA;
                return false;
            case CANCELLED:
                if (!cancelledOnce) {
                    cancelledOnce = true;
                    return request();
                }
                screen = Screen.EXPLAIN_AND_RETRY; // cancelled twice: let the user ask
                return false;
            default:
                screen = canAskAgain ? Screen.EXPLAIN_AND_RETRY : Screen.EXPLAIN_SETTINGS;
                return false;
        }
    }

    /** The retry button: returns whether to request the permission again. */
    public boolean onRetry() {
        return screen == Screen.EXPLAIN_AND_RETRY && request();
    }

    private boolean request() {
        screen = Screen.ASKING;
        pending = true;
        return true;
    }

    public Screen screen() {
        return screen;
    }

    /** Whether the camera may be opened. */
    public boolean cameraAllowed() {
        return screen == Screen.CAMERA;
    }
}
