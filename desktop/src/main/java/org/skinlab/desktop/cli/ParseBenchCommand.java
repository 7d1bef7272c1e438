package org.skinlab.desktop.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.JavaRuntime;
import org.skinlab.desktop.bench.AssimpBaseline;
import org.skinlab.desktop.bench.ParseTimer;
import org.skinlab.desktop.bench.SyntheticCollada;
import org.skinlab.desktop.bench.SyntheticGltf;
import org.skinlab.importer.ModelImporter;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code skinlab bench parse}: import speed. Files are read into memory first, so the figures
 * are the importer's (XML parsing included), not the disk's. Each file is imported repeatedly
 * after a shared warm-up; the report gives the minimum and median time per import and the
 * throughput at the median (1 MB = 10^6 bytes).
 *
 * <p>{@code --compare-assimp} also imports every file with assimp (LWJGL's binding, from the same
 * bytes in memory, after its own warm-up of the same length, with the same number of runs, right
 * after ours on each file) and reports assimp's times and the ratio assimp median / our median.
 * A file assimp refuses is reported as failed, with assimp's message, and measured for us alone.
 *
 * <p>Without FILEs it also generates one character twice, as a {@code .glb} ({@link SyntheticGltf})
 * and as a {@code .dae} ({@link SyntheticCollada}), both about 10 MB by default, and reports how
 * much faster our glTF import is than our COLLADA import of the same character (COLLADA median /
 * glTF median), beside assimp's ratio on each.
 */
@Command(name = "parse", mixinStandardHelpOptions = true,
        description = "Import speed on our assets, the shared corpus and a generated large file.")
public final class ParseBenchCommand implements Callable<Integer> {
    @Parameters(arity = "0..*", paramLabel = "FILE",
            description = "files to measure (default: our assets' .dae and .glb files, the shared corpus, a generated "
                    + ".dae and a character generated as .glb and .dae)")
    List<Path> files = new ArrayList<>();

    @Option(names = "--assets", paramLabel = "DIR", description = "our assets (default: ${DEFAULT-VALUE})")
    Path assets = Path.of("assets");

    @Option(names = "--corpus", paramLabel = "DIR",
            description = "third-party corpus, skipped when absent (default: ${DEFAULT-VALUE})")
    Path corpus = Path.of("../shared/corpus");

    @Option(names = "--twin-triangles", paramLabel = "N",
            description = "triangles of the character generated as both .glb and .dae (about 10 MB each at the "
                    + "default); 0 for none (default: ${DEFAULT-VALUE})")
    long twinTriangles = 90_000;

    @Option(names = "--generated-triangles", paramLabel = "N",
            description = "triangles of the generated file; 0 for none (default: ${DEFAULT-VALUE})")
    long generatedTriangles = 1_000_000;

    @Option(names = "--warmup-seconds", paramLabel = "S", description = "shared warm-up (default: ${DEFAULT-VALUE})")
    double warmupSeconds = 3.0;

    @Option(names = "--runs", paramLabel = "N",
            description = "measured imports per file under 10 MB (default: ${DEFAULT-VALUE}); larger files get 5")
    int runs = 25;

    @Option(names = "--json", description = "print the results as one line of JSON")
    boolean json;

    @Option(names = "--compare-assimp",
            description = "also import each file with assimp (LWJGL) and report its median and assimp/ours")
    boolean compareAssimp;

    @Option(names = "--assimp-flags", paramLabel = "N",
            description = "assimp post-processing flags (default: ${DEFAULT-VALUE} = aiProcess_Triangulate"
                    + " | aiProcess_JoinIdenticalVertices, what our importer does)")
    int assimpFlags = AssimpBaseline.FAIR_FLAGS;

    @Spec
    CommandSpec spec;

    /** The triangles the generated file has (its name in the report). */
    private long generatedActual;
    /** The names of the generated .glb and .dae of the same character in the report, or null. */
    private String twinGltf;
    private String twinCollada;

