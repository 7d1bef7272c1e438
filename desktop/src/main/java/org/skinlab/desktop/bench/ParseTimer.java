package org.skinlab.desktop.bench;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.function.IntConsumer;

import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.bench.AssimpBaseline;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.ImportException;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;

/**
 * The import timing of {@code skinlab bench parse} and {@code skinlab eval}'s load section: files
 * already in memory, a shared warm-up over the small ones, then each file imported {@code runs}
 * times (5 when 10 MB or more, each after a GC, after one untimed import) and, when compared,
 * assimp on the same bytes right after ours with the same protocol and a warm-up of the same
 * length.
 */
public final class ParseTimer {
    static final int LARGE_BYTES = 10_000_000;

    /** One file to time: its name in reports, its bytes and where it lives (for relative URLs). */
    public record Input(String name, byte[] bytes, Path location) {
    }

    /** One file's measurement. */
    public static final class Result {
        public final String name;
        public final long bytes;
        public final long triangles;
        public final double[] millis;
        /** Why our importer refused the file (tolerant timing only), else null; then millis is empty. */
        public String error;
        /** assimp's times, or null when not compared or when assimp failed. */
        public double[] assimpMillis;
        public long assimpTriangles;
        /** assimp's message when it refused the file, else null. */
        public String assimpError;

        Result(String name, long bytes, long triangles, double[] millis) {
            this.name = name;
            this.bytes = bytes;
            this.triangles = triangles;
            this.millis = millis;
        }

        public double min() {
            return min(millis);
        }

        public double median() {
            return median(millis);
        }

        public double max() {
            return Arrays.stream(millis).max().orElse(Double.NaN);
        }

        public static double min(double[] millis) {
            return Arrays.stream(millis).min().orElse(Double.NaN);
        }

        public static double median(double[] millis) {
            if (millis.length == 0) {
                return Double.NaN;
            }
            double[] s = millis.clone();
            Arrays.sort(s);
            int n = s.length;
            return n % 2 == 1 ? s[n / 2] : (s[n / 2 - 1] + s[n / 2]) / 2;
        }

        /** assimp median / our median: how many times faster we are. */
        public double assimpRatio() {
            return median(assimpMillis) / median();
        }

        public double mbPerSecond() {
            return bytes / 1e6 / (median() / 1000.0);
        }
    }

    /** One file for assimp: its bytes in native memory and what the untimed first import gave. */
    private static final class AssimpFile {
        final AssimpBaseline assimp;
        long triangles;
        String failure;

        AssimpFile(byte[] bytes, String name) {
            assimp = new AssimpBaseline(bytes, name);
        }
    }

    private final double warmupSeconds;
    private final int runs;
    /** assimp's flags, or -1 not to compare. */
    private final int assimpFlags;
    /** Whether a file our importer refuses is a result (with its error) rather than a failure. */
    private final boolean tolerant;
    /** Where each file's line goes (null: nowhere), and what starts the line. */
    private final PrintWriter log;
    private final String logPrefix;
    private IntConsumer progress = i -> { };

    public ParseTimer(double warmupSeconds, int runs, int assimpFlags, boolean tolerant, PrintWriter log, String logPrefix) {
        this.warmupSeconds = warmupSeconds;
        this.runs = runs;
        this.assimpFlags = assimpFlags;
        this.tolerant = tolerant;
        this.log = log;
        this.logPrefix = logPrefix;
    }

    /** Called with the number of files measured so far, after each file. */
    public ParseTimer onProgress(IntConsumer progress) {
        this.progress = progress;
        return this;
    }

