package org.skinlab.android.logic;

import java.io.File;
import java.io.FileOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.time.Instant;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CancellationException;
import java.util.function.Supplier;

import org.skinlab.internal.bench.DeviceResults;
import org.skinlab.internal.bench.DeviceResultsJson;
import org.skinlab.internal.bench.FrameBench;
import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.internal.bench.Rounds;
import org.skinlab.internal.bench.Spread;
import org.skinlab.internal.bench.Warmup;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.PositionSharing;
import org.skinlab.skinning.SkinningMethod;

/**
 * The app's "Measure", on its own thread ({@value #THREAD}): the evaluation's time per frame of
 * every model with every method on the CPU (core's {@link FrameBench} with the scalar kernels, the
 * ones Android's runtime runs, and {@link FrameTimes}' interleaved rounds: what
 * {@code skinlab eval}'s time section measures), then frames per second with 1, 4, 8 and 12 copies
 * of the first model drawn by the GPU ({@link DrawnCopies}, in interleaved {@link Rounds}), then
 * {@value DeviceResultsJson#FILE_NAME} in the output folder ({@link DeviceResultsJson}).
 *
 * <p>{@link #status()} says what it does and how long is left, then where the file went, or why
 * it stopped; {@link #cancel()} stops it from any thread without waiting: a CPU run in progress
 * ends first (at most a warm-up and a run's seconds), a GPU point at once. A model that does not
 * load is skipped and named in the file; nothing it does ends the app.
 */
public final class DeviceMeasurement {
    /** The measuring thread's name. */
    public static final String THREAD = "measure";

    private final ModelLoader.Source source;
    private final List<String> models;
    private final MeasureProtocol protocol;
    private final DrawnCopies drawing;
    private final DeviceResults.App app;
    private final Supplier<DeviceResults.Device> device;
    private final File folder;
    private final Thread thread;
    private final Warmup warmup;
    /** How the status line names it: "measure", or with a protocol other than the full one, e.g. "measure (quick)". */
    private final String prefix;
    private volatile boolean cancelled;
    /**
     * Set once the run has ended, just before its outcome is published in {@link #status}: a
     * reader that sees the outcome sees the measurement ended ({@link #running()} false), so a
     * status line never says "stopped" beside a button that still says "Stop measuring".
     */
    private volatile boolean finished;
    private volatile String status;
    private volatile File written;
    /** Measuring thread only: planned seconds of the runs and points started so far, and of all of them. */
    private double plannedDone;
    private double plannedTotal;
    /** Measuring thread only: the model being timed, the runs started on it and their planned seconds. */
    private String timing = "";
    private int runsStarted;
    private int firstRuns;
    private double firstRunSeconds;
    private double laterRunSeconds;
    private long startNanos;

    /**
     * A measurement of {@code models} (read from {@code source}; the first also drawn) by
     * {@code protocol}, the GPU part through {@code drawing}, into {@code folder}; {@code device}
     * is asked for the device's facts on the measuring thread.
     */
    public DeviceMeasurement(ModelLoader.Source source, List<String> models, MeasureProtocol protocol,
            DrawnCopies drawing, DeviceResults.App app, Supplier<DeviceResults.Device> device, File folder) {
        this.source = source;
        this.models = List.copyOf(models);
        this.protocol = protocol;
        this.drawing = drawing;
        this.app = app;
        this.device = device;
        this.folder = folder;
        this.thread = new Thread(this::run, THREAD);
        this.prefix = protocol.equals(MeasureProtocol.FULL) ? "measure" : "measure (" + protocol.name() + ")";
        this.status = prefix + ": starting";
        // FrameBench's warm-up is the platform's: on Android a fixed time (ART says nothing about its
        // compiler). Each run starts with one, so a cancelled measurement stops at the next run.
        this.warmup = (step, minSeconds) -> {
            startRun();
            return Warmup.FOR_TIME.run(step, minSeconds);
        };
    }

    /** Starts measuring on its own thread. */
    public void start() {
        thread.start();
    }

    /** Stops measuring (any thread; returns at once): the thread ends after the run in progress. */
    public void cancel() {
        cancelled = true;
        thread.interrupt();
    }

    /**
     * Whether the measurement is under way: started and its outcome not yet published.
     *
     * @return true from {@link #start()} until {@link #status()} says how it ended
     */
    public boolean running() {
        return thread.isAlive() && !finished;
    }

