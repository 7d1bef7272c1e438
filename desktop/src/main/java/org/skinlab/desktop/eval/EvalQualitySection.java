package org.skinlab.desktop.eval;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

import org.knowm.xchart.XYChart;
import org.knowm.xchart.XYChartBuilder;
import org.knowm.xchart.style.Styler;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.desktop.ModelFileSearch;
import org.skinlab.desktop.ModelFiles;
import org.skinlab.model.Model;
import org.skinlab.model.Node;
import org.skinlab.skinning.InfluenceCapError;
import org.skinlab.skinning.ArtifactMetrics;
import org.skinlab.skinning.JointArtifacts;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.RestPose;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * Section "quality": what each method does to the shape, over each clip of the cylinders and the
 * characters. Every measure is {@link JointArtifacts}' (as {@code skinlab compare} prints it): the
 * volume kept, the joint ring's distance from the bones over its rest distance, the bulge beyond
 * the rest distance, and the largest distance between two methods over the model's size; the cap
 * errors are {@link InfluenceCapReport}'s (as {@code skinlab inspect} prints them). Per asset the
 * measured geometry is its largest one with a joint region, the joint the one whose region (points
 * weighted on it and its parent) is largest; the joint angle is the rotation between the joint's
 * and its parent's skinning matrices (0 in the bind pose).
 */
