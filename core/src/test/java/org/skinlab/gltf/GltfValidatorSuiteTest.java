package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.DynamicTest;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestFactory;
import org.skinlab.model.Model;
import org.skinlab.testing.TestPaths;

/**
 * The glTF-Validator's own test files (KhronosGroup/glTF-Validator, folder {@code test/}: each
 * {@code .gltf}/{@code .glb} with the validator's report beside it as {@code <file>.report.json})
 * imported one by one: a file whose report has errors is refused with a {@link GltfException}
 * whose location is a JSON pointer; a file with only warnings, infos or hints loads. No file may
 * end any other way (an unchecked exception, an {@code Error}, an {@code IOException} for a file
 * that exists), take more than {@link #TIMEOUT} or allocate more than {@link #ALLOCATION_LIMIT}.
 *
 * <p>The exceptions are listed, each with its reason, in
 * {@code resources/conformance/gltf-validator-exceptions.txt}: files that load although their
 * report has errors ({@code loads}: errors only in the data of an extension we do not read, or
 * values we tolerate, each with a warning; {@code ignored}: errors in what the importer never
 * reads, the content of external image files), and files we refuse although it has none
 * ({@code refused}: our rules are stricter, e.g. no {@code http:} URIs, or there is no data to
 * read); see docs/importer.md, glTF "Conformance".
 *
 * <p>The suite is not in the repository: {@code tools/get-gltf-validator-suite.sh} places it in
 * {@code ../shared/gltf-validator} (the system property {@code skinlab.gltfValidator} or the
 * environment variable {@code GLTF_VALIDATOR_SUITE} name another folder); without it the tests
 * are skipped, saying so. The summary (loaded, refused, how often our pointer is the validator's)
 * is printed and written to {@code build/gltf-validator-summary.txt}.
 */
class GltfValidatorSuiteTest {
    private static final Duration TIMEOUT = Duration.ofSeconds(10);
    /** The suite's files are at most a few kilobytes; their data declare at most a few megabytes. */
    private static final long ALLOCATION_LIMIT = 64L << 20;
    private static final String EXCEPTIONS = "/conformance/gltf-validator-exceptions.txt";
    private static final ObjectMapper JSON = new ObjectMapper();

    private static final Map<String, Outcome> OUTCOMES = new ConcurrentHashMap<>();

    /** What importing one file did. */
    private record Outcome(boolean expectRefusal, boolean loaded, String location, List<String> errorPointers,
            int warnings) {
        boolean refused() {
            return !loaded;
        }
    }

    static Path suite() {
        String p = System.getProperty("skinlab.gltfValidator", System.getenv("GLTF_VALIDATOR_SUITE"));
        return p != null ? Path.of(p) : TestPaths.shared().resolve("gltf-validator");
    }

    private static Path suiteOrSkip() {
        Path dir = suite();
        assumeTrue(Files.isDirectory(dir.resolve("base")), () -> "glTF-Validator suite not found at " + dir
                + ": run tools/get-gltf-validator-suite.sh to get it; validator conformance tests skipped");
        return dir;
    }

    /** Every report of the suite, sorted by the path of its file relative to the suite. */
    private static List<Path> reports(Path dir) throws IOException {
        try (Stream<Path> walk = Files.walk(dir)) {
            return walk.filter(p -> p.getFileName().toString().endsWith(".report.json")).sorted()
                    .collect(Collectors.toList());
        }
    }

    /**
     * An exception to the report's verdict, and why: the file loads with a warning ("loads"), loads
     * because its errors lie in what the importer never reads ("ignored"), or is refused ("refused").
     */
    record Verdict(String outcome, String reason) {
    }

    /** The exceptions by the file's path in the suite. */
    static Map<String, Verdict> verdicts() throws IOException {
        Map<String, Verdict> files = new LinkedHashMap<>();
        try (InputStream in = GltfValidatorSuiteTest.class.getResourceAsStream(EXCEPTIONS);
                BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
            for (String line = r.readLine(); line != null; line = r.readLine()) {
                if (!line.isBlank() && !line.startsWith("#")) {
                    String[] f = line.split(" \\| ", 3);
                    if (f.length != 3 || !List.of("loads", "ignored", "refused").contains(f[0])) {
                        throw new IllegalStateException("not \"loads|ignored|refused | path | reason\": " + line);
                    }
                    files.put(f[1].trim(), new Verdict(f[0], f[2].trim()));
                }
            }
        }
        return files;
    }

