package org.skinlab.desktop.app;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;

class UiScriptTest {
    private static final Path FILE = Path.of("/tmp/demo/script.txt");

    @Test
    void parsesEveryVerb() {
        UiScript s = UiScript.parse(FILE, List.of("# a comment", "", "action next-mesh", "key j shift", "click Split view",
                "move 10 20", "drag 1 2 3 4", "scroll -2", "drop ../bad.dae  # trailing comment", "open a.dae",
                "seek 1.5", "wait 3", "wait-loaded", "screenshot out/a.png", "expect mesh characters/x.dae",
                "expect status cannot be read", "expect method DQS", "quit"));
        assertEquals(16, s.steps().size());
        assertEquals("action", s.steps().get(0).verb());
        assertEquals(3, s.steps().get(0).line());
        assertEquals("Split view", s.steps().get(2).rest());
        assertEquals(Path.of("/tmp/demo/../bad.dae"), s.resolve(s.steps().get(6).rest()));
        assertEquals(Path.of("/abs/x.dae"), s.resolve("/abs/x.dae"));
    }

    @Test
    void errorsNameTheFileAndLine() {
        for (String bad : new String[] {"jump 3", "move 1", "move a b", "wait -1", "key NOSUCHKEY", "key J hyper",
                "expect colour red", "quit now", "scroll", "drag 1 2 3"}) {
            IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                    () -> UiScript.parse(FILE, List.of("wait 1", bad)), bad);
            assertTrue(e.getMessage().startsWith(FILE + " line 2: "), e.getMessage());
            assertTrue(e.getMessage().contains(bad), e.getMessage());
        }
    }
}
