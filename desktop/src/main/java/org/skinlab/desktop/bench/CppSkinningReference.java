package org.skinlab.desktop.bench;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * The shared scalar C++ skinning reference ({@code ../shared/perf/skin_ref.cpp}), compiled with
 * the machine's g++ as its README says and run on its own synthetic data (the data
 * {@link SyntheticSkinData} reproduces bit for bit), so that our kernels are timed against it in
 * the same session. Its lines are read back as {@link Result}s.
 */
public final class CppSkinningReference {
    private static final Pattern LINE = Pattern.compile(
            "V=(\\d+)\\s+(\\S+)\\s+min\\s+([\\d.]+)\\s+median\\s+([\\d.]+) ns/vertex\\s+\\(n=(\\d+)\\)\\s+checksum\\s+(-?[\\d.]+)");
    private static final long COMPILE_SECONDS = 300;

    /** One line of the reference: a variant (c-lbs, c-dqs, ...) at V vertices, in ns per vertex. */
    public record Result(int vertices, String variant, double minNs, double medianNs, int samples, double checksum) {
    }

    private final Path binary;

    private CppSkinningReference(Path binary) {
        this.binary = binary;
    }

    /** The compiler this machine has (g++, else c++), or null. */
    public static String compiler() {
        for (String c : new String[] {"g++", "c++"}) {
            String path = System.getenv("PATH");
            if (path == null) {
                return null;
            }
            for (String dir : path.split(java.io.File.pathSeparator)) {
                if (!dir.isEmpty() && Files.isExecutable(Path.of(dir, c))) {
                    return c;
                }
            }
        }
        return null;
    }

    /**
     * Compiles {@code source} into {@code dir} with {@code compiler} ({@code -O3 -DNDEBUG
     * -std=c++17}, the reference's README).
     *
     * @throws IOException when the compiler fails (its output in the message) or takes too long
     */
    public static CppSkinningReference compile(String compiler, Path source, Path dir) throws IOException {
        Path binary = dir.resolve("skin_ref");
        Path log = dir.resolve("compile.log");
        Process p = new ProcessBuilder(compiler, "-O3", "-DNDEBUG", "-std=c++17", source.toString(), "-o",
                binary.toString(), "-lpthread").redirectErrorStream(true).redirectOutput(log.toFile()).start();
        finish(p, COMPILE_SECONDS, compiler + " " + source);
        if (p.exitValue() != 0) {
            throw new IOException(compiler + " " + source + " failed (status " + p.exitValue() + "): "
                    + Files.readString(log, StandardCharsets.UTF_8).trim());
        }
        return new CppSkinningReference(binary);
    }

    /**
     * Runs the variants ({@code VARIANTS=...}) at each size, {@code rounds} rounds of
     * {@code seconds} each, and returns its lines.
     */
    public List<Result> run(List<String> variants, int rounds, double seconds, List<Integer> sizes)
            throws IOException {
        List<String> command = new ArrayList<>(List.of(binary.toString(), Integer.toString(rounds),
                String.format(Locale.ROOT, "%.3f", seconds)));
        for (int v : sizes) {
            command.add(Integer.toString(v));
        }
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        pb.environment().put("VARIANTS", String.join(",", variants));
        Path out = Files.createTempFile(binary.getParent(), "run", ".txt");
        Process p = pb.redirectOutput(out.toFile()).start();
        // Each variant and size: rounds of the given seconds, plus building the data.
        long limit = 60 + Math.round(rounds * Math.max(seconds, 0.1) * variants.size() * sizes.size() * 3);
        finish(p, limit, binary.toString());
        String text = Files.readString(out, StandardCharsets.UTF_8);
        if (p.exitValue() != 0) {
            throw new IOException(binary + " failed (status " + p.exitValue() + "): " + text.trim());
        }
        List<Result> results = parse(text);
        if (results.size() != variants.size() * sizes.size()) {
            throw new IOException(binary + " printed " + results.size() + " results, expected "
                    + variants.size() * sizes.size() + ": " + text.trim());
        }
        return results;
    }

    /** The reference's result lines in {@code text}; other lines are ignored. */
    public static List<Result> parse(String text) {
        List<Result> results = new ArrayList<>();
        for (String line : text.split("\n")) {
            Matcher m = LINE.matcher(line.trim());
            if (m.matches()) {
                results.add(new Result(Integer.parseInt(m.group(1)), m.group(2), Double.parseDouble(m.group(3)),
                        Double.parseDouble(m.group(4)), Integer.parseInt(m.group(5)), Double.parseDouble(m.group(6))));
            }
        }
        return results;
    }

    private static void finish(Process p, long seconds, String what) throws IOException {
        try {
            if (!p.waitFor(seconds, TimeUnit.SECONDS)) {
                p.destroyForcibly();
                throw new IOException(what + ": no result after " + seconds + " s");
            }
        } catch (InterruptedException e) {
            p.destroyForcibly();
            Thread.currentThread().interrupt();
            throw new IOException(what + ": interrupted", e);
        }
    }
}
