package org.skinlab.collada;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;
import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;

/**
 * {@link NumberParser}: floats correctly rounded (checked against {@link Float#parseFloat}, which
 * is itself checked against exact decimal arithmetic), every kind of XML whitespace, signed ints
 * and refusals. Tested directly from the same package, plus one fixture that goes through the
 * XML parser.
 */
class NumberParserTest {
    private static final long SEED = 20190611L; // fixed: a failure is reproducible
    private static final int RANDOM_CASES = 200_000;

    /** An element holding {@code text}, as SafeXmlReader would hand it over (leading blanks kept: the parser must cope). */
    private static XmlElement element(String name, String text) {
        XmlElement e = new XmlElement(name, null, 7, null);
        e.setText(text);
        return e;
    }

    private static float[] floats(String text) throws ColladaException {
        XmlElement e = element("float_array", text);
        return NumberParser.floats(new ImportContext("numbers.dae", e), e, -1);
    }

    private static int[] ints(String text) throws ColladaException {
        XmlElement e = element("p", text);
        return NumberParser.ints(new ImportContext("numbers.dae", e), e, -1);
    }

    private static ColladaException floatError(String text) {
        return assertThrows(ColladaException.class, () -> floats(text), () -> "\"" + text + "\" was accepted");
    }

    private static ColladaException intError(String text) {
        return assertThrows(ColladaException.class, () -> ints(text), () -> "\"" + text + "\" was accepted");
    }

    // ---- floats: correct rounding

    @Test
    void randomDecimalStringsRoundExactlyLikeFloatParseFloat() throws ColladaException {
        Random random = new Random(SEED);
        List<String> finite = new ArrayList<>();
        List<String> overflow = new ArrayList<>();
        for (int i = 0; i < RANDOM_CASES; i++) {
            String s = randomDecimal(random);
            float expected = Float.parseFloat(s);
            assertCorrectlyRounded(s, expected);
            (Float.isInfinite(expected) ? overflow : finite).add(s);
        }
        // The generator must mostly produce usable values, and some that overflow (checked below).
        assertTrue(finite.size() > RANDOM_CASES * 3 / 4, () -> finite.size() + " finite cases");
        assertTrue(overflow.size() > 1000, () -> overflow.size() + " overflowing cases");

        // All finite values in one list, separated by random XML whitespace, as in a float_array.
        StringBuilder text = new StringBuilder();
        for (String s : finite) {
            text.append(randomWhitespace(random)).append(s);
        }
        text.append(randomWhitespace(random));
        float[] parsed = floats(text.toString());
        assertEquals(finite.size(), parsed.length);
        for (int i = 0; i < parsed.length; i++) {
            String s = finite.get(i);
            float expected = Float.parseFloat(s);
            if (Float.floatToRawIntBits(parsed[i]) != Float.floatToRawIntBits(expected)) {
                assertEquals(expected, parsed[i], "\"" + s + "\" (bits must match, -0 included)");
                assertEquals(Float.floatToRawIntBits(expected), Float.floatToRawIntBits(parsed[i]), "sign of zero of \"" + s + "\"");
            }
        }
        // Values beyond the float range are refused, never read as infinity.
        for (String s : overflow) {
            assertTrue(floatError(s).getMessage().contains("out of float range"), s);
        }
    }

