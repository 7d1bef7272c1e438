package org.skinlab.mixer;

import java.util.List;

/**
 * A layer's running cross-fade: the incoming clip's share c grows from 0 to 1 along a
 * {@link FadeCurve} over the fade's duration, and every clip playing when it started keeps its
 * starting weight times {@code 1 - c} (the incoming clip's own starting weight too, plus c). So a
 * fade started during a fade starts from the weights of that moment.
 */
final class CrossFade {
    final ClipState target;
    private final double seconds;
    private final FadeCurve curve;
    private double elapsed;

    /** Starts the fade: remembers every playing clip's weight ({@code target} among them). */
    CrossFade(ClipState target, double seconds, FadeCurve curve, List<ClipState> active) {
        this.target = target;
        this.seconds = seconds;
        this.curve = curve;
        for (int i = 0; i < active.size(); i++) {
            active.get(i).fadeFrom = active.get(i).weight;
        }
    }

    /** Advances by {@code dt} seconds and sets the weights; true once the fade is over. */
    boolean advance(double dt, List<ClipState> active) {
        elapsed += dt;
        double share = curve.share(seconds > 0 ? elapsed / seconds : 1);
        for (int i = 0; i < active.size(); i++) {
            ClipState s = active.get(i);
            s.weight = s.fadeFrom * (1 - share) + (s == target ? share : 0);
        }
        return elapsed >= seconds;
    }
}
