package org.skinlab.testsummary;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashMap;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Optional;
import java.util.Set;

import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.engine.TestSource;
import org.junit.platform.engine.support.descriptor.ClassSource;
import org.junit.platform.engine.support.descriptor.MethodSource;
import org.junit.platform.launcher.TestExecutionListener;
import org.junit.platform.launcher.TestIdentifier;
import org.junit.platform.launcher.TestPlan;

/**
 * Writes a {@link TestSummary} of the run when it ends, to the file named by the system property
 * {@value #FILE}, and its counts to {@value #COUNTS} (where the build reads whether tests failed);
 * without those properties it does nothing. The JUnit Platform finds it through
 * {@code META-INF/services} wherever the build puts this module on a test class path (the console
 * launcher of Gradle 4.4.1 and of the Robolectric runs, and Gradle 8's own test task alike).
 *
 * <p>A skipped container (a class whose condition is not met) counts each of its tests as
 * skipped with the container's reason; so does a container aborted before its tests ran (an
 * assumption in {@code @BeforeAll}). A failed container (an exception in {@code @BeforeAll}, an
 * engine that could not discover) counts once, as a failure under its own name.
 */
public final class SummaryListener implements TestExecutionListener {
    /** System property: the file the summary is written to. */
    public static final String FILE = "skinlab.testSummary";
    /** System property: a properties file for the build (tests, passed, skipped, failed). */
    public static final String COUNTS = "skinlab.testSummary.counts";
    /** System property: what the run is called in the summary (the module, e.g. {@code core}). */
    public static final String LABEL = "skinlab.testSummary.label";
    /** System property: where the run's full output goes, named in the summary. */
    public static final String LOG = "skinlab.testSummary.log";

    private static final String ASSUMPTION = "Assumption failed: ";

    private final Path file;
    private final Path counts;
    private final String log;
    private final TestSummary summary;
    private final Map<String, Long> started = new HashMap<>();
    private final Set<String> reported = new HashSet<>();
    private TestPlan plan;
    private long planStarted;

    /** The listener the JUnit Platform creates: configured by system properties. */
    public SummaryListener() {
        this(path(FILE), path(COUNTS), System.getProperty(LABEL, "tests"), System.getProperty(LOG, "(not written)"));
    }

    /**
     * @param file   where to write the summary, or null to write nothing
     * @param counts where to write the counts, or null to write none
     */
    public SummaryListener(Path file, Path counts, String label, String log) {
        this.file = file;
        this.counts = counts;
        this.log = log;
        this.summary = new TestSummary(label);
    }

    @Override
    public void testPlanExecutionStarted(TestPlan testPlan) {
        plan = testPlan;
        planStarted = System.nanoTime();
    }

    @Override
    public void executionStarted(TestIdentifier id) {
        if (id.isTest()) {
            started.put(id.getUniqueId(), System.nanoTime());
        }
    }

    @Override
    public void executionSkipped(TestIdentifier id, String reason) {
        skipUnreported(id, TestSummary.firstLine(reason));
    }

    @Override
    public void executionFinished(TestIdentifier id, TestExecutionResult result) {
        switch (result.getStatus()) {
            case SUCCESSFUL -> {
                if (id.isTest()) {
                    report(id, TestSummary.Outcome.PASSED, "");
                }
            }
            case ABORTED -> skipUnreported(id, result.getThrowable().map(SummaryListener::skipReason).orElse("aborted"));
            case FAILED -> report(id, TestSummary.Outcome.FAILED,
                    result.getThrowable().map(SummaryListener::failure).orElse("failed, without an exception"));
        }
    }

    @Override
    public void testPlanExecutionFinished(TestPlan testPlan) {
        Duration elapsed = Duration.ofNanos(System.nanoTime() - planStarted);
        if (file != null) {
            write(file, summary.lines(elapsed, log));
        }
        if (counts != null) {
            List<String> lines = new ArrayList<>();
            lines.add("tests=" + summary.total());
            for (TestSummary.Outcome outcome : TestSummary.Outcome.values()) {
                lines.add(outcome.name().toLowerCase(Locale.ROOT) + "=" + summary.count(outcome));
            }
            write(counts, lines);
        }
    }

    private static void write(Path path, List<String> lines) {
        try {
            if (path.getParent() != null) {
                Files.createDirectories(path.getParent());
            }
            Files.write(path, lines, StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot write the test summary " + path, e);
        }
    }

    private static Path path(String property) {
        String value = System.getProperty(property);
        return value == null ? null : Path.of(value);
    }

    /** Skips the test, or every test under the container that has no result yet (none: the container itself). */
    private void skipUnreported(TestIdentifier id, String reason) {
        if (id.isTest()) {
            report(id, TestSummary.Outcome.SKIPPED, reason);
            return;
        }
        Set<TestIdentifier> descendants = plan.getDescendants(id);
        if (descendants.isEmpty() && id.getParentId().isPresent()) {
            report(id, TestSummary.Outcome.SKIPPED, reason);
        }
        for (TestIdentifier d : descendants) {
            if (d.isTest() && !reported.contains(d.getUniqueId())) {
                report(d, TestSummary.Outcome.SKIPPED, reason);
            }
        }
    }

    private void report(TestIdentifier id, TestSummary.Outcome outcome, String reason) {
        reported.add(id.getUniqueId());
        Long start = started.remove(id.getUniqueId());
        Duration time = start == null ? Duration.ZERO : Duration.ofNanos(System.nanoTime() - start);
        summary.add(new TestSummary.Result(name(id), outcome, time, reason));
    }

    /**
     * "SimpleClass.method" for a method, with the invocation's display name after it for a
     * parameterized or repeated one ("SkinnerTest.agrees [3] method=dqs"); a test without a class (a
     * dynamic one, an engine's own failure) adds its display names below the nearest class.
     */
    private String name(TestIdentifier id) {
        Deque<TestIdentifier> chain = new ArrayDeque<>();
        for (TestIdentifier at = id; at != null; at = plan.getParent(at).orElse(null)) {
            chain.addFirst(at);
            if (at.getSource().filter(ClassSource.class::isInstance).isPresent()) {
                break;
            }
        }
        StringBuilder name = new StringBuilder();
        MethodSource method = null;
        for (TestIdentifier at : chain) {
            Optional<TestSource> source = at.getSource();
            if (source.isPresent() && source.get() instanceof ClassSource c) {
                String className = c.getClassName();
                name.append(className.substring(className.lastIndexOf('.') + 1));
            } else if (source.isPresent() && source.get() instanceof MethodSource m && !m.equals(method)) {
                name.append('.').append(m.getMethodName());
                method = m;
            } else if (at.getParentId().isPresent()) {
                name.append(name.length() == 0 ? "" : " ").append(at.getDisplayName());
            }
        }
        return name.length() == 0 ? id.getDisplayName() : name.toString();
    }

    /** An assumption's message, without JUnit's "Assumption failed: " before it. */
    private static String skipReason(Throwable t) {
        String line = TestSummary.firstLine(t.getMessage());
        return line.startsWith(ASSUMPTION) ? line.substring(ASSUMPTION.length()) : line.isEmpty() ? "aborted" : line;
    }

    /** An assertion's first line ("expected: <1> but was: <2>"); any other exception's type before it. */
    private static String failure(Throwable t) {
        String line = TestSummary.firstLine(t.getMessage());
        if (t instanceof AssertionError && !line.isEmpty()) {
            return line;
        }
        return t.getClass().getSimpleName() + (line.isEmpty() ? "" : ": " + line);
    }
}
