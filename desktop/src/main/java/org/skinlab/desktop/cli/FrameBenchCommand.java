package org.skinlab.desktop.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.Locale;
import java.util.concurrent.Callable;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.animation.WrapMode;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code skinlab bench frame}: one animation frame of a character, end to end on the CPU: sample
 * the clip (slerp), evaluate the skeleton, compute every geometry's skinning matrices (and, for
 * DQS, its dual quaternions), and skin every placed mesh, positions and normals. Each timed frame
 * advances the clip by 1/60 s (looping), so the sampler's key search moves as it does when playing.
 * Warm-up, then timed frames for a given time; minimum and median in microseconds per frame.
 */
@Command(name = "frame", mixinStandardHelpOptions = true,
        description = "Time of one frame (sample, skinning matrices, skin) of a character, in microseconds.")
public final class FrameBenchCommand implements Callable<Integer> {
    @Parameters(index = "0", arity = "0..1", paramLabel = "FILE",
            description = "the .dae file (default: ${DEFAULT-VALUE})")
    Path file = Path.of("assets/characters/humanoid-walk.dae");

    @Option(names = "--method", paramLabel = "lbs|dqs", description = "skinning method (default: ${DEFAULT-VALUE})")
    String method = "lbs";

    @Option(names = "--normals", paramLabel = "exact|blended",
            description = "normal rule: renormalised inverse-transpose or the blended matrix (default: ${DEFAULT-VALUE})")
    String normals = "exact";

    @Option(names = "--warmup-seconds", paramLabel = "S", description = "warm-up before timing (default: ${DEFAULT-VALUE})")
    double warmupSeconds = 2.0;

    @Option(names = "--seconds", paramLabel = "S", description = "timed frames for this long, at least 5 (default: ${DEFAULT-VALUE})")
    double seconds = 3.0;

    @Option(names = "--json", description = "print the result as one line of JSON")
    boolean json;

