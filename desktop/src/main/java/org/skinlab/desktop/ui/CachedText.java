package org.skinlab.desktop.ui;

import java.util.Locale;

/**
 * A formatted number that is only formatted again when the number changes: the interface draws
 * every frame, and most of its numbers change a few times a second at most.
 */
final class CachedText {
    private final String format;
    private double value = Double.NaN;
    private String text = "";
    private boolean empty = true;

    /** @param format a {@link String#format} pattern with one floating-point conversion */
    CachedText(String format) {
        this.format = format;
    }

    String of(double v) {
        if (empty || Double.doubleToLongBits(v) != Double.doubleToLongBits(value)) {
            value = v;
            empty = false;
            text = Double.isNaN(v) ? "-" : String.format(Locale.ROOT, format, v);
        }
        return text;
    }
}
