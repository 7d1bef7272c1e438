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

import org.skinlab.internal.bench.Rounds;
import org.skinlab.internal.bench.Spread;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.ImportException;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;

/**
 * The import timing of {@code skinlab bench parse} and {@code skinlab eval}'s load section: files
 * already in memory, a shared warm-up over the small ones, then per file {@code rounds} runs of
 * {@code importsPerRound} imports each (a file of 10 MB or more: {@value #LARGE_IMPORTS} imports
 * in all, spread over the rounds, each after a GC, after one untimed import). When compared,
 * assimp imports the same bytes with the same protocol after a warm-up of the same length, its
 * runs interleaved with ours ({@link Rounds#interleaved}: ours first in one round, assimp first in
 * the next), so that a drift of the machine falls on both. A run's value is the median of its
 * imports; every import's time is kept too (the slowest import is what a requirement judges).
 */
public final class ParseTimer {
    static final int LARGE_BYTES = 10_000_000;
    /** Timed imports of a file of {@link #LARGE_BYTES} or more, in all rounds together. */
    static final int LARGE_IMPORTS = 5;

    /** One file to time: its name in reports, its bytes and where it lives (for relative URLs). */
    public record Input(String name, byte[] bytes, Path location) {
    }

    /** One file's measurement. */
    public static final class Result {
        public final String name;
        public final long bytes;
        public final long triangles;
        /** Every timed import of ours, in the order taken (empty when refused). */
        public final double[] millis;
        /** Each run's median import, in run order (null when refused). */
        public final Spread runs;
        /** Why our importer refused the file (tolerant timing only), else null; then millis is empty. */
        public String error;
        /** assimp's imports, or null when not compared or when assimp failed. */
        public double[] assimpMillis;
        /** assimp's runs, interleaved with ours, or null as {@link #assimpMillis}. */
        public Spread assimpRuns;
        public long assimpTriangles;
        /** assimp's message when it refused the file, else null. */
        public String assimpError;

        Result(String name, long bytes, long triangles, double[] millis, Spread runs) {
            this.name = name;
            this.bytes = bytes;
            this.triangles = triangles;
            this.millis = millis;
            this.runs = runs;
        }

        /** The fastest import. */
        public double min() {
            return Arrays.stream(millis).min().orElse(Double.NaN);
        }

        /** The median of the runs (with one run, the median import). */
        public double median() {
            return runs == null ? Double.NaN : runs.median();
        }

        /** The slowest import. */
        public double max() {
            return Arrays.stream(millis).max().orElse(Double.NaN);
        }

        /** assimp's fastest import. */
        public double assimpMin() {
            return Arrays.stream(assimpMillis).min().orElse(Double.NaN);
        }

        /** assimp median / our median (of the runs): how many times faster we are. */
        public double assimpRatio() {
            return assimpRuns.median() / median();
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
    private final int rounds;
    private final int importsPerRound;
    /** assimp's flags, or -1 not to compare. */
    private final int assimpFlags;
    /** Whether a file our importer refuses is a result (with its error) rather than a failure. */
    private final boolean tolerant;
    /** Where each file's line goes (null: nowhere), and what starts the line. */
    private final PrintWriter log;
    private final String logPrefix;
    private IntConsumer progress = i -> { };

    /**
     * @param rounds          runs per file (and per tool), interleaved
     * @param importsPerRound timed imports per run of a file under 10 MB
     */
    public ParseTimer(double warmupSeconds, int rounds, int importsPerRound, int assimpFlags, boolean tolerant,
            PrintWriter log, String logPrefix) {
        if (rounds < 1 || importsPerRound < 1) {
            throw new IllegalArgumentException("need a run and an import: " + rounds + " x " + importsPerRound);
        }
        this.warmupSeconds = warmupSeconds;
        this.rounds = rounds;
        this.importsPerRound = importsPerRound;
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
                Result r = refused[i] ? refusedResult(inputs.get(i), errors[i])
                        : measureOne(inputs.get(i), assimp.isEmpty() ? null : assimp.get(i));
                results.add(r);
                log(r);
                progress.accept(i + 1);
            }
            return results;
        } finally {
            for (AssimpFile a : assimp) {
                a.assimp.close();
            }
        }
    }

    private void log(Result r) {
        if (log == null) {
            return;
        }
        if (r.assimpRuns != null) {
            log.printf(Locale.ROOT, logPrefix + "%s %.2f ms, assimp %.2f ms (%.1fx)%n", r.name, r.median(),
                    r.assimpRuns.median(), r.median() > 0 ? r.assimpRatio() : Double.NaN);
        } else if (r.assimpError != null) {
            log.printf(Locale.ROOT, logPrefix + "%s %.2f ms, assimp failed: %s%n", r.name, r.median(), r.assimpError);
        } else {
            log.printf(Locale.ROOT, logPrefix + "%s %.2f ms%n", r.name, r.median());
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
        Result r = new Result(in.name(), in.bytes().length, 0, new double[0], null);
        r.error = error;
        return r;
    }

    /**
     * Our runs of one file and, when {@code assimp} is given and imports it, assimp's, interleaved
     * round by round.
     */
    private Result measureOne(Input in, AssimpFile assimp) {
        boolean large = in.bytes().length >= LARGE_BYTES;
        int perRound = large ? Math.max(1, LARGE_IMPORTS / rounds) : importsPerRound;
        boolean compared = assimp != null && assimp.failure == null;
        Model[] model = new Model[1];
        if (large) {
            System.gc();
            model[0] = importOnce(in);
            if (compared) {
                System.gc();
                assimp.assimp.importOnce(assimpFlags);
            }
        }
        double[][] millis = new double[2][rounds * perRound];
        Spread[] runs = Rounds.interleaved(compared ? 2 : 1, rounds, (tool, round) -> {
            double[] times = new double[perRound];
            for (int k = 0; k < perRound; k++) {
                if (large) {
                    System.gc();
                }
                long t0 = System.nanoTime();
                if (tool == 0) {
                    model[0] = importOnce(in);
                } else {
                    assimp.assimp.importOnce(assimpFlags);
                }
                times[k] = (System.nanoTime() - t0) / 1e6;
            }
            System.arraycopy(times, 0, millis[tool], round * perRound, perRound);
            return Spread.of(times).median();
        });
        long triangles = model[0].meshes().stream().mapToLong(Mesh::triangleCount).sum();
        Result r = new Result(in.name(), in.bytes().length, triangles, millis[0], runs[0]);
        if (assimp != null) {
            if (compared) {
                r.assimpTriangles = assimp.triangles;
                r.assimpMillis = millis[1];
                r.assimpRuns = runs[1];
            } else {
                r.assimpError = assimp.failure;
            }
        }
        return r;
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
