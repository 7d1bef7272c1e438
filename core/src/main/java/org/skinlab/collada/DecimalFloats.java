package org.skinlab.collada;

import java.util.Locale;

/**
 * The float value of a decimal token {@link NumberScanner} has taken apart, correctly rounded:
 * the common case (at most 18 significant digits, a decimal exponent within +-22) is computed
 * exactly in double precision (Clinger's fast path) and then rounded to float; the only
 * double-rounding hazard, a double that lands exactly halfway between two floats, and every other
 * case fall back to {@link Float#parseFloat}. Also the spellings of NaN and the infinities that
 * exporters write.
 */
final class DecimalFloats {
    /** 10^k and 10^-k as doubles (rounded where not exact: 10^k is exact up to k = 22). */
    private static final double[] POWERS_OF_TEN = new double[41];
    private static final double[] NEGATIVE_POWERS_OF_TEN = new double[66];

    static {
        for (int k = 0; k < POWERS_OF_TEN.length; k++) {
            POWERS_OF_TEN[k] = Double.parseDouble("1e" + k);
        }
        for (int k = 0; k < NEGATIVE_POWERS_OF_TEN.length; k++) {
            NEGATIVE_POWERS_OF_TEN[k] = Double.parseDouble("1e-" + k);
        }
    }

    /** Mask of the 29 double mantissa bits below float precision, and the pattern of a float midpoint. */
    private static final long BELOW_FLOAT = 0x1FFF_FFFFL;
    private static final long FLOAT_MIDPOINT = 0x1000_0000L;

    private DecimalFloats() {
    }

    /**
     * The float nearest to the decimal {@code mantissa * 10^exponent} (plus the digits beyond the
     * 18th, {@code dropped}), i.e. what {@link Float#parseFloat} returns for {@code b[from, to)}.
     *
     * <p>Computed in double: the mantissa (at most 18 digits, so converting it loses at most half a
     * double ulp), times 10^exponent from a table (exact up to 10^22, else within half an ulp),
     * one rounding for the product; the dropped digits change the value by less than one ulp. So
     * the double is within 3 ulps of the exact value, and rounding it to float gives the right
     * answer unless it lies within those 3 ulps of a point halfway between two floats: then, and
     * for exponents outside the table or results outside the normal float range, the exact
     * {@link Float#parseFloat} decides. When the double is exact or correctly rounded (no dropped
     * digits, mantissa below 2^53, 0 <= exponent <= 22) only an exact halfway point is in doubt.
     */
    static float nearest(long mantissa, int exponent, boolean dropped, char[] b, int from, int to) {
        if (exponent >= POWERS_OF_TEN.length || exponent <= -NEGATIVE_POWERS_OF_TEN.length) {
            return exact(b, from, to);
        }
        double d = exponent >= 0 ? mantissa * POWERS_OF_TEN[exponent] : mantissa * NEGATIVE_POWERS_OF_TEN[-exponent];
        boolean correctlyRounded = !dropped && mantissa < (1L << 53) && exponent >= 0 && exponent <= 22;
        long distance = Math.abs((Double.doubleToRawLongBits(d) & BELOW_FLOAT) - FLOAT_MIDPOINT);
        if (distance <= (correctlyRounded ? 0 : 16) || d < Float.MIN_NORMAL || d > Float.MAX_VALUE) {
            return exact(b, from, to);
        }
        return (float) d;
    }

    /** {@link Float#parseFloat} of the token's magnitude (a decimal comma read as the point). */
    private static float exact(char[] b, int from, int to) {
        return Math.abs(Float.parseFloat(new String(b, from, to - from).replace(',', '.')));
    }

    /**
     * NaN or an infinity when {@code b[from, to)} spells one (NaN, INF, Infinity in any case,
     * with a sign; MSVC's 1.#QNAN, 1.#SNAN, 1.#IND, 1.#INF with trailing digits), else 0.
     */
    static float spelledNonFinite(char[] b, int from, int to) {
        int pos = from;
        boolean negative = false;
        if (pos < to && (b[pos] == '-' || b[pos] == '+')) {
            negative = b[pos] == '-';
            pos++;
        }
        String word = new String(b, pos, to - pos).toUpperCase(Locale.ROOT);
        if (word.startsWith("1.#")) {
            word = word.substring(3).replaceAll("[0-9]+$", "");
            if (word.equals("INF")) {
                return negative ? Float.NEGATIVE_INFINITY : Float.POSITIVE_INFINITY;
            }
            return word.equals("QNAN") || word.equals("SNAN") || word.equals("IND") ? Float.NaN : 0f;
        }
        switch (word) {
            case "NAN":
                return Float.NaN;
            case "INF":
            case "INFINITY":
                return negative ? Float.NEGATIVE_INFINITY : Float.POSITIVE_INFINITY;
            default:
                return 0f;
        }
    }
}
