package org.skinlab.desktop.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code gradle/skinlab-java.sh}, the rule that picks the Java of the start scripts and of
 * {@code gradle run}, on fake JDKs in a temporary folder (SKINLAB_JAVA_SEARCH points there, so
 * the machine's own JDKs play no part).
 */
class JavaChoiceScriptTest {
    private static final String NEW_JDK_OPTIONS = "--enable-native-access=ALL-UNNAMED --sun-misc-unsafe-memory-access=allow";

    @TempDir
    Path dir;

    private Path jdks;
    private FakeJdk build;
    private final Map<String, String> env = new HashMap<>();

    /** What skinlab_choose_java decided. */
    private static final class Choice {
        final Shell shell;
        final Map<String, String> values = new HashMap<>();

        Choice(Shell shell) {
            this.shell = shell;
            for (String line : shell.outLines()) {
                int eq = line.indexOf('=');
                values.put(line.substring(0, eq), line.substring(eq + 1));
            }
        }

        boolean chose() {
            return "0".equals(values.get("status"));
        }

        String cmd() {
            return values.get("cmd");
        }
    }

    @BeforeEach
    void setUp() throws IOException {
        Shell.assumeShell();
        jdks = Files.createDirectories(dir.resolve("jdks"));
        // The default java (the build's), outside the searched folder.
        build = FakeJdk.create(dir.resolve("build-jdk"), "17.0.15", true);
        env.put("SKINLAB_JAVA_SEARCH", jdks + "/*");
    }

    private Choice choose() throws Exception {
        return choose(build.java().toString());
    }

    private Choice choose(String defaultJava) throws Exception {
        String script = ". \"$0\"; skinlab_choose_java \"$@\"; echo \"status=$?\"; echo \"cmd=$skinlab_java_cmd\";"
                + " echo \"version=$skinlab_java_version\"; echo \"options=$skinlab_java_options\"";
        List<String> command = new ArrayList<>(List.of("sh", "-c", script,
                Shell.root().resolve("gradle/skinlab-java.sh").toString(), defaultJava, "--add-modules",
                "jdk.incubator.vector"));
        Choice c = new Choice(Shell.run(command, env, dir));
        assertEquals(0, c.shell.status, c.shell::toString);
        return c;
    }

    @Test
    void newestJdkThatStartsWinsAndGetsItsVersionsOptions() throws Exception {
        FakeJdk jdk21 = FakeJdk.create(jdks.resolve("jdk-21"), "21.0.2", true);
        FakeJdk jdk24 = FakeJdk.create(jdks.resolve("jdk-24"), "24.0.1", true);
        FakeJdk broken25 = FakeJdk.create(jdks.resolve("jdk-25"), "25.0.3", false);
        Choice c = choose();
        assertTrue(c.chose(), c.shell::toString);
        assertEquals(jdk24.java().toString(), c.cmd());
        assertEquals("24.0.1", c.values.get("version"));
        assertEquals(NEW_JDK_OPTIONS, c.values.get("options"));
        // The broken 25 was tried first, with the options it would have run with; 21 never.
        assertEquals(List.of(NEW_JDK_OPTIONS + " --add-modules jdk.incubator.vector -version"), broken25.calls());
        assertEquals(List.of(NEW_JDK_OPTIONS + " --add-modules jdk.incubator.vector -version"), jdk24.calls());
        assertEquals(List.of(), jdk21.calls());
        assertEquals(List.of(), build.calls(), "the default java is never probed");
        assertEquals("", c.shell.err);
    }

    @Test
    void jdksBefore24GetNoExtraOptions() throws Exception {
        FakeJdk jdk21 = FakeJdk.create(jdks.resolve("jdk-21"), "21.0.2", true);
        Choice c = choose();
        assertEquals(jdk21.java().toString(), c.cmd());
        assertEquals("", c.values.get("options"));
        assertEquals(List.of("--add-modules jdk.incubator.vector -version"), jdk21.calls());
    }

    @Test
    void defaultJavaWhenItIsTheNewestWithoutAProbe() throws Exception {
        FakeJdk old = FakeJdk.create(jdks.resolve("jdk-17.0.9"), "17.0.9", true);
        FakeJdk jdk8 = FakeJdk.create(jdks.resolve("jdk8"), "1.8.0_292", true);
        Choice c = choose();
        assertTrue(!c.chose(), c.shell::toString);
        assertEquals(build.java().toString(), c.cmd());
        assertEquals("17.0.15", c.values.get("version"), "17.0.15 is newer than 17.0.9 (numbers, not text)");
        assertEquals("", c.values.get("options"));
        assertEquals(List.of(), old.calls());
        assertEquals(List.of(), jdk8.calls());
        assertEquals(List.of(), build.calls());
    }

    @Test
    void theDefaultJavasOwnVersionDecidesItsOptions() throws Exception {
        FakeJdk build25 = FakeJdk.create(dir.resolve("build-25"), "25", true);
        Choice c = choose(build25.java().toString());
        assertTrue(!c.chose(), c.shell::toString);
        assertEquals("25", c.values.get("version"));
        assertEquals(NEW_JDK_OPTIONS, c.values.get("options"));
    }

    @Test
    void buildTurnsTheSearchOff() throws Exception {
        FakeJdk jdk25 = FakeJdk.create(jdks.resolve("jdk-25"), "25.0.3", true);
        env.put("SKINLAB_JAVA_HOME", "build");
        Choice c = choose();
        assertTrue(!c.chose(), c.shell::toString);
        assertEquals(build.java().toString(), c.cmd());
        assertEquals(List.of(), jdk25.calls());
    }

    @Test
    void aNamedJdkWinsOverANewerOne() throws Exception {
        FakeJdk jdk21 = FakeJdk.create(dir.resolve("my jdk 21"), "21.0.2", true);
        FakeJdk.create(jdks.resolve("jdk-25"), "25.0.3", true);
        env.put("SKINLAB_JAVA_HOME", jdk21.home + "/");
        Choice c = choose();
        assertTrue(c.chose(), c.shell::toString);
        assertEquals(jdk21.java().toString(), c.cmd());
        assertEquals("", c.shell.err);
    }

    @Test
    void aNamedJdkThatDoesNotStartFallsBackToTheDefaultWithOneLine() throws Exception {
        FakeJdk broken = FakeJdk.create(dir.resolve("broken"), "25.0.3", false);
        Path notAJdk = Files.createDirectories(dir.resolve("empty"));
        FakeJdk tooOld = FakeJdk.create(dir.resolve("jdk11"), "11.0.20", true);
        for (Path named : List.of(broken.home, notAJdk, tooOld.home, dir.resolve("missing"))) {
            env.put("SKINLAB_JAVA_HOME", named.toString());
            Choice c = choose();
            assertTrue(!c.chose(), c.shell::toString);
            assertEquals(build.java().toString(), c.cmd());
            assertEquals(List.of("skinlab: ignoring SKINLAB_JAVA_HOME=" + named + ": no Java 17 or newer there starts"
                    + " with skinlab's JVM options; using " + build.java()), c.shell.errLines());
        }
        assertEquals(List.of(), tooOld.calls(), "too old by its release file: not even started");
    }

    @Test
    void javaHomeIsSearchedAndEarlyAccessVersionsCount() throws Exception {
        FakeJdk ea = FakeJdk.create(dir.resolve("jdk-26-ea"), "26-ea", true);
        FakeJdk.create(jdks.resolve("jdk-25"), "25", true);
        env.put("JAVA_HOME", ea.home.toString());
        Choice c = choose();
        assertEquals(ea.java().toString(), c.cmd());
        assertEquals("26-ea", c.values.get("version"));
    }

    @Test
    void theDefaultJavaIsFoundThroughThePathAndItsLinks() throws Exception {
        // "java" on the PATH, a link into a JDK that is also in the searched folder: no probe.
        FakeJdk jdk25 = FakeJdk.create(jdks.resolve("jdk-25"), "25.0.3", true);
        Path bin = Files.createDirectories(dir.resolve("bin"));
        Files.createSymbolicLink(bin.resolve("java"), jdk25.java());
        env.put("PATH", bin + ":" + System.getenv().getOrDefault("PATH", "/usr/bin:/bin"));
        Choice c = choose("java");
        assertTrue(!c.chose(), c.shell::toString);
        assertEquals("java", c.cmd());
        assertEquals("25.0.3", c.values.get("version"));
        assertEquals(NEW_JDK_OPTIONS, c.values.get("options"));
        assertEquals(List.of(), jdk25.calls());
    }
}
