package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;

/** {@code skinlab bench track} runs all three contenders on the same frames and reports them (no timing asserted). */
class TrackBenchCommandTest {
    @Test
    void reportsTheThreeContendersAndWhatTheyFound() throws Exception {
        Cli cli = Cli.run("bench", "track", "--frames", "6", "--seconds", "0.1", "--warmup-seconds", "0", "--json");
        assertEquals(0, cli.status, cli.toString());
        JsonNode o = new ObjectMapper().readTree(cli.out);
        assertEquals(6, o.get("frames").asInt());
        assertTrue(o.get("rounds").asInt() >= 3);
        for (String f : new String[] {"boofcvDefaultMs", "detectMs", "trackMs"}) {
            assertTrue(o.get(f).asDouble() > 0, f);
        }
        // One marker in every frame: our tracker finds exactly it, in both modes.
        assertEquals(1.0, o.get("markersPerFrameDetect").asDouble(), 0);
        assertEquals(1.0, o.get("markersPerFrameTrack").asDouble(), 0);
        Cli bad = Cli.run("bench", "track", "--frames", "1");
        assertEquals(ExitCodes.USAGE, bad.status);
    }
}
