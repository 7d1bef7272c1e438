package org.skinlab.android.backport;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.util.SplittableRandom;

import org.junit.jupiter.api.Test;

/** The backport gives what the JDK's Math.fma gives, bit for bit, special values and roundings included. */
class MathsTest {
    private static final double[] SPECIAL = {0.0, -0.0, 1.0, -1.0, Double.MIN_VALUE, -Double.MIN_VALUE,
        Double.MIN_NORMAL, Double.MAX_VALUE, -Double.MAX_VALUE, Double.POSITIVE_INFINITY, Double.NEGATIVE_INFINITY,
        Double.NaN, 1e-300, 1e300, 0.1, 3.0, Math.ulp(1.0), 1 + Math.ulp(1.0)};

    @Test
    void doublesAsTheJdk() {
        for (double a : SPECIAL) {
            for (double b : SPECIAL) {
                for (double c : SPECIAL) {
                    assertSameDouble(Math.fma(a, b, c), Maths.fma(a, b, c), a, b, c);
                }
            }
        }
        SplittableRandom random = new SplittableRandom(26);
        for (int i = 0; i < 200_000; i++) {
            double a = random.nextDouble(-4, 4) * Math.pow(2, random.nextInt(-60, 60));
            double b = random.nextDouble(-4, 4) * Math.pow(2, random.nextInt(-60, 60));
            // c near -a*b, so that the sum cancels and only the single rounding gets it right
            double c = i % 2 == 0 ? -a * b * (1 + random.nextDouble(-1e-12, 1e-12)) : random.nextDouble(-8, 8);
            assertSameDouble(Math.fma(a, b, c), Maths.fma(a, b, c), a, b, c);
        }
    }

    @Test
    void floatsAsTheJdk() {
        float[] special = {0f, -0f, 1f, -1f, Float.MIN_VALUE, Float.MIN_NORMAL, Float.MAX_VALUE, -Float.MAX_VALUE,
            Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NaN, 1e-30f, 1e30f, 0.1f, Math.ulp(1f)};
        for (float a : special) {
            for (float b : special) {
                for (float c : special) {
                    assertEquals(Float.floatToIntBits(Math.fma(a, b, c)), Float.floatToIntBits(Maths.fma(a, b, c)),
                            a + " * " + b + " + " + c);
                }
            }
        }
        SplittableRandom random = new SplittableRandom(37);
        for (int i = 0; i < 200_000; i++) {
            float a = (float) random.nextDouble(-100, 100);
            float b = (float) random.nextDouble(-100, 100);
            float c = i % 2 == 0 ? -a * b : (float) random.nextDouble(-100, 100);
            assertEquals(Float.floatToIntBits(Math.fma(a, b, c)), Float.floatToIntBits(Maths.fma(a, b, c)),
                    a + " * " + b + " + " + c);
        }
    }

    private static void assertSameDouble(double expected, double actual, double a, double b, double c) {
        assertEquals(Double.doubleToLongBits(expected), Double.doubleToLongBits(actual), a + " * " + b + " + " + c);
    }
}
