package org.skinlab.desktop.cli;

import java.io.PrintWriter;
import java.util.Locale;
import java.util.concurrent.Callable;

import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.JavaRuntime;
import org.skinlab.desktop.bench.SkinningTiming;
import org.skinlab.desktop.bench.SyntheticSkinData;
import org.skinlab.desktop.bench.ThesisSkinningBaseline;
import org.skinlab.skinning.JointPalette;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.ParallelSkinner;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.Skinner;
import org.skinlab.skinning.Skinners;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code skinlab bench skinning}: skinning speed on the synthetic data of the shared C++ reference
 * ({@code ../shared/perf/skin_ref.cpp}, bit-identical input: {@link SyntheticSkinData}), with the
 * reference's protocol: one untimed run for the checksum, a warm-up, then timed runs of the whole
 * mesh for a given time (at least 5); the report gives the minimum and median time per vertex. By
 * default the work is the reference's: normals by the blended matrix
 * ({@link NormalTransform#BLENDED_MATRIX}), the joint matrices straight from the data, DQS's dual
 * quaternions derived from them once per frame by the palette, influences in the order drawn.
 * {@code --normals none} skins positions only (LBS and DQS; {@code bench/cpp/skin_positions.cpp} is
 * its C++ counterpart), {@code --influences} draws another number of joints per vertex the same
 * way (the reference's data has 4).
 */
@Command(name = "skinning", mixinStandardHelpOptions = true,
        description = "Skinning speed on the synthetic data of the shared C++ reference (ns per vertex).")
public final class SkinningBenchCommand implements Callable<Integer> {
    @Option(names = "--vertices", paramLabel = "N", description = "points of the synthetic mesh (default: ${DEFAULT-VALUE})")
    int vertices = 100_000;

    @Option(names = "--threads", paramLabel = "T", description = "threads, the caller's included (default: ${DEFAULT-VALUE})")
    int threads = 1;

    @Option(names = "--method", paramLabel = MethodKeys.KEYS, description = "skinning method (default: ${DEFAULT-VALUE})")
    String method = "lbs";

    @Option(names = "--implementation", paramLabel = "auto|scalar|vector",
            description = "kernel: the fastest available, core's scalar one, or the Vector API one (default: ${DEFAULT-VALUE})")
    String implementation = "auto";

    @Option(names = "--normals", paramLabel = "blended|exact|none",
            description = "normal rule: the blended matrix (the C++ reference's), the renormalised inverse-transpose,"
                    + " or none: positions only, lbs and dqs (default: ${DEFAULT-VALUE})")
    String normals = "blended";

    @Option(names = "--influences", paramLabel = "K",
            description = "joints per vertex, 1 to " + SyntheticSkinData.JOINTS + " (default: ${DEFAULT-VALUE}, the"
                    + " reference's data; others are drawn the same way)")
    int influences = SyntheticSkinData.INFLUENCES;

    @Option(names = "--warmup-seconds", paramLabel = "S", description = "warm-up before timing (default: ${DEFAULT-VALUE})")
    double warmupSeconds = 2.0;

    @Option(names = "--seconds", paramLabel = "S", description = "timed runs for this long, at least 5 (default: ${DEFAULT-VALUE})")
    double seconds = 3.0;

    @Option(names = "--baseline", paramLabel = "thesis",
            description = "also time the thesis-style loop (objects per vertex; for DQS a matrix to dual quaternion"
                    + " conversion per influence and vertex) with the same protocol and report its median / ours")
    String baseline;

    @Option(names = "--json", description = "print the result as one line of JSON")
    boolean json;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        SkinningMethod m = parseMethod();
        NormalTransform rule = parseNormals();
        if (vertices < 1) {
            throw usage("--vertices must be at least 1");
        }
        if (threads < 1) {
            throw usage("--threads must be at least 1");
        }
        if (baseline != null && !baseline.equals("thesis")) {
            throw usage("unknown baseline \"" + baseline + "\" (expected thesis)");
        }
        if (baseline != null && m == SkinningMethod.COR) {
            throw usage("the thesis baseline skins with LBS or DQS only");
        }
        if (rule == NormalTransform.NONE && !m.skinsPositionsOnly()) {
            throw usage("--normals none: " + m.key() + " has no positions-only kernel (lbs and dqs have)");
        }
        if (baseline != null && rule == NormalTransform.NONE) {
            throw usage("the thesis baseline writes normals: time it with --normals blended");
        }
        if (influences < 1 || influences > SyntheticSkinData.JOINTS) {
            throw usage("--influences must be 1 to " + SyntheticSkinData.JOINTS);
        }
        SyntheticSkinData data = new SyntheticSkinData(vertices, SyntheticSkinData.SEED, influences);
        SkinnedGeometry geometry = data.geometry();
        JointPalette palette = data.palette();
        Skinner kernel = kernel(m, geometry, rule);
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        float[] positions = new float[3 * vertices];
        float[] normalsOut = rule == NormalTransform.NONE ? null : new float[3 * vertices];
        SkinningTiming ours;
        String name;
        try (ParallelSkinner skinner = new ParallelSkinner(kernel, threads)) {
            name = kernel.implementation();
            ours = measure(() -> skinner.skinAll(palette, positions, normalsOut), positions, normalsOut);
        }
        SkinningTiming thesis = null;
        if (baseline != null) {
            ThesisSkinningBaseline b = new ThesisSkinningBaseline(geometry, m);
            thesis = measure(() -> b.skinAll(palette, positions, normalsOut), positions, normalsOut);
        }
        if (json) {
            out.println(toJson(m, name, ours, thesis));
        } else {
            out.printf(Locale.ROOT, "skinning %s, %d vertices, %d influences, %d thread%s, %s, %s, %s%n", m.key(),
                    vertices, influences, threads, threads == 1 ? "" : "s", name, describe(rule),
                    JavaRuntime.describe());
            out.printf(Locale.ROOT, "min %.3f ns/vertex, median %.3f ns/vertex (%d runs), checksum %.6f%n",
                    ours.min(), ours.median(), ours.nsPerVertex.length, ours.checksum);
            if (thesis != null) {
                out.printf(Locale.ROOT, "thesis-style baseline: min %.3f, median %.3f ns/vertex (%d runs),"
                        + " checksum %.6f; baseline / ours: %.1fx at the median, %.1fx at the minimum%n", thesis.min(),
                        thesis.median(), thesis.nsPerVertex.length, thesis.checksum, thesis.median() / ours.median(),
                        thesis.min() / ours.min());
            }
        }
        out.flush();
        err.flush();
        return ExitCodes.OK;
    }

    private Skinner kernel(SkinningMethod m, SkinnedGeometry unbound, NormalTransform rule) {
        SkinnedGeometry geometry = unbound.boundFor(m);
        switch (implementation.toLowerCase(Locale.ROOT)) {
            case "auto":
                return Skinners.create(m, geometry, rule);
            case "scalar":
                return Skinners.scalar(m, geometry, rule);
            case "vector":
                Skinner s = Skinners.create(m, geometry, rule);
                if (s.implementation().equals("scalar")) {
                    throw new CommandFailure(ExitCodes.USAGE, "bench skinning: no vector kernel here (the JVM needs"
                            + " --add-modules jdk.incubator.vector and 256-bit vectors)", null);
                }
                return s;
            default:
                throw usage("unknown implementation \"" + implementation + "\" (expected auto, scalar or vector)");
        }
    }

    private SkinningTiming measure(Runnable frame, float[] positions, float[] normalsOut) {
        return SkinningTiming.measure(frame, positions, normalsOut, vertices, warmupSeconds, seconds);
    }

    private String toJson(SkinningMethod m, String name, SkinningTiming ours, SkinningTiming thesis) {
        ObjectMapper mapper = new ObjectMapper();
        ObjectNode root = mapper.createObjectNode();
        root.put("method", m.key());
        root.put("vertices", vertices);
        root.put("threads", threads);
        root.put("influences", influences);
        root.put("normals", normals.toLowerCase(Locale.ROOT));
        root.put("minNsPerVertex", round(ours.min()));
        root.put("medianNsPerVertex", round(ours.median()));
        root.put("checksum", ours.checksum);
        root.put("implementation", name);
        root.put("java", JavaRuntime.version());
        root.put("javaVendor", JavaRuntime.vendor());
        if (thesis != null) {
            root.put("baselineMinNsPerVertex", round(thesis.min()));
            root.put("baselineMedianNsPerVertex", round(thesis.median()));
            root.put("baselineChecksum", thesis.checksum);
            root.put("baselineRatio", round(thesis.median() / ours.median()));
        }
        try {
            return mapper.writeValueAsString(root);
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }

    private SkinningMethod parseMethod() {
        SkinningMethod m;
        try {
            m = MethodKeys.parse(method);
        } catch (IllegalArgumentException e) {
            throw usage(e.getMessage());
        }
        if (m.usesBones()) {
            // The shared reference's joints are frames at the origin without a hierarchy: no bones.
            throw usage("--method " + m.key() + " reads bones, which the shared reference's synthetic data does not"
                    + " have; time it on a rig with bench frame FILE --method " + m.key());
        }
        return m;
    }

    private NormalTransform parseNormals() {
        switch (normals.toLowerCase(Locale.ROOT)) {
            case "blended":
                return NormalTransform.BLENDED_MATRIX;
            case "exact":
                return NormalTransform.INVERSE_TRANSPOSE;
            case "none":
                return NormalTransform.NONE;
            default:
                throw usage("unknown normal rule \"" + normals + "\" (expected blended, exact or none)");
        }
    }

    private static String describe(NormalTransform rule) {
        switch (rule) {
            case BLENDED_MATRIX:
                return "normals by the blended matrix";
            case INVERSE_TRANSPOSE:
                return "normals by the inverse-transpose";
            default:
                return "positions only";
        }
    }

    private CommandFailure usage(String message) {
        return new CommandFailure(ExitCodes.USAGE, "bench skinning: " + message, null);
    }

    private static double round(double d) {
        return Math.round(d * 1000.0) / 1000.0;
    }
}