    @Test
    void everyExceptionGoesAgainstItsReport() throws IOException {
        Path dir = suiteOrSkip();
        for (Map.Entry<String, Verdict> e : verdicts().entrySet()) {
            Path report = dir.resolve(e.getKey() + ".report.json");
            assertTrue(Files.isRegularFile(report), () -> e.getKey() + " is not in the suite");
            boolean errors = JSON.readTree(report.toFile()).path("issues").path("numErrors").asInt() > 0;
            assertTrue(errors != e.getValue().outcome().equals("refused"), () -> e.getKey() + " "
                    + e.getValue().outcome() + " as its report says: it needs no exception");
        }
    }

    @TestFactory
    Stream<DynamicTest> everyFileLoadsOrIsRefusedAsItsReportSays() throws IOException {
        Path dir = suiteOrSkip();
        Map<String, Verdict> verdicts = verdicts();
        return reports(dir).stream().map(report -> {
            String name = report.getFileName().toString();
            Path file = report.resolveSibling(name.substring(0, name.length() - ".report.json".length()));
            String relative = dir.relativize(file).toString().replace('\\', '/');
            return DynamicTest.dynamicTest(relative, () -> check(file, relative, report, verdicts.get(relative)));
        });
    }

    private static void check(Path file, String relative, Path report, Verdict verdict)
            throws Exception {
        JsonNode issues = JSON.readTree(report.toFile()).path("issues");
        List<String> errorPointers = new ArrayList<>();
        for (JsonNode m : issues.path("messages")) {
            if (m.path("severity").asInt() == 0) {
                errorPointers.add(m.path("pointer").asText(""));
            }
        }
        boolean errors = issues.path("numErrors").asInt() > 0;
        boolean expectRefusal = verdict == null ? errors : verdict.outcome().equals("refused");
        Model model;
        try {
            model = importWithLimits(file);
        } catch (GltfException e) {
            OUTCOMES.put(relative, new Outcome(expectRefusal, false, e.location(), errorPointers, 0));
            assertTrue(e.getMessage().startsWith(file.getFileName() + ": "), e::getMessage);
            assertTrue(e.location().startsWith("/") || e.location().startsWith("(GLB "),
                    () -> "the location is neither a JSON pointer nor a place in the GLB container: " + e.getMessage());
            assertTrue(expectRefusal, () -> "refused, but " + (verdict != null ? "we load it: " + verdict.reason()
                    : "the validator finds no error") + "; " + e.getMessage());
            return;
        }
        OUTCOMES.put(relative, new Outcome(expectRefusal, true, null, errorPointers, model.warnings().size()));
        if (expectRefusal) {
            fail("loaded, but " + (verdict != null ? "we refuse it: " + verdict.reason()
                    : "the validator finds errors at " + errorPointers) + "; warnings: " + model.warnings());
        }
        if (errors && verdict.outcome().equals("loads")) {
            // A file we load despite errors in what we read says what it tolerated.
            assertTrue(!model.warnings().isEmpty(), () -> "loaded without a warning: " + verdict.reason());
        }
    }

    /**
     * Imports on a thread of its own, so that a hang fails after {@link #TIMEOUT} (the thread is
     * interrupted and abandoned) and the bytes it allocates can be counted.
     */
    private static Model importWithLimits(Path file) throws Exception {
        ExecutorService executor = Executors.newSingleThreadExecutor(r -> {
            Thread t = new Thread(r, "import " + file.getFileName());
            t.setDaemon(true);
            return t;
        });
        try {
            Future<Model> result = executor.submit(() -> {
                long before = allocatedBytes();
                Model m;
                try {
                    m = GltfImporter.read(file);
                } finally {
                    long allocated = allocatedBytes() - before;
                    if (allocated > ALLOCATION_LIMIT) {
                        throw new AssertionError(String.format(Locale.ROOT,
                                "allocated %,d bytes importing a file of %,d bytes", allocated, Files.size(file)));
                    }
                }
                return m;
            });
            try {
                return result.get(TIMEOUT.toMillis(), TimeUnit.MILLISECONDS);
            } catch (TimeoutException e) {
                result.cancel(true);
                throw new AssertionError("no result after " + TIMEOUT.toSeconds() + " s: a hang");
            } catch (java.util.concurrent.ExecutionException e) {
                Throwable cause = e.getCause();
                if (cause instanceof GltfException g) {
                    throw g;
                }
                throw new AssertionError("neither a model nor a GltfException: " + cause, cause);
            }
        } finally {
            executor.shutdownNow();
        }
    }

