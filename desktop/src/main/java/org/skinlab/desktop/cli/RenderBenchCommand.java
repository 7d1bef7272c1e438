package org.skinlab.desktop.cli;

import java.io.IOException;
import java.io.PrintWriter;
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

import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.JavaRuntime;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.bench.CrowdBench;
import org.skinlab.desktop.bench.RenderBench;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.desktop.viewer.ModelLibrary;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code skinlab bench-render [FILE]}: the thesis' frames-per-second-against-meshes figure
 * redone. For CPU and GPU skinning and the crowds' methods ({@link CrowdBench#METHODS}), it renders a grid of 1, 4, 8, 12, 16, ...
 * animated copies, each its own simulation stepped every frame (as the thesis' meshes were), in
 * an off-screen window without vsync, and stops a series when it falls below 30 fps. It also
 * reports the bytes the render loop allocated per frame. The loop is {@link RenderBench}'s.
 */
@Command(name = "bench-render", mixinStandardHelpOptions = true,
        description = {"Frames per second against the number of animated copies, CPU and GPU skinning, LBS and DQS "
                + "(the thesis' figure).", "Each series stops below 30 fps (or at --max-instances)."})
public final class RenderBenchCommand implements Callable<Integer> {
    @Parameters(index = "0", arity = "0..1", paramLabel = "FILE",
            description = "a model file, .dae/.gltf/.glb (default: the bundled walking character)")
    Path file;

    @Option(names = "--size", paramLabel = "WxH", converter = WindowOptions.SizeConverter.class,
            description = "framebuffer size (default: 640x480)")
    WindowOptions.Size size = new WindowOptions.Size(640, 480);

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

    @Override
    public Integer call() throws IOException {
        Path path = file != null ? file : ModelLibrary.find().defaultModel();
        if (path == null) {
            throw new CommandFailure(ExitCodes.USAGE, "no FILE given and no bundled assets found", null);
        }
        Model model = ModelFiles.load(path).model;
        PrintWriter out = spec.commandLine().getOut();
        List<RenderBench.Point> points = new ArrayList<>();
        RenderBench bench;
        try {
            bench = RenderBench.open(size.width(), size.height());
        } catch (GlWindow.WindowUnavailableException e) {
            throw new CommandFailure(ExitCodes.UNAVAILABLE, e.getMessage(), e);
        }
        try (bench) {
            out.printf(Locale.ROOT, "%s, %dx%d, %s %s%n", path.getFileName(), size.width(), size.height(),
                    bench.renderer(), bench.version());
            // Warm-up, discarded: the JIT compiles the kernels (the Vector API allocates until it has).
            bench.warmUp(model, Math.max(2.0, seconds));
            out.printf("%-4s %-4s %9s %9s %9s %12s%n", "skin", "meth", "instances", "fps", "ms/frame", "bytes/frame");
            for (boolean gpu : new boolean[] {false, true}) {
                for (SkinningMethod method : CrowdBench.METHODS) {
                    for (int n : RenderBench.steps(maxInstances)) {
                        RenderBench.Point p = bench.measure(model, gpu, method, n, seconds);
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
}