    /** What it is doing, or where the file went, or why it stopped: one line for the status line. */
    public String status() {
        return status;
    }

    /** The file written, or null until it is. */
    public File written() {
        return written;
    }

    private void run() {
        String outcome;
        startNanos = System.nanoTime();
        String started = Instant.now().toString();
        drawing.begin();
        try {
            DeviceResults.Device d = device.get();
            List<SkinningMethod> methods = Arrays.asList(SkinningMethod.values());
            plannedTotal = protocol.cpuSeconds(models.size(), methods.size()) + protocol.drawnSeconds(d.refreshHz());
            List<DeviceResults.ModelTimes> times = new ArrayList<>();
            List<DeviceResults.Skipped> skipped = new ArrayList<>();
            Model first = null;
            String firstName = null;
            for (String name : models) {
                Model model = load(name, skipped);
                if (model == null) {
                    plannedDone += protocol.cpuSeconds(1, methods.size());
                    continue;
                }
                times.add(cpu(name, model, methods));
                if (first == null) {
                    first = model;
                    firstName = name;
                }
            }
            DeviceResults.Drawn drawn = first == null ? DeviceResults.Drawn.unavailable("no model loaded")
                    : drawn(firstName, first, d.refreshHz());
            DeviceResults results = new DeviceResults(app, started, (System.nanoTime() - startNanos) / 1e9, d,
                    drawing.gpu(), new DeviceResults.Protocol(protocol.name(), protocol.times()), times, skipped, drawn);
            File file = write(results);
            written = file;
            outcome = prefix + ": wrote " + file.getPath() + " (" + seconds() + ")" + (drawn.measured() ? ""
                    : "; the GPU part was not measured: " + drawn.unavailable());
        } catch (CancellationException e) {
            outcome = prefix + ": stopped";
        } catch (Throwable e) { // errors too: a measurement must never end the app
            outcome = prefix + ": failed: " + (e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName());
        } finally {
            drawing.end();
        }
        finished = true;
        status = outcome;
    }

    /** The model in {@code name}, or null (and why, in {@code skipped}) when it does not load or has no skin. */
    private Model load(String name, List<DeviceResults.Skipped> skipped) {
        status = prefix + ": loading " + name;
        try (InputStream in = source.open(name)) {
            Model m = ModelImporter.read(in, name, null);
            if (m.instances().stream().noneMatch(MeshInstance::isSkinned)) {
                skipped.add(new DeviceResults.Skipped(name, "no skinned mesh: nothing to time"));
                return null;
            }
            return m;
        } catch (Exception | OutOfMemoryError e) {
            String message = e.getMessage() != null ? e.getMessage() : e.getClass().getSimpleName();
            skipped.add(new DeviceResults.Skipped(name, message.contains(name) ? message : name + ": " + message));
            return null;
        }
    }

    /** Every method's frame time on {@code model}, the evaluation's protocol with the scalar kernels. */
    private DeviceResults.ModelTimes cpu(String name, Model model, List<SkinningMethod> methods) {
        status = prefix + ": preparing " + name;
        FrameTimes.Protocol p = protocol.times();
        FrameBench bench = new FrameBench(model, NormalTransform.INVERSE_TRANSPOSE, PositionSharing.AUTO, true, 0,
                methods, warmup);
        timing = name;
        runsStarted = 0;
        // FrameTimes' first round warms each method up for longer (the compiler's work).
        firstRuns = methods.size();
        firstRunSeconds = p.firstWarmupSeconds() + p.seconds();
        laterRunSeconds = p.warmupSeconds() + p.seconds();
        return new DeviceResults.ModelTimes(name, bench.shape(), FrameTimes.measure(bench, methods, p));
    }

    /** Before each CPU run: stops when cancelled, counts the run's planned time, says what is left. */
    private void startRun() {
        if (cancelled) {
            throw new CancellationException();
        }
        plannedDone += runsStarted++ < firstRuns ? firstRunSeconds : laterRunSeconds;
        status = prefix + ": CPU, " + timing + ", " + left();
    }

