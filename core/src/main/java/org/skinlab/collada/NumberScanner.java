package org.skinlab.collada;

import java.util.Arrays;

/**
 * Parses a whitespace-separated list of numbers from character chunks, as the SAX parser
 * delivers an element's text, without building a String: the numbers of a {@code float_array} or
 * {@code <p>} go straight from the parser's buffer into a {@code float[]} or {@code int[]}. A
 * token split between two chunks is carried over.
 *
 * <p>The scanner takes a float token apart into its decimal digits and exponent;
 * {@link DecimalFloats} rounds that correctly to a float. A comma in place of the
 * decimal point ({@code 0,5}: exporters running under a German or French locale) is read as the
 * point and remembered ({@link #decimalCommas()}), so the importer can say so.
 *
 * <p>NaN and infinities (also MSVC's spellings such as {@code 1.#QNAN}) and floats beyond float
 * range are kept as values but remembered apart from bad tokens ({@link #nonFiniteIndex()}): a
 * non-finite coordinate, weight or key time is never meaningful and is refused, but a NaN in a
 * texture coordinate or colour source can be replaced and the rest of the file read. Which is
 * which is the importer's decision, not the scanner's.
 *
 * <p>Problems do not stop the scan: the first bad token is remembered (with its index) and
 * counted as a value, so the importer can report it, or a count mismatch, when someone asks for
 * the values ({@link NumberParser}). A file may hold arrays nobody uses; their problems stay
 * silent.
 */
final class NumberScanner {
    /** Longer tokens are refused; no real number needs this many characters. */
    static final int MAX_TOKEN = 400;
    /** The largest array allocated on the word of a count attribute before any value is seen. */
    private static final int MAX_CAPACITY_HINT = 1 << 16;
    private static final String OUT_OF_RANGE = "out of float range";

    private final boolean floats;
    private float[] floatValues;
    private int[] intValues;
    private int size;

    private char[] carry = new char[32];
    private int carryLength;

    private String badToken;
    private String badReason;
    private int badIndex = -1;

    private String nonFiniteToken;
    private String nonFiniteReason;
    private int nonFiniteIndex = -1;
    private int nonFiniteCount;
    private int decimalCommas;

    /** Where the token parsed last ended (the first character after it). */
    private int tokenEnd;

    // Results of the scanners below, handed to parseToken.
    private float pendingFloat;
    private int pendingInt;
    private String pendingProblem;
    private boolean pendingComma; // the float scanned last was written with a decimal comma (reset when used)

    /**
     * @param floats       parse floats (else ints)
     * @param capacityHint expected number of values (e.g. a count attribute), or -1; only a hint
     */
    NumberScanner(boolean floats, int capacityHint) {
        this.floats = floats;
        int capacity = capacityHint < 4 ? 16 : Math.min(capacityHint, MAX_CAPACITY_HINT);
        if (floats) {
            floatValues = new float[capacity];
        } else {
            intValues = new int[capacity];
        }
    }

    /** Scans a whole text at once. */
    static NumberScanner scan(String text, boolean floats) {
        NumberScanner s = new NumberScanner(floats, -1);
        char[] chars = text.toCharArray();
        s.feed(chars, 0, chars.length);
        s.finish();
        return s;
    }

    boolean isFloats() {
        return floats;
    }

    /** Number of values (bad tokens included). */
    int size() {
        return size;
    }

    /** The values as floats, exactly {@link #size()} of them (after {@link #finish()}). */
    float[] floats() {
        if (floats) {
            return floatValues;
        }
        float[] f = new float[size];
        for (int i = 0; i < size; i++) {
            f[i] = intValues[i];
        }
        return f;
    }

    /** The values as ints (after {@link #finish()}); only for an int scanner. */
    int[] ints() {
        if (floats) {
            throw new IllegalStateException("a float list has no ints");
        }
        return intValues;
    }

    /** Index of the first bad token, or -1. */
    int badIndex() {
        return badIndex;
    }

    /** The first bad token (at most 40 characters), or null. */
    String badToken() {
        return badToken;
    }

    /** Why the first bad token is bad, e.g. "not an integer". */
    String badReason() {
        return badReason;
    }

    /** Index of the first NaN, infinity or out-of-range float, or -1. */
    int nonFiniteIndex() {
        return nonFiniteIndex;
    }

    /** The first non-finite token (at most 40 characters), or null. */
    String nonFiniteToken() {
        return nonFiniteToken;
    }

    /** Why the first non-finite token is refused where values must be finite. */
    String nonFiniteReason() {
        return nonFiniteReason;
    }

    /** Number of non-finite values. */
    int nonFiniteCount() {
        return nonFiniteCount;
    }

    /** Number of floats written with a decimal comma. */
    int decimalCommas() {
        return decimalCommas;
    }

