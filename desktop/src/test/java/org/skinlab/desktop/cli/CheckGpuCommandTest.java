package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.render.GlTestDisplay;
import org.skinlab.skinning.SkinningGlsl;
import org.skinlab.skinning.SkinningMethod;

/**
 * GPU skinning (the viewer's vertex shader, read back with transform feedback) against the CPU
 * kernels on the same frames: within 1e-4 of the model's size (float rounding gives about 1e-7)
 * for LBS, DQS and CoR, on our assets and on a corpus character with 6 influences per vertex (the
 * shader's 8-influence view).
 */
class CheckGpuCommandTest {
    @BeforeAll
    static void display() {
        GlTestDisplay.assume();
    }

    /** Methods check-gpu compares: those with shader code; the others it names on one last line. */
    private static final List<SkinningMethod> WITH_CODE = Arrays.stream(SkinningMethod.values())
            .filter(SkinningGlsl::hasCode).toList();

    /** Every method with shader code "ok" on each of {@code files} files, then the line naming the rest. */
    private static void assertAllOk(Cli r, int files) {
        assertEquals(0, r.status, r::toString);
        List<String> out = r.out.lines().toList();
        boolean someWithoutCode = WITH_CODE.size() < SkinningMethod.values().length;
        assertEquals(files * WITH_CODE.size() + (someWithoutCode ? 1 : 0), out.size(), r::toString);
        for (String line : out.subList(0, files * WITH_CODE.size())) {
            assertTrue(line.startsWith("ok"), line);
        }
        if (someWithoutCode) {
            assertTrue(out.get(out.size() - 1).startsWith("not checked, no shader code"), r::toString);
        }
    }

    @Test
    void ourAssetsSkinTheSameOnGpuAndCpu() throws Exception {
        List<String> args = new ArrayList<>(List.of("check-gpu", "--tolerance", "1e-4"));
        try (var files = Files.list(Cli.root().resolve("assets").resolve("cylinders"))) {
            files.filter(p -> p.toString().endsWith(".dae")).sorted().forEach(p -> args.add(p.toString()));
        }
        args.add(Cli.root().resolve("assets/characters/humanoid-walk.dae").toString());
        args.add(Cli.root().resolve("assets/creatures/tentacle-wave.dae").toString());
        args.add(Cli.root().resolve("assets/characters/humanoid-walk.glb").toString());
        assertAllOk(Cli.run(args.toArray(String[]::new)), args.size() - 3);
    }

    @Test
    void aSixInfluenceCharacterToo() {
        Path cowboy = Cli.corpusFileOrSkip("S01_cowboy.dae");
        assertAllOk(Cli.run("check-gpu", "--time", "0,0.3,0.9,1.7", cowboy.toString()), 1);
    }

    @Test
    void aToleranceBelowFloatRoundingFails() {
        Cli r = Cli.run("check-gpu", "--method", "dqs", "--tolerance", "1e-12",
                Cli.root().resolve("assets/characters/humanoid-walk.dae").toString());
        assertEquals(1, r.status, r::toString);
        assertTrue(r.out.startsWith("FAIL dqs"), r::toString);
    }
}
