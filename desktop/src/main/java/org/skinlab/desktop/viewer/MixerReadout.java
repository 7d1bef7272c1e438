package org.skinlab.desktop.viewer;

import java.util.Locale;
import java.util.Map;

import org.skinlab.mixer.Layer;
import org.skinlab.mixer.LayerMode;
import org.skinlab.mixer.Mixer;

/**
 * A mixer's layers in words, for the scripts' {@code expect layer} (docs/desktop.md): one line per
 * layer, e.g. {@code "base: walk 0.76 + run 0.24, weight 1.00, all joints, override, blend space,
 * root motion"} or {@code "layer 1: wave 1.00, weight 0.50, below spine, additive, fading"}.
 * Weights have two decimals. Read on the simulation thread (inside {@code direct}), where the
 * mixer lives.
 */
public final class MixerReadout {
    private MixerReadout() {
    }

    /** Layer {@code index} (0: the base), or why there is none. */
    public static String layer(Mixer mixer, int index) {
        if (index < 0 || index >= mixer.layers().size()) {
            return "no layer " + index + " (the mixer has " + mixer.layers().size() + ")";
        }
        Layer l = mixer.layers().get(index);
        StringBuilder b = new StringBuilder(l.name()).append(": ");
        Map<String, Double> weights = l.clipWeights();
        if (weights.isEmpty()) {
            b.append("nothing");
        }
        boolean rootMotion = false;
        String sep = "";
        for (Map.Entry<String, Double> e : weights.entrySet()) {
            b.append(sep).append(e.getKey()).append(' ').append(String.format(Locale.ROOT, "%.2f", e.getValue()));
            sep = " + ";
            rootMotion |= mixer.rootMotion(e.getKey());
        }
        b.append(String.format(Locale.ROOT, ", weight %.2f, ", l.weight()));
        b.append(l.mask() == null ? "all joints" : l.mask().toString());
        b.append(l.mode() == LayerMode.ADDITIVE ? ", additive" : ", override");
        if (l.blendSpace() != null) {
            b.append(", blend space");
        }
        if (index == 0 && rootMotion) {
            b.append(", root motion");
        }
        if (l.isFading()) {
            b.append(", fading");
        }
        return b.toString();
    }
}
