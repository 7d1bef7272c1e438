package org.skinlab.desktop.eval;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.skinlab.desktop.ModelFileSearch;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.internal.metrics.ArtifactMetrics;
import org.skinlab.internal.metrics.InfluenceCapError;
import org.skinlab.internal.metrics.JointArtifacts;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * Section "quality": what each method does to the shape, over the first clip of every skinned
 * asset of ours and the corpus' characters, every method. At one joint of the largest geometry
 * (the largest region, points weighted on it and its parent, among the joints that move: {@link
 * MeasuredJoint#choose}): the volume kept, the joint
 * ring's distance from the bones and its turn about the joint's axis ({@link RingTurn}), the bulge
 * beyond the rest distance ({@link JointArtifacts}, as {@code skinlab compare} measures), each
 * against the joint's unwrapped angle ({@link JointAngle}), so that a twist or bend to 360
 * degrees reads as one; the values at stated angles are measured at those angles (the clip time
 * is found by bisection), the extremes are given as extremes with where they happen. Then every
 * pair of methods: how far apart they place points, in the scene and on a phone's screen
 * ({@link MethodPairs}, {@link PhoneView}); and the error of capping influences
 * ({@link InfluenceCapReport}). The report is {@link EvalQualityReport}.
 */
final class EvalQualitySection implements EvalSection {
    /** Samples per second of clip: a full run's (the caps' rate) and a quick run's. */
    static final int SAMPLES_PER_SECOND = InfluenceCapError.SAMPLES_PER_SECOND;
    static final int QUICK_SAMPLES_PER_SECOND = 10;
    /** The angles values are quoted at, where a clip reaches them (never 180: a half turn has no sign). */
    static final double[] QUOTED_DEGREES = {45, 90, 135, 170, 179, 181, 190, 225, 270, 315, 360};
    /** Files whose joint turns about one axis, whose values are quoted at {@link #QUOTED_DEGREES}. */
    static final List<String> ANGLE_KINDS = List.of("twist", "bend");
    private static final double ANGLE_TOLERANCE = 0.005;

    @Override
    public String key() {
        return "quality";
    }

    @Override
    public String title() {
        return "Quality";
    }

    @Override
    public double estimatedSeconds(EvalContext context) {
        return context.quick() ? 12 : 45;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        boolean quick = context.quick();
        results.put("samplesPerSecond", quick ? QUICK_SAMPLES_PER_SECOND : SAMPLES_PER_SECOND);
        results.put("capSamplesPerSecond", InfluenceCapError.SAMPLES_PER_SECOND);
        results.put("cap4", InfluenceCapReport.CAP_4);
        results.put("cap8", InfluenceCapReport.CAP_8);
        results.put("angleToleranceDegrees", ANGLE_TOLERANCE);
        results.put("movingDegrees", MeasuredJoint.MOVING_DEGREES);
        results.put("halfTurnDegrees", MeasuredJoint.HALF_TURN_DEGREES);
        ArrayNode quoted = results.putArray("quotedDegrees");
        for (double d : QUOTED_DEGREES) {
            quoted.add(d);
        }
        putPhone(results.putObject("phone"));
        List<Path> files = files(context, results);
        ArrayNode assets = results.putArray("assets");
        for (int f = 0; f < files.size(); f++) {
            asset(files.get(f), quick, assets.addObject());
            context.progress((double) (f + 1) / files.size());
        }
    }

    private static void putPhone(ObjectNode phone) {
        phone.put("characterMetres", PhoneView.CHARACTER_METRES);
        phone.put("distanceMetres", PhoneView.DISTANCE_METRES);
        phone.put("width", PhoneView.WIDTH);
        phone.put("height", PhoneView.HEIGHT);
        phone.put("fovDegrees", PhoneView.FOV_DEGREES);
        phone.put("focalPixels", EvalReport.round(PhoneView.FOCAL_PIXELS));
        phone.put("views", PhoneView.VIEWS);
    }

    /** Our skinned assets, then the corpus' characters the time section times. */
    private static List<Path> files(EvalContext context, ObjectNode results) {
        List<Path> files = new ArrayList<>();
        for (ModelFileSearch.Entry e : ModelFileSearch.expand(List.of(context.root().resolve("assets")),
                ModelFileSearch.COLLADA)) {
            Model model = ModelFiles.load(e.path()).model;
            if (model.instances().stream().anyMatch(MeshInstance::isSkinned) && !model.clips().isEmpty()) {
                files.add(e.path());
            }
        }
        ArrayNode skipped = results.putArray("corpusSkipped");
        for (String name : EvalTimeSection.CORPUS) {
            Path f = context.corpus() == null ? null : context.corpus().resolve(name);
            if (f != null && Files.isRegularFile(f)) {
                files.add(f);
            } else {
                skipped.add(name + ": not in the shared corpus at " + context.corpusPlace());
            }
        }
        return files;
    }

    private static void asset(Path file, boolean quick, ObjectNode asset) {
        String name = file.getFileName().toString();
        asset.put("file", name);
        Model model = ModelFiles.load(file).model;
        SkinnedModel skinned = new SkinnedModel(model, model.clips().get(0), NormalTransform.INVERSE_TRANSPOSE);
        PosedMethods posed = new PosedMethods(model, skinned);
        float start = skinned.sampler().start();
        float[] times = times(start, skinned.sampler().end(), quick ? QUICK_SAMPLES_PER_SECOND : SAMPLES_PER_SECOND);
        posed.pose(times[0]);
        double[][] bounds = posed.bounds(SkinningMethod.LBS);
        double size = Math.sqrt(square(bounds[1][0] - bounds[0][0]) + square(bounds[1][1] - bounds[0][1])
                + square(bounds[1][2] - bounds[0][2]));
        asset.put("sizeMetres", EvalReport.round(size));
        asset.put("clipSeconds", EvalReport.round(skinned.sampler().end() - start));
        MethodPairs pairs = new MethodPairs(new PhoneView(bounds[0], bounds[1]), posed.points());
        MeasuredJoint joint = MeasuredJoint.choose(skinned, times);
        if (joint == null) {
            asset.put("skipped", "no skinned geometry has a joint whose parent is in its skin");
        } else {
            putJoint(asset, model, skinned, joint);
        }
        ArrayNode t = asset.putArray("times");
        ArrayNode angles = asset.putArray("angleDegrees");
        Map<SkinningMethod, ObjectNode> byMethod = methodNodes(asset.putObject("methods"));
        double unwrapped = 0;
        double signed = 0;
        for (int i = 0; i < times.length; i++) {
            posed.pose(times[i]);
            pairs.add(posed, times[i] - start);
            t.add(EvalReport.round(times[i] - start));
            if (joint != null) {
                float[] matrices = skinned.palette(joint.geometry).matrices();
                double s = joint.angle.signedDegrees(matrices);
                unwrapped = i == 0 ? s : JointAngle.continued(unwrapped, signed, s);
                signed = s;
                angles.add(EvalReport.round(unwrapped));
                joint.measure(posed, matrices, unwrapped, byMethod);
            }
        }
        pairs.put(asset.putArray("pairs"), size);
        if (joint != null) {
            putExtremes(byMethod);
            if (ANGLE_KINDS.stream().anyMatch(name::contains)) {
                atAngles(asset, skinned, posed, joint, times, byMethod);
            }
            caps(model, skinned.geometries().get(joint.geometry), asset);
        }
    }

    /** The measured joint and region: mesh, joint and parent by name, and the region's points. */
    private static void putJoint(ObjectNode asset, Model model, SkinnedModel skinned, MeasuredJoint joint) {
        SkinnedGeometry geometry = skinned.geometries().get(joint.geometry);
        asset.put("mesh", geometry.mesh() == null ? "?" : geometry.mesh().id());
        asset.put("joint", name(model, geometry.jointNode(joint.joint)));
        asset.put("parent", name(model, geometry.jointNode(joint.parent)));
        asset.put("regionPoints", joint.artifacts.regionSize());
        asset.put("closed", ArtifactMetrics.isClosed(geometry));
    }

    /**
     * The measures at each quoted angle the clip reaches, at the clip time where the joint's
     * unwrapped angle is that angle (bisection between the two samples around its first crossing).
     */
    private static void atAngles(ObjectNode asset, SkinnedModel skinned, PosedMethods posed, MeasuredJoint joint,
            float[] times, Map<SkinningMethod, ObjectNode> byMethod) {
        JsonNode angles = asset.get("angleDegrees");
        ArrayNode out = asset.putArray("atAngles");
        float start = skinned.sampler().start();
        for (double target : QUOTED_DEGREES) {
            int k = crossing(angles, target);
            if (k < 0) {
                continue;
            }
            double lo = times[k];
            double hi = times[Math.min(k + 1, times.length - 1)];
            double unwrappedLo = angles.get(k).asDouble();
            posed.pose((float) lo);
            double signedLo = joint.angle.signedDegrees(skinned.palette(joint.geometry).matrices());
            double t = lo;
            double angle = unwrappedLo;
            for (int i = 0; i < 60 && Math.abs(angle - target) > ANGLE_TOLERANCE && hi > lo; i++) {
                t = (lo + hi) / 2;
                posed.pose((float) t);
                angle = JointAngle.continued(unwrappedLo, signedLo,
                        joint.angle.signedDegrees(skinned.palette(joint.geometry).matrices()));
                if ((angle < target) == (angles.get(k).asDouble() < target)) {
                    lo = t;
                } else {
                    hi = t;
                }
            }
            posed.pose((float) t);
            Map<SkinningMethod, ObjectNode> at = methodNodes(out.addObject().put("angleDegrees", target)
                    .put("time", EvalReport.round(t - start)).putObject("methods"));
            joint.measure(posed, skinned.palette(joint.geometry).matrices(), target, at);
        }
    }

    /** The first sample k where the angle reaches {@code target} between samples k and k + 1 (or at k); -1 if never. */
    private static int crossing(JsonNode angles, double target) {
        for (int k = 0; k < angles.size(); k++) {
            double a = angles.get(k).asDouble();
            if (Math.abs(a - target) <= ANGLE_TOLERANCE) {
                return k;
            }
            if (k + 1 < angles.size() && (a - target) * (angles.get(k + 1).asDouble() - target) < 0) {
                return k;
            }
        }
        return -1;
    }

    /** Per method, its node with the empty series filled per sampled time. */
    private static Map<SkinningMethod, ObjectNode> methodNodes(ObjectNode methods) {
        Map<SkinningMethod, ObjectNode> byMethod = new EnumMap<>(SkinningMethod.class);
        for (SkinningMethod m : SkinningMethod.values()) {
            ObjectNode node = methods.putObject(m.key());
            node.putArray("volume");
            node.putArray("ringRadius");
            node.putArray("bulge");
            node.putArray("ringTurnDegrees");
            byMethod.put(m, node);
        }
        return byMethod;
    }

    /** Each method's least volume and ring radius and its largest bulge over the samples, with the sample's index. */
    private static void putExtremes(Map<SkinningMethod, ObjectNode> byMethod) {
        for (ObjectNode node : byMethod.values()) {
            extreme(node, "volume", "minVolume", false);
            extreme(node, "ringRadius", "minRingRadius", false);
            extreme(node, "bulge", "maxBulge", true);
        }
    }

    private static void extreme(ObjectNode node, String series, String key, boolean max) {
        int best = -1;
        JsonNode values = node.get(series);
        for (int i = 0; i < values.size(); i++) {
            JsonNode v = values.get(i);
            if (v.isNumber() && (best < 0 || (max ? v.asDouble() > values.get(best).asDouble()
                    : v.asDouble() < values.get(best).asDouble()))) {
                best = i;
            }
        }
        if (best < 0) {
            node.putNull(key);
        } else {
            node.put(key, values.get(best).asDouble());
            node.put(key + "Sample", best);
        }
    }

    /** The cap errors of the measured geometry's mesh ({@code InfluenceCapReport}, every clip at its own 30 samples a second). */
    private static void caps(Model model, SkinnedGeometry geometry, ObjectNode asset) {
        InfluenceCapReport.MeshReport mesh = InfluenceCapReport.of(model).get(geometry.mesh());
        if (mesh == null) {
            return;
        }
        asset.put("influences", mesh.influences());
        ArrayNode caps = asset.putArray("caps");
        for (InfluenceCapReport.Cap c : mesh.caps()) {
            ObjectNode cap = caps.addObject();
            cap.put("cap", c.cap());
            cap.put("cappedPositions", c.cappedPositions());
            cap.put("lbsPercent", EvalReport.round(100 * zeroIfNaN(c.lbs().worst().relative())));
            cap.put("dqsPercent", EvalReport.round(100 * zeroIfNaN(c.dqs().worst().relative())));
        }
    }

    /** The comparison of methods {@code a} and {@code b} (keys, in {@code SkinningMethod} order) on an asset of the results. */
    static JsonNode pair(JsonNode asset, String a, String b) {
        for (JsonNode p : asset.get("pairs")) {
            if (p.get("a").asText().equals(a) && p.get("b").asText().equals(b)) {
                return p;
            }
        }
        throw new IllegalStateException("no pair " + a + " - " + b + " in " + asset.get("file"));
    }

    private static double zeroIfNaN(double d) {
        return Double.isNaN(d) ? 0 : d;
    }

    /** Clip times from start to end, {@code perSecond} a second, both ends included. */
    static float[] times(float start, float end, int perSecond) {
        int n = Math.max(2, (int) Math.ceil((end - start) * perSecond) + 1);
        float[] times = new float[n];
        for (int i = 0; i < n; i++) {
            times[i] = start + (end - start) * i / (n - 1);
        }
        return times;
    }

    private static void add(ArrayNode array, double value) {
        if (Double.isNaN(value)) {
            array.addNull();
        } else {
            array.add(EvalReport.round(value));
        }
    }

    private static double square(double d) {
        return d * d;
    }

    private static String name(Model model, int node) {
        Node n = model.node(node);
        return n.name() != null ? n.name() : n.id();
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        EvalQualityReport.write(results, report);
    }
}
