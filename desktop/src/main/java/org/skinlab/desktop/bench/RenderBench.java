package org.skinlab.desktop.bench;

import static org.lwjgl.glfw.GLFW.glfwPollEvents;
import static org.lwjgl.glfw.GLFW.glfwSwapInterval;
import static org.lwjgl.opengl.GL33C.*;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

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
 * thesis' meshes were) and drawn with its own palette, in an off-screen window without vsync; 10
 * frames of warm-up, then frames for a given time (at least 5), and the bytes the render thread
 * allocated per timed frame.
 */
public final class RenderBench implements AutoCloseable {
    /** Words of GL_RENDERER that name a rasteriser running on the CPU. */
    private static final List<String> SOFTWARE = List.of("llvmpipe", "softpipe", "swrast", "swiftshader",
            "lavapipe", "software rasterizer", "software renderer");
    private static final int WARMUP_FRAMES = 10;

    public record Point(String skinning, String method, int instances, double fps, double msPerFrame,
            double bytesPerFrame) {
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

    /** {@code instances} copies, CPU or GPU skinning, one method: frames for {@code seconds} after the warm-up frames. */
    public Point measure(Model model, boolean gpu, SkinningMethod method, int instances, double seconds) {
        AnimationConfig config = new AnimationConfig();
        config.setMethod(method);
        config.setCpuSkinning(!gpu);
        List<SkeletalAnimatedMesh> meshes = new ArrayList<>();
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
            DrawSettings draw = new DrawSettings();
            draw.gpuSkinning = gpu;
            draw.method = method;
            draw.instances = 1;
            draw.gridColumns = DrawSettings.squareColumns(instances);
            draw.spacing = framing.gridSpacing();
            draw.model.set(framing.upright());
            OrbitCamera camera = new OrbitCamera();
            camera.frame(framing, instances, draw.gridColumns);
            camera.projection(width / (float) height, draw.viewProjection);
            camera.viewTimesInto(draw.viewProjection);
            camera.eye(draw.eye);
            glViewport(0, 0, width, height);
            glEnable(GL_DEPTH_TEST);
            try (ModelRenderer renderer = new ModelRenderer(shader, model, meshes.get(0).geometries(), img -> 0)) {
                return loop(meshes, renderer, draw, gpu, method, seconds);
            }
        } finally {
            meshes.forEach(SkeletalAnimatedMesh::close);
        }
    }

    private Point loop(List<SkeletalAnimatedMesh> meshes, ModelRenderer renderer, DrawSettings draw, boolean gpu,
            SkinningMethod method, double seconds) {
        com.sun.management.ThreadMXBean threads = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        long thread = Thread.currentThread().getId();
        int instances = meshes.size();
        long start = 0;
        long bytesAtStart = 0;
        int frames = 0;
        double dt = 1.0 / 60;
        for (int frame = 0;; frame++) {
            if (frame == WARMUP_FRAMES) {
                glFinish();
                start = System.nanoTime();
                bytesAtStart = threads.getThreadAllocatedBytes(thread);
            }
            glClearColor(0.17f, 0.18f, 0.21f, 1f);
            glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
            for (int i = 0; i < instances; i++) {
                SkeletalAnimatedMesh m = meshes.get(i);
                m.step(dt);
                try (Frame f = m.acquire()) {
                    renderer.upload(f);
                    draw.firstInstance = i;
                    renderer.draw(draw);
                }
            }
            window.swapBuffers();
            glfwPollEvents();
            if (frame >= WARMUP_FRAMES) {
                frames++;
                long elapsed = System.nanoTime() - start;
                if (elapsed >= seconds * 1e9 && frames >= 5) {
                    glFinish();
                    elapsed = System.nanoTime() - start;
                    long bytes = threads.getThreadAllocatedBytes(thread) - bytesAtStart;
                    double ms = elapsed / 1e6 / frames;
                    return new Point(gpu ? "gpu" : "cpu", method.key(), instances, 1000 / ms, ms,
                            (double) bytes / frames);
                }
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
