package org.skinlab.desktop.bench;

import static org.lwjgl.glfw.GLFW.glfwPollEvents;
import static org.lwjgl.glfw.GLFW.glfwSwapInterval;
import static org.lwjgl.opengl.GL33C.*;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

import org.skinlab.internal.bench.FrameTimes;
import org.skinlab.internal.bench.Rounds;
import org.skinlab.internal.bench.Spread;
import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.desktop.render.ModelRenderer;
import org.skinlab.desktop.render.SkinningShader;
import org.skinlab.desktop.viewer.OrbitCamera;
import org.skinlab.model.Model;
import org.skinlab.scene.ModelFraming;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.SkinningMethod;

/**
 * Frames per second against animated copies, the measuring loop of {@code skinlab bench-render}
 * (and of {@code skinlab eval}'s crowds section): a grid of copies of a model, each its own
 * simulation stepped every frame on the render thread (so CPU skinning skins every copy, as the
 * thesis' meshes were) and drawn with its own palette, in an off-screen window without vsync.
 * A run of a {@link Scene} is frames of warm-up (at least {@value #MIN_WARMUP_FRAMES}), then
 * frames for a given time (at least {@value #MIN_FRAMES}), timed between two {@code glFinish}es
 * (so the time is the frames' mean, with the renderer's queue drained), with the bytes the render
 * thread allocated per timed frame. {@link #measure(Model, List, int, FrameTimes.Protocol, Runnable)} runs several
 * scenes in interleaved rounds.
 */
public final class RenderBench implements AutoCloseable {
    /** Words of GL_RENDERER that name a rasteriser running on the CPU. */
    private static final List<String> SOFTWARE = List.of("llvmpipe", "softpipe", "swrast", "swiftshader",
            "lavapipe", "software rasterizer", "software renderer");
    /** Fewest frames of a run's warm-up (the first uploads and a drained queue). */
    public static final int MIN_WARMUP_FRAMES = 2;
    /** Fewest timed frames of a run. */
    public static final int MIN_FRAMES = 5;
    /** The warm-up of a single {@link #measure(Model, boolean, SkinningMethod, int, double)}. */
    private static final double WARMUP_SECONDS = 0.1;

    /** One run's frames: skinning "cpu" or "gpu" (the vertex shader), method, copies, and the time per frame. */
    public record Point(String skinning, String method, int instances, double fps, double msPerFrame,
            double bytesPerFrame) {
    }

    /**
     * A series of the figure: copies skinned by core's CPU kernels ({@code shader} false) or by the
     * vertex shader (true; on the GPU, or on the CPU where the renderer is a software rasteriser),
     * with {@code method}.
     */
    public record Series(boolean shader, SkinningMethod method) {
    }

    /**
     * A series at some copies over several runs: each run's time per frame in ms ({@code msPerFrame},
     * in run order), the frames timed in all runs, and the bytes the render thread allocated per timed frame.
     */
    public record Timing(Series series, int instances, Spread msPerFrame, int frames, double bytesPerFrame) {
    }

    private final GlWindow window;
    private final SkinningShader shader;
    private final int width;
    private final int height;
    private final String renderer;
    private final String version;

    private RenderBench(GlWindow window, int width, int height) {
        this.window = window;
        this.width = width;
        this.height = height;
        glfwSwapInterval(0);
        this.shader = new SkinningShader();
        this.renderer = glGetString(GL_RENDERER);
        this.version = glGetString(GL_VERSION);
    }

    /** An off-screen window of {@code width} x {@code height} with its context current. */
    public static RenderBench open(int width, int height) throws GlWindow.WindowUnavailableException {
        GlWindow window = new GlWindow("skinlab bench-render", width, height, false, false);
        try {
            return new RenderBench(window, width, height);
        } catch (RuntimeException | Error e) {
            window.close();
            throw e;
        }
    }

    /** Instance counts: the thesis' 1, 4, 8, 12, 16, then on in steps of 8, 16, 32 ... */
    public static List<Integer> steps(int max) {
        List<Integer> n = new ArrayList<>();
        n.add(1);
        for (int i = 4; i <= Math.min(16, max); i += 4) {
            n.add(i);
        }
        int step = 8;
        for (int i = 24; i <= max; i += step) {
            n.add(i);
            if (i >= 8 * step) {
                step *= 2;
            }
        }
        return n;
    }

    /** Whether a GL_RENDERER string names a software rasteriser (Mesa's llvmpipe, SwiftShader ...). */
    public static boolean isSoftware(String renderer) {
        String r = renderer.toLowerCase(Locale.ROOT);
        return SOFTWARE.stream().anyMatch(r::contains);
    }

    /** GL_RENDERER. */
    public String renderer() {
        return renderer;
    }

    /** GL_VERSION. */
    public String version() {
        return version;
    }

    /**
     * Renders one copy with CPU skinning for {@code seconds} per method, discarded: the JIT
     * compiles the kernels (the Vector API allocates until it has).
     */
    public void warmUp(Model model, double seconds) {
        for (SkinningMethod method : CrowdBench.METHODS) {
            measure(model, false, method, 1, seconds);
        }
    }

    /**
     * {@code instances} copies, CPU or GPU skinning, one method: one run, frames for {@code seconds}
     * after a warm-up of {@value #WARMUP_SECONDS} s.
     */
    public Point measure(Model model, boolean gpu, SkinningMethod method, int instances, double seconds) {
        try (Scene scene = scene(model, new Series(gpu, method), instances)) {
            Scene.Run run = scene.run(WARMUP_SECONDS, seconds);
            return new Point(gpu ? "gpu" : "cpu", method.key(), instances, 1000 / run.msPerFrame(), run.msPerFrame(),
                    (double) run.bytes() / run.frames());
        }
    }