    /** Bytes the calling thread has allocated so far (HotSpot's per-thread counter). */
    private static long allocatedBytes() {
        return ((com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean())
                .getThreadAllocatedBytes(Thread.currentThread().getId());
    }

    @AfterAll
    static void summary() throws IOException {
        if (OUTCOMES.isEmpty()) {
            return;
        }
        String text = summaryText(OUTCOMES);
        System.out.println(text);
        Path out = TestPaths.root().resolve("core/build/gltf-validator-summary.txt");
        Files.createDirectories(out.getParent());
        Files.writeString(out, text);
    }

    /**
     * The figures docs/importer.md quotes: files loaded and refused, against the reports; and for
     * the refused files with errors, how often our location is one of the validator's error
     * pointers, or a prefix of one (we stopped at the object, it names the property).
     */
    static String summaryText(Map<String, Outcome> outcomes) {
        int files = outcomes.size();
        long withErrors = outcomes.values().stream().filter(o -> !o.errorPointers().isEmpty()).count();
        long loaded = outcomes.values().stream().filter(Outcome::loaded).count();
        long loadedWithWarnings = outcomes.values().stream().filter(o -> o.loaded() && o.warnings() > 0).count();
        long refusedAsExpected = outcomes.values().stream().filter(o -> o.refused() && o.expectRefusal()).count();
        long wronglyLoaded = outcomes.values().stream().filter(o -> o.loaded() && o.expectRefusal()).count();
        long wronglyRefused = outcomes.values().stream().filter(o -> o.refused() && !o.expectRefusal()).count();
        long acceptedWithErrors = outcomes.values().stream()
                .filter(o -> o.loaded() && !o.errorPointers().isEmpty() && !o.expectRefusal()).count();
        int equal = 0;
        int prefix = 0;
        int container = 0;
        int other = 0;
        List<String> disagreeing = new ArrayList<>();
        for (Map.Entry<String, Outcome> e : new java.util.TreeMap<>(outcomes).entrySet()) {
            Outcome o = e.getValue();
            if (!o.refused() || o.errorPointers().isEmpty()) {
                continue;
            }
            // GltfException writes the document's pointer "" as "/".
            String ours = o.location().equals("/") ? "" : o.location();
            if (o.errorPointers().contains(ours)) {
                equal++;
            } else if (o.errorPointers().stream().anyMatch(p -> p.startsWith(ours + "/"))) {
                prefix++;
            } else if (ours.startsWith("(GLB ") && o.errorPointers().contains("")) {
                // The validator gives GLB container errors no pointer; we name the header or chunk.
                container++;
            } else {
                other++;
                disagreeing.add("  " + e.getKey() + ": ours " + o.location() + ", validator's "
                        + o.errorPointers().stream().distinct().collect(Collectors.toList()));
            }
        }
        int compared = equal + prefix + container + other;
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "glTF-Validator suite: %d files, %d with errors in their report%n",
                files, withErrors));
        sb.append(String.format(Locale.ROOT, "  loaded %d (%d with warnings; %d of them with errors we accept),"
                + " refused %d%n", loaded, loadedWithWarnings, acceptedWithErrors, files - loaded));
        sb.append(String.format(Locale.ROOT, "  against the reports: %d refused as expected, %d loaded but should"
                + " be refused, %d refused but should load%n", refusedAsExpected, wronglyLoaded, wronglyRefused));
        sb.append(String.format(Locale.ROOT, "  our pointer vs the validator's error pointers (%d refused files):"
                + " equal %d (%.0f%%), a prefix %d (%.0f%%), GLB container (no pointer) %d, elsewhere %d%n", compared,
                equal, 100.0 * equal / Math.max(1, compared), prefix, 100.0 * prefix / Math.max(1, compared),
                container, other));
        disagreeing.forEach(line -> sb.append(line).append(System.lineSeparator()));
        return sb.toString();
    }
}