    /**
     * Frames per second of 1, 4, 8 and 12 copies of {@code model} drawn with each of
     * {@link MeasureProtocol#DRAWN_METHODS}, in interleaved rounds; or why it could not be drawn.
     */
    private DeviceResults.Drawn drawn(String name, Model model, double refreshHz) {
        List<Integer> copies = MeasureProtocol.COPIES;
        List<SkinningMethod> methods = MeasureProtocol.DRAWN_METHODS;
        int points = copies.size() * methods.size();
        AnimationConfig config = new AnimationConfig(AnimationConfig.Settings.DEFAULT.withCpuSkinning(false));
        List<SkeletalAnimatedMesh> meshes = copies(model, copies.get(copies.size() - 1), config);
        int[] frames = new int[points];
        double pointSeconds = protocol.drawSeconds() + protocol.drawWarmupFrames() / refreshHz;
        Spread[] fps;
        try {
            fps = Rounds.interleaved(points, protocol.drawRounds(), (i, round) -> {
                int n = copies.get(i / methods.size());
                SkinningMethod method = methods.get(i % methods.size());
                if (cancelled) {
                    throw new CancellationException();
                }
                plannedDone += pointSeconds;
                status = String.format(Locale.ROOT, "measure: GPU, %d cop%s of %s, %s, %s", n, n == 1 ? "y" : "ies",
                        name, method.key().toUpperCase(Locale.ROOT), left());
                config.setMethod(method);
                try {
                    DrawnCopies.Run run = drawing.draw(meshes.subList(0, n), protocol.drawWarmupFrames(),
                            protocol.drawSeconds());
                    frames[i] += run.frames();
                    return run.fps();
                } catch (InterruptedException e) {
                    throw new CancellationException();
                } catch (DrawnCopies.Undrawable e) {
                    throw new UndrawableInRound(e);
                }
            });
        } catch (UndrawableInRound e) {
            return DeviceResults.Drawn.unavailable(e.getCause().getMessage());
        }
        List<DeviceResults.DrawnPoint> result = new ArrayList<>();
        for (int i = 0; i < points; i++) {
            result.add(new DeviceResults.DrawnPoint(copies.get(i / methods.size()), methods.get(i % methods.size()),
                    fps[i], frames[i]));
        }
        return new DeviceResults.Drawn(name, protocol.drawSeconds(), protocol.drawRounds(),
                protocol.drawWarmupFrames(), result, null);
    }

    /** {@link DrawnCopies.Undrawable} through {@link Rounds}' measurement, which throws nothing checked. */
    private static final class UndrawableInRound extends RuntimeException {
        private static final long serialVersionUID = 1L;

        UndrawableInRound(DrawnCopies.Undrawable cause) {
            super(cause);
        }
    }

    /**
     * {@code count} copies of {@code model} playing its first clip out of step (as a crowd would),
     * palette only: the GPU skins them. CoR's centres are computed here, not on the GL thread,
     * for the geometries the GL thread uploads (the first copy's). The copies are never started,
     * so they own no thread: they are dropped afterwards rather than closed, since the GL thread
     * may still be drawing a frame of a withdrawn request.
     */
    private static List<SkeletalAnimatedMesh> copies(Model model, int count, AnimationConfig config) {
        List<SkeletalAnimatedMesh> meshes = new ArrayList<>();
        for (int i = 0; i < count; i++) {
            SkeletalAnimatedMesh m = new SkeletalAnimatedMesh(model, model.clips().isEmpty() ? null
                    : model.clips().get(0), config);
            m.seek(0.37 * i);
            meshes.add(m);
        }
        return meshes;
    }

    /** The file in the folder, written whole before it replaces an earlier one. */
    private File write(DeviceResults results) throws IOException {
        if (!folder.isDirectory() && !folder.mkdirs()) {
            throw new IOException("cannot make the folder " + folder);
        }
        File file = new File(folder, DeviceResultsJson.FILE_NAME);
        File partial = new File(folder, DeviceResultsJson.FILE_NAME + ".partial");
        try (OutputStream out = new FileOutputStream(partial)) {
            DeviceResultsJson.write(results, out);
        }
        if (!partial.renameTo(file)) {
            throw new IOException("cannot write " + file);
        }
        return file;
    }

    /** About how long is left, from the planned time of what has not started. */
    private String left() {
        double seconds = Math.max(0, plannedTotal - plannedDone);
        return seconds < 90 ? String.format(Locale.ROOT, "about %.0f s left", Math.ceil(seconds))
                : String.format(Locale.ROOT, "about %.0f min left", Math.ceil(seconds / 60));
    }

    private String seconds() {
        double s = (System.nanoTime() - startNanos) / 1e9;
        return s < 90 ? String.format(Locale.ROOT, "in %.0f s", s) : String.format(Locale.ROOT, "in %.1f min", s / 60);
    }
}
