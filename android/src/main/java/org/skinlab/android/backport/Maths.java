package org.skinlab.android.backport;

import java.math.BigDecimal;

/**
 * {@code Math.fma} (Java 9, Android API 33) for Android 8: R8 rewrites every call to it in the APK
 * into a call to this class (android/backports.json). JOML's {@code Math.fma} is the only caller,
 * and JOML calls it only when the system property {@code joml.useMathFma} is set, which the app
 * never does; the rewrite keeps the APK free of calls that Android 8 lacks, and this class computes
 * what {@code Math.fma} computes in case it is ever reached: {@code a * b + c} rounded once.
 */
public final class Maths {
    private Maths() {
    }

    /** {@code a * b + c} rounded once to the nearest double, as {@code Math.fma(double, double, double)}. */
    public static double fma(double a, double b, double c) {
        if (Double.isNaN(a) || Double.isNaN(b) || Double.isNaN(c)) {
            return Double.NaN;
        }
        if (Double.isInfinite(a) || Double.isInfinite(b)) {
            return a * b + c; // the infinities and NaNs (inf * 0, inf - inf) IEEE 754 gives
        }
        if (Double.isInfinite(c)) {
            return c; // the exact product is finite, even where a * b would overflow
        }
        if (a == 0.0 || b == 0.0) {
            return a * b + c; // the product is an exact (signed) zero: the sum rounds once
        }
        if (c == 0.0) {
            return a * b; // a nonzero exact product plus a zero is that product, rounded once
        }
        BigDecimal sum = new BigDecimal(a).multiply(new BigDecimal(b)).add(new BigDecimal(c));
        return sum.signum() == 0 ? 0.0 : sum.doubleValue(); // an exact cancellation is +0
    }

    /** {@code a * b + c} rounded once to the nearest float, as {@code Math.fma(float, float, float)}. */
    public static float fma(float a, float b, float c) {
        if (Float.isNaN(a) || Float.isNaN(b) || Float.isNaN(c)) {
            return Float.NaN;
        }
        if (Float.isInfinite(a) || Float.isInfinite(b) || a == 0.0f || b == 0.0f) {
            return a * b + c;
        }
        if (Float.isInfinite(c)) {
            return c;
        }
        // A product of two floats is exact in a double; the sum is rounded once, to a float.
        if (c == 0.0f) {
            return (float) ((double) a * (double) b);
        }
        BigDecimal sum = new BigDecimal((double) a * (double) b).add(new BigDecimal(c));
        return sum.signum() == 0 ? 0.0f : sum.floatValue();
    }
}