    /** Consumes the next chunk of the element's text. */
    void feed(char[] ch, int start, int length) {
        int pos = start;
        int limit = start + length;
        if (carryLength > 0) {
            // The previous chunk ended inside a token: it goes on until the next whitespace.
            while (pos < limit && !SafeXmlReader.isXmlWhitespace(ch[pos])) {
                appendCarry(ch[pos++]);
            }
            if (pos == limit) {
                return;
            }
            parseCarry();
        }
        while (true) {
            while (pos < limit && SafeXmlReader.isXmlWhitespace(ch[pos])) {
                pos++;
            }
            if (pos == limit) {
                return;
            }
            if (!parseToken(ch, pos, limit, false)) {
                // The token runs to the end of the chunk and may go on in the next one.
                for (int k = pos; k < limit; k++) {
                    appendCarry(ch[k]);
                }
                return;
            }
            pos = tokenEnd;
        }
    }

    /** Ends the text: parses a carried token and trims the arrays to their size. */
    void finish() {
        if (carryLength > 0) {
            parseCarry();
        }
        if (floats) {
            if (floatValues.length != size) {
                floatValues = Arrays.copyOf(floatValues, size);
            }
        } else if (intValues.length != size) {
            intValues = Arrays.copyOf(intValues, size);
        }
        carry = null;
    }

    private void appendCarry(char c) {
        if (carryLength == carry.length) {
            if (carryLength >= MAX_TOKEN) {
                carryLength++; // remember that it is too long; keep the start for the message
                return;
            }
            carry = Arrays.copyOf(carry, Math.min(MAX_TOKEN, carry.length * 2));
        }
        if (carryLength < carry.length) {
            carry[carryLength] = c;
        }
        carryLength++;
    }

    private void parseCarry() {
        if (carryLength > MAX_TOKEN) {
            bad(carry, 0, Math.min(carryLength, carry.length), "longer than " + MAX_TOKEN + " characters");
            add(0);
        } else {
            parseToken(carry, 0, carryLength, true);
        }
        carryLength = 0;
    }

    /**
     * Parses the token at {@code b[from]}. Returns false, consuming nothing, when the token
     * reaches {@code limit} and {@code limitEndsToken} is false (it may continue elsewhere);
     * otherwise records the value (or the problem) and sets {@link #tokenEnd}.
     */
    private boolean parseToken(char[] b, int from, int limit, boolean limitEndsToken) {
        // Kept small so that the JIT inlines it into feed(): every problem goes to a cold method.
        pendingProblem = null;
        int stop = floats ? scanFloat(b, from, limit) : scanInt(b, from, limit);
        if (stop == limit && !limitEndsToken) {
            return false;
        }
        if (stop < limit && !SafeXmlReader.isXmlWhitespace(b[stop])) {
            return notANumber(b, from, stop, limit, limitEndsToken);
        }
        tokenEnd = stop;
        if (pendingProblem != null || stop - from > MAX_TOKEN) {
            problem(b, from, stop);
        } else if (floats) {
            if (pendingComma) {
                decimalCommas++;
                pendingComma = false;
            }
            add(pendingFloat);
        } else {
            add(pendingInt);
        }
        return true;
    }

    /** A token with characters after its number: NaN or an infinity spelled out, or a bad token. */
    private boolean notANumber(char[] b, int from, int stop, int limit, boolean limitEndsToken) {
        int end = stop;
        while (end < limit && !SafeXmlReader.isXmlWhitespace(b[end])) {
            end++;
        }
        if (end == limit && !limitEndsToken) {
            return false; // the token may go on in the next chunk
        }
        pendingComma = false;
        float special = floats ? DecimalFloats.spelledNonFinite(b, from, end) : 0f;
        if (special != 0f) {
            nonFinite(b, from, end, "not a finite number");
            add(special);
        } else {
            bad(b, from, end, floats ? "not a number" : "not an integer");
            add(0);
        }
        tokenEnd = end;
        return true;
    }

    /** A token that ends like a number but is none (or is too long, or beyond float range). */
    private void problem(char[] b, int from, int stop) {
        pendingComma = false;
        if (stop - from > MAX_TOKEN) {
            bad(b, from, stop, "longer than " + MAX_TOKEN + " characters");
            add(0);
        } else if (pendingProblem == OUT_OF_RANGE) {
            nonFinite(b, from, stop, pendingProblem);
            add(b[from] == '-' ? Float.NEGATIVE_INFINITY : Float.POSITIVE_INFINITY);
        } else {
            float special = floats ? DecimalFloats.spelledNonFinite(b, from, stop) : 0f;
            if (special != 0f) {
                nonFinite(b, from, stop, "not a finite number");
                add(special);
            } else {
                bad(b, from, stop, pendingProblem);
                add(0);
            }
        }
    }

