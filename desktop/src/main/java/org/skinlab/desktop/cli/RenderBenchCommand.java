package org.skinlab.desktop.cli;

import static org.lwjgl.glfw.GLFW.glfwPollEvents;
import static org.lwjgl.glfw.GLFW.glfwSwapInterval;
import static org.lwjgl.opengl.GL33C.*;

import java.io.IOException;
import java.io.PrintWriter;
import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.SerializationFeature;

import org.skinlab.desktop.render.DrawSettings;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.desktop.render.ModelRenderer;
import org.skinlab.desktop.render.SkinningShader;
import org.skinlab.desktop.viewer.ModelLibrary;
import org.skinlab.desktop.viewer.OrbitCamera;
import org.skinlab.model.Model;
import org.skinlab.scene.ModelFraming;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code skinlab bench-render [FILE]}: the thesis' frames-per-second-against-meshes figure
 * redone. For CPU and GPU skinning, LBS and DQS, it renders a grid of 1, 4, 8, 12, 16, ...
 * animated copies, each its own simulation stepped every frame (as the thesis' meshes were), in
 * an off-screen window without vsync, and stops a series when it falls below 30 fps. It also
 * reports the bytes the render loop allocated per frame.
 */
@Command(name = "bench-render", mixinStandardHelpOptions = true,
        description = {"Frames per second against the number of animated copies, CPU and GPU skinning, LBS and DQS "
                + "(the thesis' figure).", "Each series stops below 30 fps (or at --max-instances)."})
public final class RenderBenchCommand implements Callable<Integer> {
    @Parameters(index = "0", arity = "0..1", paramLabel = "FILE", description = "a .dae file (default: the bundled "
            + "walking character)")
    Path file;

    @Option(names = "--size", paramLabel = "WxH", converter = ViewCommand.SizeConverter.class,
            description = "framebuffer size (default: 640x480)")
    ViewCommand.Size size = new ViewCommand.Size(640, 480);

    @Option(names = "--seconds", paramLabel = "S", description = "measured time per point (default: 1.5)")
    double seconds = 1.5;

    @Option(names = "--max-instances", paramLabel = "N", description = "largest grid (default: 256)")
    int maxInstances = 256;

    @Option(names = "--min-fps", paramLabel = "F", description = "a series stops below this (default: 30)")
    double minFps = 30;

    @Option(names = "--json", paramLabel = "OUT", description = "also write the results as JSON")
    Path json;

    @Spec
    CommandSpec spec;

    /** Instance counts: the thesis' 1, 4, 8, 12, 16, then on in steps of 8, 16, 32 ... */
    static List<Integer> steps(int max) {
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

    record Point(String skinning, String method, int instances, double fps, double msPerFrame,
            double bytesPerFrame) {
    }

    @Override
    public Integer call() throws IOException {
        Path path = file != null ? file : ModelLibrary.find().defaultModel();
        if (path == null) {
            throw new CommandFailure(ExitCodes.USAGE, "no FILE given and no bundled assets found", null);
        }
        Model model = ModelFiles.load(path).model;
        PrintWriter out = spec.commandLine().getOut();
        List<Point> points = new ArrayList<>();
        GlWindow window;
        try {
            window = new GlWindow("skinlab bench-render", size.width(), size.height(), false, false);
        } catch (GlWindow.WindowUnavailableException e) {
            throw new CommandFailure(ExitCodes.INTERNAL, e.getMessage(), e);
        }
        try (window; SkinningShader shader = new SkinningShader()) {
            glfwSwapInterval(0);
            out.printf(Locale.ROOT, "%s, %dx%d, %s %s%n", path.getFileName(), size.width(), size.height(),
                    glGetString(GL_RENDERER), glGetString(GL_VERSION));
            // Warm-up, discarded: the JIT compiles the kernels (the Vector API allocates until it has).
            double measured = seconds;
            seconds = Math.max(2.0, seconds);
            for (SkinningMethod method : SkinningMethod.values()) {
                measure(window, shader, model, false, method, 1);
            }
            seconds = measured;
            out.printf("%-4s %-4s %9s %9s %9s %12s%n", "skin", "meth", "instances", "fps", "ms/frame", "bytes/frame");
            for (boolean gpu : new boolean[] {false, true}) {
                for (SkinningMethod method : SkinningMethod.values()) {
                    for (int n : steps(maxInstances)) {
                        Point p = measure(window, shader, model, gpu, method, n);
                        points.add(p);
                        out.printf(Locale.ROOT, "%-4s %-4s %9d %9.1f %9.2f %12.0f%n", p.skinning(), p.method(),
                                n, p.fps(), p.msPerFrame(), p.bytesPerFrame());
                        out.flush();
                        if (p.fps() < minFps) {
                            break;
                        }
                    }
                }
            }
        }
        if (json != null) {
            Map<String, Object> doc = new LinkedHashMap<>();
            doc.put("file", path.toString());
            doc.put("width", size.width());
            doc.put("height", size.height());
            doc.put("java", JavaRuntime.describe());
            doc.put("points", points);
            Files.writeString(json, new ObjectMapper().enable(SerializationFeature.INDENT_OUTPUT)
                    .writeValueAsString(doc));
        }
        return ExitCodes.OK;
    }

    private Point measure(GlWindow window, SkinningShader shader, Model model, boolean gpu, SkinningMethod method,
            int instances) {
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
            camera.projection(size.width() / (float) size.height(), draw.viewProjection);
            camera.viewTimesInto(draw.viewProjection);
            camera.eye(draw.eye);
            glViewport(0, 0, size.width(), size.height());
            glEnable(GL_DEPTH_TEST);
            try (ModelRenderer renderer = new ModelRenderer(shader, model, meshes.get(0).geometries(), img -> 0)) {
                com.sun.management.ThreadMXBean threads =
                        (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
                long thread = Thread.currentThread().getId();
                int warmup = 10;
                long start = 0;
                long bytesAtStart = 0;
                int frames = 0;
                double dt = 1.0 / 60;
                for (int frame = 0;; frame++) {
                    if (frame == warmup) {
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
                    if (frame >= warmup) {
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
        } finally {
            meshes.forEach(SkeletalAnimatedMesh::close);
        }
    }
}
