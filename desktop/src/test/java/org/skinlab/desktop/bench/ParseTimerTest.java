package org.skinlab.desktop.bench;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.internal.bench.Rounds;
import org.skinlab.internal.bench.Spread;
import org.skinlab.desktop.Cli;

/**
 * {@link ParseTimer} in rounds (the evaluation's protocol): each run's value is the median of its
 * imports, every import is kept, and assimp, when its library loads, gets as many runs as ours.
 * No time is judged.
 */
class ParseTimerTest {
    @Test
    void eachRunIsTheMedianOfItsImportsAndEveryImportIsKept() throws Exception {
        Path file = Cli.defaultAsset();
        ParseTimer.Input in = new ParseTimer.Input(file.getFileName().toString(), Files.readAllBytes(file), file);
        int flags = assimpFlags();
        ParseTimer.Result r = new ParseTimer(0, Rounds.MIN_RUNS, 3, flags, true, null, "").measure(List.of(in)).get(0);
        assertNull(r.error);
        assertEquals(Rounds.MIN_RUNS, r.runs.count());
        assertEquals(3 * Rounds.MIN_RUNS, r.millis.length);
        double[] runs = r.runs.runs();
        for (int round = 0; round < runs.length; round++) {
            double[] imports = Arrays.copyOfRange(r.millis, 3 * round, 3 * round + 3);
            assertEquals(Spread.of(imports).median(), runs[round], 0, "run " + round);
        }
        assertEquals(Arrays.stream(r.millis).max().getAsDouble(), r.max(), 0);
        assertTrue(r.max() >= r.runs.max() && r.triangles > 0, r.name);
        if (flags >= 0) {
            assertEquals(Rounds.MIN_RUNS, r.assimpRuns.count());
            assertEquals(3 * Rounds.MIN_RUNS, r.assimpMillis.length);
            assertEquals(r.assimpRuns.median() / r.runs.median(), r.assimpRatio(), 1e-12);
        }
    }

    /** assimp's flags when its native library loads here, else -1 (then ours alone is timed). */
    private static int assimpFlags() {
        try {
            AssimpBaseline.loadAndVersion();
            return AssimpBaseline.FAIR_FLAGS;
        } catch (IllegalStateException e) {
            return -1;
        }
    }
}
