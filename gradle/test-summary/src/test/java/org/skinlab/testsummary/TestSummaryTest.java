package org.skinlab.testsummary;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.time.Duration;
import java.util.List;

import org.junit.jupiter.api.Test;

class TestSummaryTest {
    private static TestSummary.Result result(String name, TestSummary.Outcome outcome, long millis, String reason) {
        return new TestSummary.Result(name, outcome, Duration.ofMillis(millis), reason);
    }

    @Test
    void countsEachSkipReasonOnceAndNamesFailuresAndTheSlowestFive() {
        TestSummary summary = new TestSummary("core");
        summary.add(result("A.a", TestSummary.Outcome.PASSED, 1200, ""));
        summary.add(result("A.b", TestSummary.Outcome.SKIPPED, 0, "no corpus"));
        summary.add(result("A.c", TestSummary.Outcome.FAILED, 30, "expected: <1> but was: <2>"));
        summary.add(result("B.a", TestSummary.Outcome.SKIPPED, 0, "no display"));
        summary.add(result("B.b", TestSummary.Outcome.SKIPPED, 0, "no corpus"));
        for (int i = 0; i < 6; i++) {
            summary.add(result("C.t" + i, TestSummary.Outcome.PASSED, 100L * i, ""));
        }
        assertEquals(List.of(
                "core: 11 tests, 7 passed, 3 skipped, 1 failed in 1 min 05 s (full log: core/build/x.log)",
                "  skipped 2: no corpus",
                "  skipped 1: no display",
                "  FAILED A.c: expected: <1> but was: <2>",
                "  slowest: A.a 1.2 s, C.t5 0.5 s, C.t4 0.4 s, C.t3 0.3 s, C.t2 0.2 s"),
                summary.lines(Duration.ofSeconds(65), "core/build/x.log"));
    }

    @Test
    void manyReasonsAndFailuresAreCountedBeyondTheirCaps() {
        TestSummary summary = new TestSummary("desktop");
        for (int i = 0; i < 8; i++) {
            summary.add(result("S.s" + i, TestSummary.Outcome.SKIPPED, 0, "reason " + i));
        }
        summary.add(result("S.again", TestSummary.Outcome.SKIPPED, 0, "reason 7"));
        for (int i = 0; i < 23; i++) {
            summary.add(result("F.f" + i, TestSummary.Outcome.FAILED, 0, "broke " + i));
        }
        List<String> lines = summary.lines(Duration.ofSeconds(1), "l");
        assertEquals(List.of("  skipped 1: reason 0", "  skipped 1: reason 1", "  skipped 1: reason 2",
                "  skipped 1: reason 3", "  skipped 1: reason 4",
                "  skipped 4 more, for 3 other reasons (the log names them)"), lines.subList(1, 7));
        assertEquals("  FAILED F.f0: broke 0", lines.get(7));
        assertEquals("  FAILED F.f19: broke 19", lines.get(26));
        assertEquals("  and 3 more failures (the log has them)", lines.get(27));
        assertEquals(29, lines.size(), "with the slowest line");
    }

    @Test
    void aRunWithoutTestsIsOneLine() {
        assertEquals(List.of("simd: 0 tests, 0 passed, 0 skipped, 0 failed in 0.3 s (full log: l)"),
                new TestSummary("simd").lines(Duration.ofMillis(300), "l"));
    }

    @Test
    void durationsReadAsAPersonWouldSayThem() {
        assertEquals("0.0 s", TestSummary.duration(Duration.ZERO));
        assertEquals("9.9 s", TestSummary.duration(Duration.ofMillis(9_940)));
        assertEquals("10 s", TestSummary.duration(Duration.ofMillis(9_960)));
        assertEquals("59 s", TestSummary.duration(Duration.ofMillis(59_400)));
        assertEquals("1 min 00 s", TestSummary.duration(Duration.ofMillis(59_600)));
        assertEquals("12 min 34 s", TestSummary.duration(Duration.ofSeconds(754)));
    }

    @Test
    void firstLineSkipsBlankLinesAndTrims() {
        assertEquals("expected: <1>", TestSummary.firstLine("\n  \n  expected: <1>  \r\nbut was: <2>"));
        assertEquals("", TestSummary.firstLine(null));
        assertEquals("", TestSummary.firstLine(" \n "));
    }
}
