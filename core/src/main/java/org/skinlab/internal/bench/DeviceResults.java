package org.skinlab.internal.bench;

import java.util.List;

import org.skinlab.skinning.SkinningMethod;

/**
 * One device's measurement, what the Android app's "Measure" writes into
 * {@code results-android.json} ({@link DeviceResultsJson}) and {@code skinlab eval --add-device}
 * reads: the time per frame of each bundled model with each method on the CPU (core's scalar
 * kernels, {@link FrameTimes}' protocol, the evaluation's) and the frames per second the GPU drew
 * with 1, 4, 8 and 12 copies of a model. docs/evaluation.md, "The device file".
 *
 * @param app      the app that measured
 * @param started  when the measurement started (an ISO-8601 instant)
 * @param seconds  how long it took
 * @param device   the phone (or what the platform says it is)
 * @param gpu      the GL driver's strings, or why they are unknown
 * @param protocol how long each part of a CPU timing ran
 * @param models   per model file, its shape and each method's timing, in the order measured
 * @param skipped  the model files that could not be measured, with the reason (none in a sound APK)
 * @param drawn    the GPU part, or why it was not measured
 */
public record DeviceResults(App app, String started, double seconds, Device device, Gpu gpu, Protocol protocol,
        List<ModelTimes> models, List<Skipped> skipped, Drawn drawn) {

    public DeviceResults {
        models = List.copyOf(models);
        skipped = List.copyOf(skipped);
    }

    /** The app: its package, version name and version code. */
    public record App(String packageName, String versionName, long versionCode) {
    }

    /**
     * The device as the platform names it (Android's {@code Build}): maker, model, device (the
     * industrial design's name), the OS release and its API level, the ABIs it runs, the CPU and
     * the display's refresh rate in Hz (with vsync, the most frames a second it shows).
     */
    public record Device(String manufacturer, String model, String device, String release, int sdk, List<String> abis,
            Cpu cpu, double refreshHz) {
        public Device {
            abis = List.copyOf(abis);
        }
    }

    /**
     * The CPU: the cores the runtime may use, and its name with where the name came from
     * ({@code name} and {@code nameFrom} null when nothing named it).
     */
    public record Cpu(int cores, String name, String nameFrom) {
    }

    /**
     * The GL driver's {@code GL_RENDERER}, {@code GL_VENDOR} and {@code GL_VERSION}; or, with those
     * null, why they could not be read ({@code unavailable}).
     */
    public record Gpu(String renderer, String vendor, String version, String unavailable) {
        public static Gpu of(String renderer, String vendor, String version) {
            return new Gpu(renderer, vendor, version, null);
        }

        public static Gpu unavailable(String reason) {
            return new Gpu(null, null, null, reason);
        }

        public boolean known() {
            return unavailable == null;
        }
    }

    /** The CPU timings' protocol: its name ("full", "quick") and its rounds and seconds. */
    public record Protocol(String name, FrameTimes.Protocol times) {
    }

    /** One model file: what a frame of it skins, and each method's timing. */
    public record ModelTimes(String file, FrameBench.Shape shape, List<FrameTimes.Result> methods) {
        public ModelTimes {
            methods = List.copyOf(methods);
        }
    }

    /** A model file that could not be measured (it did not load), and why. */
    public record Skipped(String file, String reason) {
    }

    /**
     * The GPU part: copies of {@code file} drawn with GPU skinning, each point for {@code seconds}
     * in {@code rounds} interleaved rounds after {@code warmupFrames} frames; or, with
     * {@code points} empty, why it was not measured ({@code unavailable}).
     */
    public record Drawn(String file, double seconds, int rounds, int warmupFrames, List<DrawnPoint> points,
            String unavailable) {
        public Drawn {
            points = List.copyOf(points);
        }

        public static Drawn unavailable(String reason) {
            return new Drawn(null, 0, 0, 0, List.of(), reason);
        }

        public boolean measured() {
            return unavailable == null;
        }
    }

    /** Copies of the model drawn with a method: frames per second (each run's), frames drawn in all. */
    public record DrawnPoint(int copies, SkinningMethod method, Spread fps, int frames) {
    }
}
