package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;

/**
 * The exit statuses are a contract (see {@link ExitCodes}): 0 success, 2 usage error (including a
 * file that does not exist), 3 a file that cannot be imported, with exactly one line on stderr
 * naming the file and the element, and never a stack trace.
 */
class ExitStatusTest {
    /** A triangle whose third corner is position 3 of 0..2 (value 2 of its <p>). */
    static final String BROKEN = """
            <?xml version="1.0" encoding="utf-8"?>
            <COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
              <library_geometries>
                <geometry id="tri">
                  <mesh>
                    <source id="tri-pos">
                      <float_array id="tri-pos-array" count="9">0 0 0  1 0 0  0 1 0</float_array>
                      <technique_common>
                        <accessor source="#tri-pos-array" count="3" stride="3">
                          <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
                        </accessor>
                      </technique_common>
                    </source>
                    <vertices id="tri-vtx"><input semantic="POSITION" source="#tri-pos"/></vertices>
                    <triangles count="1">
                      <input semantic="VERTEX" source="#tri-vtx" offset="0"/>
                      <p>0 1 3</p>
                    </triangles>
                  </mesh>
                </geometry>
              </library_geometries>
            </COLLADA>
            """;

    @TempDir
    Path dir;

    private static void assertNoStackTrace(Cli r) {
        assertFalse(r.err.contains("\tat ") || r.err.contains("Exception"), r::toString);
    }

    @Test
    void successIsZero() {
        Cli r = Cli.run("inspect", Cli.defaultAsset().toString());
        assertEquals(0, r.status, r::toString);
    }

    @Test
    void helpAndVersionAreZero() {
        Cli help = Cli.run("--help");
        assertEquals(0, help.status, help::toString);
        assertTrue(help.out.startsWith("Usage: skinlab"), help::toString);
        Cli version = Cli.run("--version");
        assertEquals(0, version.status, version::toString);
        assertTrue(version.out.startsWith("skinlab "), version::toString);
        // The second line names the Java that runs it (the start scripts choose one).
        assertEquals("Java " + System.getProperty("java.version") + " (" + System.getProperty("java.vendor") + ") at "
                + System.getProperty("java.home"), version.out.lines().skip(1).findFirst().orElse(""), version::toString);
    }

    @Test
    void noSubcommandMeansTheViewer() {
        // `skinlab` alone opens the window (ViewerWindowTest runs it); options alone are the viewer's.
        org.junit.jupiter.api.Assertions.assertArrayEquals(new String[] {"view"}, SkinlabCommand.withDefaultCommand());
        org.junit.jupiter.api.Assertions.assertArrayEquals(new String[] {"view", "--exit-after-frames", "5"},
                SkinlabCommand.withDefaultCommand("--exit-after-frames", "5"));
        org.junit.jupiter.api.Assertions.assertArrayEquals(new String[] {"--version"},
                SkinlabCommand.withDefaultCommand("--version"));
        org.junit.jupiter.api.Assertions.assertArrayEquals(new String[] {"inspect", "a.dae"},
                SkinlabCommand.withDefaultCommand("inspect", "a.dae"));
        Cli r = Cli.run("--no-such-option");
        assertEquals(2, r.status, r::toString);
        assertTrue(r.err.contains("Usage: skinlab view"), r::toString);
        assertNoStackTrace(r);
    }

    @Test
    void unknownOptionIsAUsageError() {
        Cli r = Cli.run("inspect", "--bogus", Cli.defaultAsset().toString());
        assertEquals(2, r.status, r::toString);
        assertTrue(r.err.startsWith("Unknown option: '--bogus'"), r::toString);
        assertNoStackTrace(r);
    }

    @Test
    void missingFileArgumentIsAUsageError() {
        Cli r = Cli.run("inspect");
        assertEquals(2, r.status, r::toString);
        assertTrue(r.err.startsWith("Missing required parameter: 'FILE'"), r::toString);
    }

    @Test
    void benchWithoutABenchmarkIsAUsageError() {
        Cli r = Cli.run("bench");
        assertEquals(2, r.status, r::toString);
        assertTrue(r.err.startsWith("a benchmark is required"), r::toString);
    }

