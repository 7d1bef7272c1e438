package org.skinlab;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayOutputStream;
import java.io.File;
import java.io.IOException;
import java.io.PrintStream;
import java.lang.reflect.InvocationTargetException;
import java.net.URISyntaxException;
import java.net.URL;
import java.net.URLClassLoader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

import javax.tools.JavaCompiler;
import javax.tools.ToolProvider;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;

/**
 * Keeps the README's Java walk-through true: its {@code java} block is compiled against core and
 * run on the default character, and what it prints must be a skinned vertex and its palette's size.
 */
class ReadmeExampleTest {
    private static final Pattern JAVA_BLOCK = Pattern.compile("```java\n(.*?)```", Pattern.DOTALL);
    private static final Pattern PRINTED = Pattern.compile(
            "clip time (\\S+) s: vertex 0 at \\((\\S+), (\\S+), (\\S+)\\), (\\d+) joints in the palette\\s*");

    @Test
    void readmeWalkThroughCompilesRunsAndPrintsASkinnedVertex(@TempDir Path dir) throws Exception {
        String block = readmeJavaBlock();
        Path source = dir.resolve("ReadmeExample.java");
        Files.writeString(source, asClass(block));

        JavaCompiler javac = ToolProvider.getSystemJavaCompiler();
        assertNotNull(javac, "tests run on a JDK, which has a compiler");
        ByteArrayOutputStream diagnostics = new ByteArrayOutputStream();
        int status = javac.run(null, null, diagnostics, "-classpath", compileClasspath(), "-d", dir.toString(),
                source.toString());
        assertEquals(0, status, () -> "the README's java block does not compile:\n" + diagnostics);

        String printed = runMain(dir);
        Matcher m = PRINTED.matcher(printed);
        assertTrue(m.matches(), () -> "unexpected output: " + printed);
        for (int i = 1; i <= 4; i++) {
            assertTrue(Double.isFinite(Double.parseDouble(m.group(i))), printed);
        }
        assertTrue(Double.parseDouble(m.group(1)) > 0, () -> "the clip played on the thread: " + printed);
        assertEquals(19, Integer.parseInt(m.group(5)), () -> "the walking character has 19 joints: " + printed);
    }

    private static String readmeJavaBlock() throws IOException {
        String readme = Files.readString(TestPaths.root().resolve("README.md"));
        Matcher m = JAVA_BLOCK.matcher(readme);
        assertTrue(m.find(), "README.md has a ```java block");
        String block = m.group(1);
        assertTrue(!m.find(), "README.md has one ```java block");
        return block;
    }

    /**
     * The block's imports, then its statements as a main method; its asset path, relative to the
     * repository root as the README says, resolved there.
     */
    private static String asClass(String block) {
        StringBuilder imports = new StringBuilder();
        StringBuilder body = new StringBuilder();
        for (String line : block.split("\n")) {
            (line.startsWith("import ") ? imports : body).append(line).append('\n');
        }
        String root = TestPaths.root().toAbsolutePath().toString().replace("\\", "\\\\");
        String statements = body.toString().replace("Path.of(\"assets/", "Path.of(\"" + root + "/assets/");
        return imports + "public class ReadmeExample {\n"
                + "    public static void main(String[] args) throws Exception {\n" + statements + "    }\n}\n";
    }

    /** The test's class path and, where class loaders hide it, core's classes and JOML's jar. */
    private static String compileClasspath() throws URISyntaxException {
        Set<String> entries = new LinkedHashSet<>(List.of(System.getProperty("java.class.path").split(File.pathSeparator)));
        for (Class<?> c : new Class<?>[] {Model.class, org.joml.Matrix4f.class}) {
            entries.add(Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI()).toString());
        }
        return String.join(File.pathSeparator, new ArrayList<>(entries));
    }

    private static String runMain(Path classes) throws Exception {
        PrintStream original = System.out;
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        try (URLClassLoader loader = new URLClassLoader(new URL[] {classes.toUri().toURL()},
                ReadmeExampleTest.class.getClassLoader())) {
            System.setOut(new PrintStream(out, true, StandardCharsets.UTF_8));
            loader.loadClass("ReadmeExample").getMethod("main", String[].class).invoke(null, (Object) new String[0]);
        } catch (InvocationTargetException e) {
            throw e.getCause() instanceof Exception ex ? ex : e;
        } finally {
            System.setOut(original);
        }
        return out.toString(StandardCharsets.UTF_8);
    }
}