final class EvalQualitySection implements EvalSection {
    /** Samples per clip in a quick run (evenly spaced, both ends included); a full run takes 30 per second. */
    static final int QUICK_SAMPLES = 9;
    private static final List<String> FOLDERS = List.of("assets/cylinders", "assets/characters", "assets/creatures");

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
        return context.quick() ? 6 : 20;
    }

    @Override
    public void measure(EvalContext context, ObjectNode results) {
        boolean quick = context.quick();
        if (quick) {
            results.put("samplesPerClip", QUICK_SAMPLES);
        } else {
            results.put("samplesPerSecond", InfluenceCapError.SAMPLES_PER_SECOND);
        }
        results.put("capSamplesPerSecond", InfluenceCapError.SAMPLES_PER_SECOND);
        results.put("cap4", InfluenceCapReport.CAP_4);
        results.put("cap8", InfluenceCapReport.CAP_8);
        List<Path> files = new ArrayList<>();
        for (String folder : FOLDERS) {
            Path dir = context.root().resolve(folder);
            for (ModelFileSearch.Entry e : ModelFileSearch.expand(List.of(dir), ModelFileSearch.COLLADA)) {
                files.add(e.path());
            }
        }
        // The thesis' cowboy: the one file here with more influences than 4, which the caps need.
        Path cowboy = context.corpus() == null ? null : context.corpus().resolve(EvalTimeSection.THESIS.get(0).file());
        if (cowboy != null && Files.isRegularFile(cowboy)) {
            files.add(cowboy);
        } else {
            results.put("cowboySkipped", "no " + EvalTimeSection.THESIS.get(0).file() + " in the shared corpus at "
                    + context.corpusPlace());
        }
        ArrayNode assets = results.putArray("assets");
        for (int f = 0; f < files.size(); f++) {
            asset(files.get(f), quick, assets.addObject());
            context.progress((double) (f + 1) / files.size());
        }
    }

    private static void asset(Path file, boolean quick, ObjectNode asset) {
        asset.put("file", file.getFileName().toString());
        Model model = ModelFiles.load(file).model;
        SkinnedModel skinned = new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0),
                NormalTransform.INVERSE_TRANSPOSE);
        Measured measured = largestRegion(skinned);
        if (measured == null) {
            asset.put("skipped", "no skinned geometry has a joint whose parent is in its skin");
            return;
        }
        int g = measured.geometry();
        int joint = measured.joint();
        int parent = measured.parent();
        JointArtifacts artifacts = measured.artifacts();
        SkinnedGeometry geometry = skinned.geometries().get(g);
        putRegion(asset, model, geometry, measured);
        // The bulge in percent of the model's size (the distances' unit): model units rounded to 3
        // decimals would step the bend's curve in thousandths of a cylinder.
        double size = ArtifactMetrics.boundsDiagonal(geometry.positionArray(), geometry.vertexCount());
        float[] times = times(skinned.sampler().start(), skinned.sampler().end(), quick);
        ArrayNode t = asset.putArray("times");
        ArrayNode angles = asset.putArray("angleDegrees");
        Map<SkinningMethod, ObjectNode> byMethod = methodNodes(asset.putObject("methods"));
        double lbsDqs = 0;
        double dqsCor = 0;
        Map<SkinningMethod, float[]> posed = posedPerMethod(geometry.pointCount());
        float[] normals = new float[3 * geometry.pointCount()];
        for (float time : times) {
            skinned.pose(time, RotationInterpolation.SLERP);
            for (SkinningMethod m : SkinningMethod.values()) {
                skinned.skin(g, m, posed.get(m), normals);
            }
            float[] matrices = skinned.palette(g).matrices();
            t.add(EvalReport.round(time));
            angles.add(EvalReport.round(Math.toDegrees(relativeAngle(matrices, parent, joint))));
            for (JointArtifacts.Report r : artifacts.report(posed, matrices)) {
                addSample(byMethod.get(r.method()), r, size);
                if (r.method() == SkinningMethod.LBS) {
                    lbsDqs = Math.max(lbsDqs, r.distanceTo().get(SkinningMethod.DQS));
                } else if (r.method() == SkinningMethod.DQS) {
                    dqsCor = Math.max(dqsCor, r.distanceTo().get(SkinningMethod.COR));
                }
            }
        }
        putExtremes(byMethod);
        // Relative to the model's size: in percent, so that 3 decimals keep small differences.
        asset.put("maxLbsDqsPercent", EvalReport.round(100 * lbsDqs));
        asset.put("maxDqsCorPercent", EvalReport.round(100 * dqsCor));
        caps(model, geometry, asset);
    }

    /** The measured joint region: its mesh, joint and parent by name, and its points. */
    private static void putRegion(ObjectNode asset, Model model, SkinnedGeometry geometry, Measured measured) {
        asset.put("mesh", geometry.mesh() == null ? "?" : geometry.mesh().id());
        asset.put("joint", name(model, geometry.jointNode(measured.joint())));
        asset.put("parent", name(model, geometry.jointNode(measured.parent())));
        asset.put("regionPoints", measured.artifacts().regionSize());
    }

    /** A position array per method for {@code points} points. */
    private static Map<SkinningMethod, float[]> posedPerMethod(int points) {
        Map<SkinningMethod, float[]> posed = new EnumMap<>(SkinningMethod.class);
        for (SkinningMethod m : SkinningMethod.values()) {
            posed.put(m, new float[3 * points]);
        }
        return posed;
    }

    /** One sample of a method's region: volume, ring radius and bulge (in percent of {@code size} when known). */
    private static void addSample(ObjectNode node, JointArtifacts.Report r, double size) {
        add((ArrayNode) node.get("volume"), r.volume());
        add((ArrayNode) node.get("ringRadius"), r.ringRadius());
        add((ArrayNode) node.get("bulge"), size > 0 ? 100 * r.bulge() / size : r.bulge());
    }

    /** Each method's least volume and ring radius and its largest bulge over the samples. */
    private static void putExtremes(Map<SkinningMethod, ObjectNode> byMethod) {
        for (SkinningMethod m : SkinningMethod.values()) {
            ObjectNode node = byMethod.get(m);
            extreme(node, "volume", "minVolume", false);
            extreme(node, "ringRadius", "minRingRadius", false);
            extreme(node, "bulge", "maxBulge", true);
        }
    }

    /** The joint measured in a file: its geometry, palette indices and the region it moves. */
    private record Measured(int geometry, int joint, int parent, JointArtifacts artifacts) {
    }

    /**
     * The joint with the largest region (of points it and its parent move) in the geometry with
     * the most points that has one; null when no joint's parent is in its skin.
     */
    private static Measured largestRegion(SkinnedModel skinned) {
        int g = -1;
        int joint = -1;
        int parent = -1;
        JointArtifacts artifacts = null;
        RestPose rest = RestPose.of(skinned);
        for (int k = 0; k < skinned.geometries().size(); k++) {
            SkinnedGeometry geometry = skinned.geometries().get(k);
            if (g >= 0 && geometry.pointCount() <= skinned.geometries().get(g).pointCount()) {
                continue;
            }
            for (int j = 0; j < geometry.jointCount(); j++) {
                int p = geometry.jointParent(j);
                if (p < 0) {
                    continue;
                }
                JointArtifacts a = new JointArtifacts(rest, k, j, p);
                if (a.regionSize() > 0 && (artifacts == null || k != g || a.regionSize() > artifacts.regionSize())) {
                    g = k;
                    joint = j;
                    parent = p;
                    artifacts = a;
                }
            }
        }
        return artifacts == null ? null : new Measured(g, joint, parent, artifacts);
    }

    /** Per method, its node with the empty series filled per sampled time. */
    private static Map<SkinningMethod, ObjectNode> methodNodes(ObjectNode methods) {
        Map<SkinningMethod, ObjectNode> byMethod = new EnumMap<>(SkinningMethod.class);
        for (SkinningMethod m : SkinningMethod.values()) {
            ObjectNode node = methods.putObject(m.key());
            node.putArray("volume");
            node.putArray("ringRadius");
            node.putArray("bulge");
            byMethod.put(m, node);
        }
        return byMethod;
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

    private static double zeroIfNaN(double d) {
        return Double.isNaN(d) ? 0 : d;
    }

    static float[] times(float start, float end, boolean quick) {
        if (!quick) {
            return InfluenceCapError.sampleTimes(start, end);
        }
        float[] times = new float[QUICK_SAMPLES];
        for (int i = 0; i < QUICK_SAMPLES; i++) {
            times[i] = start + (end - start) * i / (QUICK_SAMPLES - 1);
        }
        return times;
    }

    /** The angle (radians) of the rotation from joint p's skinning matrix to joint j's (3x4 row-major each). */
    static double relativeAngle(float[] m, int p, int j) {
        // trace(Rp^T Rj) = sum of the products of matching entries; columns normalised against bone scale.
        double trace = 0;
        for (int c = 0; c < 3; c++) {
            double dot = 0;
            double np = 0;
            double nj = 0;
            for (int r = 0; r < 3; r++) {
                double a = m[12 * p + 4 * r + c];
                double b = m[12 * j + 4 * r + c];
                dot += a * b;
                np += a * a;
                nj += b * b;
            }
            trace += np > 0 && nj > 0 ? dot / Math.sqrt(np * nj) : 0;
        }
        return Math.acos(Math.max(-1, Math.min(1, (trace - 1) / 2)));
    }

    private static void add(ArrayNode array, double value) {
        if (Double.isNaN(value)) {
            array.addNull();
        } else {
            array.add(EvalReport.round(value));
        }
    }

    private static void extreme(ObjectNode node, String series, String key, boolean max) {
        double best = Double.NaN;
        for (JsonNode v : node.get(series)) {
            if (v.isNumber() && (Double.isNaN(best) || (max ? v.asDouble() > best : v.asDouble() < best))) {
                best = v.asDouble();
            }
        }
        if (Double.isNaN(best)) {
            node.putNull(key);
        } else {
            node.put(key, best);
        }
    }

    private static String name(Model model, int node) {
        Node n = model.node(node);
        return n.name() != null ? n.name() : n.id();
    }

    @Override
    public void report(JsonNode results, EvalReport report) {
        report.paragraph("Each asset's first clip, sampled " + (results.has("samplesPerClip")
                ? EvalReport.num(results, "/samplesPerClip") + " times from start to end"
                : EvalReport.num(results, "/samplesPerSecond") + " times a second") + ", deformed by each method;"
                + " measured as `skinlab compare` measures (docs/skinning.md): the volume over the rest volume (closed"
                + " meshes), the joint ring's distance from the bones over its rest distance (the candy wrapper collapses"
                + " it), the bulge (how far the joint region stands out beyond its rest distance, in"
                + " percent of the model's size) and the largest distance between two methods' points, in percent of the model's size."
                + " The joint is the one with the largest joint region; its angle is the rotation from the bind pose"
                + " between it and its parent.");
        if (results.has("cowboySkipped")) {
            report.paragraph("The thesis' cowboy is skipped: `" + results.get("cowboySkipped").asText() + "`.");
        }
        List<String> header = new ArrayList<>(List.of("asset", "joint"));
        for (String measure : new String[] {"min volume", "min ring"}) {
            for (SkinningMethod m : SkinningMethod.values()) {
                header.add(m.key().toUpperCase(Locale.ROOT) + " " + measure);
            }
        }
        header.add("max abs(LBS - DQS) %");
        header.add("max abs(DQS - CoR) %");
        report.header(header.toArray(new String[0]));
        JsonNode assets = results.get("assets");
        for (int a = 0; a < assets.size(); a++) {
            JsonNode asset = assets.get(a);
            String p = "/assets/" + a;
            if (asset.has("skipped")) {
                String[] row = new String[header.size()];
                java.util.Arrays.fill(row, "");
                row[0] = "`" + asset.get("file").asText() + "`";
                row[1] = "skipped: " + asset.get("skipped").asText();
                report.row(row);
                continue;
            }
            List<String> cells = new ArrayList<>();
            cells.add("`" + asset.get("file").asText() + "`");
            cells.add("`" + asset.get("joint").asText() + "`");
            for (String measure : new String[] {"minVolume", "minRingRadius"}) {
                for (SkinningMethod m : SkinningMethod.values()) {
                    cells.add(EvalReport.numOrDash(results, p + "/methods/" + m.key() + "/" + measure));
                }
            }
            cells.add(EvalReport.num(results, p + "/maxLbsDqsPercent"));
            cells.add(EvalReport.num(results, p + "/maxDqsCorPercent"));
            report.row(cells.toArray(new String[0]));
        }
        report.line("");
        capTable(results, report);
        for (int a = 0; a < assets.size(); a++) {
            if (!assets.get(a).has("skipped")) {
                volumeFigure(assets.get(a), report);
            }
        }
        angleFigure(assets, "twist", "ringRadius", "joint ring / rest", "quality-twist-ring.png",
                "Joint ring radius of the twist cylinders against the twist angle", Styler.LegendPosition.InsideSW, report);
        angleFigure(assets, "bend", "bulge", "bulge (% of the model's size)", "quality-bend-bulge.png",
                "Bulge of the bend cylinder against the bend angle", Styler.LegendPosition.InsideNW, report);
    }

    private static void capTable(JsonNode results, EvalReport report) {
        report.paragraph("The error that capping influences causes (`InfluenceCapReport`, as `skinlab inspect` prints"
                + " it: every clip at "
                + EvalReport.num(results, "/capSamplesPerSecond") + " samples a second): the largest distance a position moves when only its "
                + EvalReport.num(results, "/cap4") + " or " + EvalReport.num(results, "/cap8") + " heaviest influences"
                + " are kept, in percent of the model's size. An asset with no more influences than the cap loses"
                + " nothing.");
        report.header("asset", "influences", "cap", "positions capped", "LBS error %", "DQS error %");
        JsonNode assets = results.get("assets");
        for (int a = 0; a < assets.size(); a++) {
            JsonNode caps = assets.get(a).get("caps");
            if (caps == null) {
                continue;
            }
            for (int c = 0; c < caps.size(); c++) {
                String p = "/assets/" + a + "/caps/" + c;
                report.row("`" + assets.get(a).get("file").asText() + "`", EvalReport.num(results, "/assets/" + a
                        + "/influences"), EvalReport.num(results, p + "/cap"), EvalReport.num(results,
                        p + "/cappedPositions"), EvalReport.num(results, p + "/lbsPercent"),
                        EvalReport.num(results, p + "/dqsPercent"));
            }
        }
        report.line("");
    }

    /** Volume over rest against clip time, one line per method (closed meshes only). */
    private static void volumeFigure(JsonNode asset, EvalReport report) {
        String file = asset.get("file").asText();
        XYChart chart = new XYChartBuilder().width(900).height(500).title("Volume over rest: " + file)
                .xAxisTitle("clip time (s)").yAxisTitle("volume / rest").build();
        chart.getStyler().setLegendPosition(Styler.LegendPosition.InsideSW);
        int series = 0;
        for (SkinningMethod m : SkinningMethod.values()) {
            series += addSeries(chart, m.key().toUpperCase(Locale.ROOT), asset.get("times"),
                    asset.at("/methods/" + m.key() + "/volume")) ? 1 : 0;
        }
        if (series > 0) {
            String png = "quality-volume-" + file.replaceAll("\\.dae$", "").replaceAll("[^A-Za-z0-9_-]", "_") + ".png";
            report.figure(png, "Volume over rest against clip time, " + file, chart);
        } else {
            report.paragraph("`" + file + "`: not a closed mesh, so no volume.");
        }
    }

    /** A measure against the joint angle for the assets whose file name has {@code kind}, a line per method and asset. */
    private static void angleFigure(JsonNode assets, String kind, String measure, String axis, String png,
            String caption, Styler.LegendPosition legend, EvalReport report) {
        XYChart chart = new XYChartBuilder().width(900).height(500).title(caption)
                .xAxisTitle("joint angle (degrees)").yAxisTitle(axis).build();
        chart.getStyler().setLegendPosition(legend);
        int series = 0;
        for (JsonNode asset : assets) {
            String file = asset.get("file").asText();
            if (asset.has("skipped") || !file.contains(kind)) {
                continue;
            }
            for (SkinningMethod m : SkinningMethod.values()) {
                series += addSeries(chart, m.key().toUpperCase(Locale.ROOT) + " " + file.replaceAll("\\.dae$", ""),
                        asset.get("angleDegrees"), asset.at("/methods/" + m.key() + "/" + measure)) ? 1 : 0;
            }
        }
        if (series > 0) {
            report.figure(png, caption, chart);
        }
    }

    /** Adds the (x, y) pairs whose y is a number; false when none is. */
    private static boolean addSeries(XYChart chart, String name, JsonNode xs, JsonNode ys) {
        List<Double> x = new ArrayList<>();
        List<Double> y = new ArrayList<>();
        for (int i = 0; i < xs.size(); i++) {
            if (ys.get(i).isNumber()) {
                x.add(xs.get(i).asDouble());
                y.add(ys.get(i).asDouble());
            }
        }
        if (x.isEmpty()) {
            return false;
        }
        chart.addSeries(name, x, y);
        return true;
    }
}
