package org.skinlab.desktop.cli;

import java.util.Locale;

/**
 * The Java runtime this process runs on, as {@code --version} and the benchmarks name it. Which
 * runtime that is, the start scripts and {@code gradle run} decide (README, "Which Java runs
 * skinlab"); the Vector API kernels' speed depends on it.
 */
final class JavaRuntime {
    private JavaRuntime() {
    }

    /** {@code java.version}, e.g. "25.0.3". */
    static String version() {
        return System.getProperty("java.version");
    }

    /** {@code java.vendor}, e.g. "Eclipse Adoptium". */
    static String vendor() {
        return System.getProperty("java.vendor");
    }

    /** The version and vendor in words, e.g. "Java 25.0.3 (Eclipse Adoptium)". */
    static String describe() {
        return String.format(Locale.ROOT, "Java %s (%s)", version(), vendor());
    }

    /** {@link #describe()} and the runtime's folder. */
    static String describeWithHome() {
        return describe() + " at " + System.getProperty("java.home");
    }
}
