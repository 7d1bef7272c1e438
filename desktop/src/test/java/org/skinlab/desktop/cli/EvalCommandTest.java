package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.eval.Evaluation;

/** {@code skinlab eval}'s options: a section or a folder it cannot use is a usage error. */
class EvalCommandTest {
    @Test
    void anUnknownSectionIsAUsageErrorNamingTheValidOnes(@TempDir Path dir) {
        Cli run = Cli.run("eval", "--only", "load,crowd", "--out", dir.toString());
        assertEquals(ExitCodes.USAGE, run.status);
        String valid = String.join(", ", Evaluation.keys());
        assertTrue(run.err.contains("unknown section \"crowd\" (valid: " + valid + ")"), run.err);
        assertTrue(valid.startsWith("load, time"), valid);
    }

    @Test
    void anOutThatIsAFileIsAUsageError(@TempDir Path dir) throws Exception {
        Path file = Files.writeString(dir.resolve("report"), "");
        Cli run = Cli.run("eval", "--only", "load", "--out", file.toString());
        assertEquals(ExitCodes.USAGE, run.status);
        assertTrue(run.err.contains("--out: not a folder: " + file), run.err);
    }

    @Test
    void arVideoOptionsAreCheckedBeforeMeasuring(@TempDir Path dir) throws Exception {
        Cli alone = Cli.run("eval", "--only", "ar-frame", "--ar-intrinsics", "k.json", "--out", dir.toString());
        assertEquals(ExitCodes.USAGE, alone.status, alone::toString);
        assertTrue(alone.err.contains("describe --ar-video, which is not given"), alone.err);
        Cli missing = Cli.run("eval", "--only", "ar-frame", "--ar-video", dir.resolve("none.mp4").toString(), "--out",
                dir.toString());
        assertEquals(ExitCodes.USAGE, missing.status, missing::toString);
        assertTrue(missing.err.contains("none.mp4"), missing.err);
        Path junk = Files.writeString(dir.resolve("junk.mp4"), "not a video");
        Cli bad = Cli.run("eval", "--only", "ar-frame", "--ar-video", junk.toString(), "--out", dir.toString());
        assertEquals(ExitCodes.INVALID_FILE, bad.status, bad::toString);
        assertTrue(bad.err.contains("junk.mp4"), bad.err);
        Cli dictionary = Cli.run("eval", "--only", "ar-frame", "--ar-video", junk.toString(), "--ar-dictionary", "aruco_9x9",
                "--out", dir.toString());
        assertEquals(ExitCodes.USAGE, dictionary.status, dictionary::toString);
        assertTrue(dictionary.err.contains("--ar-dictionary"), dictionary.err);
        assertTrue(!Files.exists(dir.resolve("results.json")), "nothing measured");
    }
}
