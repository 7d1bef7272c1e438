package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.gltf.GltfImporter;
import org.skinlab.model.Model;

/** {@code skinlab export}: the GLB written and its summary line, and the exit statuses of bad input. */
class ExportCommandTest {
    private static final Path WALK = Cli.root().resolve("assets/characters/humanoid-walk.dae");

    @Test
    void writesAGlbThatReadsBackAndSaysWhatItWrote(@TempDir Path dir) throws Exception {
        Path out = dir.resolve("walk.glb");
        Cli r = Cli.run("export", WALK.toString(), "--out", out.toString(), "--methods", "lbs,cor");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        long bytes = Files.size(out);
        assertTrue(r.out.contains(": 1 meshes, 950 vertices, 1 clips, methods lbs,cor, " + bytes + " bytes"), r::toString);
        Model back = GltfImporter.read(out);
        assertEquals(1, back.instances().size());
        assertEquals(950, back.instances().get(0).mesh().vertexCount());
        assertTrue(Files.readString(out, java.nio.charset.StandardCharsets.ISO_8859_1)
                .contains("\"SKINLAB_skinning\":{\"methods\":[\"lbs\",\"cor\"],\"attributes\":{\"cor\":\"_COR_CENTER\"}"),
                "the primitive's extension");
    }

    @Test
    void withoutCorNoCentresAreWritten(@TempDir Path dir) throws Exception {
        Path out = dir.resolve("walk.glb");
        Cli r = Cli.run("export", WALK.toString(), "--out", out.toString(), "--methods", "dqs");
        assertEquals(ExitCodes.OK, r.status, r::toString);
        String text = Files.readString(out, java.nio.charset.StandardCharsets.ISO_8859_1);
        assertFalse(text.contains("_COR_CENTER"), "no centres without cor");
        assertTrue(text.contains("\"methods\":[\"dqs\"],\"attributes\":{}"), "the extension still says dqs");
    }

    @Test
    void aMethodWithoutExportDataIsAUsageError(@TempDir Path dir) {
        Cli r = Cli.run("export", WALK.toString(), "--out", dir.resolve("x.glb").toString(), "--methods", "lbs,bfdqs");
        assertEquals(ExitCodes.USAGE, r.status, r::toString);
        assertTrue(r.err.contains("no data for bfdqs; only lbs, dqs and cor are accepted"), r::toString);
        assertFalse(Files.exists(dir.resolve("x.glb")));
        Cli unknown = Cli.run("export", WALK.toString(), "--out", dir.resolve("x.glb").toString(), "--methods", "fast");
        assertEquals(ExitCodes.USAGE, unknown.status, unknown::toString);
        Cli noOut = Cli.run("export", WALK.toString());
        assertEquals(ExitCodes.USAGE, noOut.status, noOut::toString);
    }

    @Test
    void aTruncatedOrGarbageFileExitsThreeNamingIt(@TempDir Path dir) throws Exception {
        byte[] glb = Files.readAllBytes(Cli.root().resolve("assets/characters/humanoid-walk.glb"));
        Path truncated = dir.resolve("truncated.glb");
        Files.write(truncated, Arrays.copyOf(glb, glb.length / 2));
        Path garbage = dir.resolve("garbage.dae");
        Files.write(garbage, "<COLLADA><library_geometries><geometry id=\"g\"><mesh>\u0001".getBytes());
        for (Path bad : new Path[] {truncated, garbage}) {
            Path out = dir.resolve("out.glb");
            Cli r = Cli.run("export", bad.toString(), "--out", out.toString());
            assertEquals(ExitCodes.INVALID_FILE, r.status, r::toString);
            assertTrue(r.err.contains(bad.getFileName().toString()), r::toString);
            assertFalse(Files.exists(out), "nothing written for " + bad);
        }
    }

    @Test
    void anOutputInAMissingFolderIsAUsageError(@TempDir Path dir) {
        Cli r = Cli.run("export", WALK.toString(), "--out", dir.resolve("no/such/x.glb").toString());
        assertEquals(ExitCodes.USAGE, r.status, r::toString);
        assertTrue(r.err.contains("cannot write"), r::toString);
    }
}
