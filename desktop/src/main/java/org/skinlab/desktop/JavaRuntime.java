package org.skinlab.desktop;

import java.util.Locale;

/**
 * The Java runtime this process runs on, as {@code --version} and the benchmarks name it. Which
 * runtime that is, the start scripts and {@code gradle run} decide (README, "Which Java runs
 * skinlab"); the Vector API kernels' speed depends on it.
 */
public final class JavaRuntime {
    private JavaRuntime() {
    }

    /** {@code java.version}, e.g. "25.0.3". */
    public static String version() {
        return System.getProperty("java.version");
    }

    /** {@code java.vendor}, e.g. "Eclipse Adoptium". */
    public static String vendor() {
        return System.getProperty("java.vendor");
    }

    /** The version and vendor in words, e.g. "Java 25.0.3 (Eclipse Adoptium)". */
    public static String describe() {
        return String.format(Locale.ROOT, "Java %s (%s)", version(), vendor());
    }

    /** {@link #describe()} and the runtime's folder. */
    public static String describeWithHome() {
        return describe() + " at " + System.getProperty("java.home");
    }
}
