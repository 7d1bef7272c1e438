package org.skinlab.desktop.cli;

import java.util.regex.Pattern;

/**
 * The numbers the commands take as text: plain decimals with an optional exponent. Java's own
 * parser also accepts {@code NaN}, {@code Infinity}, hexadecimal and a type suffix ({@code 1f}),
 * none of which a user means as a time or a weight.
 */
final class Decimal {
    private static final Pattern DECIMAL = Pattern.compile("[+-]?(\\d+\\.?\\d*|\\.\\d+)([eE][+-]?\\d+)?");

    private Decimal() {
    }

    /** Whether {@code text} (already trimmed) is such a decimal. */
    static boolean matches(String text) {
        return DECIMAL.matcher(text).matches();
    }
}
