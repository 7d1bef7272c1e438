package org.skinlab.android.apicheck;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.codehaus.mojo.animal_sniffer.Clazz;

/**
 * The build's entry point: checks dex files against the platform's API at the min SDK and prints
 * one line on success, every violation on failure (exit status 1).
 *
 * <pre>
 * --dex FILE|DIR       a dex file, or a directory of them (repeatable)
 * --api FILE           animal-sniffer signature of the platform at the min SDK
 * --newer-api FILE     signature of API 33 (tells a missing member's level)
 * --min-sdk N          the app's min SDK
 * --classpath JAR      a library the dex was compiled against but does not hold (repeatable)
 * --exceptions FILE    reviewed exceptions (optional)
 * --name TEXT          what is checked, for the message
 * --report FILE        where to write the message too (the build's record of a passed check)
 * </pre>
 */
public final class ApiCheckMain {
    private ApiCheckMain() {
    }

    public static void main(String[] args) throws IOException {
        Map<String, List<String>> options = options(args);
        List<Path> dexFiles = new ArrayList<>();
        for (String dex : required(options, "--dex")) {
            dexFiles.addAll(dexFiles(Path.of(dex)));
        }
        List<Path> classpath = options.getOrDefault("--classpath", List.of()).stream().map(Path::of).toList();
        int minSdk = Integer.parseInt(single(options, "--min-sdk"));
        ApiExceptions exceptions = options.containsKey("--exceptions")
                ? ApiExceptions.read(Path.of(single(options, "--exceptions"))) : ApiExceptions.none();
        ApiReport report = check(single(options, "--name"), dexFiles, classpath, Path.of(single(options, "--api")),
                Path.of(single(options, "--newer-api")), minSdk, exceptions);
        String message = report.message();
        if (options.containsKey("--report")) {
            Path out = Path.of(single(options, "--report"));
            Files.createDirectories(out.toAbsolutePath().getParent());
            Files.writeString(out, message + "\n");
        }
        if (!report.passed()) {
            System.err.println(message);
            System.exit(1);
        }
        System.out.println(message);
    }

    /** Reads the dex files, the signatures and the libraries, and runs the check. */
    static ApiReport check(String name, List<Path> dexFiles, List<Path> classpath, Path api, Path newerApi, int minSdk,
            ApiExceptions exceptions) throws IOException {
        DexProgram program = DexProgram.read(dexFiles);
        Map<String, Clazz> ours = new HashMap<>(Signatures.ofJars(classpath));
        ours.putAll(program.models());
        ClassModels atMinSdk = new ClassModels(ours, Signatures.read(api));
        ClassModels newer = new ClassModels(ours, Signatures.read(newerApi));
        return new ApiCheck(atMinSdk, newer, minSdk, exceptions).run(name, program);
    }

    private static List<Path> dexFiles(Path path) throws IOException {
        if (!Files.isDirectory(path)) {
            return List.of(path);
        }
        try (Stream<Path> files = Files.list(path)) {
            List<Path> dex = files.filter(f -> f.getFileName().toString().endsWith(".dex")).sorted().toList();
            if (dex.isEmpty()) {
                throw new IOException("no .dex file in " + path);
            }
            return dex;
        }
    }

    private static Map<String, List<String>> options(String[] args) {
        Map<String, List<String>> options = new HashMap<>();
        for (int i = 0; i < args.length; i += 2) {
            if (!args[i].startsWith("--") || i + 1 >= args.length) {
                throw new IllegalArgumentException("expected '--option value' pairs, got: " + String.join(" ", args));
            }
            options.computeIfAbsent(args[i], k -> new ArrayList<>()).add(args[i + 1]);
        }
        return options;
    }

    private static List<String> required(Map<String, List<String>> options, String name) {
        List<String> values = options.get(name);
        if (values == null) {
            throw new IllegalArgumentException("missing " + name);
        }
        return values;
    }

    private static String single(Map<String, List<String>> options, String name) {
        List<String> values = required(options, name);
        if (values.size() != 1) {
            throw new IllegalArgumentException(name + " given " + values.size() + " times");
        }
        return values.get(0);
    }
}
