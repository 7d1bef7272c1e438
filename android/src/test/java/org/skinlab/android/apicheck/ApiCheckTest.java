package org.skinlab.android.apicheck;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The API check on small dex files that D8 makes from the fixture classes: references to APIs
 * Android 8 lacks are reported with class, method, source line, member and level, unless an
 * SDK_INT guard as high as the member's level covers them.
 */
class ApiCheckTest {
    private static final String FIXTURES = FixtureDex.PACKAGE + ".";
    private static final String PATH_OF = "java.nio.file.Path.of(java.lang.String, java.lang.String[])";

    @TempDir
    Path dir;

    @Test
    void unguardedPathOfIsReportedWithClassMethodLineMemberAndLevel() throws Exception {
        ApiReport report = FixtureDex.check(FixtureDex.d8(dir, "UnguardedPathOf"));
        Violation v = single(report);
        assertEquals(FIXTURES + "UnguardedPathOf", v.className());
        assertEquals("run()", v.method());
        assertEquals("UnguardedPathOf.java:11", v.source());
        assertEquals(Reference.Use.CALLS, v.use());
        assertEquals(PATH_OF, v.member());
        assertEquals(LevelRange.ABOVE_API_33, v.level());
        assertTrue(report.message().contains("  " + FIXTURES + "UnguardedPathOf.run() (UnguardedPathOf.java:11)\n"
                + "      calls " + PATH_OF + ": above API 33"), report.message());
        assertTrue(report.message().startsWith("api-check: FAILED: fixture: 1 class, "), report.message());
    }

    @Test
    void pathOfUnderSdkIntAtLeast34Passes() throws Exception {
        ApiReport report = FixtureDex.check(FixtureDex.d8(dir, "GuardedPathOf"));
        assertTrue(report.passed(), report.message());
        assertEquals(1, report.guarded(), "the Path.of call counts as guarded");
        assertTrue(report.message().matches("api-check: fixture: 1 class, \\d+ references to the platform, "
                + "all at API 26 \\(1 guarded\\)"), report.message());
    }

    @Test
    void pathOfAfterAnEarlyReturnBelow34WithTheConstantOnTheLeftPasses() throws Exception {
        ApiReport report = FixtureDex.check(FixtureDex.d8(dir, "EarlyReturnPathOf"));
        assertTrue(report.passed(), report.message());
        assertEquals(1, report.guarded());
    }

    @Test
    void guardsBelowTheMembersLevelFail() throws Exception {
        ApiReport report = FixtureDex.check(FixtureDex.d8(dir, "UselessGuardPathOf"));
        List<String> methods = report.violations().stream().map(Violation::method).sorted().toList();
        assertEquals(List.of("atLeast26()", "atLeast30()"), methods, report.message());
        assertEquals(0, report.guarded());
    }

    @Test
    void unguardedReadOfANewerFieldIsReported() throws Exception {
        Violation v = single(FixtureDex.check(FixtureDex.d8(dir, "NewerField")));
        assertEquals(Reference.Use.READS, v.use());
        assertEquals("android.os.Build$VERSION.MEDIA_PERFORMANCE_CLASS", v.member());
        assertEquals(LevelRange.API_27_TO_33, v.level());
    }

    @Test
    void newerClassInstantiatedIsReported() throws Exception {
        ApiReport report = FixtureDex.check(FixtureDex.d8(dir, "NewerClassInstantiated"));
        assertTrue(report.violations().stream().anyMatch(v -> v.use() == Reference.Use.INSTANTIATES
                && v.member().equals("java.util.concurrent.SubmissionPublisher") && v.level() == LevelRange.API_27_TO_33
                && v.method().equals("run()")), report.message());
    }

    @Test
    void newerClassInInstanceofIsReported() throws Exception {
        Violation v = single(FixtureDex.check(FixtureDex.d8(dir, "NewerClassInstanceof")));
        assertEquals(Reference.Use.USES_CLASS, v.use());
        assertEquals("java.lang.invoke.VarHandle", v.member());
        assertEquals("run(java.lang.Object)", v.method());
    }

    @Test
    void newerSuperclassIsReportedOnTheClassDeclaration() throws Exception {
        ApiReport report = FixtureDex.check(FixtureDex.d8(dir, "NewerSuperclass"));
        assertTrue(report.violations().stream().anyMatch(v -> v.use() == Reference.Use.EXTENDS && v.method() == null
                && v.className().equals(FIXTURES + "NewerSuperclass")
                && v.member().equals("java.util.concurrent.SubmissionPublisher")), report.message());
    }

    @Test
    void memberInheritedFromTheActivityAt26PassesAndOneAddedLaterFails() throws Exception {
        ApiReport report = FixtureDex.check(FixtureDex.d8(dir, "InheritingActivity"));
        Violation v = single(report);
        assertEquals("display()", v.method(), "title() calls setTitle, which android.app.Activity has at 26");
        assertEquals(FIXTURES + "InheritingActivity.getDisplay()", v.member());
        assertEquals(LevelRange.API_27_TO_33, v.level());
    }

    @Test
    void exceptionsFileAllowsItsEntryAndReportsEntriesNothingNeeds() throws Exception {
        Path file = dir.resolve("exceptions.txt");
        Files.writeString(file, "# reviewed\n" + PATH_OF + " | " + FIXTURES + "UnguardedPathOf | a test's reason\n"
                + "java.lang.Math.fma(float, float, float) | " + FIXTURES + "UnguardedPathOf | nothing calls it\n");
        ApiReport report = FixtureDex.check(FixtureDex.d8(dir.resolve("dex"), "UnguardedPathOf"), ApiExceptions.read(file));
        assertTrue(report.violations().isEmpty(), report.message());
        assertEquals(1, report.allowed());
        assertEquals(List.of("java.lang.Math.fma(float, float, float) | " + FIXTURES + "UnguardedPathOf"),
                report.unusedExceptions().stream().map(ApiExceptions.Entry::format).toList());
        assertTrue(!report.passed() && report.message().contains("no longer makes"), report.message());
    }

    private static Violation single(ApiReport report) {
        assertEquals(1, report.violations().size(), report.message());
        return report.violations().get(0);
    }
}
