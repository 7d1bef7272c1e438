package org.skinlab.android.apicheck;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.stream.Stream;

import com.android.tools.r8.CompilationFailedException;
import com.android.tools.r8.D8;
import com.android.tools.r8.D8Command;
import com.android.tools.r8.R8;
import com.android.tools.r8.R8Command;
import com.android.tools.r8.origin.Origin;

/**
 * Dex files made from the fixture classes (src/apicheckFixtures/java, compiled against
 * android-all) the way the build makes the app's and core's: D8, or R8 (which moves calls to APIs
 * above the min SDK into its outline classes), both at the min SDK; and the check run on them.
 * The build passes the paths as system properties (api-check.gradle).
 */
final class FixtureDex {
    static final String PACKAGE = "org.skinlab.android.apicheck.fixtures";

    private FixtureDex() {
    }

    static int minSdk() {
        return Integer.parseInt(property("apicheck.minSdk"));
    }

    /** Dexes the named fixture classes (and their nested classes) with D8 into dir. */
    static Path d8(Path dir, String... fixtures) throws IOException, CompilationFailedException {
        D8.run(D8Command.parse(arguments(dir, fixtures), Origin.root()).build());
        return dir;
    }

    /**
     * Shrinks and dexes the named fixture classes with R8 as the app's rules do (no obfuscation, no
     * optimising), keeping one static method as the entry point: R8 moves calls to APIs above the
     * min SDK into outlines only in code it may change.
     */
    static Path r8(Path dir, String entryClass, String entryMethod, String... fixtures)
            throws IOException, CompilationFailedException {
        List<String> rules = List.of("-keep class " + PACKAGE + "." + entryClass + " { public static *** " + entryMethod
                + "(...); }", "-dontobfuscate", "-dontoptimize");
        R8.run(R8Command.parse(arguments(dir, fixtures), Origin.root()).addProguardConfiguration(rules, Origin.unknown())
                .build());
        return dir;
    }

    /**
     * The command line the build gives D8 and R8 (android/build.gradle, api-check.gradle), read by
     * their own parser: built through R8Command's builder with the JDK as a library provider
     * instead, R8 8.5.35 made no API outlines of these classes.
     */
    private static String[] arguments(Path dir, String... fixtures) throws IOException {
        Files.createDirectories(dir);
        List<String> args = new ArrayList<>(List.of("--release", "--min-api", String.valueOf(minSdk()), "--lib",
                property("apicheck.androidAll"), "--lib", System.getProperty("java.home"), "--output", dir.toString()));
        classFiles(fixtures).forEach(f -> args.add(f.toString()));
        return args.toArray(String[]::new);
    }

    /** The check on a directory of dex files, against the build's signatures, with no exceptions. */
    static ApiReport check(Path dexDir) throws IOException {
        return check(dexDir, ApiExceptions.none());
    }

    static ApiReport check(Path dexDir, ApiExceptions exceptions) throws IOException {
        List<Path> dex;
        try (Stream<Path> files = Files.list(dexDir)) {
            dex = files.filter(f -> f.toString().endsWith(".dex")).sorted().toList();
        }
        return ApiCheckMain.check("fixture", dex, List.of(), Path.of(property("apicheck.api")),
                Path.of(property("apicheck.newerApi")), minSdk(), exceptions);
    }

    private static List<Path> classFiles(String... fixtures) throws IOException {
        List<Path> files = new ArrayList<>();
        for (String root : property("apicheck.fixtures").split(File.pathSeparator)) {
            Path dir = Path.of(root, PACKAGE.split("\\."));
            if (!Files.isDirectory(dir)) {
                continue;
            }
            try (Stream<Path> all = Files.list(dir)) {
                all.filter(f -> Arrays.stream(fixtures).anyMatch(n -> isClassOf(f, n))).forEach(files::add);
            }
        }
        if (files.isEmpty()) {
            throw new IOException("no class files of " + Arrays.toString(fixtures) + " in " + property("apicheck.fixtures"));
        }
        return files;
    }

    private static boolean isClassOf(Path file, String fixture) {
        String name = file.getFileName().toString();
        return name.equals(fixture + ".class") || name.startsWith(fixture + "$") && name.endsWith(".class");
    }

    private static String property(String name) {
        String value = System.getProperty(name);
        if (value == null) {
            throw new IllegalStateException("system property " + name + " not set: run through gradle :android:test");
        }
        return value;
    }
}
