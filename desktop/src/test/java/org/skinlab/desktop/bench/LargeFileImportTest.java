package org.skinlab.desktop.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTimeoutPreemptively;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.File;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.desktop.cli.SkinlabMain;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.model.Skin;

/**
 * The large-file check: a generated file of more than a million triangles (about 117 MB) imports
 * with the counts its generator promises, in reasonable time, and within a bounded heap.
 *
 * <p>Counts: {@code cellsPerSide(1,000,000)} = ceil(sqrt(500,000)) = 708 cells per side, so
 * 2 * 708^2 = 1,002,528 triangles on a grid of 709^2 = 502,681 positions, each with 4 influences
 * over the 8 joints; one clip of 8 matrix channels, keys at 0, 0.25, ..., 1.0 s.
 */
class LargeFileImportTest {
    private static final int POSITIONS = 709 * 709;
    private static final int TRIANGLES = 1_002_528;

    /**
     * The heap the command line gets in the memory check. The import needed between 320 and
     * 352 MB when this test was written (JDK 17, G1); 512 MB leaves room for noise, not for a
     * doubling.
     */
    private static final String HEAP = "-Xmx512m";

    @TempDir
    static Path dir;

    private static Path file;

    @BeforeAll
    static void generate() throws IOException {
        file = dir.resolve("grid.dae");
        assertEquals(708, SyntheticCollada.cellsPerSide(1_000_000));
        assertEquals(TRIANGLES, SyntheticCollada.write(file, 1_000_000));
        assertTrue(Files.size(file) > 100_000_000, () -> "only " + file.toFile().length() + " bytes");
    }

    @Test
    void millionTriangleGridImportsWithExactCounts() {
        Model m = assertTimeoutPreemptively(Duration.ofSeconds(60), () -> ColladaImporter.read(file));
        assertEquals(1, m.meshes().size());
        Mesh grid = m.meshes().get(0);
        assertEquals(POSITIONS, grid.positionCount());
        assertEquals(TRIANGLES, grid.triangleCount());
        Skin skin = m.skins().get(0);
        assertEquals(SyntheticCollada.JOINTS, skin.jointCount());
        assertEquals(8, skin.jointCount());
        assertEquals(4, skin.maxInfluences());
        assertEquals(4L * POSITIONS, skin.influenceTotal());
        assertEquals(1, m.clips().size());
        AnimationClip clip = m.clips().get(0);
        assertEquals(8, clip.channels().size());
        assertEquals(1.0f, clip.duration(), 0f);
        assertEquals(0, m.warnings().size(), () -> m.warnings().toString());
    }

    /**
     * The jars and class folders of the application: the test JVM's class path (every library the
     * command line's subcommands name, BoofCV, PDFBox, JCodec, ...), plus the places of its own
     * classes, found from them (a test runner's own {@code java.class.path} need not list those).
     */
    private static String classPath() throws Exception {
        Set<String> entries = new LinkedHashSet<>();
        for (String e : System.getProperty("java.class.path", "").split(File.pathSeparator)) {
            if (!e.isEmpty()) {
                entries.add(e);
            }
        }
        for (Class<?> c : new Class<?>[] {SkinlabMain.class, ColladaImporter.class, org.joml.Matrix4f.class,
                picocli.CommandLine.class, ObjectMapper.class, com.fasterxml.jackson.core.JsonParser.class,
                com.fasterxml.jackson.annotation.JsonProperty.class}) {
            entries.add(Path.of(c.getProtectionDomain().getCodeSource().getLocation().toURI()).toString());
        }
        return String.join(File.pathSeparator, entries);
    }

    @Test
    void commandLineInspectsItWithinHalfAGigabyteOfHeap() throws Exception {
        // A separate JVM with a small heap: an OutOfMemoryError there is exit status 1, not a
        // test JVM that happens to have 3 GB.
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Path out = dir.resolve("inspect.json");
        Process p = new ProcessBuilder(java.toString(), HEAP, "-cp", classPath(),
                SkinlabMain.class.getName(), "inspect", "--json", file.toString())
                .redirectOutput(out.toFile()).redirectErrorStream(false).redirectError(dir.resolve("inspect.err").toFile())
                .start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "inspect did not finish in 120 s");
        String err = Files.readString(dir.resolve("inspect.err"), StandardCharsets.UTF_8);
        assertEquals(0, p.exitValue(), () -> "exit " + p.exitValue() + " with " + HEAP + ": " + err);

        JsonNode root = new ObjectMapper().readTree(out.toFile());
        JsonNode mesh = root.get("meshes").get(0);
        assertEquals(List.of(POSITIONS, TRIANGLES, 8, 4), List.of(mesh.get("positions").intValue(),
                mesh.get("triangles").intValue(), mesh.get("joints").intValue(), mesh.get("maxInfluences").intValue()));
        assertEquals(8, root.get("clips").get(0).get("channels").intValue());
    }

    @Test
    void tooLittleHeapIsOneLineAndExitStatusOneNotAStackTrace() throws Exception {
        // 48 MB cannot hold this file's model: the command must say so on one line.
        Path java = Path.of(System.getProperty("java.home"), "bin", "java");
        Path err = dir.resolve("oom.err");
        Process p = new ProcessBuilder(java.toString(), "-Xmx48m", "-cp", classPath(),
                SkinlabMain.class.getName(), "inspect", file.toString())
                .redirectOutput(ProcessBuilder.Redirect.DISCARD).redirectError(err.toFile()).start();
        assertTrue(p.waitFor(120, TimeUnit.SECONDS), "inspect did not finish in 120 s");
        List<String> lines = Files.readAllLines(err, StandardCharsets.UTF_8);
        assertEquals(1, p.exitValue(), () -> String.join("\n", lines));
        assertEquals(1, lines.size(), () -> String.join("\n", lines));
        assertTrue(lines.get(0).startsWith("skinlab: out of memory"), lines.get(0));
    }
}
