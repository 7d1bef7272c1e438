package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.Random;

import org.junit.jupiter.api.Test;

/**
 * {@link NumberScanner} gets an element's text in chunks of any size (as the SAX parser hands
 * it over), so a token may be split anywhere. Whatever the split, the result must equal scanning
 * the whole text at once: same values, same size, same first problem.
 */
class NumberScannerTest {
    private static final long SEED = 42L;

    /** Feeds {@code text} in random chunks of 1 to maxChunk characters. */
    private static NumberScanner chunked(String text, boolean floats, Random random, int maxChunk) {
        NumberScanner s = new NumberScanner(floats, -1);
        char[] chars = text.toCharArray();
        int pos = 0;
        while (pos < chars.length) {
            int n = Math.min(chars.length - pos, 1 + random.nextInt(maxChunk));
            // Copy into a fresh buffer with garbage around it, as a parser's buffer would have.
            char[] buffer = new char[n + 8];
            java.util.Arrays.fill(buffer, 'x');
            System.arraycopy(chars, pos, buffer, 4, n);
            s.feed(buffer, 4, n);
            pos += n;
        }
        s.finish();
        return s;
    }

    private static void assertSame(NumberScanner whole, NumberScanner split, String text) {
        assertEquals(whole.size(), split.size(), text);
        assertEquals(whole.badIndex(), split.badIndex(), text);
        assertEquals(whole.badToken(), split.badToken(), text);
        assertEquals(whole.badReason(), split.badReason(), text);
        if (whole.isFloats()) {
            assertArrayEquals(whole.floats(), split.floats(), text);
        } else {
            assertArrayEquals(whole.ints(), split.ints(), text);
        }
    }

    @Test
    void floatsSplitAnywhereGiveTheSameValuesAsTheWholeText() {
        Random random = new Random(SEED);
        String[] tokens = {"1", "-0.5", "3.14159265358979323846", "1e-3", "+7E+2", ".25", "5.", "-0",
            "123456789012345678901234567890", "1.17549435E-38", "3.4028235e38", "0.000000000000000000001"};
        for (int round = 0; round < 2000; round++) {
            StringBuilder sb = new StringBuilder();
            int n = 1 + random.nextInt(40);
            for (int i = 0; i < n; i++) {
                sb.append(" \t\n\r".charAt(random.nextInt(4)));
                sb.append(tokens[random.nextInt(tokens.length)]);
            }
            String text = sb.toString();
            assertSame(NumberScanner.scan(text, true), chunked(text, true, random, 1 + random.nextInt(12)), text);
        }
    }

    @Test
    void longDecimalsNearFloatMidpointsRoundLikeFloatParseFloat() {
        // The double fast path is trusted only away from float midpoints; here every input is a
        // midpoint between two adjacent floats nudged by a tiny relative amount, written with
        // 17 to 24 significant digits (so digits beyond the 18th are dropped, the exponent often
        // lies beyond 10^22, and the double lands a few ulps from the midpoint).
        Random random = new Random(SEED + 4);
        StringBuilder text = new StringBuilder();
        java.util.List<String> tokens = new java.util.ArrayList<>();
        for (int i = 0; i < 20_000; i++) {
            float f = Float.intBitsToFloat(0x00800000 + random.nextInt(0x7F000000 - 0x00800000));
            java.math.BigDecimal lo = new java.math.BigDecimal(f);
            java.math.BigDecimal hi = new java.math.BigDecimal(Math.nextUp(f));
            java.math.BigDecimal mid = lo.add(hi).divide(java.math.BigDecimal.valueOf(2));
            java.math.BigDecimal nudge = mid.multiply(java.math.BigDecimal.valueOf(random.nextInt(2001) - 1000))
                    .movePointLeft(20 + random.nextInt(6));
            java.math.BigDecimal value = mid.add(nudge).round(new java.math.MathContext(17 + random.nextInt(8)));
            String token = (random.nextBoolean() ? "-" : "") + value.toString();
            tokens.add(token);
            text.append(token).append(' ');
        }
        float[] scanned = NumberScanner.scan(text.toString(), true).floats();
        for (int i = 0; i < tokens.size(); i++) {
            assertEquals(Float.floatToIntBits(Float.parseFloat(tokens.get(i))), Float.floatToIntBits(scanned[i]),
                    tokens.get(i));
        }
    }