    @Test
    void floatMidpointsAndDecimalsNearThemRoundHalfToEven() throws ColladaException {
        // Decimal strings exactly halfway between two adjacent floats, a hair either side, and
        // short decimals (15 or 16 digits) next to a midpoint: the last are the double-rounding
        // hazard of a parser that computes a double first, because such a decimal's nearest
        // double can be the midpoint itself although the decimal is not. Integers between 2^24
        // and 2^53 are exact in double.
        Random random = new Random(SEED + 1);
        List<String> cases = new ArrayList<>(List.of("16777217", "16777219", "33554434", "33554438",
                "1.6777217e7", "16777217.0", "167772170e-1", "-16777217", "16777217.000000001", "16777216.99999999"));
        int hazards = 0;
        for (int i = 0; i < 20_000; i++) {
            float f = Float.intBitsToFloat(random.nextInt(0x7F7F_FFFF));
            BigDecimal mid = new BigDecimal(f).add(new BigDecimal(Math.nextUp(f))).divide(BigDecimal.valueOf(2));
            BigDecimal hair = mid.ulp().movePointLeft(3);
            cases.add(mid.toString());
            cases.add(mid.add(hair).toString());
            cases.add(mid.subtract(hair).toString());
            if (f >= 16777216f && f < 9.007199e15f) {
                cases.add(mid.toBigInteger().toString()); // exact integer midpoint
            }
            for (int digits = 15; digits <= 16; digits++) {
                BigDecimal near = mid.round(new MathContext(digits, RoundingMode.HALF_EVEN));
                cases.add(near.toString());
                if (near.compareTo(mid) != 0 && new BigDecimal(Double.parseDouble(near.toString())).compareTo(mid) == 0) {
                    hazards++;
                }
            }
        }
        // The seed must yield plenty of real hazards (about one case in ten is one).
        assertTrue(hazards > 1000, hazards + " hazards");
        StringBuilder text = new StringBuilder();
        for (String s : cases) {
            text.append(' ').append(s);
        }
        float[] parsed = floats(text.toString());
        for (int i = 0; i < parsed.length; i++) {
            String s = cases.get(i);
            float expected = Float.parseFloat(s);
            assertCorrectlyRounded(s, expected);
            assertEquals(Float.floatToRawIntBits(expected), Float.floatToRawIntBits(parsed[i]), s);
        }
        // Worked by hand: 16777217 = 2^24 + 1 lies halfway between 2^24 and 2^24 + 2; the even
        // one is 2^24. 33554434 = 2^25 + 2 lies halfway between 2^25 and 2^25 + 4; even: 2^25.
        assertEquals(16777216f, parsed[0]);
        assertEquals(16777220f, parsed[1]); // 2^24 + 3: halfway between +2 (odd mantissa) and +4 (even)
        assertEquals(33554432f, parsed[2]);
        assertEquals(16777218f, parsed[8]); // just above the midpoint rounds up
        assertEquals(16777216f, parsed[9]); // just below the midpoint rounds down
    }

    @Test
    void shortDecimalsWhoseNearestDoubleIsAFloatMidpointRoundByTheirExactValue() throws ColladaException {
        // Found with BigDecimal while writing this test: both have 16 digits and a small
        // exponent (the parser's exact double fast path), neither is a float midpoint, but the
        // nearest double of each is one, so rounding that double to float (ties to even) picks
        // the wrong neighbour. The asserts prove each step.
        for (String s : new String[] {"7.023263022160282E+16", "3.110383630655633E-7"}) {
            float expected = Float.parseFloat(s);
            assertCorrectlyRounded(s, expected);
            double d = Double.parseDouble(s);
            assertTrue((float) d != expected, s + ": rounding through double goes wrong here");
            assertEquals(Float.floatToRawIntBits(expected), Float.floatToRawIntBits(floats(s)[0]), s);
            assertEquals(Float.floatToRawIntBits(-expected), Float.floatToRawIntBits(floats("-" + s)[0]), s);
        }
    }

    @Test
    void spellingsOfNumbersAreReadAsTheirValues() throws ColladaException {
        float[] f = floats(".5 5. 1e3 1E-3 +1 -0 0 +0 -.25 007.50 1.e2 0.000 1e+2 -0e-0 1.4e-45 1e-46");
        assertArrayEquals(new float[] {0.5f, 5f, 1000f, 0.001f, 1f, -0f, 0f, 0f, -0.25f, 7.5f, 100f, 0f, 100f, -0f,
            Float.MIN_VALUE, 0f}, f);
        // assertArrayEquals already compares floats by bits; state the zeros' signs explicitly too.
        assertEquals(Float.floatToRawIntBits(-0f), Float.floatToRawIntBits(f[5]), "-0 keeps its sign");
        assertEquals(0, Float.floatToRawIntBits(f[7]), "+0 is positive zero");
        assertEquals(Float.floatToRawIntBits(-0f), Float.floatToRawIntBits(f[13]), "-0e-0 keeps its sign");
    }

    @Test
    void nonFiniteAndMalformedFloatsAreRefusedNamingTheValue() {
        String[] bad = {"NaN", "nan", "inf", "-Infinity", "1.#QNAN", "-1.#IND", "1e", "1e+", ".", "-", "+", "e5",
            "1.5.2", "1,5,2", "5,", "1.5,2", "0x10", "1f", "1d", "1e39", "-3.5e38", "1\u00A02"};
        for (String s : bad) {
            ColladaException e = floatError("0 " + s + " 1");
            String m = e.getMessage();
            assertTrue(m.contains("value 1 \"" + s + "\""), () -> s + ": " + m);
            assertTrue(m.contains("numbers.dae") && m.contains("<float_array>"), m);
        }
    }

