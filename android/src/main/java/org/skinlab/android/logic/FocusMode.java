package org.skinlab.android.logic;

/**
 * The autofocus mode the camera is asked for: continuous video focus (smooth, for a moving
 * phone), else continuous picture focus, else none at all: a mode the camera does not list makes
 * the whole capture request fail on some devices, and fixed-focus cameras list only "off".
 * Values are Camera2's {@code CONTROL_AF_MODE_*} constants.
 */
public final class FocusMode {
    public static final int CONTINUOUS_VIDEO = 3;
    public static final int CONTINUOUS_PICTURE = 4;

    private FocusMode() {
    }

    /** The mode to set among {@code available} (CONTROL_AF_AVAILABLE_MODES, may be null), or -1 for none. */
    public static int choose(int[] available) {
        if (available == null) {
            return -1;
        }
        int chosen = -1;
        for (int mode : available) {
            if (mode == CONTINUOUS_VIDEO) {
                return mode;
            }
            if (mode == CONTINUOUS_PICTURE) {
                chosen = mode;
            }
        }
        return chosen;
    }
}
