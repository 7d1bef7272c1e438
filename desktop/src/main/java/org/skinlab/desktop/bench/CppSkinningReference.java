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

import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinningMethod;

/**
 * A scalar C++ skinning program compiled with the machine's g++ and run on the shared reference's
 * synthetic data (the data {@link SyntheticSkinData} reproduces bit for bit), so that our kernels
 * are timed against it in the same session: the shared reference ({@code ../shared/perf/skin_ref.cpp},
 * {@link #REFERENCE_VARIANTS}: positions and normals) and our positions-only counterpart
 * ({@link #POSITIONS_SOURCE}, {@link #POSITIONS_VARIANTS}), which print the same lines, read back
 * as {@link Result}s. {@link #runBoth} compiles and runs the two side by side.
 */
public final class CppSkinningReference {
    private static final Pattern LINE = Pattern.compile(
            "V=(\\d+)\\s+(\\S+)\\s+min\\s+([\\d.]+)\\s+median\\s+([\\d.]+) ns/vertex\\s+\\(n=(\\d+)\\)\\s+checksum\\s+(-?[\\d.]+)");
    private static final long COMPILE_SECONDS = 300;

    /** Our positions-only C++ program, relative to the repository root. */
    public static final String POSITIONS_SOURCE = "bench/cpp/skin_positions.cpp";
    /** The shared reference's variants with one thread: LBS and DQS with normals (by the blended matrix, rotated). */
    public static final List<String> REFERENCE_VARIANTS = List.of("c-lbs", "c-dqs");
    /**
     * Our program's variants: LBS and DQS positions only ({@code -pos}, checksum the positions'
     * sum), and with normals by the reference's rules ({@code -nrm}: a calibration whose checksums
     * equal the reference's at 4 influences).
     */
    public static final List<String> POSITIONS_VARIANTS = List.of("c-lbs-pos", "c-dqs-pos", "c-lbs-nrm", "c-dqs-nrm");

    /**
     * One line of a program: a variant (c-lbs, c-dqs-pos, ...) at V vertices, in ns per vertex, and
     * its checksum: the sum of the output positions plus half the sum of the normals
     * ({@link SyntheticSkinData#checksum}).
     */
    public record Result(int vertices, String variant, double minNs, double medianNs, int samples, double checksum) {
        /** The method the variant skins with ({@code c-lbs...}: LBS, {@code c-dqs...}: DQS). */
        public SkinningMethod method() {
            String[] parts = variant.split("-");
            return SkinningMethod.fromKey(parts.length > 1 ? parts[1] : variant);
        }

        /**
         * The rule of our kernels that does the same work: {@link NormalTransform#NONE} for a
         * positions-only variant ({@code -pos}), else {@link NormalTransform#BLENDED_MATRIX} (the
         * reference's normals).
         */
        public NormalTransform normals() {
            return variant.endsWith("-pos") ? NormalTransform.NONE : NormalTransform.BLENDED_MATRIX;
        }
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
     * -std=c++17}, the reference's README), the binary named after the source ({@code skin_ref},
     * {@code skin_positions}), so that both programs can share a folder.
     *
     * @throws IOException when the compiler fails (its output in the message) or takes too long
     */
    public static CppSkinningReference compile(String compiler, Path source, Path dir) throws IOException {
        String name = source.getFileName().toString().replaceFirst("\\.[^.]*$", "");
        Path binary = dir.resolve(name);
        Path log = dir.resolve(name + "-compile.log");
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
        return run(variants, rounds, seconds, sizes, SyntheticSkinData.INFLUENCES);
    }

    /**
     * As {@link #run(List, int, double, List)} with {@code influences} joints per vertex
     * ({@code INFLUENCES=K}, 1 to 16): our positions-only program draws them as
     * {@link SyntheticSkinData#SyntheticSkinData(int, long, int)} does; the shared reference
     * ignores it and always has 4.
     */
    public List<Result> run(List<String> variants, int rounds, double seconds, List<Integer> sizes, int influences)
            throws IOException {
        List<String> command = new ArrayList<>(List.of(binary.toString(), Integer.toString(rounds),
                String.format(Locale.ROOT, "%.3f", seconds)));
        for (int v : sizes) {
            command.add(Integer.toString(v));
        }
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        pb.environment().put("VARIANTS", String.join(",", variants));
        pb.environment().put("INFLUENCES", Integer.toString(influences));
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

    /**
     * Compiles the shared reference and our positions-only program into {@code dir} and runs them
     * one after the other at each size (the reference's {@link #REFERENCE_VARIANTS}, then our
     * {@link #POSITIONS_VARIANTS}), 4 influences: per size six results, C++ LBS and DQS with and
     * without normals, with the reference's own timings of the same work beside our calibration's.
     */
    public static List<Result> runBoth(String compiler, Path referenceSource, Path positionsSource, Path dir,
            int rounds, double seconds, List<Integer> sizes) throws IOException {
        CppSkinningReference reference = compile(compiler, referenceSource, dir);
        CppSkinningReference positions = compile(compiler, positionsSource, dir);
        List<Result> results = new ArrayList<>();
        for (int v : sizes) {
            results.addAll(reference.run(REFERENCE_VARIANTS, rounds, seconds, List.of(v)));
            results.addAll(positions.run(POSITIONS_VARIANTS, rounds, seconds, List.of(v)));
        }
        return results;
    }

    /** The result lines in {@code text} (the reference's format); other lines are ignored. */
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
