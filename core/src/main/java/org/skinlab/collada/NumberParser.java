package org.skinlab.collada;

/**
 * The numbers and names of an element, checked: COLLADA's whitespace-separated lists
 * ({@code float_array}, {@code int_array}, {@code <p>}, {@code <v>}, {@code <matrix>}, ...).
 *
 * <p>Elements that only ever hold numbers are scanned while the XML is parsed
 * (by {@link SafeXmlReader}, with a {@link NumberScanner}); any other element is scanned from its
 * text here. Either way the first bad token, or a count that disagrees with the values, becomes a
 * {@link ColladaException} naming the element.
 */
final class NumberParser {
    private NumberParser() {
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
     * The element's values as floats.
     *
     * @param expected the count the file declares, or -1 when it declares none
     */
    static float[] floats(ImportContext ctx, XmlElement element, int expected) throws ColladaException {
        NumberScanner n = scannedFloats(ctx, element);
        requireFinite(ctx, element, n);
        checkCount(ctx, element, n, expected);
        return n.floats();
    }

    /**
     * The element's floats as scanned, NaN and infinities included (see
     * {@link NumberScanner#nonFiniteIndex()}): for {@code float_array}s, whose users decide whether
     * a non-finite value is acceptable. Tokens that are no number at all are refused here.
     */
    static NumberScanner scannedFloats(ImportContext ctx, XmlElement element) throws ColladaException {
        NumberScanner n = element.numbers();
        if (n == null) {
            n = NumberScanner.scan(element.text(), true);
        }
        if (n.badIndex() >= 0) {
            throw ctx.error(element, "value " + n.badIndex() + " \"" + n.badToken() + "\" is " + n.badReason());
        }
        if (n.decimalCommas() > 0) {
            ctx.warnDecimalComma(element);
        }
        return n;
    }

    /** Refuses the first non-finite value of the scanned element. */
    static void requireFinite(ImportContext ctx, XmlElement element, NumberScanner n) throws ColladaException {
        if (n.nonFiniteIndex() >= 0) {
            throw ctx.error(element, "value " + n.nonFiniteIndex() + " \"" + n.nonFiniteToken() + "\" is "
                    + n.nonFiniteReason());
        }
    }

    /** The element's values as ints (see {@link #floats}). */
    static int[] ints(ImportContext ctx, XmlElement element, int expected) throws ColladaException {
        NumberScanner n = element.numbers();
        if (n == null || n.isFloats()) {
            // A float-scanned element read as ints (no loader does this): rescan is impossible,
            // its text was never kept, so refuse rather than guess.
            if (n != null) {
                throw ctx.error(element, "holds decimal numbers where integers are expected");
            }
            n = NumberScanner.scan(element.text(), false);
        }
        check(ctx, element, n, expected);
        return n.ints();
    }

    private static void check(ImportContext ctx, XmlElement element, NumberScanner n, int expected)
            throws ColladaException {
        if (n.badIndex() >= 0) {
            throw ctx.error(element, "value " + n.badIndex() + " \"" + n.badToken() + "\" is " + n.badReason());
        }
        checkCount(ctx, element, n, expected);
    }

    private static void checkCount(ImportContext ctx, XmlElement element, NumberScanner n, int expected)
            throws ColladaException {
        if (expected >= 0 && n.size() != expected) {
            throw ctx.error(element, "count=\"" + expected + "\" but " + (n.size() < expected ? "only " : "")
                    + n.size() + " values");
        }
    }

    /** Splits the element's text into names ({@code Name_array}, {@code IDREF_array}). */
    static String[] names(ImportContext ctx, XmlElement element, int expected) throws ColladaException {
        String text = element.text();
        int n = countTokens(text);
        if (expected >= 0 && n != expected) {
            throw ctx.error(element, "count=\"" + expected + "\" but " + (n < expected ? "only " : "") + n + " names");
        }
        String[] out = new String[n];
        int pos = 0;
        int end = text.length();
        for (int i = 0; i < n; i++) {
            while (SafeXmlReader.isXmlWhitespace(text.charAt(pos))) {
                pos++;
            }
            int start = pos;
            while (pos < end && !SafeXmlReader.isXmlWhitespace(text.charAt(pos))) {
                pos++;
            }
            out[i] = text.substring(start, pos);
        }
        return out;
    }
}
