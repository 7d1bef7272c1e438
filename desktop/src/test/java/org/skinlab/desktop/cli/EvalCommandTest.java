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
}
