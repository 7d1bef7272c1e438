package org.skinlab.testing;

import static org.junit.jupiter.params.provider.Arguments.arguments;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import org.junit.jupiter.api.Named;
import org.junit.jupiter.params.provider.Arguments;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;

/**
 * What every importer's Jazzer fuzz test shares: the rule for an acceptable outcome and the seeds.
 * A fuzz test for another importer is one more class that calls {@link #check} with its own
 * reader and exception type, and {@link #seeds} with its own file extensions (run by
 * {@code gradle test} over its committed inputs, fuzzed by {@code gradle fuzz}; see
 * {@code docs/importer.md}, "Fuzzing").
 *
 * <p>The only acceptable outcomes of importing any bytes are a {@link Model} whose positions are
 * finite, or the importer's own exception, raised on purpose (not its last-resort wrapper of a
 * {@code RuntimeException}) with a one-line message that starts with the file name. Anything else
 * is rethrown, so Jazzer reports it as a finding: an unchecked exception, an {@code Error}
 * ({@code StackOverflowError}, {@code OutOfMemoryError}), an {@code IOException} from bytes in
 * memory, or an {@link AssertionError} for a broken rule. Hangs are the fuzz test's
 * {@code @Timeout}.
 */
public final class ImporterFuzzing {
    /** An importer's stream entry point: bytes, the name for messages, the document's location. */
    @FunctionalInterface
    public interface Reader {
        Model read(InputStream in, String name, Path location) throws Exception;
    }

    /**
     * The folder the fuzzed documents claim to live in: a fresh, empty, private directory, so a
     * relative image or document URL resolves to nothing that exists.
     */
    private static final Path FOLDER = createFolder();

    private ImporterFuzzing() {
    }

    private static Path createFolder() {
        try {
            Path dir = Files.createTempDirectory("skinlab-fuzz-");
            dir.toFile().deleteOnExit();
            return dir;
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Imports {@code data} as a file called {@code fileName} and returns normally only for an
     * acceptable outcome (see the class comment); otherwise throws what went wrong.
     *
     * @param refusal the importer's exception type for a file it cannot import
     */
    public static void check(byte[] data, String fileName, Reader reader, Class<? extends Exception> refusal)
            throws Throwable {
        Model model;
        try {
            model = reader.read(new ByteArrayInputStream(data), fileName, FOLDER.resolve(fileName));
        } catch (Exception e) {
            if (!refusal.isInstance(e)) {
                throw e;
            }
            if (e.getCause() instanceof RuntimeException || e.getCause() instanceof Error) {
                // The importer's safety net caught a crash (the glTF importer's also catches
                // StackOverflowError): report the crash itself, so Jazzer tells different bugs
                // apart by their stack traces.
                throw e.getCause();
            }
            String message = e.getMessage();
            if (message == null || !message.startsWith(fileName + ": ") || message.contains("\n")) {
                throw new AssertionError("not one line starting with \"" + fileName + ": \": " + message, e);
            }
            return;
        }
        for (Mesh mesh : model.meshes()) {
            for (float f : mesh.positions()) {
                if (!Float.isFinite(f)) {
                    throw new AssertionError("imported a non-finite position in mesh " + mesh.id());
                }
            }
        }
    }

    /**
     * Seeds: every file of ours whose name ends with one of {@code extensions}, from the assets
     * ({@code assets/}) and the test fixtures ({@code core/src/test/resources/fixtures/}), read
     * where they are so that a new asset or fixture is a seed without a copy.
     */
    public static Stream<Arguments> seeds(String... extensions) throws IOException {
        return seeds(List.of("assets", "core/src/test/resources/fixtures"), extensions);
    }

    /**
     * Seeds: every file whose name ends with one of {@code extensions} in the given folders
     * (relative to the repository root; a folder that does not exist gives none).
     */
    public static Stream<Arguments> seeds(List<String> folders, String... extensions) throws IOException {
        Path root = TestPaths.root();
        List<Path> files = new ArrayList<>();
        for (String folder : folders) {
            Path dir = root.resolve(folder);
            if (!Files.isDirectory(dir)) {
                continue;
            }
            try (Stream<Path> walk = Files.walk(dir)) {
                files.addAll(walk.filter(Files::isRegularFile)
                        .filter(p -> Stream.of(extensions).anyMatch(x -> p.getFileName().toString().endsWith(x)))
                        .sorted()
                        .collect(Collectors.toList()));
            }
        }
        List<Arguments> seeds = new ArrayList<>();
        for (Path file : files) {
            String name = root.relativize(file).toString();
            seeds.add(arguments(Named.of(name, Files.readAllBytes(file))));
        }
        return seeds.stream();
    }
}
