package org.skinlab.glsl;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

/** The include line's rules, on core's two real GLSL files and on one that is not there. */
class GlslIncludeTest {
    private static final GlslInclude LENS = new GlslInclude("/org/skinlab/ar/lens.glsl", "the lens shader's formulas");

    @Test
    void theLineQuotesTheFilesLastName() {
        assertEquals("#include \"lens.glsl\"", LENS.line());
        assertEquals("#include \"skinning.glsl\"",
                new GlslInclude("/org/skinlab/skinning/skinning.glsl", "x").line());
    }

    @Test
    void onlyALineOfItsOwnIsReplacedAndCarriageReturnsEndIt() {
        String text = LENS.text();
        assertTrue(text.contains("lensSourceCoord"), "the lens formulas define lensSourceCoord");
        assertEquals("a\r\n" + text + "\r\nb", LENS.expand("a\r\n" + LENS.line() + "\r\nb"));
        assertEquals(text, LENS.expand(LENS.line()));
        String inside = "x " + LENS.line() + "\n" + LENS.line() + " y\n";
        assertEquals(inside, LENS.expand(inside));
    }

    @Test
    void twiceAndMissingAreSaidByName() {
        IllegalStateException twice = assertThrows(IllegalStateException.class,
                () -> LENS.expand(LENS.line() + "\n" + LENS.line()));
        assertEquals("a shader includes lens.glsl twice", twice.getMessage());
        GlslInclude missing = new GlslInclude("/org/skinlab/glsl/none.glsl", "the test's formulas");
        assertEquals("x\n", missing.expand("x\n"), "a shader without the line needs no file");
        IllegalStateException absent = assertThrows(IllegalStateException.class,
                () -> missing.expand(missing.line()));
        assertTrue(absent.getMessage().startsWith("the test's formulas /org/skinlab/glsl/none.glsl are missing"),
                absent.getMessage());
        assertThrows(IllegalArgumentException.class, () -> new GlslInclude("lens.glsl", "relative"));
    }
}
