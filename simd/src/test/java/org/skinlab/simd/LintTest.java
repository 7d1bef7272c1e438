package org.skinlab.simd;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Stream;

import javax.tools.Diagnostic;
import javax.tools.DiagnosticCollector;
import javax.tools.JavaCompiler;
import javax.tools.JavaFileObject;
import javax.tools.StandardJavaFileManager;
import javax.tools.ToolProvider;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * simd's sources held to javac's lint warnings, as every other module's are by the build. The build
 * compiles simd with {@code -nowarn}: javac 17 says "using incubating module(s)" on each compile
 * that adds the Vector API module and has no lint category for that one warning (newer javac
 * calls it "incubating"), so the build would print it twice in every clean build. Here the same
 * sources are compiled with the build's lint options, and every warning but that one fails.
 */
class LintTest {
    private static final String INCUBATING = "compiler.warn.incubating.modules";

    @Test
    void simdsSourcesCompileWithoutALintWarning(@TempDir Path out) throws IOException {
        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assumeTrue(javac != null, "no javac in the JVM that runs the tests (a JRE)");
        String lint = System.getProperty("skinlab.javacLint");
        assumeTrue(lint != null, "the build's lint options are not given (-Dskinlab.javacLint)");
        Path root = Path.of(System.getProperty("skinlab.root", "..")).toAbsolutePath().normalize();
        List<Path> sources = new ArrayList<>();
        for (String dir : List.of("simd/src/main/java", "simd/src/test/java")) {
            try (Stream<Path> files = Files.walk(root.resolve(dir))) {
                files.filter(f -> f.toString().endsWith(".java")).sorted().forEach(sources::add);
            }
        }
        List<String> options = new ArrayList<>(List.of(lint, "-parameters", "-proc:none",
                "--add-modules", "jdk.incubator.vector",
                "-classpath", System.getProperty("java.class.path"), "-d", out.toString()));
        // As the build does (gradle/compat.gradle): --release cannot reach an incubator module beyond
        // the running JDK's own release.
        options.addAll(Runtime.version().feature() == 17 ? List.of("--release", "17") : List.of("-source", "17", "-target", "17"));

        DiagnosticCollector<JavaFileObject> diagnostics = new DiagnosticCollector<>();
        boolean compiled;
        try (StandardJavaFileManager files = javac.getStandardFileManager(diagnostics, Locale.ROOT, StandardCharsets.UTF_8)) {
            compiled = javac.getTask(null, files, diagnostics, options, null, files.getJavaFileObjectsFromPaths(sources)).call();
        }
        List<String> warnings = diagnostics.getDiagnostics().stream()
                .filter(d -> d.getKind() != Diagnostic.Kind.NOTE && !INCUBATING.equals(d.getCode()))
                .map(d -> d.getKind() + " " + d.getCode() + " " + d.getMessage(Locale.ROOT)
                        + (d.getSource() == null ? "" : " (" + d.getSource().getName() + ":" + d.getLineNumber() + ")"))
                .toList();
        assertTrue(sources.size() > 20, "simd's sources found: " + sources.size());
        assertEquals(List.of(), warnings, "javac's lint on simd");
        assertTrue(compiled, "simd compiles");
        assertTrue(diagnostics.getDiagnostics().stream().anyMatch(d -> INCUBATING.equals(d.getCode())),
                "javac still names the incubating module it compiled against (what -nowarn hides in the build)");
    }
}
