package org.skinlab.testsummary;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.platform.engine.discovery.DiscoverySelectors.selectClass;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Set;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.platform.launcher.Launcher;
import org.junit.platform.launcher.core.LauncherConfig;
import org.junit.platform.launcher.core.LauncherDiscoveryRequestBuilder;
import org.junit.platform.launcher.core.LauncherFactory;
import org.skinlab.testsummary.fixtures.Outcomes;

/** The listener on a real JUnit run of {@link Outcomes}' classes, one per outcome. */
class SummaryListenerTest {
    @Test
    void summarisesEveryOutcomeOfARealRun(@TempDir Path dir) throws Exception {
        Path file = dir.resolve("out/summary.txt");
        Path counts = dir.resolve("out/counts.properties");
        SummaryListener listener = new SummaryListener(file, counts, "fixtures", "build/test-output/x.log");
        // Only this listener: the one the build registers (META-INF/services) must not see the nested run.
        Launcher launcher = LauncherFactory.create(LauncherConfig.builder()
                .enableTestExecutionListenerAutoRegistration(false)
                .addTestExecutionListeners(listener)
                .build());
        launcher.execute(LauncherDiscoveryRequestBuilder.request()
                .selectors(selectClass(Outcomes.Passing.class), selectClass(Outcomes.Failing.class),
                        selectClass(Outcomes.Assuming.class), selectClass(Outcomes.DisabledClass.class),
                        selectClass(Outcomes.AbortedBeforeAll.class), selectClass(Outcomes.FailedBeforeAll.class))
                .build());

        List<String> lines = Files.readAllLines(file, StandardCharsets.UTF_8);
        // Passing: 4 (one, slow, two invocations); Failing: 2; Assuming: 3 skipped; DisabledClass: 2
        // skipped; AbortedBeforeAll: 2 skipped; FailedBeforeAll: 1 failure (the class).
        assertTrue(lines.get(0).startsWith("fixtures: 14 tests, 4 passed, 7 skipped, 3 failed in "), lines.get(0));
        assertTrue(lines.get(0).endsWith(" (full log: build/test-output/x.log)"), lines.get(0));
        assertEquals(List.of(
                "  skipped 2: no corpus at ../shared/corpus",
                "  skipped 3: no display",
                "  skipped 2: not on this machine"),
                lines.subList(1, 4));
        // Failures in the order they ran (Jupiter's method order is deterministic, not alphabetical).
        assertEquals(Set.of(
                "  FAILED Outcomes$Failing.assertion: counted",
                "  FAILED Outcomes$Failing.withoutMessage: IllegalStateException",
                "  FAILED Outcomes$FailedBeforeAll: IllegalArgumentException: cannot read fixture.dae"),
                Set.copyOf(lines.subList(4, 7)));
        // The three tests that sleep (200 ms, and 100 ms in each invocation, named by its argument)
        // are among the five slowest, whatever else the machine is doing.
        assertTrue(lines.get(7).startsWith("  slowest: "), lines.get(7));
        for (String name : List.of("Outcomes$Passing.slow ", "Outcomes$Passing.method [1] name=dqs ",
                "Outcomes$Passing.method [2] name=lbs ")) {
            assertTrue(lines.get(7).contains(name), name + " in " + lines.get(7));
        }
        assertEquals(8, lines.size());
        assertEquals(List.of("tests=14", "passed=4", "skipped=7", "failed=3"), Files.readAllLines(counts, StandardCharsets.UTF_8));
    }
}
