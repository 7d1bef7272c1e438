package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.skinlab.desktop.Cli;

/** {@code skinlab twist-plot}: the table of twist and radius per ring, and the PNG. */
class TwistPlotCommandTest {
    private static final Path ARM = Cli.root().resolve("assets/twist/arm-twist.dae");

    @Test
    void theForearmsTwistIsSpreadByStbsAndConcentratedByDqs(@TempDir Path dir) throws Exception {
        Path png = dir.resolve("twist.png");
        Cli r = Cli.run("twist-plot", ARM.toString(), "--joint", "forearm", "--time", "0.875", "--png", png.toString());
        assertEquals(0, r.status, r::toString);
        assertTrue(r.out.contains("21 rings"), r::toString);
        // Mid-forearm: STBS has half of the 170 degrees, DQS all of it; LBS's elbow ring collapses.
        assertTrue(r.out.lines().anyMatch(l -> l.startsWith("stbs-dqs") && l.contains(" 0.50:85.0/1.000")), r::toString);
        assertTrue(r.out.lines().anyMatch(l -> l.startsWith("dqs") && l.contains(" 0.50:170.0/1.000")), r::toString);
        assertTrue(r.out.lines().anyMatch(l -> l.startsWith("lbs") && l.contains(" 0.00:85.0/0.087")), r::toString);
        byte[] head = Files.readAllBytes(png);
        assertTrue(head.length > 1000 && head[1] == 'P' && head[2] == 'N' && head[3] == 'G', "a PNG was written");
    }

    @Test
    void anUnknownJointIsAUsageError() {
        Cli r = Cli.run("twist-plot", ARM.toString(), "--joint", "tail");
        assertTrue(r.status != 0, r::toString);
        assertTrue(r.err.contains("no skin has a joint named tail"), r::toString);
    }
}
