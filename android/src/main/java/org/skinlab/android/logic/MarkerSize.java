package org.skinlab.android.logic;

import java.util.Locale;
import java.util.function.DoubleConsumer;

/**
 * The printed marker's black-square width the app assumes: the user measures the print and taps
 * through the common sizes (the default is docs/marker's 100 mm). Poses scale with it, so a wrong
 * size puts the model too near or too far, too big or too small. The listener hears each change
 * (on the caller's thread).
 */
public final class MarkerSize {
    /** The sizes the button steps through, in millimetres. */
    public static final double[] SIZES_MM = {100, 150, 200, 50, 80};

    private final DoubleConsumer listener;
    private int index;

    public MarkerSize(DoubleConsumer listener) {
        this.listener = listener;
    }

    public double millimetres() {
        return SIZES_MM[index];
    }

    public double metres() {
        return SIZES_MM[index] / 1000;
    }

    public String label() {
        return String.format(Locale.ROOT, "Marker %.0f mm", SIZES_MM[index]);
    }

    /** Makes {@code millimetres} the size if it is one of {@link #SIZES_MM}, without telling the listener. */
    public boolean select(double millimetres) {
        for (int i = 0; i < SIZES_MM.length; i++) {
            if (SIZES_MM[i] == millimetres) {
                index = i;
                return true;
            }
        }
        return false;
    }

    /** The next size (wrapping), told to the listener. */
    public void next() {
        index = (index + 1) % SIZES_MM.length;
        listener.accept(metres());
    }
}
