package org.skinlab.desktop.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;

import org.skinlab.animation.RotationInterpolation;
import org.skinlab.desktop.CommandFailure;
import org.skinlab.desktop.ExitCodes;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.internal.metrics.JointArtifacts;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.internal.metrics.RestPose;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code skinlab compare FILE --joint NAME [--time T,...] [--method KEY,...|all]}: where each
 * skinning method wins at one joint of a user's file, as a markdown table per time and per part
 * whose points the joint and its parent share: the part's volume, joint ring, bulge, and the
 * distance to every other method compared ({@code JointArtifacts}, docs/skinning.md), all against
 * the model's rest pose ({@link RestPose}); each part says why its volume is missing, and parts
 * with no such point are named on one line. Every method by default, or the ones named, in
 * {@link SkinningMethod}'s order.
 */
@Command(name = "compare", mixinStandardHelpOptions = true,
        description = {"The skinning methods at one joint: volume kept, joint ring, bulge, distance between the methods "
                + "(a markdown table per time)."})
public final class CompareCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "FILE", description = "a model file (.dae, .gltf, .glb)")
    Path file;

    @Option(names = "--joint", required = true, paramLabel = "NAME",
            description = "the joint (node name, id or sid) whose region is measured with its parent's bone")
    String joint;

    @Option(names = "--time", split = ",", paramLabel = "T", description = "clip times in seconds (default: the clip's"
            + " start, middle and end)")
    List<Float> times;

    @Option(names = "--method", split = ",", paramLabel = MethodKeys.KEYS_OR_ALL,
            description = "the methods compared, comma-separated, or all (default: all)")
    List<String> methods = List.of("all");

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        List<SkinningMethod> compared = compared();
        Model model = ModelFiles.load(file).model;
        SkinnedModel skinned = new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0),
                NormalTransform.INVERSE_TRANSPOSE, EnumSet.copyOf(compared));
        PrintWriter out = spec.commandLine().getOut();
        RestPose rest = RestPose.of(skinned);
        int found = 0;
        int measured = 0;
        List<String> without = new ArrayList<>();
        String parentName = null;
        for (int g = 0; g < skinned.geometries().size(); g++) {
            SkinnedGeometry geometry = skinned.geometries().get(g);
            int j = paletteIndex(model, geometry, joint);
            if (j < 0) {
                continue;
            }
            int p = geometry.jointParent(j);
            if (p < 0) {
                throw new CommandFailure(ExitCodes.USAGE, joint + " has no parent joint in its skin: no joint region"
                        + " to measure", null);
            }
            found++;
            parentName = name(model, geometry.jointNode(p));
            JointArtifacts artifacts = new JointArtifacts(rest, g, j, p);
            if (artifacts.regionSize() == 0) {
                without.add(part(model, geometry));
                continue;
            }
            out.printf(Locale.ROOT, "%s%s, %s: joint %s with parent %s, %d points in the joint region%n",
                    measured++ > 0 ? "\n" : "", file.getFileName(), part(model, geometry), joint, parentName,
                    artifacts.regionSize());
            out.printf(Locale.ROOT, "volume: %s; distances over the model's size, %.4g (its rest pose's bounds)%n",
                    rest.partVolume(g) == RestPose.PartVolume.CLOSED ? "the part's, against its own rest"
                            : "- (the part is " + rest.partNote(g) + ")", rest.size());
            tables(out, skinned, g, artifacts, compared);
        }
        if (found == 0) {
            throw new CommandFailure(ExitCodes.USAGE, file + ": no skin has a joint named " + joint, null);
        }
        if (!without.isEmpty()) {
            out.printf(Locale.ROOT, "%sno point of %s is weighted on both %s and %s: no joint region%n",
                    measured > 0 ? "\n" : "", String.join(", ", without), joint, parentName);
        }
        out.flush();
        return ExitCodes.OK;
    }

    /** Part g's table at each time: every compared method's numbers at the joint. */
    private void tables(PrintWriter out, SkinnedModel skinned, int g, JointArtifacts artifacts,
            List<SkinningMethod> compared) {
        float start = skinned.sampler().start();
        float end = skinned.sampler().end();
        List<Float> at = times != null ? times : List.of(start, (start + end) / 2, end);
        int points = skinned.geometries().get(g).pointCount();
        for (float t : at) {
            skinned.pose(skinned.sampler().clamp(t), RotationInterpolation.SLERP);
            Map<SkinningMethod, float[]> posed = new EnumMap<>(SkinningMethod.class);
            for (SkinningMethod m : compared) {
                float[] positions = new float[3 * points];
                skinned.skin(g, m, positions, new float[positions.length]);
                posed.put(m, positions);
            }
            table(out, t, compared, artifacts.report(posed, skinned.palette(g).matrices()));
        }
    }

    /** The methods --method names, each once, in the enum's order. */
    private List<SkinningMethod> compared() {
        java.util.EnumSet<SkinningMethod> set = java.util.EnumSet.noneOf(SkinningMethod.class);
        for (String key : methods) {
            set.addAll(MethodKeys.parseOneOrAll("--method", key.trim()));
        }
        return new ArrayList<>(set);
    }

    private static void table(PrintWriter out, float time, List<SkinningMethod> methods,
            List<JointArtifacts.Report> reports) {
        List<String> names = new ArrayList<>();
        methods.forEach(m -> names.add(label(m)));
        out.printf(Locale.ROOT, "%n| t = %.3f s | volume / rest | joint ring / rest | bulge | distance to %s |%n",
                time, String.join(" | ", names));
        out.println("|---|---:|---:|---:|" + "---:|".repeat(methods.size()));
        for (JointArtifacts.Report r : reports) {
            List<String> cells = new ArrayList<>();
            for (SkinningMethod other : methods) {
                Double d = r.distanceTo().get(other);
                cells.add(d == null ? "" : String.format(Locale.ROOT, "%.4f", d));
            }
            out.printf(Locale.ROOT, "| %s | %s | %s | %s | %s |%n", label(r.method()), number(r.volume()),
                    number(r.ringRadius()), number(r.bulge()), String.join(" | ", cells));
        }
    }

    /** A method in the tables: its key in capitals (LBS, STBS-DQS). */
    private static String label(SkinningMethod m) {
        return m.key().toUpperCase(Locale.ROOT);
    }

    private static String number(double v) {
        return Double.isNaN(v) ? "-" : String.format(Locale.ROOT, "%.4f", v);
    }

    private static String name(Model model, int node) {
        if (node < 0) {
            return "(bind shape)";
        }
        Node n = model.node(node);
        return n.name() != null ? n.name() : n.id();
    }

    /** A part by its mesh and, when it has one, the name of the node that places it. */
    private static String part(Model model, SkinnedGeometry geometry) {
        if (geometry.instance() == null) {
            return "mesh ?";
        }
        Node node = model.node(geometry.instance().node());
        String mesh = geometry.mesh().name() != null ? geometry.mesh().name() : geometry.mesh().id();
        boolean sameName = node.name() == null || node.name().equals(mesh);
        return sameName ? "mesh " + mesh : "mesh " + mesh + " (node " + node.name() + ")";
    }

    private static int paletteIndex(Model model, SkinnedGeometry g, String name) {
        for (int j = 0; j < g.jointCount(); j++) {
            int node = g.jointNode(j);
            if (node >= 0) {
                Node n = model.node(node);
                if (name.equals(n.name()) || name.equals(n.id()) || name.equals(n.sid())) {
                    return j;
                }
            }
        }
        return -1;
    }
}
