package org.skinlab.desktop.launch;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The unix start script of installDist (the build runs installDist before these tests) with the
 * Java choice written into it: what it executes, its fallback, and a clean stderr on whatever JDK
 * it picks on this machine.
 */
class StartScriptTest {
    private static final String INCUBATOR_WARNING = "WARNING: Using incubator modules: jdk.incubator.vector";

    @TempDir
    Path dir;

    private Path script;
    private final Map<String, String> env = new HashMap<>();

    @BeforeEach
    void setUp() {
        Shell.assumeShell();
        script = Shell.root().resolve("desktop/build/install/skinlab/bin/skinlab");
        assertTrue(Files.isExecutable(script), "run installDist first (the build does): " + script);
        // The default java is the one running these tests.
        env.put("JAVA_HOME", System.getProperty("java.home"));
    }

    private Shell skinlab(String... args) throws Exception {
        List<String> command = new java.util.ArrayList<>(List.of(script.toString()));
        command.addAll(List.of(args));
        return Shell.run(command, env, dir);
    }

    @Test
    void execsTheNewestJdkWithItsOptionsBeforeTheProgram() throws Exception {
        FakeJdk jdk = FakeJdk.create(dir.resolve("jdks/jdk-99"), "99.0.1", true);
        env.put("SKINLAB_JAVA_SEARCH", dir.resolve("jdks") + "/*");
        Shell r = skinlab("--version", "two words");
        assertEquals(0, r.status, r::toString);
        List<String> args = r.outLines();
        assertEquals("fake-java", args.get(0), r::toString);
        assertEquals(List.of("--enable-native-access=ALL-UNNAMED", "--sun-misc-unsafe-memory-access=allow",
                "--add-modules", "jdk.incubator.vector", "-classpath"), args.subList(1, 6), r::toString);
        assertEquals(List.of("org.skinlab.desktop.cli.SkinlabMain", "--version", "two words"),
                args.subList(7, args.size()), r::toString);
        assertEquals("", r.err);
        // Probed once with the options it then ran with.
        assertEquals("--enable-native-access=ALL-UNNAMED --sun-misc-unsafe-memory-access=allow --add-modules "
                + "jdk.incubator.vector -version", jdk.calls().get(0));
    }

    @Test
    void aNamedJdkThatDoesNotStartFallsBackToJavaHome() throws Exception {
        FakeJdk broken = FakeJdk.create(dir.resolve("broken"), "25.0.3", false);
        env.put("SKINLAB_JAVA_HOME", broken.home.toString());
        Shell r = skinlab("--version");
        assertEquals(0, r.status, r::toString);
        assertEquals("Java " + System.getProperty("java.version") + " (" + System.getProperty("java.vendor")
                + ") at " + System.getProperty("java.home"), r.outLines().get(1), r::toString);
        assertEquals(List.of("skinlab: ignoring SKINLAB_JAVA_HOME=" + broken.home + ": no Java 17 or newer there"
                + " starts with skinlab's JVM options; using " + System.getProperty("java.home") + "/bin/java",
                INCUBATOR_WARNING), r.errLines());
    }

    @Test
    void buildRunsJavaHome() throws Exception {
        env.put("SKINLAB_JAVA_HOME", "build");
        Shell r = skinlab("--version");
        assertEquals(0, r.status, r::toString);
        assertTrue(r.outLines().get(1).endsWith(" at " + System.getProperty("java.home")), r::toString);
        assertEquals(List.of(INCUBATOR_WARNING), r.errLines());
    }

    @Test
    void theJdkFoundHereKeepsStderrToTheIncubatorLine() throws Exception {
        // The machine's own JDKs: on a machine with JDK 24 or newer this checks its options.
        Shell r = skinlab("inspect", "assets/characters/humanoid-walk.dae");
        assertEquals(0, r.status, r::toString);
        assertEquals(List.of(INCUBATOR_WARNING), r.errLines());
        // assimp through LWJGL loads a native library and uses sun.misc.Unsafe: no JVM warning either.
        r = skinlab("bench", "parse", "--compare-assimp", "--runs", "1", "--warmup-seconds", "0",
                "assets/cylinders/cylinder-twist-low.dae");
        assertEquals(0, r.status, r::toString);
        assertEquals(List.of(INCUBATOR_WARNING), r.errLines().stream().filter(l -> l.startsWith("WARNING")).toList(),
                r::toString);
    }
}
