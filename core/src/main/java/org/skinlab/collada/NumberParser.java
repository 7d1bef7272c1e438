package org.skinlab.collada;

/**
 * Parses the whitespace-separated lists of COLLADA ({@code float_array}, {@code int_array},
 * {@code <p>}, {@code <v>}, {@code <matrix>}, ...) straight from element text, without a String
 * per token.
 *
 * <p>Floats are correctly rounded: the common case (at most 19 significant digits, a decimal
 * exponent within +-22) is computed exactly in double precision (Clinger's fast path) and then
 * rounded to float; the only double-rounding hazard, a double that lands exactly halfway between
 * two floats, and every other case fall back to {@link Float#parseFloat}. NaN and infinities
 * (and MSVC spellings such as {@code 1.#QNAN}) are refused: a non-finite coordinate, weight or
 * key time is never meaningful and would silently poison everything downstream.
 */
final class NumberParser {
    private static final double[] POWERS_OF_TEN = {
        1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11,
        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
    };

    private final ImportContext ctx;
    private final XmlElement element;
    private final String s;
    private final int end;
    private int pos;

    private NumberParser(ImportContext ctx, XmlElement element, String text) {
        this.ctx = ctx;
        this.element = element;
        this.s = text;
        this.end = text.length();
    }

    /** Number of whitespace-separated tokens in the text. */
    static int countTokens(String text) {
        int n = 0;
        boolean inToken = false;
        for (int i = 0, len = text.length(); i < len; i++) {
            boolean ws = SafeXmlReader.isXmlWhitespace(text.charAt(i));
            if (!ws && !inToken) {
                n++;
            }
            inToken = !ws;
        }
        return n;
    }

    /**
     * Parses the element's text as floats.
     *
     * @param expected the count the file declares, or -1 when it declares none
     */
    static float[] floats(ImportContext ctx, XmlElement element, int expected) throws ColladaException {
        String text = element.text();
        int n = expected >= 0 ? checkedCount(ctx, element, text, expected) : countTokens(text);
        float[] out = new float[n];
        NumberParser p = new NumberParser(ctx, element, text);
        for (int i = 0; i < n; i++) {
            if (!p.skipWhitespace()) {
                throw ctx.error(element, "count=\"" + expected + "\" but only " + i + " values");
            }
            out[i] = p.nextFloat(i);
        }
        if (p.skipWhitespace()) {
            throw ctx.error(element, "count=\"" + expected + "\" but " + countTokens(text) + " values");
        }
        return out;
    }

    /** Parses the element's text as non-negative or negative ints (see {@link #floats}). */
    static int[] ints(ImportContext ctx, XmlElement element, int expected) throws ColladaException {
        String text = element.text();
        int n = expected >= 0 ? checkedCount(ctx, element, text, expected) : countTokens(text);
        int[] out = new int[n];
        NumberParser p = new NumberParser(ctx, element, text);
        for (int i = 0; i < n; i++) {
            if (!p.skipWhitespace()) {
                throw ctx.error(element, "count=\"" + expected + "\" but only " + i + " values");
            }
            out[i] = p.nextInt(i);
        }
        if (p.skipWhitespace()) {
            throw ctx.error(element, "count=\"" + expected + "\" but " + countTokens(text) + " values");
        }
        return out;
    }

    /** Splits the element's text into names ({@code Name_array}, {@code IDREF_array}). */
    static String[] names(ImportContext ctx, XmlElement element, int expected) throws ColladaException {
        String text = element.text();
        int n = expected >= 0 ? checkedCount(ctx, element, text, expected) : countTokens(text);
        String[] out = new String[n];
        NumberParser p = new NumberParser(ctx, element, text);
        for (int i = 0; i < n; i++) {
            if (!p.skipWhitespace()) {
                throw ctx.error(element, "count=\"" + expected + "\" but only " + i + " names");
            }
            int start = p.pos;
            while (p.pos < p.end && !SafeXmlReader.isXmlWhitespace(p.s.charAt(p.pos))) {
                p.pos++;
            }
            out[i] = text.substring(start, p.pos);
        }
        if (p.skipWhitespace()) {
            throw ctx.error(element, "count=\"" + expected + "\" but " + countTokens(text) + " names");
        }
        return out;
    }

    /**
     * Refuses a declared count that the text cannot possibly hold (each value needs at least one
     * character and one separator) before anything is allocated for it.
     */
    private static int checkedCount(ImportContext ctx, XmlElement element, String text, int expected)
            throws ColladaException {
        if (expected > (text.length() + 1) / 2) {
            throw ctx.error(element, "count=\"" + expected + "\" but the element holds only "
                    + countTokens(text) + " values");
        }
        return expected;
    }