    // ---- whitespace

    @Test
    void everyKindOfXmlWhitespaceSeparatesAndSurroundsValues() throws ColladaException {
        assertArrayEquals(new float[] {1f, 2.5f, -3f, 4f, 5f, 6f},
                floats(" \t\r\n1\t2.5\r-3\n4\r\n5 \t \r\n 6\r\n\t "));
        assertArrayEquals(new int[] {1, 2, 3, 4, 5, 6}, ints("\r\n\t 1\t2\r3\n4\r\n5 \t\r\n 6 \t\r\n"));
        assertArrayEquals(new float[0], floats(" \t\r\n "));
        assertArrayEquals(new int[0], ints(""));
    }

    @Test
    void whitespaceThatXmlDoesNotDefineIsNotASeparator() {
        // Form feed, vertical tab and no-break space are whitespace to Java, not to XML.
        for (String sep : new String[] {"\f", "\u000B", "\u00A0", "\u2003"}) {
            assertThrows(ColladaException.class, () -> floats("1" + sep + "2"), () -> "separator U+"
                    + Integer.toHexString(sep.charAt(0)));
            assertThrows(ColladaException.class, () -> ints("1" + sep + "2"));
        }
    }

    @Test
    void carriageReturnsAndTabsInTheFileSeparateValues() {
        // Through the XML parser: a literal CR LF is normalised to LF by XML, so &#13; is the only
        // way a CR reaches the number parser; &#9; is a tab.
        Model m = Fixtures.read("whitespace.dae", """
                <?xml version="1.0" encoding="utf-8"?>
                <COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
                  <asset><up_axis>Y_UP</up_axis></asset>
                  <library_geometries>
                    <geometry id="g">
                      <mesh>
                        <source id="pos">
                          <float_array id="pos-array" count="9">&#13;0&#9;0&#13;0&#13;&#10;1\t0 0
                              0&#13;1&#9;&#9;0&#13;</float_array>
                          <technique_common>
                            <accessor source="#pos-array" count="3" stride="3">
                              <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
                            </accessor>
                          </technique_common>
                        </source>
                        <vertices id="v"><input semantic="POSITION" source="#pos"/></vertices>
                        <triangles count="1">
                          <input semantic="VERTEX" source="#v" offset="0"/>
                          <p>&#9;0&#13;1&#13;&#10;2&#9;</p>
                        </triangles>
                      </mesh>
                    </geometry>
                  </library_geometries>
                </COLLADA>
                """);
        Mesh mesh = m.meshes().get(0);
        assertArrayEquals(new float[] {0, 0, 0, 1, 0, 0, 0, 1, 0}, mesh.positions());
        assertEquals(1, mesh.triangleCount());
        assertArrayEquals(new int[] {0, 1, 2}, new int[] {mesh.vertexPosition(mesh.triangleVertex(0, 0)),
            mesh.vertexPosition(mesh.triangleVertex(0, 1)), mesh.vertexPosition(mesh.triangleVertex(0, 2))});
    }

    // ---- ints

    @Test
    void intsAcceptSignsAndTheWholeIntRange() throws ColladaException {
        assertArrayEquals(new int[] {5, -7, 0, 0, 0, 2147483647, -2147483648, 12},
                ints("+5 -7 0 -0 +0 2147483647 -2147483648 0012"));
    }

    @Test
    void intsOutOfRangeAreRefused() {
        for (String s : new String[] {"2147483648", "-2147483649", "+2147483648", "99999999999999999999",
            "-9223372036854775809"}) {
            ColladaException e = intError("1 " + s);
            assertTrue(e.getMessage().contains("value 1 \"" + s + "\" is integer out of range"), e::getMessage);
        }
    }

    @Test
    void nonIntegersAreRefused() {
        for (String s : new String[] {"1.0", "1e3", "-", "+", "--1", "+-1", "0x10", "1-2", "one", "1.", ".5"}) {
            ColladaException e = intError("0 " + s);
            assertTrue(e.getMessage().contains("value 1 \"" + s + "\" is not an integer"), e::getMessage);
        }
    }

