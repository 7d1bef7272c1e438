package org.skinlab.android.apicheck;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Path;

import org.jf.dexlib2.iface.ClassDef;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The check on R8's output, where each call to an API above the min SDK sits in a synthetic
 * outline class and the guard, if any, stays at the call site (one R8 run for the class: ~10 s).
 */
class ApiOutlineTest {
    @TempDir
    static Path dir;

    private static DexProgram program;
    private static ApiReport report;

    @BeforeAll
    static void shrinkGuardedAndUnguardedPathOf() throws Exception {
        Path dex = FixtureDex.r8(dir, "PathOfCallers", "run", "PathOfCallers", "GuardedPathOf", "UnguardedPathOf");
        program = DexProgram.read(java.util.List.of(dex.resolve("classes.dex")));
        report = FixtureDex.check(dex);
    }

    @Test
    void r8MovedPathOfIntoAnOutline() {
        assertTrue(program.classes().stream().map(ClassDef::getType).anyMatch(t -> t.contains(DexMethod.API_OUTLINE)),
                () -> "R8 made no API outline class: the tests below would not test outlines; classes: " + program.classes().stream().map(ClassDef::getType).toList());
    }

    @Test
    void unguardedCallThroughAnOutlineIsReportedAtItsCaller() {
        assertEquals(1, report.violations().size(), report.message());
        Violation v = report.violations().get(0);
        assertEquals(FixtureDex.PACKAGE + ".UnguardedPathOf", v.className());
        assertEquals("run()", v.method());
        assertEquals("java.nio.file.Path.of(java.lang.String, java.lang.String[])", v.member());
        assertTrue(v.outline() != null && v.outline().contains(DexMethod.API_OUTLINE), v.outline());
        assertTrue(report.message().contains("(through R8's outline "), report.message());
    }

    @Test
    void guardedCallThroughAnOutlinePasses() {
        assertTrue(report.violations().stream().noneMatch(v -> v.className().endsWith(".GuardedPathOf")), report.message());
        assertEquals(1, report.guarded(), report.message());
    }
}