    @Option(names = "--palette-only",
            description = "time only the joint palette (sample, skinning matrices, dual quaternions), no skinning")
    boolean paletteOnly;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        SkinningMethod m;
        try {
            m = SkinningMethod.fromKey(method);
        } catch (IllegalArgumentException e) {
            throw new CommandFailure(ExitCodes.USAGE, "bench frame: " + e.getMessage(), e);
        }
        NormalTransform rule;
        switch (normals.toLowerCase(Locale.ROOT)) {
            case "exact":
                rule = NormalTransform.INVERSE_TRANSPOSE;
                break;
            case "blended":
                rule = NormalTransform.BLENDED_MATRIX;
                break;
            default:
                throw new CommandFailure(ExitCodes.USAGE, "bench frame: unknown normal rule \"" + normals
                        + "\" (expected exact or blended)", null);
        }
        Model model = ModelFiles.load(file).model;
        SkinnedModel skinned = new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0), rule);
        if (paletteOnly) {
            return paletteOnly(skinned);
        }
        int geometries = skinned.geometries().size();
        float[][] positions = new float[geometries][];
        float[][] normalsOut = new float[geometries][];
        int points = 0;
        int joints = 0;
        for (int g = 0; g < geometries; g++) {
            SkinnedGeometry geometry = skinned.geometries().get(g);
            positions[g] = new float[3 * geometry.pointCount()];
            normalsOut[g] = new float[3 * geometry.pointCount()];
            points += geometry.pointCount();
            joints += geometry.jointCount();
        }
        String implementation = geometries == 0 ? "none" : skinned.skinner(0, m).implementation();
        long[] frame = {0};
        Runnable step = () -> {
            float t = skinned.sampler().clipTime(frame[0]++ / 60.0, WrapMode.LOOP);
            skinned.pose(t, RotationInterpolation.SLERP);
            for (int g = 0; g < geometries; g++) {
                skinned.skin(g, m, positions[g], normalsOut[g]);
            }
        };
        long warmupEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
        do {
            step.run();
        } while (System.nanoTime() < warmupEnd);
        double[] micros = new double[1024];
        int n = 0;
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (n < 5 || System.nanoTime() < end) {
            long t0 = System.nanoTime();
            step.run();
            long t1 = System.nanoTime();
            if (n == micros.length) {
                micros = Arrays.copyOf(micros, 2 * n);
            }
            micros[n++] = (t1 - t0) / 1e3;
        }
        double[] sorted = Arrays.copyOf(micros, n);
        Arrays.sort(sorted);
        double min = sorted[0];
        double median = sorted[n / 2];
        PrintWriter out = spec.commandLine().getOut();
        String name = file.getFileName().toString();
        if (json) {
            ObjectMapper mapper = new ObjectMapper();
            ObjectNode root = mapper.createObjectNode();
            root.put("benchmark", "frame");
            root.put("file", name);
            root.put("method", m.key());
            root.put("normals", normals.toLowerCase(Locale.ROOT));
            root.put("points", points);
            root.put("joints", joints);
            root.put("frames", n);
            root.put("minMicrosPerFrame", round(min));
            root.put("medianMicrosPerFrame", round(median));
            root.put("implementation", implementation);
            out.println(mapper.writeValueAsString(root));
        } else {
            out.printf(Locale.ROOT, "frame of %s: %d points, %d joints, %s, normals %s, %s%n", name, points, joints,
                    m.key(), normals.toLowerCase(Locale.ROOT), implementation);
            out.printf(Locale.ROOT, "min %.2f µs, median %.2f µs per frame (%d frames: sample, skinning matrices, skin)%n",
                    min, median, n);
        }
        out.flush();
        return ExitCodes.OK;
    }

    /**
     * {@code --palette-only}: per frame, {@link SkinnedModel#pose} (sample, evaluate, skinning
     * matrices) and then every palette's dual quaternions, timed apart. Besides minimum and
     * median it reports the mean, which shows frames that are slow for a reason of their own.
     */
    private int paletteOnly(SkinnedModel skinned) throws Exception {
        int geometries = skinned.geometries().size();
        int joints = 0;
        for (int g = 0; g < geometries; g++) {
            joints += skinned.geometries().get(g).jointCount();
        }
        long frame = 0;
        long warmupEnd = System.nanoTime() + (long) (warmupSeconds * 1e9);
        do {
            skinned.pose(skinned.sampler().clipTime(frame++ / 60.0, WrapMode.LOOP), RotationInterpolation.SLERP);
            for (int g = 0; g < geometries; g++) {
                skinned.palette(g).prepareDualQuaternions();
            }
        } while (System.nanoTime() < warmupEnd);
        double[] pose = new double[1024];
        double[] dq = new double[1024];
        int n = 0;
        long end = System.nanoTime() + (long) (seconds * 1e9);
        while (n < 5 || System.nanoTime() < end) {
            float t = skinned.sampler().clipTime(frame++ / 60.0, WrapMode.LOOP);
            long t0 = System.nanoTime();
            skinned.pose(t, RotationInterpolation.SLERP);
            long t1 = System.nanoTime();
            for (int g = 0; g < geometries; g++) {
                skinned.palette(g).prepareDualQuaternions();
            }
            long t2 = System.nanoTime();
            if (n == pose.length) {
                pose = Arrays.copyOf(pose, 2 * n);
                dq = Arrays.copyOf(dq, 2 * n);
            }
            pose[n] = (t1 - t0) / 1e3;
            dq[n++] = (t2 - t1) / 1e3;
        }
        double[] total = new double[n];
        for (int i = 0; i < n; i++) {
            total[i] = pose[i] + dq[i];
        }
        double[][] stats = {stats(total, n), stats(pose, n), stats(dq, n)};
        String[] parts = {"palette", "pose", "dualQuaternions"};
        PrintWriter out = spec.commandLine().getOut();
        String name = file.getFileName().toString();
        if (json) {
            ObjectMapper mapper = new ObjectMapper();
            ObjectNode root = mapper.createObjectNode();
            root.put("benchmark", "frame-palette");
            root.put("file", name);
            root.put("joints", joints);
            root.put("frames", n);
            for (int p = 0; p < parts.length; p++) {
                ObjectNode part = root.putObject(parts[p]);
                part.put("minMicros", round(stats[p][0]));
                part.put("medianMicros", round(stats[p][1]));
                part.put("meanMicros", round(stats[p][2]));
            }
            out.println(mapper.writeValueAsString(root));
        } else {
            out.printf(Locale.ROOT, "palette of %s: %d joints, %d frames (slerp)%n", name, joints, n);
            for (int p = 0; p < parts.length; p++) {
                out.printf(Locale.ROOT, "%-16s min %.3f µs, median %.3f µs, mean %.3f µs%n", parts[p], stats[p][0],
                        stats[p][1], stats[p][2]);
            }
        }
        out.flush();
        return ExitCodes.OK;
    }

    /** Minimum, median and mean of the first n values. */
    private static double[] stats(double[] values, int n) {
        double[] sorted = Arrays.copyOf(values, n);
        Arrays.sort(sorted);
        double sum = 0;
        for (double v : sorted) {
            sum += v;
        }
        return new double[] {sorted[0], sorted[n / 2], sum / n};
    }

    private static double round(double d) {
        return Math.round(d * 1000.0) / 1000.0;
    }
}
