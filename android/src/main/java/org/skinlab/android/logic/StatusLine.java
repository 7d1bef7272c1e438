package org.skinlab.android.logic;

import java.util.Locale;

import org.skinlab.ar.ArPose;
import org.skinlab.simulation.AnimationConfig;

/**
 * The AR app's status line: fps, tracking state (with the followed marker's id and the markers in
 * view, {@link ArPose#markerLabel()}), method, interpolation, speed, the clips ({@link
 * MixerControl#status()}), model; below it,
 * each current problem on its own line. Problems come from different sources (the GL driver, the
 * camera, the model loader) and each is kept and cleared by its own source, so that one's success
 * never hides another's failure.
 */
public final class StatusLine {
    private StatusLine() {
    }

    /** What the marker line says before the camera delivers: no tracking runs yet. */
    public static final String NO_CAMERA = "waiting for the camera";

    /**
     * The line; {@code pose} is the tracking session's latest, or null while no camera is open
     * (so that "searching" always means: the camera runs and the marker is not in view); {@code
     * clips} what the mixer plays ("" for nothing to say). The model comes last.
     */
    public static String format(double fps, ArPose pose, AnimationConfig.Settings s, String clips, String model) {
        String marker = pose == null ? NO_CAMERA
                : String.format(Locale.ROOT, "%s (%.1f ms)", pose.markerLabel(), pose.trackerMillis());
        return String.format(Locale.ROOT, "%.0f fps | marker: %s | %s %s x%.2f%s%s | %s", fps, marker,
                s.method().key().toUpperCase(Locale.ROOT), s.interpolation().name(), s.speed(),
                s.followCamera() ? " | follow" : "", clips.isEmpty() ? "" : " | " + clips, model);
    }

    /** The notes that are not null joined by "; ", or null when all are null (one problem line made of several). */
    public static String joined(String... notes) {
        StringBuilder text = new StringBuilder();
        for (String n : notes) {
            if (n != null) {
                text.append(text.length() > 0 ? "; " : "").append(n);
            }
        }
        return text.length() > 0 ? text.toString() : null;
    }

    /** The line followed by every problem that is not empty (null counts as none), one per line. */
    public static String withProblems(String line, String... problems) {
        StringBuilder text = new StringBuilder(line);
        for (String p : problems) {
            if (p != null && !p.isEmpty()) {
                text.append('\n').append(p);
            }
        }
        return text.toString();
    }
}
