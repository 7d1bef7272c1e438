package org.skinlab.android.logic;

import java.util.Locale;

import org.skinlab.ar.TrackingState;
import org.skinlab.simulation.AnimationConfig;

/** The AR app's status line: fps, tracking state, method, interpolation, speed, model. */
public final class StatusLine {
    private StatusLine() {
    }

    public static String format(double fps, TrackingState state, double trackerMillis, AnimationConfig.Settings s,
            String model) {
        return String.format(Locale.ROOT, "%.0f fps | marker: %s (%.1f ms) | %s %s x%.2f%s | %s", fps, state.label(),
                trackerMillis, s.method().key().toUpperCase(Locale.ROOT), s.interpolation().name(), s.speed(),
                s.followCamera() ? " | follow" : "", model);
    }
}
