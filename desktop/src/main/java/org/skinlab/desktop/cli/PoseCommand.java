package org.skinlab.desktop.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.io.Writer;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import java.util.function.IntConsumer;
import java.util.stream.Collectors;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonGenerator;

import org.skinlab.animation.LocalPose;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.mixer.Mixer;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code skinlab pose FILE --time T1[,T2...] --method KEY [--clip NAME | --blend CLIP=W[,...]
 * [--additive CLIP=W[@REFTIME]]] [--json OUT]}: the deformed positions of every placed mesh at the
 * given clip times, of one clip or of a blend of clips ({@link BlendSpec}, played by a
 * {@link Mixer}). The JSON form is a contract other tools compare against:
 * <pre>
 * {"file":..., "clip":..., "method":..., "times":[T1,...],
 *  ["blend":[{"clip", "weight", "times"}], "additive":[{"clip", "weight", "referenceTime", "times"}],]
 *  "meshes":[{"geometry":ID, "name":NAME, "poses":[[x,y,z, x,y,z, ...] one array per time]}]}
 * </pre>
 * <ul>
 * <li>{@code file}: the path as given on the command line.</li>
 * <li>{@code clip}: the name of the clip played ({@code --clip}, else the file's first clip);
 *     null when the file has no animation: then every time gives the rest pose.</li>
 * <li>{@code method}: the method's key ({@link SkinningMethod#key()}): {@code "lbs"}, {@code "dqs"},
 *     {@code "cor"}, {@code "bfdqs"}, {@code "stbs-lbs"}, {@code "stbs-dqs"} or {@code "spline"}.</li>
 * <li>{@code times}: the times actually used, in the order given: clamped to
 *     [clip start, clip end]; as given when there is no clip, and with {@code --blend}, where each
 *     is T seconds after every clip's own start, looped within it.</li>
 * <li>{@code blend} and {@code additive}, with {@code --blend} only: the base layer's clips with
 *     their weights (a clip named twice once, with the sum of its weights), and the additive
 *     layers' clips with their weights and reference times (seconds after the clip's start);
 *     {@code times}: per time, the clip time (on the clip's keys' timeline) it was sampled at.
 *     {@code clip} is then the heaviest clip of the base layer (the first of equals).</li>
 * <li>{@code meshes}: one entry per placed mesh ({@code <instance_controller>} or
 *     {@code <instance_geometry>}), in scene order, skinned or static; a static mesh is placed
 *     by its node's world matrix at that time. {@code geometry} is the {@code <geometry>} id,
 *     {@code name} its name (null if none).</li>
 * <li>{@code poses}: per time, the deformed world position of every entry of the mesh's
 *     {@code <vertices>} POSITION source, in source order (3 numbers each), in the document's own
 *     frame: no up-axis or unit conversion.</li>
 * </ul>
 * Numbers are the float results printed so that they read back to the same float (Java's
 * {@link Float#toString(float)}).
 */
@Command(name = "pose", mixinStandardHelpOptions = true, sortOptions = false,
        description = {"Deform every placed mesh of a model file (COLLADA or glTF) at given clip times (LBS, DQS or "
                + "CoR) and write the world positions.",
                "",
                "JSON (--json OUT, '-' for stdout): {\"file\", \"clip\", \"method\", \"times\", \"meshes\":[{\"geometry\", "
                        + "\"name\", \"poses\":[[x,y,z, ...] per time]}]}. One mesh entry per placed mesh in scene order "
                        + "(static meshes placed by their node); one x,y,z per entry of the mesh's <vertices> POSITION "
                        + "source, in source order; world coordinates in the document's own frame (no up-axis or unit "
                        + "conversion). \"times\" are the times used: clamped to the clip's [start, end]. \"clip\" is "
                        + "null when the file has no animation (every time is then the rest pose). \"name\" is null "
                        + "when the geometry has none. Floats print so that they read back exactly.",
                "With --blend: \"times\" as given (seconds after each clip's start, looped within it), \"clip\" the "
                        + "heaviest clip, and after \"times\": \"blend\":[{\"clip\", \"weight\", \"times\"}], "
                        + "\"additive\":[{\"clip\", \"weight\", \"referenceTime\", \"times\"}], each \"times\" the "
                        + "clip times sampled.",
                "Without --json: a short summary (bounding box per mesh and time)."})
public final class PoseCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "FILE", description = "the model file (.dae, .gltf, .glb)")
    Path file;

    @Option(names = "--time", required = true, split = ",", paramLabel = "T", converter = TimeConverter.class,
            description = "clip times in seconds, comma-separated; clamped to the clip (with --blend: seconds after"
                    + " each clip's start, looped)")
    List<Float> times = new ArrayList<>();

    @Option(names = "--method", paramLabel = MethodKeys.KEYS, converter = MethodKeys.Converter.class,
            defaultValue = "lbs",
            description = "skinning method: lbs (linear blend, the default: what glTF viewers and three.js do), dqs"
                    + " (dual quaternion), cor (optimized centres of rotation), bfdqs (bulge-free DQS), stbs-lbs or"
                    + " stbs-dqs (stretchable and twistable bones on LBS or DQS), spline (spline-based)")
    SkinningMethod method;

    @Option(names = "--clip", paramLabel = "NAME", description = "the clip to play (default: the file's first clip)")
    String clipName;

    @Mixin
    BlendOptions blendOptions;

    @Option(names = "--interpolation", paramLabel = "slerp|nlerp|lerp", converter = RotationConverter.class,
            description = "rotation blending between keys (default: slerp)")
    RotationInterpolation interpolation = RotationInterpolation.SLERP;

    @Option(names = "--json", paramLabel = "OUT", description = "write the poses as JSON to OUT ('-': stdout)")
    String json;

    @Spec
    CommandSpec spec;

    /** Deformed positions per mesh and time: the command's result before it is printed. */
    static final class Result {
        final String file;
        final String clip;
        final SkinningMethod method;
        final float[] times;
        final List<Mesh> meshes;
        /** [mesh][time]: 3 floats per POSITION entry. */
        final float[][][] poses;
        /** The blend played, or null for one clip. */
        final BlendSpec blend;
        /** With a blend, [clip][time]: the clip time each of {@link BlendSpec#clips()} was sampled at. */
        final float[][] clipTimes;
        /** What the mixer told about the blend (each once), and what a blend leaves out. */
        final List<String> warnings;

        Result(String file, String clip, SkinningMethod method, float[] times, List<Mesh> meshes, float[][][] poses) {
            this(file, clip, method, times, meshes, poses, null, null, List.of());
        }

        Result(String file, String clip, SkinningMethod method, float[] times, List<Mesh> meshes, float[][][] poses,
                BlendSpec blend, float[][] clipTimes, List<String> warnings) {
            this.file = file;
            this.clip = clip;
            this.method = method;
            this.times = times;
            this.meshes = meshes;
            this.poses = poses;
            this.blend = blend;
            this.clipTimes = clipTimes;
            this.warnings = warnings;
        }
    }

    @Override
    public Integer call() throws IOException {
        BlendSpec blend = blendOptions.spec("pose");
        if (blend != null && clipName != null) {
            throw new CommandFailure(ExitCodes.USAGE, "pose: --clip and --blend exclude each other (name the clip in"
                    + " --blend: --blend " + clipName + "=1)", null);
        }
        Model model = ModelFiles.load(file).model;
        Result result;
        if (blend == null) {
            result = compute(file.toString(), model, chooseClip(model), method, interpolation, times);
        } else {
            try {
                blend = blend.resolve(model, file.toString());
            } catch (IllegalArgumentException e) {
                throw new CommandFailure(ExitCodes.USAGE, "pose: " + e.getMessage(), e);
            }
            result = compute(file.toString(), model, blend, method, interpolation, times);
        }
        PrintWriter err = spec.commandLine().getErr();
        for (String w : result.warnings) {
            err.println("skinlab: warning: " + SkinlabCommand.oneLine(w));
        }
        err.flush();
        PrintWriter out = spec.commandLine().getOut();
        if (json == null) {
            out.print(text(result));
        } else if (json.equals("-")) {
            writeJson(result, out);
            out.println();
        } else {
            Path target = Path.of(json);
            try (Writer w = Files.newBufferedWriter(target, StandardCharsets.UTF_8)) {
                writeJson(result, w);
                w.write('\n');
            } catch (IOException e) {
                throw new CommandFailure(ExitCodes.USAGE, "cannot write " + target + ": " + e.getMessage(), e);
            }
        }
        out.flush();
        return ExitCodes.OK;
    }

    private AnimationClip chooseClip(Model model) {
        if (clipName == null) {
            return model.clips().isEmpty() ? null : model.clips().get(0);
        }
        return model.clip(clipName).orElseThrow(() -> new CommandLine.ParameterException(spec.commandLine(),
                "unknown clip '" + clipName + "' in " + file + "; available clips: "
                        + (model.clips().isEmpty() ? "(none)"
                                : model.clips().stream().map(c -> "'" + c.name() + "'").collect(Collectors.joining(", ")))));
    }

    /** Poses the model at each time (clamped to the clip) and keeps every mesh's positions in source order. */
    static Result compute(String fileName, Model model, AnimationClip clip, SkinningMethod method,
            RotationInterpolation rotations, List<Float> requested) {
        // Normals are computed by the skinners anyway; the command reports positions only.
        SkinnedModel skinned = new SkinnedModel(model, clip, NormalTransform.INVERSE_TRANSPOSE, EnumSet.of(method));
        float[] used = new float[requested.size()];
        for (int i = 0; i < used.length; i++) {
            used[i] = clip == null ? requested.get(i) : skinned.sampler().clamp(requested.get(i));
        }
        float[][][] poses = skinAtEachTime(skinned, method, used.length,
                t -> skinned.pose(clip == null ? 0f : used[t], rotations));
        return new Result(fileName, clip == null ? null : clip.name(), method, used, meshes(skinned), poses);
    }

    /**
     * Poses the model in a blend at each time (seconds after each clip's start, looped within it):
     * the mixer's layers evaluated into local transforms, then the skeleton and the skins.
     */
    static Result compute(String fileName, Model model, BlendSpec blend, SkinningMethod method,
            RotationInterpolation rotations, List<Float> requested) {
        // No clip of its own: the mixer poses it (morph weights stay the file's).
        SkinnedModel skinned = new SkinnedModel(model, null, NormalTransform.INVERSE_TRANSPOSE, EnumSet.of(method));
        Mixer mixer = blend.mixer(model, skinned.skeleton());
        LocalPose local = skinned.skeleton().newLocalPose();
        float[] used = new float[requested.size()];
        for (int i = 0; i < used.length; i++) {
            used[i] = requested.get(i);
        }
        float[][][] poses = skinAtEachTime(skinned, method, used.length, t -> {
            BlendSpec.setTime(mixer, used[t]);
            mixer.evaluate(rotations, local);
            skinned.pose(local);
        });
        List<String> warnings = new ArrayList<>(mixer.warnings());
        for (String c : blend.clipsAnimatingMorphWeights(model)) {
            warnings.add(fileName + ": clip \"" + c + "\" animates morph weights, which a blend does not play: the"
                    + " meshes keep the file's weights");
        }
        return new Result(fileName, mixer.base().heaviestClip(), method, used, meshes(skinned), poses, blend,
                blend.clipTimes(model, skinned.skeleton(), used), warnings);
    }

    /** Poses the model by {@code poseAt} for each time index and skins every geometry, positions in source order. */
    private static float[][][] skinAtEachTime(SkinnedModel skinned, SkinningMethod method, int times,
            IntConsumer poseAt) {
        List<SkinnedGeometry> geometries = skinned.geometries();
        float[][][] poses = new float[geometries.size()][times][];
        float[][] points = new float[geometries.size()][];
        float[][] normals = new float[geometries.size()][];
        for (int g = 0; g < geometries.size(); g++) {
            points[g] = new float[3 * geometries.get(g).pointCount()];
            normals[g] = new float[3 * geometries.get(g).pointCount()];
        }
        for (int t = 0; t < times; t++) {
            poseAt.accept(t);
            for (int g = 0; g < geometries.size(); g++) {
                SkinnedGeometry geometry = geometries.get(g);
                skinned.skin(g, method, points[g], normals[g]);
                poses[g][t] = geometry.positionsInSourceOrder(points[g], new float[3 * geometry.positionCount()]);
            }
        }
        return poses;
    }

    private static List<Mesh> meshes(SkinnedModel skinned) {
        return skinned.geometries().stream().map(SkinnedGeometry::mesh).collect(Collectors.toList());
    }

    /** The contract's JSON, streamed (a pose of a large mesh is millions of numbers). */
    static void writeJson(Result r, Writer w) throws IOException {
        try (JsonGenerator json = new JsonFactory().createGenerator(w)) {
            json.disable(JsonGenerator.Feature.AUTO_CLOSE_TARGET);
            write(r, json);
        }
    }

    private static void write(Result r, JsonGenerator json) throws IOException {
        json.writeStartObject();
        json.writeStringField("file", r.file);
        json.writeStringField("clip", r.clip);
        json.writeStringField("method", r.method.key());
        json.writeArrayFieldStart("times");
        for (float t : r.times) {
            json.writeNumber(t);
        }
        json.writeEndArray();
        if (r.blend != null) {
            writeBlend(r, json);
        }
        json.writeArrayFieldStart("meshes");
        for (int g = 0; g < r.meshes.size(); g++) {
            Mesh mesh = r.meshes.get(g);
            json.writeStartObject();
            json.writeStringField("geometry", mesh.id());
            json.writeStringField("name", mesh.name());
            json.writeArrayFieldStart("poses");
            for (float[] pose : r.poses[g]) {
                json.writeStartArray();
                for (float v : pose) {
                    // Jackson prints a float with Float.toString: the digits that read back to it.
                    json.writeNumber(v);
                }
                json.writeEndArray();
            }
            json.writeEndArray();
            json.writeEndObject();
        }
        json.writeEndArray();
        json.writeEndObject();
    }

    /** A blend's two fields: the base layer's clips, then the additive layers'. */
    private static void writeBlend(Result r, JsonGenerator json) throws IOException {
        int c = 0;
        json.writeArrayFieldStart("blend");
        for (BlendSpec.Weighted w : r.blend.base()) {
            json.writeStartObject();
            json.writeStringField("clip", w.clip());
            json.writeNumberField("weight", w.weight());
            writeTimes(json, r.clipTimes[c++]);
            json.writeEndObject();
        }
        json.writeEndArray();
        json.writeArrayFieldStart("additive");
        for (BlendSpec.Additive a : r.blend.additive()) {
            json.writeStartObject();
            json.writeStringField("clip", a.clip());
            json.writeNumberField("weight", a.weight());
            json.writeNumberField("referenceTime", a.referenceTime());
            writeTimes(json, r.clipTimes[c++]);
            json.writeEndObject();
        }
        json.writeEndArray();
    }

    private static void writeTimes(JsonGenerator json, float[] times) throws IOException {
        json.writeArrayFieldStart("times");
        for (float t : times) {
            json.writeNumber(t);
        }
        json.writeEndArray();
    }

    /** The human summary: what was played, then each mesh's bounding box at each time. */
    static String text(Result r) {
        StringBuilder sb = new StringBuilder();
        sb.append(r.file).append('\n');
        sb.append("  clip:   ").append(r.blend != null ? "blend " + r.blend.describe()
                : r.clip == null ? "none (rest pose)" : r.clip).append(", method ").append(r.method.key()).append('\n');
        sb.append("  times:  ");
        for (int t = 0; t < r.times.length; t++) {
            sb.append(t == 0 ? "" : ", ").append(Float.toString(r.times[t]));
        }
        sb.append(" s\n");
        for (int g = 0; g < r.meshes.size(); g++) {
            Mesh mesh = r.meshes.get(g);
            sb.append(String.format(Locale.ROOT, "  %s%s: %d positions%n", mesh.id(),
                    mesh.name() == null || mesh.name().equals(mesh.id()) ? "" : " (" + mesh.name() + ")",
                    mesh.positionCount()));
            for (int t = 0; t < r.times.length; t++) {
                float[] p = r.poses[g][t];
                float[] lo = {Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY, Float.POSITIVE_INFINITY};
                float[] hi = {Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY, Float.NEGATIVE_INFINITY};
                for (int i = 0; i < p.length; i++) {
                    lo[i % 3] = Math.min(lo[i % 3], p[i]);
                    hi[i % 3] = Math.max(hi[i % 3], p[i]);
                }
                sb.append(String.format(Locale.ROOT, "    t=%-9s box (%.4f, %.4f, %.4f) .. (%.4f, %.4f, %.4f)%n",
                        Float.toString(r.times[t]), lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]));
            }
        }
        return sb.toString();
    }

    static final class TimeConverter implements CommandLine.ITypeConverter<Float> {
        @Override
        public Float convert(String value) {
            String s = value.trim();
            if (!Decimal.matches(s)) {
                throw new CommandLine.TypeConversionException("'" + value + "' is not a time in seconds (a decimal number)");
            }
            float t = Float.parseFloat(s);
            if (Float.isInfinite(t)) {
                throw new CommandLine.TypeConversionException("'" + value + "' is beyond the float range");
            }
            return t;
        }
    }

    static final class RotationConverter implements CommandLine.ITypeConverter<RotationInterpolation> {
        @Override
        public RotationInterpolation convert(String value) {
            for (RotationInterpolation r : RotationInterpolation.values()) {
                if (r.name().equalsIgnoreCase(value)) {
                    return r;
                }
            }
            throw new CommandLine.TypeConversionException("'" + value + "' is not a rotation interpolation (expected "
                    + "slerp, nlerp or lerp)");
        }
    }
}