    @Test
    void declaredCountMustMatchTheValues() {
        XmlElement e = element("float_array", "1 2 3 4");
        ImportContext ctx = new ImportContext("numbers.dae", e);
        assertThrows(ColladaException.class, () -> NumberParser.floats(ctx, e, 3));
        assertThrows(ColladaException.class, () -> NumberParser.floats(ctx, e, 5));
        XmlElement p = element("int_array", "1 2 3");
        assertThrows(ColladaException.class, () -> NumberParser.ints(new ImportContext("numbers.dae", p), p, 2));
    }

    // ---- generators and the exact oracle

    /**
     * A random decimal: optional sign, 1 to 25 digits (possibly with leading zeros), the point
     * anywhere (".5" and "5." included) or absent, optional exponent -45..39 written as e or E
     * with or without sign and leading zeros.
     */
    private static String randomDecimal(Random r) {
        StringBuilder sb = new StringBuilder(40);
        switch (r.nextInt(4)) {
            case 0: sb.append('-'); break;
            case 1: if (r.nextInt(4) == 0) { sb.append('+'); } break;
            default: break;
        }
        int digits = 1 + r.nextInt(25);
        int leadingZeros = r.nextInt(5) == 0 ? Math.min(digits - 1, r.nextInt(4)) : 0;
        int point;
        switch (r.nextInt(5)) {
            case 0: point = -1; break;          // no point
            case 1: point = 0; break;           // ".5"
            case 2: point = digits; break;      // "5."
            default: point = r.nextInt(digits + 1); break;
        }
        for (int i = 0; i < digits; i++) {
            if (i == point) {
                sb.append('.');
            }
            sb.append(i < leadingZeros ? '0' : (char) ('0' + (i == leadingZeros ? 1 + r.nextInt(9) : r.nextInt(10))));
        }
        if (point == digits) {
            sb.append('.');
        }
        if (r.nextInt(3) != 0) {
            sb.append(r.nextBoolean() ? 'e' : 'E');
            int exp = -45 + r.nextInt(85);
            if (exp < 0) {
                sb.append('-');
            } else if (r.nextInt(3) == 0) {
                sb.append('+');
            }
            if (r.nextInt(8) == 0) {
                sb.append('0');
            }
            sb.append(Math.abs(exp));
        }
        return sb.toString();
    }

    private static String randomWhitespace(Random r) {
        String[] kinds = {" ", " ", " ", "\t", "\n", "\r", "\r\n", "  ", " \t", "\n\t\t"};
        return kinds[r.nextInt(kinds.length)];
    }

    /**
     * Checks that {@code f} is the float nearest to the exact decimal value of {@code s}, ties to
     * the even mantissa, with exact BigDecimal arithmetic: the reference itself is verified.
     */
    private static void assertCorrectlyRounded(String s, float f) {
        BigDecimal x = new BigDecimal(s).abs();
        float a = Math.abs(f);
        if (x.signum() == 0) {
            assertEquals(0f, a, s);
            return;
        }
        if (Float.isInfinite(a)) {
            // Overflow iff x is at least halfway between MAX_VALUE and 2^128.
            BigDecimal max = new BigDecimal(Float.MAX_VALUE);
            BigDecimal limit = max.add(new BigDecimal(Math.ulp(Float.MAX_VALUE)).divide(BigDecimal.valueOf(2)));
            assertTrue(x.compareTo(limit) >= 0, () -> s + " overflowed below the limit");
            return;
        }
        BigDecimal mine = new BigDecimal(a);
        BigDecimal up = a == Float.MAX_VALUE
                ? mine.add(new BigDecimal(Math.ulp(a)))
                : new BigDecimal(Math.nextUp(a));
        BigDecimal down = a == 0f ? mine.negate() : new BigDecimal(Math.nextDown(a));
        BigDecimal two = BigDecimal.valueOf(2);
        BigDecimal upperMid = mine.add(up).divide(two);
        BigDecimal lowerMid = mine.add(down).divide(two);
        boolean even = (Float.floatToRawIntBits(a) & 1) == 0;
        int cu = x.compareTo(upperMid);
        int cl = x.compareTo(lowerMid);
        boolean ok = (cu < 0 || (cu == 0 && even)) && (cl > 0 || (cl == 0 && even));
        assertTrue(ok, () -> s + " -> " + f + " is not the nearest float (" + x.setScale(60, RoundingMode.HALF_EVEN) + ")");
        if (s.startsWith("-")) {
            assertEquals(Float.floatToRawIntBits(-a), Float.floatToRawIntBits(f), () -> s + " lost its sign");
        }
    }
}
