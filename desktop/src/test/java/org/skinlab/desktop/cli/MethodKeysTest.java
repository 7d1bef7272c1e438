package org.skinlab.desktop.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.skinlab.desktop.Cli;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine;

/** Every command's --method takes every method's key: one list of keys, one converter. */
class MethodKeysTest {
    @Test
    void theKeysLabelIsEveryMethodsKeyInOrder() {
        List<String> keys = new ArrayList<>();
        for (SkinningMethod m : SkinningMethod.values()) {
            keys.add(m.key());
        }
        assertEquals(String.join("|", keys), MethodKeys.KEYS);
    }

    @Test
    void everyKeyParsesInEveryCommandThatTakesOne() {
        for (SkinningMethod m : SkinningMethod.values()) {
            for (String key : new String[] {m.key(), m.key().toUpperCase(java.util.Locale.ROOT), m.name()}) {
                assertEquals(m, new MethodKeys.Converter().convert(key));
                assertEquals(List.of(m), MethodKeys.parseOneOrAll("--method", key));
                PoseCommand pose = new PoseCommand();
                new CommandLine(pose).parseArgs("f.dae", "--time", "0", "--method", key);
                assertEquals(m, pose.method);
                ViewCommand view = new ViewCommand();
                new CommandLine(view).parseArgs("--method", key, "--split", key);
                assertEquals(m, view.window.method);
                assertEquals(m, view.split);
                ArCommand ar = new ArCommand();
                new CommandLine(ar).parseArgs("--images", "frames", "--method", key);
                assertEquals(m, ar.window.method);
                TwistPlotCommand twist = new TwistPlotCommand();
                new CommandLine(twist).parseArgs("f.dae", "--joint", "j", "--methods", key + "," + key);
                assertEquals(List.of(m, m), twist.methods);
            }
        }
        assertEquals(List.of(SkinningMethod.values()), MethodKeys.parseOneOrAll("--method", "ALL"));
        // bench skinning's synthetic data has no bones: the bone methods are refused, saying where to time them.
        for (SkinningMethod m : SkinningMethod.values()) {
            if (m.usesBones()) {
                Cli r = Cli.run("bench", "skinning", "--method", m.key(), "--vertices", "10");
                assertEquals(ExitCodes.USAGE, r.status, r::toString);
                assertTrue(r.err.contains("bench frame FILE --method " + m.key()), r::toString);
            }
        }
        CommandFailure bad = assertThrows(CommandFailure.class, () -> MethodKeys.parseOneOrAll("--method", "lbs2"));
        assertEquals(ExitCodes.USAGE, bad.status());
        assertEquals("--method lbs2: unknown skinning method \"lbs2\" (expected one of " + MethodKeys.KEYS.replace("|", ", ")
                + "), or all", bad.getMessage());
    }

    @Test
    void anUnknownKeyIsAUsageErrorNamingEveryKeyInEveryCommand() {
        String unknown = "unknown skinning method \"lbs2\" (expected one of " + MethodKeys.KEYS.replace("|", ", ") + ")";
        Cli view = Cli.run("view", "--method", "lbs2");
        assertEquals(ExitCodes.USAGE, view.status, view::toString);
        assertEquals("Invalid value for option '--method': " + unknown, view.errLines()[0]);
        Cli twist = Cli.run("twist-plot", "f.dae", "--joint", "j", "--methods", "lbs,lbs2");
        assertEquals(ExitCodes.USAGE, twist.status, twist::toString);
        assertEquals("Invalid value for option '--methods' (KEY): " + unknown, twist.errLines()[0]);
        Cli bench = Cli.run("bench", "skinning", "--method", "lbs2", "--vertices", "10");
        assertEquals(ExitCodes.USAGE, bench.status, bench::toString);
        assertEquals("skinlab: bench skinning: " + unknown, bench.errLines()[0]);
        Cli frame = Cli.run("bench", "frame", "--method", "lbs2",
                Cli.root().resolve("assets/characters/humanoid-walk.dae").toString());
        assertEquals(ExitCodes.USAGE, frame.status, frame::toString);
        assertEquals("skinlab: bench frame: " + unknown + ", or all (or both)", frame.errLines()[0]);
    }
}
