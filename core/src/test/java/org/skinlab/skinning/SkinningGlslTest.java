package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.HashSet;
import java.util.Set;

import org.junit.jupiter.api.Test;

/**
 * The shared skinning formulas reach a shader in place of its include line, and only there (the
 * GLSL itself is compiled and checked against the kernels by the apps' tests: the desktop's
 * {@code skinlab check-gpu}, the Android module's GlesSkinningTest).
 */
class SkinningGlslTest {
    @Test
    void theIncludeLineBecomesTheFormulas() {
        String formulas = SkinningGlsl.formulas();
        for (String function : new String[] {"void lbs(", "void dqs(", "void cor(", "vec3 cofactorTimes("}) {
            assertTrue(formulas.contains(function), function);
        }
        String shader = "#version 330 core\nuniform int u;\n" + SkinningGlsl.INCLUDE + "\nvoid main() {}\n";
        assertEquals("#version 330 core\nuniform int u;\n" + formulas + "\nvoid main() {}\n", SkinningGlsl.expand(shader));
        assertEquals("head\n" + formulas, SkinningGlsl.expand("head\n" + SkinningGlsl.INCLUDE));
    }

    @Test
    void aShaderWithoutTheLineIsLeftAlone() {
        String shader = "#version 330 core\n// " + SkinningGlsl.INCLUDE + " in a comment is not the line\nvoid main() {}\n";
        assertEquals(shader, SkinningGlsl.expand(shader));
    }

    @Test
    void includingTwiceIsRefused() {
        String twice = SkinningGlsl.INCLUDE + "\n" + SkinningGlsl.INCLUDE + "\n";
        assertThrows(IllegalStateException.class, () -> SkinningGlsl.expand(twice));
    }

    @Test
    void everyMethodWithShaderCodeHasItsOwnCodeAndNoneIsTheCpusZero() {
        Set<Integer> codes = new HashSet<>();
        for (SkinningMethod m : SkinningMethod.values()) {
            if (!SkinningGlsl.hasCode(m)) {
                assertThrows(IllegalArgumentException.class, () -> SkinningGlsl.methodCode(m), m.key());
                continue;
            }
            int code = SkinningGlsl.methodCode(m);
            assertTrue(code > 0 && codes.add(code), m + " -> " + code);
            assertTrue(SkinningGlsl.formulas().contains("method == " + code),
                    "skin() dispatches " + m);
        }
        assertTrue(SkinningGlsl.hasCode(SkinningMethod.LBS) && SkinningGlsl.hasCode(SkinningMethod.DQS)
                && SkinningGlsl.hasCode(SkinningMethod.COR), "the first three methods run on the GPU");
    }
}