    /**
     * Scans a float at {@code b[from]}; returns the index after it (where it stopped). Sets
     * {@link #pendingFloat}, or {@link #pendingProblem} when the characters form no number.
     */
    private int scanFloat(char[] b, int from, int limit) {
        int pos = from;
        boolean negative = false;
        char c = b[pos];
        if (c == '-' || c == '+') {
            negative = c == '-';
            pos++;
        }
        long mantissa = 0;
        int significant = 0;      // significant digits kept in the mantissa (at most 18: fits a long)
        int exponent = 0;         // decimal exponent applied to the mantissa
        boolean dropped = false;  // digits beyond 18 were dropped: not exact any more
        int digits = 0;
        boolean point = false;    // the decimal point has been seen
        boolean comma = false;    // ... and it was a comma
        while (pos < limit) {
            int d = b[pos] - '0';
            if (d >= 0 && d <= 9) {
                digits++;
                if (significant < 18) {
                    if (mantissa != 0 || d != 0) {
                        mantissa = mantissa * 10 + d;
                        significant++;
                    }
                    if (point) {
                        exponent--;
                    }
                } else {
                    if (!point) {
                        exponent++;
                    }
                    dropped |= d != 0;
                }
            } else if ((b[pos] == '.' || b[pos] == ',') && !point) {
                point = true;
                comma = b[pos] == ',';
            } else {
                break;
            }
            pos++;
        }
        if (digits == 0) {
            pendingProblem = "not a finite number";
            return pos == from ? Math.min(from + 1, limit) : pos;
        }
        if (pos < limit && (b[pos] == 'e' || b[pos] == 'E')) {
            pos++;
            boolean negExp = false;
            if (pos < limit && (b[pos] == '-' || b[pos] == '+')) {
                negExp = b[pos] == '-';
                pos++;
            }
            int e = 0;
            int expDigits = 0;
            while (pos < limit) {
                int d = b[pos] - '0';
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
                pendingProblem = "not a finite number";
                return pos;
            }
            exponent += negExp ? -e : e;
        }
        if (comma && !decimalComma(b, pos)) {
            return pos;
        }
        float f;
        if (mantissa == 0) {
            f = 0f;
        } else {
            f = DecimalFloats.nearest(mantissa, exponent, dropped, b, from, pos);
        }
        if (Float.isInfinite(f)) {
            pendingProblem = OUT_OF_RANGE;
            return pos;
        }
        pendingFloat = negative ? -f : f;
        return pos;
    }

    /**
     * Whether the comma that ends at {@code b[pos - 1]} or before is a decimal comma; "5," is no
     * decimal number (a comma-separated list would be misread as one). Out of line: rare, and
     * {@link #scanFloat} must stay small enough for the JIT to inline what it calls.
     */
    private boolean decimalComma(char[] b, int pos) {
        if (b[pos - 1] == ',') {
            pendingProblem = "not a number";
            return false;
        }
        pendingComma = true;
        return true;
    }

    /** Scans an int at {@code b[from]} (see {@link #scanFloat}). */
    private int scanInt(char[] b, int from, int limit) {
        int pos = from;
        boolean negative = false;
        char c = b[pos];
        if (c == '-' || c == '+') {
            negative = c == '-';
            pos++;
        }
        long value = 0;
        int digits = 0;
        boolean tooLarge = false;
        while (pos < limit) {
            int d = b[pos] - '0';
            if (d < 0 || d > 9) {
                break;
            }
            if (!tooLarge) {
                value = value * 10 + d;
                tooLarge = value > Integer.MAX_VALUE + 1L;
            }
            digits++;
            pos++;
        }
        if (digits == 0) {
            pendingProblem = "not an integer";
            return pos == from ? Math.min(from + 1, limit) : pos;
        }
        long v = negative ? -value : value;
        if (tooLarge || v > Integer.MAX_VALUE) {
            pendingProblem = "integer out of range";
            return pos;
        }
        pendingInt = (int) v;
        return pos;
    }

    private void nonFinite(char[] b, int from, int to, String reason) {
        if (nonFiniteIndex < 0) {
            nonFiniteIndex = size;
            nonFiniteToken = new String(b, from, Math.min(to - from, 40));
            nonFiniteReason = reason;
        }
        nonFiniteCount++;
    }

    private void bad(char[] b, int from, int to, String reason) {
        if (badIndex < 0) {
            badIndex = size;
            badToken = new String(b, from, Math.min(to - from, 40));
            badReason = reason;
        }
    }

    private void add(float value) {
        if (size == floatValues.length) {
            floatValues = Arrays.copyOf(floatValues, size * 2);
        }
        floatValues[size++] = value;
    }

    private void add(int value) {
        if (floats) {
            add((float) value);
            return;
        }
        if (size == intValues.length) {
            intValues = Arrays.copyOf(intValues, size * 2);
        }
        intValues[size++] = value;
    }
}
