package org.skinlab.desktop.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;

import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.render.GlWindow;
import org.skinlab.desktop.render.ModelRenderer;
import org.skinlab.desktop.render.SkinningShader;
import org.skinlab.model.Model;
import org.skinlab.simulation.AnimationConfig;
import org.skinlab.simulation.Frame;
import org.skinlab.simulation.SkeletalAnimatedMesh;
import org.skinlab.internal.metrics.ArtifactMetrics;
import org.skinlab.skinning.SkinningGlsl;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code skinlab check-gpu FILE... [--method KEY|all] [--time T,...] [--tolerance R]}: skins
 * each file, with every method that has shader code ({@link SkinningGlsl#hasCode}; it names the
 * others), on the GPU (the viewer's vertex shader, read back with transform feedback) and on the
 * CPU (core's kernels) from the same frame, and reports the largest distance between the two
 * relative to the model's size. Exit status 1 when a distance exceeds the tolerance: a driver, a
 * shader or a kernel that skins wrongly is caught on the user's own machine and files.
 */
@Command(name = "check-gpu", mixinStandardHelpOptions = true,
        description = {"Compare GPU skinning (the viewer's shader, read back with transform feedback) with the CPU "
                + "kernels on the same frames.", "Exit status 1 when they differ by more than the tolerance."})
public final class CheckGpuCommand implements Callable<Integer> {
    @Parameters(arity = "1..*", paramLabel = "FILE", description = "model files (.dae, .gltf, .glb)")
    List<Path> files;

    @Option(names = "--method", paramLabel = MethodKeys.KEYS_OR_ALL,
            description = "methods to check (default: all, that is every method with shader code)")
    String method = "all";

    @Option(names = "--time", split = ",", paramLabel = "T", description = "playback times in seconds "
            + "(default: 0, a quarter, half and three quarters of the clip)")
    List<Double> times;

    @Option(names = "--tolerance", paramLabel = "R",
            description = "largest distance allowed, relative to the model's size (default: 1e-4)")
    double tolerance = 1e-4;

    @Spec
    CommandSpec spec;

    /** One file and method: the largest GPU-CPU distance found. */
    record Result(String file, SkinningMethod method, int vertices, double maxDistance, double size) {
        double relative() {
            return size > 0 ? maxDistance / size : maxDistance;
        }
    }

    @Override
    public Integer call() {
        List<SkinningMethod> asked = MethodKeys.parseOneOrAll("--method", method);
        List<SkinningMethod> methods = new ArrayList<>();
        List<SkinningMethod> withoutCode = new ArrayList<>();
        for (SkinningMethod m : asked) {
            (SkinningGlsl.hasCode(m) ? methods : withoutCode).add(m);
        }
        if (methods.isEmpty()) {
            throw new CommandFailure(ExitCodes.USAGE, "--method " + method + ": " + MethodKeys.keys(withoutCode)
                    + " has no shader code (the viewer and the app skin it on the CPU): nothing to check", null);
        }
        PrintWriter out = spec.commandLine().getOut();
        List<Result> results = new ArrayList<>();
        GlWindow window;
        try {
            window = new GlWindow("skinlab check-gpu", 64, 64, false, false);
        } catch (GlWindow.WindowUnavailableException e) {
            throw new CommandFailure(ExitCodes.UNAVAILABLE, e.getMessage(), e);
        }
        try (window; SkinningShader shader = new SkinningShader()) {
            for (Path file : files) {
                Model model = ModelFiles.load(file).model;
                for (SkinningMethod m : methods) {
                    results.add(check(shader, file, model, m));
                }
            }
        }
        boolean ok = true;
        for (Result r : results) {
            boolean pass = r.relative() <= tolerance;
            ok &= pass;
            out.printf(Locale.ROOT, "%s %-8s %s: %d vertices, largest GPU-CPU distance %.3g (%.3g of the model's size)%n",
                    pass ? "ok  " : "FAIL", r.method().key(), r.file(), r.vertices(), r.maxDistance(), r.relative());
        }
        if (!withoutCode.isEmpty()) {
            out.println("not checked, no shader code (skinned on the CPU in the viewer and the app): "
                    + MethodKeys.keys(withoutCode));
        }
        out.flush();
        return ok ? ExitCodes.OK : ExitCodes.INTERNAL;
    }


    private Result check(SkinningShader shader, Path file, Model model, SkinningMethod method) {
        AnimationConfig config = new AnimationConfig();
        config.setMethod(method);
        config.stopAnimation();
        double maxDistance = 0;
        double size = 0;
        int vertices = 0;
        try (SkeletalAnimatedMesh mesh = new SkeletalAnimatedMesh(model,
                model.clips().isEmpty() ? null : model.clips().get(0), config)) {
            double duration = mesh.clipDuration();
            List<Double> at = times != null ? times : List.of(0.0, duration / 4, duration / 2, 3 * duration / 4);
            try (ModelRenderer renderer = new ModelRenderer(shader, model, mesh.geometries(), image -> 0)) {
                for (double t : at) {
                    mesh.seek(t);
                    mesh.step(0.0);
                    try (Frame frame = mesh.acquire()) {
                        renderer.upload(frame);
                        for (int g = 0; g < renderer.geometryCount(); g++) {
                            int n = renderer.vertexCount(g);
                            float[] gpu = new float[3 * n];
                            renderer.captureSkinned(g, method, gpu);
                            float[] cpu = frame.positions(g);
                            for (int i = 0; i < 3 * n; i += 3) {
                                double dx = gpu[i] - cpu[i];
                                double dy = gpu[i + 1] - cpu[i + 1];
                                double dz = gpu[i + 2] - cpu[i + 2];
                                maxDistance = Math.max(maxDistance, Math.sqrt(dx * dx + dy * dy + dz * dz));
                            }
                            size = Math.max(size, ArtifactMetrics.boundsDiagonal(cpu, n));
                        }
                    }
                }
                vertices = renderer.vertexCount();
            }
        }
        return new Result(file.toString(), method, vertices, maxDistance, size);
    }
}