    @Override
    public Integer call() throws IOException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        List<Path> inputs = new ArrayList<>(files);
        if (inputs.isEmpty()) {
            inputs.addAll(modelFiles(assets));
            if (Files.isDirectory(corpus)) {
                inputs.addAll(modelFiles(corpus));
            } else {
                err.println("bench parse: no corpus at " + corpus + "; measuring our assets only");
            }
        }
        Path generated = null;
        Path twinFolder = null;
        try {
            if (twinTriangles > 0 && files.isEmpty()) {
                twinFolder = Files.createTempDirectory("skinlab-twin-");
                inputs.addAll(writeTwins(twinFolder, err));
            }
            if (generatedTriangles > 0 && files.isEmpty()) {
                generated = writeGenerated(err);
                inputs.add(generated);
            }
            List<byte[]> data = readAll(inputs);
            String assimpVersion = compareAssimp ? loadAssimp(err) : null;
            List<ParseTimer.Result> results = measure(inputs, data, generated, err);
            if (json) {
                out.println(new ObjectMapper().writeValueAsString(toJson(results, assimpVersion)));
            } else {
                out.print(table(results, compareAssimp));
                out.print(twinLine(results));
            }
            out.flush();
            return ExitCodes.OK;
        } finally {
            if (generated != null) {
                Files.deleteIfExists(generated);
            }
            if (twinFolder != null) {
                try (Stream<Path> s = Files.list(twinFolder)) {
                    for (Path p : s.collect(Collectors.toList())) {
                        Files.deleteIfExists(p);
                    }
                }
                Files.deleteIfExists(twinFolder);
            }
        }
    }

    /** A generated file of {@code --generated-triangles} in a temporary file (the caller deletes it). */
    private Path writeGenerated(PrintWriter err) throws IOException {
        Path generated = Files.createTempFile("skinlab-generated-", ".dae");
        long t;
        try {
            t = SyntheticCollada.write(generated, generatedTriangles);
        } catch (IOException | RuntimeException e) {
            Files.deleteIfExists(generated);
            throw e;
        }
        generatedActual = t;
        err.printf(Locale.ROOT, "bench parse: generated %s (%d triangles, %.1f MB)%n", generated, t,
                Files.size(generated) / 1e6);
        return generated;
    }

    /** Every file's bytes, read before anything is timed. */
    private static List<byte[]> readAll(List<Path> inputs) throws IOException {
        List<byte[]> data = new ArrayList<>();
        for (Path p : inputs) {
            if (!Files.isRegularFile(p)) {
                throw new CommandFailure(ExitCodes.USAGE, "file not found: " + p, null);
            }
            data.add(Files.readAllBytes(p));
        }
        return data;
    }

    /** Loads assimp's library and names its version, or fails as unavailable. */
    private String loadAssimp(PrintWriter err) {
        String assimpVersion;
        try {
            assimpVersion = AssimpBaseline.loadAndVersion();
        } catch (IllegalStateException e) {
            throw new CommandFailure(ExitCodes.UNAVAILABLE, "bench parse --compare-assimp: " + e.getMessage(), e);
        }
        err.printf(Locale.ROOT, "bench parse: comparing with assimp %s, flags %s%n", assimpVersion,
                AssimpBaseline.describe(assimpFlags));
        return assimpVersion;
    }

    /** The same character as a .glb and as a .dae, in {@code folder}; their names go into the report. */
    private List<Path> writeTwins(Path folder, PrintWriter err) throws IOException {
        twinGltf = "twin-" + twinTriangles + "-triangles.glb";
        twinCollada = "twin-" + twinTriangles + "-triangles.dae";
        Path glb = folder.resolve(twinGltf);
        Path dae = folder.resolve(twinCollada);
        long t = SyntheticGltf.write(glb, twinTriangles);
        SyntheticCollada.write(dae, twinTriangles);
        err.printf(Locale.ROOT, "bench parse: generated one character (%d triangles) as %s (%.1f MB) and %s (%.1f MB)%n",
                t, twinGltf, Files.size(glb) / 1e6, twinCollada, Files.size(dae) / 1e6);
        return List.of(glb, dae);
    }

    /** The generated .glb's and .dae's results (same character), or null when not generated. */
    private ParseTimer.Result[] twins(List<ParseTimer.Result> results) {
        ParseTimer.Result gltf = null;
        ParseTimer.Result collada = null;
        for (ParseTimer.Result r : results) {
            if (r.name.equals(twinGltf)) {
                gltf = r;
            } else if (r.name.equals(twinCollada)) {
                collada = r;
            }
        }
        return gltf == null || collada == null ? null : new ParseTimer.Result[] {gltf, collada};
    }

    private String twinLine(List<ParseTimer.Result> results) {
        ParseTimer.Result[] t = twins(results);
        if (t == null) {
            return "";
        }
        String line = String.format(Locale.ROOT, "same character: .glb %.2f ms, .dae %.2f ms: our glTF import is "
                + "%.2fx our COLLADA import", t[0].median(), t[1].median(), t[1].median() / t[0].median());
        if (t[0].assimpMillis != null) {
            line += String.format(Locale.ROOT, "; assimp/ours %.2f on the .glb", t[0].assimpRatio());
        }
        if (t[1].assimpMillis != null) {
            line += String.format(Locale.ROOT, ", %.2f on the .dae", t[1].assimpRatio());
        }
        return line + System.lineSeparator();
    }

    private List<ParseTimer.Result> measure(List<Path> inputs, List<byte[]> data, Path generated, PrintWriter err) {
        List<ParseTimer.Input> timed = new ArrayList<>();
        for (int i = 0; i < inputs.size(); i++) {
            Path p = inputs.get(i);
            String name = p.equals(generated) ? "generated-" + generatedActual + "-triangles.dae"
                    : p.getFileName().toString();
            timed.add(new ParseTimer.Input(name, data.get(i), null));
        }
        // One run of --runs imports per file: the command's figures are the minimum and the median import.
        return new ParseTimer(warmupSeconds, 1, runs, compareAssimp ? assimpFlags : -1, false, err, "bench parse: ")
                .measure(timed);
    }

    private static List<Path> modelFiles(Path dir) throws IOException {
        if (!Files.isDirectory(dir)) {
            return List.of();
        }
        try (Stream<Path> s = Files.walk(dir)) {
            return s.filter(p -> ModelImporter.isModelFile(p.getFileName().toString()))
                    .sorted().collect(Collectors.toList());
        }
    }

    private ObjectNode toJson(List<ParseTimer.Result> results, String assimpVersion) {
        ObjectMapper mapper = new ObjectMapper();
        ObjectNode root = mapper.createObjectNode();
        root.put("benchmark", "parse");
        root.put("java", JavaRuntime.version());
        root.put("cores", Runtime.getRuntime().availableProcessors());
        if (assimpVersion != null) {
            root.put("assimpVersion", assimpVersion);
            root.put("assimpFlags", AssimpBaseline.describe(assimpFlags));
        }
        ArrayNode list = root.putArray("files");
        for (ParseTimer.Result r : results) {
            ObjectNode f = list.addObject();
            f.put("file", r.name);
            f.put("bytes", r.bytes);
            f.put("triangles", r.triangles);
            f.put("runs", r.millis.length);
            f.put("minMillis", round(r.min()));
            f.put("medianMillis", round(r.median()));
            f.put("mbPerSecond", round(r.mbPerSecond()));
            if (assimpVersion != null) {
                // Present for every file when compared; null times (and assimpError) where assimp failed.
                f.put("assimpTriangles", r.assimpError == null ? r.assimpTriangles : null);
                if (r.assimpMillis != null) {
                    f.put("assimpMinMillis", round(r.assimpMin()));
                    f.put("assimpMedianMillis", round(r.assimpRuns.median()));
                    f.put("assimpRatio", round(r.assimpRatio()));
                } else {
                    f.putNull("assimpMinMillis");
                    f.putNull("assimpMedianMillis");
                    f.putNull("assimpRatio");
                    f.put("assimpError", r.assimpError);
                }
            }
        }
        ParseTimer.Result[] t = twins(results);
        if (t != null) {
            ObjectNode same = root.putObject("sameCharacter");
            same.put("gltf", t[0].name);
            same.put("collada", t[1].name);
            same.put("colladaOverGltf", round(t[1].median() / t[0].median()));
        }
        return root;
    }

    private static double round(double d) {
        return Math.round(d * 1000.0) / 1000.0;
    }

    private static String table(List<ParseTimer.Result> results, boolean withAssimp) {
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "%-40s %9s %10s %9s %9s %8s", "file", "MB", "triangles", "min ms",
                "median ms", "MB/s"));
        sb.append(withAssimp ? String.format(Locale.ROOT, " %10s %12s%n", "assimp ms", "assimp/ours") : System.lineSeparator());
        long bytes = 0;
        double millis = 0;
        for (ParseTimer.Result r : results) {
            sb.append(String.format(Locale.ROOT, "%-40s %9.3f %10d %9.2f %9.2f %8.1f", r.name, r.bytes / 1e6,
                    r.triangles, r.min(), r.median(), r.mbPerSecond()));
            if (!withAssimp) {
                sb.append(System.lineSeparator());
            } else if (r.assimpMillis != null) {
                sb.append(String.format(Locale.ROOT, " %10.2f %12.2f%n", r.assimpRuns.median(),
                        r.assimpRatio()));
            } else {
                sb.append(String.format(Locale.ROOT, " %10s%n", "failed"));
            }
            bytes += r.bytes;
            millis += r.median();
        }
        sb.append(String.format(Locale.ROOT, "%-40s %9.3f %10s %9s %9.2f %8.1f%n", "all files (sum of medians)",
                bytes / 1e6, "", "", millis, bytes / 1e6 / (millis / 1000.0)));
        return sb.toString();
    }
}