    public List<Result> measure(List<Input> inputs) {
        boolean[] refused = new boolean[inputs.size()];
        String[] errors = new String[inputs.size()];
        for (int i = 0; i < inputs.size() && tolerant; i++) {
            errors[i] = tryImport(inputs.get(i));
            refused[i] = errors[i] != null;
        }
        long warmupEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
        do {
            for (int i = 0; i < inputs.size(); i++) {
                if (!refused[i] && inputs.get(i).bytes().length < LARGE_BYTES) {
                    importOnce(inputs.get(i));
                }
            }
        } while (System.nanoTime() < warmupEnd);
        List<AssimpFile> assimp = new ArrayList<>();
        try {
            if (assimpFlags >= 0) {
                for (Input in : inputs) {
                    assimp.add(new AssimpFile(in.bytes(), in.name()));
                }
                assimpWarmup(assimp);
            }
            List<Result> results = new ArrayList<>();
            for (int i = 0; i < inputs.size(); i++) {
                Result r = refused[i] ? refusedResult(inputs.get(i), errors[i]) : measureOne(inputs.get(i));
                results.add(r);
                if (!assimp.isEmpty()) {
                    measureAssimp(assimp.get(i), inputs.get(i).bytes().length >= LARGE_BYTES,
                            Math.max(1, r.millis.length), r);
                } else if (log != null) {
                    log.printf(Locale.ROOT, logPrefix + "%s %.2f ms%n", r.name, r.median());
                }
                progress.accept(i + 1);
            }
            return results;
        } finally {
            for (AssimpFile a : assimp) {
                a.assimp.close();
            }
        }
    }

    /** Null when the file imports, else why not (an exception other than a refusal is a bug: said so). */
    private static String tryImport(Input in) {
        try {
            importOnce(in);
            return null;
        } catch (CommandFailure e) {
            return e.getMessage();
        } catch (RuntimeException e) {
            return "internal error: " + e;
        }
    }

    private static Result refusedResult(Input in, String error) {
        Result r = new Result(in.name(), in.bytes().length, 0, new double[0]);
        r.error = error;
        return r;
    }

    private Result measureOne(Input in) {
        boolean large = in.bytes().length >= LARGE_BYTES;
        if (large) {
            System.gc();
            importOnce(in);
        }
        int n = large ? 5 : runs;
        double[] millis = new double[n];
        Model model = null;
        for (int r = 0; r < n; r++) {
            if (large) {
                System.gc();
            }
            long t0 = System.nanoTime();
            model = importOnce(in);
            millis[r] = (System.nanoTime() - t0) / 1e6;
        }
        long triangles = model.meshes().stream().mapToLong(Mesh::triangleCount).sum();
        return new Result(in.name(), in.bytes().length, triangles, millis);
    }

    /**
     * Imports each file once with assimp (counting triangles, noting the files it refuses), then
     * warms assimp up as ours: the same seconds over the small files it accepts.
     */
    private void assimpWarmup(List<AssimpFile> files) {
        for (AssimpFile f : files) {
            try {
                f.triangles = f.assimp.triangles(assimpFlags);
            } catch (IllegalArgumentException e) {
                f.failure = e.getMessage();
            }
        }
        long warmupEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
        do {
            for (AssimpFile f : files) {
                if (f.assimp.size() < LARGE_BYTES && f.failure == null) {
                    f.assimp.importOnce(assimpFlags);
                }
            }
        } while (System.nanoTime() < warmupEnd);
    }

    /** assimp on one file: the same protocol as ours (one untimed import first when large). */
    private void measureAssimp(AssimpFile f, boolean large, int n, Result result) {
        if (f.failure != null) {
            result.assimpError = f.failure;
            if (log != null) {
                log.printf(Locale.ROOT, logPrefix + "%s %.2f ms, assimp failed: %s%n", result.name, result.median(),
                        result.assimpError);
            }
            return;
        }
        result.assimpTriangles = f.triangles;
        if (large) {
            System.gc();
            f.assimp.importOnce(assimpFlags);
        }
        double[] millis = new double[n];
        for (int r = 0; r < n; r++) {
            if (large) {
                System.gc();
            }
            long t0 = System.nanoTime();
            f.assimp.importOnce(assimpFlags);
            millis[r] = (System.nanoTime() - t0) / 1e6;
        }
        result.assimpMillis = millis;
        if (log != null) {
            log.printf(Locale.ROOT, logPrefix + "%s %.2f ms, assimp %.2f ms (%.1fx)%n", result.name, result.median(),
                    Result.median(millis), result.median() > 0 ? result.assimpRatio() : Double.NaN);
        }
    }

    private static Model importOnce(Input in) {
        try {
            return ModelImporter.read(new ByteArrayInputStream(in.bytes()), in.name(), in.location());
        } catch (ImportException e) {
            throw new CommandFailure(ExitCodes.INVALID_FILE, e.getMessage(), e);
        } catch (IOException e) {
            throw new CommandFailure(ExitCodes.INVALID_FILE, in.name() + ": " + e.getMessage(), e);
        }
    }
}