    @Test
    void intsSplitAnywhereGiveTheSameValuesAsTheWholeText() {
        Random random = new Random(SEED + 1);
        for (int round = 0; round < 2000; round++) {
            StringBuilder sb = new StringBuilder();
            int n = 1 + random.nextInt(60);
            for (int i = 0; i < n; i++) {
                sb.append(' ').append(random.nextInt() >> random.nextInt(31));
            }
            String text = sb.toString();
            NumberScanner whole = NumberScanner.scan(text, false);
            assertEquals(n, whole.size());
            assertSame(whole, chunked(text, false, random, 1 + random.nextInt(9)), text);
        }
    }

    @Test
    void aBadTokenSplitAcrossChunksIsReportedWhole() {
        Random random = new Random(SEED + 2);
        String text = "1 2 3 1.#QNAN 5 NaN 7 1.2.3 9";
        for (int round = 0; round < 500; round++) {
            NumberScanner split = chunked(text, true, random, 1 + random.nextInt(6));
            assertEquals(9, split.size());
            assertEquals(3, split.nonFiniteIndex());
            assertEquals("1.#QNAN", split.nonFiniteToken());
            assertEquals("not a finite number", split.nonFiniteReason());
            assertEquals(2, split.nonFiniteCount());
            assertTrue(Float.isNaN(split.floats()[3]) && Float.isNaN(split.floats()[5]));
            assertEquals(7, split.badIndex());
            assertEquals("1.2.3", split.badToken());
            assertEquals("not a number", split.badReason());
        }
    }

    @Test
    void decimalCommasAreReadAsPointsSplitOrNot() {
        Random random = new Random(SEED + 4);
        String text = "0,5 -1,25 3 1,5e2 7.5";
        for (int round = 0; round < 500; round++) {
            NumberScanner split = chunked(text, true, random, 1 + random.nextInt(6));
            assertArrayEquals(new float[] {0.5f, -1.25f, 3f, 150f, 7.5f}, split.floats());
            assertEquals(3, split.decimalCommas());
            assertEquals(-1, split.badIndex());
        }
        // Long mantissas take the exact path, which must read the comma too.
        NumberScanner exact = NumberScanner.scan("0,1000000000000000055511151231257827", true);
        assertEquals(0.1f, exact.floats()[0]);
        // In integer lists a comma is no decimal separator.
        assertEquals(0, NumberScanner.scan("1,5", false).badIndex());
    }

    @Test
    void nonFiniteSpellingsBecomeValuesAndAreCountedApartFromBadTokens() {
        NumberScanner n = NumberScanner.scan("NaN -INF inf Infinity -1.#IND 1.#INF00 1e39 nanx", true);
        float[] f = n.floats();
        assertTrue(Float.isNaN(f[0]));
        assertEquals(Float.NEGATIVE_INFINITY, f[1]);
        assertEquals(Float.POSITIVE_INFINITY, f[2]);
        assertEquals(Float.POSITIVE_INFINITY, f[3]);
        assertTrue(Float.isNaN(f[4]));
        assertEquals(Float.POSITIVE_INFINITY, f[5]);
        assertEquals(Float.POSITIVE_INFINITY, f[6]);
        assertEquals(7, n.nonFiniteCount());
        assertEquals(7, n.badIndex(), "nanx is no spelling of NaN");
    }

    @Test
    void tokensLongerThanTheLimitAreRefusedWhetherSplitOrNot() {
        Random random = new Random(SEED + 3);
        String longToken = "1" + "0".repeat(NumberScanner.MAX_TOKEN);
        String text = "4 " + longToken + " 6";
        NumberScanner whole = NumberScanner.scan(text, true);
        assertEquals(3, whole.size());
        assertEquals(1, whole.badIndex());
        assertEquals("longer than " + NumberScanner.MAX_TOKEN + " characters", whole.badReason());
        for (int round = 0; round < 50; round++) {
            assertSame(whole, chunked(text, true, random, 1 + random.nextInt(64)), "long token");
        }
        // A token of exactly the limit is a number like any other: 1 followed by 394 zeros, e-394.
        String atLimit = "1" + "0".repeat(NumberScanner.MAX_TOKEN - 6) + "e-394";
        assertEquals(NumberScanner.MAX_TOKEN, atLimit.length());
        NumberScanner ok = NumberScanner.scan(atLimit, true);
        assertEquals(-1, ok.badIndex());
        assertArrayEquals(new float[] {1f}, ok.floats());
    }
}
