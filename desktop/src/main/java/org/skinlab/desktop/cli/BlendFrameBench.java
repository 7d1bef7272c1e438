package org.skinlab.desktop.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;

import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.JavaRuntime;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.desktop.bench.JitWarmup;
import org.skinlab.desktop.bench.MixerBench;
import org.skinlab.mixer.Mixer;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.PositionSharing;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * {@code skinlab bench frame FILE --blend ... [--additive ...]}: {@link FrameBenchCommand}'s
 * options applied to one file whose frame a mixer directs ({@link MixerBench}); per method three
 * lines (what was measured; the mixer's step with its ns per joint per layer; pose, skin and the
 * bytes allocated per step) or one line of JSON. A layer here is a clip sampled per step (weight
 * above 0), a joint a node of the skeleton: what the mixer's sampling and blending go over.
 */
final class BlendFrameBench {
    private final Path file;
    private final BlendSpec blend;
    private final NormalTransform rule;
    private final String normals;
    private final PositionSharing sharing;
    private final boolean json;

    BlendFrameBench(Path file, BlendSpec blend, NormalTransform rule, String normals, PositionSharing sharing,
            boolean json) {
        this.file = file;
        this.blend = blend;
        this.rule = rule;
        this.normals = normals;
        this.sharing = sharing;
        this.json = json;
    }

    /** Measures each method in turn (a method's mixer starts at time 0) and prints it as it is measured. */
    int run(List<SkinningMethod> methods, double warmup, double timed, PrintWriter out, PrintWriter err) {
        Model model = ModelFiles.load(file).model;
        BlendSpec resolved;
        try {
            resolved = blend.resolve(model, file.toString());
        } catch (IllegalArgumentException e) {
            throw usage(e.getMessage());
        }
        int layers = resolved.sampledClips();
        if (layers == 0) {
            throw usage("--blend: every weight is 0, so no clip is sampled (nothing to measure)");
        }
        SkinnedModel skinned = new SkinnedModel(model, null, rule, EnumSet.copyOf(methods));
        int joints = skinned.skeleton().nodeCount();
        boolean warned = false;
        for (SkinningMethod m : methods) {
            Mixer mixer = resolved.mixer(model, skinned.skeleton());
            BlendSpec.setTime(mixer, 0);
            MixerBench bench = new MixerBench(skinned, mixer, m, rule, sharing, JitWarmup.WARMUP);
            MixerBench.Result r = bench.measure(warmup, timed);
            if (!warned) {
                mixer.warnings().forEach(w -> err.println("skinlab: warning: " + SkinlabCommand.oneLine(w)));
                err.flush();
                warned = true;
            }
            double perJointPerLayer = 1000 * r.mixerMicros().median() / ((double) joints * layers);
            if (json) {
                out.println(toJson(resolved, layers, joints, r, perJointPerLayer));
            } else {
                printLines(out, resolved, layers, joints, r, perJointPerLayer);
            }
            out.flush();
        }
        return ExitCodes.OK;
    }

    private void printLines(PrintWriter out, BlendSpec resolved, int layers, int joints, MixerBench.Result r,
            double perJointPerLayer) {
        out.printf(Locale.ROOT, "frame of %s with blend %s: %d layers (clips sampled), %d joints (skeleton nodes), %s,"
                + " normals %s, %s, %s%n", file.getFileName(), resolved.describe(), layers, joints, r.method().key(),
                normals, r.kernel(), JavaRuntime.describe());
        out.printf(Locale.ROOT, "mixer (advance, sample, blend): median %.3f µs per step (%d runs, medians %.3f to %.3f"
                + " µs; %d steps); %.2f ns per joint per layer%n", r.mixerMicros().median(), r.mixerMicros().count(),
                r.mixerMicros().min(), r.mixerMicros().max(), r.steps(), perJointPerLayer);
        out.printf(Locale.ROOT, "pose (skeleton, palette) median %.3f µs, skin median %.3f µs per step; allocated per"
                + " step: mixer %s, whole frame %s%n", r.poseMicros().median(), r.skinMicros().median(),
                bytes(r.mixerBytesPerStep()), bytes(r.frameBytesPerStep()));
    }

    private static String bytes(double b) {
        return Double.isNaN(b) ? "unknown (no allocation counter)" : String.format(Locale.ROOT, "%.0f bytes", b);
    }

    private String toJson(BlendSpec resolved, int layers, int joints, MixerBench.Result r, double perJointPerLayer) {
        ObjectMapper mapper = new ObjectMapper();
        ObjectNode root = mapper.createObjectNode();
        root.put("benchmark", "frame-blend");
        root.put("file", file.getFileName().toString());
        root.put("method", r.method().key());
        root.put("normals", normals);
        root.put("blend", resolved.describe());
        root.put("layers", layers);
        root.put("joints", joints);
        root.put("steps", r.steps());
        ArrayNode runs = root.putArray("mixerRunsMicros");
        for (double v : r.mixerMicros().runs()) {
            runs.add(round(v));
        }
        root.put("mixerMedianMicros", round(r.mixerMicros().median()));
        root.put("nanosPerJointPerLayer", round(perJointPerLayer));
        root.put("poseMedianMicros", round(r.poseMicros().median()));
        root.put("skinMedianMicros", round(r.skinMicros().median()));
        putBytes(root, "mixerBytesPerStep", r.mixerBytesPerStep());
        putBytes(root, "frameBytesPerStep", r.frameBytesPerStep());
        root.put("implementation", r.kernel());
        root.put("java", JavaRuntime.version());
        root.put("javaVendor", JavaRuntime.vendor());
        try {
            return mapper.writeValueAsString(root);
        } catch (JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }

    private static void putBytes(ObjectNode root, String key, double bytes) {
        if (Double.isNaN(bytes)) {
            root.putNull(key);
        } else {
            root.put(key, round(bytes));
        }
    }

    private static double round(double d) {
        return Math.round(d * 1000.0) / 1000.0;
    }

    private static CommandFailure usage(String message) {
        return new CommandFailure(ExitCodes.USAGE, "bench frame: " + message, null);
    }
}