    /** Advances to the next token; false at the end of the text. */
    private boolean skipWhitespace() {
        while (pos < end && SafeXmlReader.isXmlWhitespace(s.charAt(pos))) {
            pos++;
        }
        return pos < end;
    }

    private int nextInt(int index) throws ColladaException {
        int start = pos;
        boolean negative = false;
        char c = s.charAt(pos);
        if (c == '-' || c == '+') {
            negative = c == '-';
            pos++;
        }
        long value = 0;
        int digits = 0;
        while (pos < end) {
            c = s.charAt(pos);
            int d = c - '0';
            if (d < 0 || d > 9) {
                break;
            }
            value = value * 10 + d;
            if (value > Integer.MAX_VALUE + 1L) {
                throw badToken(start, index, "integer out of range");
            }
            digits++;
            pos++;
        }
        if (digits == 0 || (pos < end && !SafeXmlReader.isXmlWhitespace(s.charAt(pos)))) {
            throw badToken(start, index, "not an integer");
        }
        long v = negative ? -value : value;
        if (v > Integer.MAX_VALUE) {
            throw badToken(start, index, "integer out of range");
        }
        return (int) v;
    }

    private float nextFloat(int index) throws ColladaException {
        int start = pos;
        boolean negative = false;
        char c = s.charAt(pos);
        if (c == '-' || c == '+') {
            negative = c == '-';
            pos++;
        }
        long mantissa = 0;
        int significant = 0;      // significant digits kept in the mantissa (at most 18: fits a long)
        int exponent = 0;         // decimal exponent applied to the mantissa
        boolean dropped = false;  // digits beyond 18 were dropped: not exact any more
        int digits = 0;
        while (pos < end) {
            int d = s.charAt(pos) - '0';
            if (d < 0 || d > 9) {
                break;
            }
            digits++;
            if (significant < 18) {
                if (mantissa != 0 || d != 0) {
                    mantissa = mantissa * 10 + d;
                    significant++;
                }
            } else {
                exponent++;
                dropped |= d != 0;
            }
            pos++;
        }
        if (pos < end && s.charAt(pos) == '.') {
            pos++;
            while (pos < end) {
                int d = s.charAt(pos) - '0';
                if (d < 0 || d > 9) {
                    break;
                }
                digits++;
                if (significant < 18) {
                    if (mantissa != 0 || d != 0) {
                        mantissa = mantissa * 10 + d;
                        significant++;
                    }
                    exponent--;
                } else {
                    dropped |= d != 0;
                }
                pos++;
            }
        }
        if (digits == 0) {
            throw badToken(start, index, "not a finite number");
        }
        if (pos < end && (s.charAt(pos) == 'e' || s.charAt(pos) == 'E')) {
            pos++;
            boolean negExp = false;
            if (pos < end && (s.charAt(pos) == '-' || s.charAt(pos) == '+')) {
                negExp = s.charAt(pos) == '-';
                pos++;
            }
            int e = 0;
            int expDigits = 0;
            while (pos < end) {
                int d = s.charAt(pos) - '0';
                if (d < 0 || d > 9) {
                    break;
                }
                if (e < 100_000) {
                    e = e * 10 + d;
                }
                expDigits++;
                pos++;
            }
            if (expDigits == 0) {
                throw badToken(start, index, "not a finite number");
            }
            exponent += negExp ? -e : e;
        }
        if (pos < end && !SafeXmlReader.isXmlWhitespace(s.charAt(pos))) {
            throw badToken(start, index, "not a finite number");
        }
        float f;
        if (mantissa == 0) {
            f = 0f;
        } else if (!dropped && mantissa < (1L << 53) && exponent >= -22 && exponent <= 22) {
            double d = exponent >= 0 ? mantissa * POWERS_OF_TEN[exponent] : mantissa / POWERS_OF_TEN[-exponent];
            long bits = Double.doubleToRawLongBits(d);
            boolean floatMidpoint = (bits & 0x1FFF_FFFFL) == 0x1000_0000L;
            if (floatMidpoint || d < Float.MIN_NORMAL || d > Float.MAX_VALUE) {
                f = Math.abs(Float.parseFloat(s.substring(start, pos)));
            } else {
                f = (float) d;
            }
        } else {
            f = Math.abs(Float.parseFloat(s.substring(start, pos)));
        }
        if (Float.isInfinite(f)) {
            throw badToken(start, index, "out of float range");
        }
        return negative ? -f : f;
    }

    private ColladaException badToken(int start, int index, String what) {
        int stop = start;
        while (stop < end && stop - start < 40 && !SafeXmlReader.isXmlWhitespace(s.charAt(stop))) {
            stop++;
        }
        return ctx.error(element, "value " + index + " \"" + s.substring(start, stop) + "\" is " + what);
    }
}