    @Test
    void nonexistentFileIsAUsageErrorOnOneLine() {
        Path missing = dir.resolve("missing.dae");
        Cli r = Cli.run("inspect", missing.toString());
        assertEquals(2, r.status, r::toString);
        assertEquals("", r.out, r::toString);
        assertEquals(1, r.errLines().length, r::toString);
        assertEquals("skinlab: file not found: " + missing, r.errLines()[0]);
    }

    @Test
    void directoryIsAUsageErrorForPose() {
        Cli r = Cli.run("pose", dir.toString(), "--time", "0", "--method", "lbs");
        assertEquals(2, r.status, r::toString);
        assertEquals("skinlab: " + dir + " is a directory, not a model file", r.errLines()[0]);
    }

    /** {@code inspect} searches a folder (InspectBatchTest); one without a model file names nothing to inspect. */
    @Test
    void folderWithoutDaeFilesIsAUsageErrorForInspect() {
        Cli r = Cli.run("inspect", dir.toString());
        assertEquals(2, r.status, r::toString);
        assertEquals("", r.out, r::toString);
        assertEquals(1, r.errLines().length, r::toString);
        assertEquals("skinlab: no model file (.dae, .gltf, .glb) in folder " + dir, r.errLines()[0]);
    }

    @Test
    void brokenFileIsThreeWithOneLineNamingFileAndElement() throws Exception {
        Path broken = dir.resolve("broken.dae");
        Files.writeString(broken, BROKEN);
        for (String[] args : new String[][] {{"inspect", broken.toString()}, {"inspect", "--json", broken.toString()}}) {
            Cli r = Cli.run(args);
            assertEquals(3, r.status, r::toString);
            assertEquals("", r.out, r::toString);
            assertEquals(1, r.errLines().length, r::toString);
            // <p> starts on line 17 of the text block.
            assertEquals("skinlab: broken.dae: <p> in <geometry id=\"tri\"> at line 17: index 3 (value 2) is out of range:"
                    + " <vertices> has 3 positions", r.errLines()[0]);
            assertNoStackTrace(r);
        }
    }

    @Test
    void malformedXmlIsThreeWithOneLine() throws Exception {
        // Cut off inside the <float_array> (line 7).
        Path cut = dir.resolve("cut.dae");
        Files.writeString(cut, BROKEN.substring(0, BROKEN.indexOf("1 0 0")));
        Cli r = Cli.run("inspect", cut.toString());
        assertEquals(3, r.status, r::toString);
        assertEquals(1, r.errLines().length, r::toString);
        assertTrue(r.errLines()[0].startsWith("skinlab: cut.dae: XML at line 7"), r::toString);
        assertTrue(r.errLines()[0].contains("inside <float_array id=\"tri-pos-array\"> at line 7"), r::toString);
        assertNoStackTrace(r);
    }

    @Test
    void emptyFileIsThree() throws Exception {
        Path empty = dir.resolve("empty.dae");
        Files.write(empty, new byte[0]);
        Cli r = Cli.run("inspect", "--json", empty.toString());
        assertEquals(3, r.status, r::toString);
        assertEquals(1, r.errLines().length, r::toString);
        assertTrue(r.errLines()[0].startsWith("skinlab: empty.dae: XML at line 1"), r::toString);
        assertTrue(r.errLines()[0].contains("Premature end of file"), r::toString);
    }

    @Test
    void benchParseOfABrokenFileIsThree() throws Exception {
        Path broken = dir.resolve("broken.dae");
        Files.writeString(broken, BROKEN);
        Cli r = Cli.run("bench", "parse", broken.toString(), "--generated-triangles", "0", "--warmup-seconds", "0",
                "--runs", "1", "--json");
        assertEquals(3, r.status, r::toString);
        assertEquals("", r.out, r::toString);
        assertEquals(1, r.errLines().length, r::toString);
        assertTrue(r.errLines()[0].startsWith("skinlab: broken.dae: <p> in <geometry id=\"tri\">"), r::toString);
    }
}