    /**
     * Each series at {@code instances} copies in {@code protocol.rounds()} runs, interleaved
     * ({@link Rounds}: each round runs every series once, each round starting one further along),
     * so that the machine's drift falls on every series alike. The scenes are built once and kept
     * between their runs (their simulations play on); a run warms up for the protocol's warm-up
     * (the first round's for round 0) and times frames for {@code protocol.seconds()}.
     * {@code afterRun} runs after each run (progress). Results in the order of {@code series}.
     */
    public List<Timing> measure(Model model, List<Series> series, int instances, FrameTimes.Protocol protocol,
            Runnable afterRun) {
        int n = series.size();
        List<Scene> scenes = new ArrayList<>(n);
        try {
            for (Series s : series) {
                scenes.add(scene(model, s, instances));
            }
            int[] frames = new int[n];
            long[] bytes = new long[n];
            Spread[] spreads = Rounds.interleaved(n, protocol.rounds(), (i, round) -> {
                Scene.Run run = scenes.get(i).run(round == 0 ? protocol.firstWarmupSeconds()
                        : protocol.warmupSeconds(), protocol.seconds());
                frames[i] += run.frames();
                bytes[i] += run.bytes();
                afterRun.run();
                return run.msPerFrame();
            });
            List<Timing> timings = new ArrayList<>(n);
            for (int i = 0; i < n; i++) {
                timings.add(new Timing(series.get(i), instances, spreads[i], frames[i], bytes[i] / (double) frames[i]));
            }
            return timings;
        } finally {
            scenes.forEach(Scene::close);
        }
    }

    /** A grid of {@code instances} copies of {@code model}, drawn as {@code series} says. */
    Scene scene(Model model, Series series, int instances) {
        return new Scene(model, series, instances);
    }

    /**
     * A grid of copies, each its own simulation, and the renderer that draws them: built once, run
     * as often as a measurement needs; its simulations play on from run to run.
     */
    final class Scene implements AutoCloseable {
        /** One run's frames: how many, their mean time in ms, the bytes the render thread allocated. */
        record Run(int frames, double msPerFrame, long bytes) {
        }

        private final List<SkeletalAnimatedMesh> meshes = new ArrayList<>();
        private final DrawSettings draw = new DrawSettings();
        private final ModelRenderer renderer;

        private Scene(Model model, Series series, int instances) {
            AnimationConfig config = new AnimationConfig();
            config.setMethod(series.method());
            config.setCpuSkinning(!series.shader());
            try {
                for (int i = 0; i < instances; i++) {
                    SkeletalAnimatedMesh m = new SkeletalAnimatedMesh(model, model.clips().isEmpty() ? null
                            : model.clips().get(0), config);
                    // Copies out of step, as a crowd would be.
                    m.seek(0.37 * i);
                    meshes.add(m);
                }
                meshes.get(0).step(0);
                ModelFraming framing;
                try (Frame f = meshes.get(0).acquire()) {
                    framing = ModelFraming.of(model.asset(), meshes.get(0).geometries(), f);
                }
                draw.gpuSkinning = series.shader();
                draw.method = series.method();
                draw.instances = 1;
                draw.gridColumns = DrawSettings.squareColumns(instances);
                draw.spacing = framing.gridSpacing();
                draw.model.set(framing.upright());
                OrbitCamera camera = new OrbitCamera();
                camera.frame(framing, instances, draw.gridColumns);
                camera.projection(width / (float) height, draw.viewProjection);
                camera.viewTimesInto(draw.viewProjection);
                camera.eye(draw.eye);
                renderer = new ModelRenderer(shader, model, meshes.get(0).geometries(), img -> 0);
            } catch (RuntimeException | Error e) {
                meshes.forEach(SkeletalAnimatedMesh::close);
                throw e;
            }
        }

        /**
         * Frames for {@code warmupSeconds} (at least {@value #MIN_WARMUP_FRAMES}), then timed frames
         * for {@code seconds} (at least {@value #MIN_FRAMES}).
         */
        Run run(double warmupSeconds, double seconds) {
            com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory
                    .getThreadMXBean();
            long thread = Thread.currentThread().getId();
            glViewport(0, 0, width, height);
            glEnable(GL_DEPTH_TEST);
            long warmupEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
            for (int f = 0; f < MIN_WARMUP_FRAMES || System.nanoTime() < warmupEnd; f++) {
                frame();
            }
            glFinish();
            long start = System.nanoTime();
            long bytesAtStart = threads.getThreadAllocatedBytes(thread);
            int frames = 0;
            long end = start + (long) (seconds * 1e9);
            while (frames < MIN_FRAMES || System.nanoTime() < end) {
                frame();
                frames++;
            }
            glFinish();
            long elapsed = System.nanoTime() - start;
            long bytes = threads.getThreadAllocatedBytes(thread) - bytesAtStart;
            return new Run(frames, elapsed / 1e6 / frames, bytes);
        }

        /** Steps every copy by a 60 Hz frame and draws it. */
        private void frame() {
            glClearColor(0.17f, 0.18f, 0.21f, 1f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            for (int i = 0; i < meshes.size(); i++) {
                SkeletalAnimatedMesh m = meshes.get(i);
                m.step(1.0 / 60);
                try (Frame f = m.acquire()) {
                    renderer.upload(f);
                    draw.firstInstance = i;
                    renderer.draw(draw);
                }
            }
            window.swapBuffers();
            glfwPollEvents();
        }

        @Override
        public void close() {
            try {
                renderer.close();
            } finally {
                meshes.forEach(SkeletalAnimatedMesh::close);
            }
        }
    }

    @Override
    public void close() {
        try {
            shader.close();
        } finally {
            window.close();
        }
    }
}
