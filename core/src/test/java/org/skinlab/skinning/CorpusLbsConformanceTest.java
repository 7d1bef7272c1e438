package org.skinlab.skinning;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;

import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.collada.ColladaException;
import org.skinlab.collada.ColladaImporter;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.skinning.reference.IndependentLbs;
import org.skinlab.testing.TestPaths;

/**
 * Linear Blend Skinning at key times agrees with {@link IndependentLbs}, an evaluator that reads
 * the file with the JDK's DOM parser and shares no code with our importer, animation or skinning
 * (see its documentation): on every file of the third-party corpus ({@code ../shared/corpus};
 * skipped, saying so, when absent) that our importer reads and that has skinned meshes and
 * animation, and on our own assets.
 *
 * <p>What is compared: every entry of every placed mesh's POSITION source (skinned and static),
 * through {@link SkinnedGeometry#pointOfPosition}, at the key times of the first clip shared by
 * all its channels (at most {@value #MAX_TIMES}, evenly chosen with the first and last, to keep
 * the test fast). At a key time no interpolation is involved: the reference takes each channel's
 * key value as written, our sampler reproduces the key (see {@code AnimationSampler}).
 *
 * <p>Tolerance: the largest distance of any position from the reference, at most
 * {@value #TOLERANCE} of the file's extent (the diagonal of the bounding box of the reference's
 * positions over the checked times). Ours is float arithmetic (about 6e-8 relative per operation,
 * through joint chains ten or more deep), the reference double; the measured deviations, printed
 * in the tables, are at most 3e-7 of the extent (stormtrooper, 52 joints, 6 influences), so the
 * tolerance leaves a margin of 30, while multiplying local and parent matrices in the wrong order
 * (tried on purpose in the evaluator) shows up as 0.19 to 1.2 of the extent (the "moves up to"
 * column says how far each file's positions travel, so no comparison is between still poses).
 *
 * <p>Also here: the evaluator itself against Blender on our assets, and the importer's fixtures
 * (IDREF joints, {@code <instance_node>}, member targets such as {@code rotationY.ANGLE}, joint
 * index -1, several skins, static meshes), which the corpus lacks; fixtures without animation are
 * compared at rest.
 */
class CorpusLbsConformanceTest {
    static final double TOLERANCE = 1e-5;
    static final int MAX_TIMES = 10;

    /** One line of the printed table. */
    private static final class Row {
        final String file;
        String meshes = "";
        int times;
        double deviation = Double.NaN;
        String note = "";
        boolean compared;
        boolean failed;

        Row(String file) {
            this.file = file;
        }
    }

    @Test
    void corpusLbsAtKeyTimesAgreesWithTheIndependentEvaluator() throws Exception {
        Path corpus = TestPaths.corpusOrSkip();
        List<Row> rows = checkAll(corpus, "corpus");
        // The ten skinned, animated files of the corpus (SOURCES.md, category S) use only what the
        // evaluator implements: each one must be there and be compared, not skipped.
        for (String f : List.of("S01_cowboy.dae", "S02_bob_lamp.dae", "S03_stormtrooper.dae",
                "S11_box_nested_animation.dae", "S12_library_animation_clips.dae", "S13_letter_f_animated.dae",
                "S14_two_skinned_cubes.dae", "S15_leg_control_bones.dae", "S16_suzanne_lines.dae",
                "S17_trion_scene.dae")) {
            TestPaths.corpusFile(f);
            assertTrue(rows.stream().anyMatch(r -> r.file.equals(f) && r.compared), f + " was not compared");
        }
        assertTrue(rows.stream().anyMatch(r -> r.compared), "no corpus file was compared");
        assertNoFailures(rows);
    }

    @Test
    void ownAssetsLbsAtKeyTimesAgreesWithTheIndependentEvaluator() throws Exception {
        List<Row> rows = checkAll(TestPaths.root().resolve("assets"), "assets");
        assertEquals(10, rows.stream().filter(r -> r.compared).count(), "all ten assets compared");
        assertNoFailures(rows);
    }

    /**
     * The evaluator itself agrees with Blender: on six of our assets its LBS at every key is
     * within the tolerance of Blender 3.4's (the committed full-vertex references, see
     * docs/references.md; their own 'extent'), a check of the reference that involves none of our
     * code.
     */
    @Test
    void theIndependentEvaluatorAgreesWithBlender() throws Exception {
        for (String name : new String[] {"cylinders/cylinder-twist-low", "cylinders/cylinder-twist-full",
                "characters/humanoid-walk", "creatures/tentacle-wave", "stretch/limb-stretch", "twist/arm-twist"}) {
            IndependentLbs ref = IndependentLbs.read(TestPaths.asset(name + ".dae"));
            JsonNode blender = new ObjectMapper().readTree(TestPaths.root()
                    .resolve("assets/reference/skinning/" + name.substring(name.indexOf('/') + 1) + ".json").toFile());
            double extent = blender.get("extent").doubleValue();
            JsonNode times = blender.get("times");
            double max = 0;
            for (int k = 0; k < times.size(); k++) {
                double[] ours = ref.pose(times.get(k).doubleValue())[0];
                JsonNode theirs = blender.get("lbs").get(k);
                assertEquals(ours.length, theirs.size(), name);
                for (int i = 0; i < ours.length; i += 3) {
                    double dx = ours[i] - theirs.get(i).doubleValue();
                    double dy = ours[i + 1] - theirs.get(i + 1).doubleValue();
                    double dz = ours[i + 2] - theirs.get(i + 2).doubleValue();
                    max = Math.max(max, Math.sqrt(dx * dx + dy * dy + dz * dz));
                }
            }
            System.out.printf(Locale.ROOT, "independent LBS vs Blender, %s: max deviation / extent %.2e%n", name,
                    max / extent);
            assertTrue(max <= TOLERANCE * extent, name + ": " + max / extent + " of the extent from Blender");
        }
    }

    /**
     * The importer's own fixtures (hand-written files for IDREF joints, instance_node, several
     * skins, seven influences, member targets like {@code rotationZ.ANGLE}...): every file with a
     * placed mesh, at its key times, or at rest when it has no animation. Not {@code quirks/}: those
     * files bend the specification on purpose (decimal commas, unnamed params, morphs...), which
     * the evaluator, reading COLLADA as written, does not; ExporterQuirksTest and its neighbours
     * check them value by value.
     */
    @Test
    void importerFixturesAgreeWithTheIndependentEvaluator() throws Exception {
        Path folder = TestPaths.root().resolve("core/src/test/resources/fixtures");
        List<Path> files;
        try (Stream<Path> s = Files.walk(folder)) {
            files = s.filter(p -> p.toString().endsWith(".dae") && !folder.relativize(p).startsWith("quirks"))
                    .sorted().collect(Collectors.toList());
        }
        List<Row> rows = new ArrayList<>();
        for (Path file : files) {
            rows.add(check(file, folder.relativize(file).toString(), false));
        }
        print("importer fixtures", rows);
        List<String> compared = rows.stream().filter(r -> r.compared).map(r -> r.file.replace('\\', '/'))
                .collect(Collectors.toList());
        for (String f : List.of("robustness/skinned-quad.dae", "scene/two-characters-same-sids.dae",
                "skin/seven-influences.dae", "skin/two-skins-and-a-static-mesh.dae",
                "skin/animated-members-and-idrefs.dae")) {
            assertTrue(compared.contains(f), f + " not compared");
        }
        assertNoFailures(rows);
    }

    private static void assertNoFailures(List<Row> rows) {
        List<String> failures = rows.stream().filter(r -> r.failed).map(r -> r.file + ": " + r.note)
                .collect(Collectors.toList());
        assertEquals(List.of(), failures);
    }

    private static List<Row> checkAll(Path folder, String label) throws IOException {
        List<Path> files;
        try (Stream<Path> s = Files.walk(folder)) {
            files = s.filter(p -> p.toString().endsWith(".dae")).sorted().collect(Collectors.toList());
        }
        List<Row> rows = new ArrayList<>();
        for (Path file : files) {
            rows.add(check(file, folder.relativize(file).toString()));
        }
        print(label, rows);
        return rows;
    }

    private static void print(String label, List<Row> rows) {
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "LBS at key times vs the independent evaluator (%s; tolerance %.0e of the "
                + "extent)%n", label, TOLERANCE));
        sb.append(String.format(Locale.ROOT, "%-36s %-7s %5s %12s  %s%n", "file", "meshes", "times", "max dev/ext",
                "note"));
        for (Row r : rows) {
            sb.append(String.format(Locale.ROOT, "%-36s %-7s %5s %12s  %s%n", r.file, r.meshes,
                    r.compared ? String.valueOf(r.times) : "-",
                    Double.isNaN(r.deviation) ? "-" : String.format(Locale.ROOT, "%.2e", r.deviation),
                    (r.failed ? "FAILED: " : "") + r.note));
        }
        System.out.print(sb);
    }

    private static Row check(Path file, String name) {
        return check(file, name, true);
    }

    /**
     * @param animatedSkinsOnly skip files without skinned meshes or animation (else they are
     *     compared at rest)
     */
    private static Row check(Path file, String name, boolean animatedSkinsOnly) {
        Row row = new Row(name);
        Model model;
        try {
            model = ColladaImporter.read(file);
        } catch (ColladaException | IOException e) {
            row.note = "skipped: our importer refuses it (" + e.getMessage() + ")";
            return row;
        }
        row.meshes = model.instances().stream().filter(MeshInstance::isSkinned).count() + "/"
                + model.instances().size();
        if (model.instances().isEmpty()) {
            row.note = "skipped: no placed mesh";
            return row;
        }
        if (animatedSkinsOnly && model.instances().stream().noneMatch(MeshInstance::isSkinned)) {
            row.note = "skipped: no skinned mesh";
            return row;
        }
        if (animatedSkinsOnly && model.clips().isEmpty()) {
            row.note = "skipped: no animation";
            return row;
        }
        IndependentLbs ref;
        try {
            ref = IndependentLbs.read(file);
        } catch (IndependentLbs.Unsupported e) {
            row.note = "skipped: the evaluator does not implement " + e.getMessage();
            return row;
        } catch (IOException e) {
            row.note = "skipped: the DOM parser cannot read it (" + e.getMessage() + ")";
            return row;
        }
        String problem = samePlacements(model, ref);
        if (problem != null) {
            row.failed = true;
            row.note = problem;
            return row;
        }
        boolean animated = !model.clips().isEmpty();
        double[] keys = animated ? ref.keyTimes() : new double[] {Double.NaN};
        if (keys.length == 0) {
            row.note = "skipped: no key time shared by all " + ref.channelCount() + " channels";
            return row;
        }
        double[] times = sample(keys);
        SkinnedModel ours = new SkinnedModel(model, animated ? model.clips().get(0) : null,
                NormalTransform.INVERSE_TRANSPOSE);
        double[] first = null;
        double[] lo = {Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY, Double.POSITIVE_INFINITY};
        double[] hi = {Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY, Double.NEGATIVE_INFINITY};
        double maxDistance = 0;
        String worst = "";
        double motion = 0;
        for (double t : times) {
            double[][] expected = animated ? ref.pose(t) : ref.restPose();
            ours.pose(animated ? (float) t : 0f, RotationInterpolation.SLERP);
            motion = Math.max(motion, largestMove(expected, first));
            if (first == null) {
                first = flatten(expected);
            }
            for (int g = 0; g < expected.length; g++) {
                SkinnedGeometry geometry = ours.geometries().get(g);
                float[] points = new float[3 * geometry.pointCount()];
                ours.skin(g, SkinningMethod.LBS, points, new float[3 * geometry.pointCount()]);
                double[] e = expected[g];
                for (int p = 0; p < e.length / 3; p++) {
                    int q = 3 * geometry.pointOfPosition(p);
                    double d = 0;
                    for (int c = 0; c < 3; c++) {
                        lo[c] = Math.min(lo[c], e[3 * p + c]);
                        hi[c] = Math.max(hi[c], e[3 * p + c]);
                        d += (points[q + c] - e[3 * p + c]) * (points[q + c] - e[3 * p + c]);
                    }
                    if (Math.sqrt(d) > maxDistance) {
                        maxDistance = Math.sqrt(d);
                        worst = String.format(Locale.ROOT, "worst: %s position %d at t=%s", geometry.mesh().id(), p, t);
                    }
                }
            }
        }
        double extent = Math.sqrt(sq(hi[0] - lo[0]) + sq(hi[1] - lo[1]) + sq(hi[2] - lo[2]));
        row.compared = true;
        row.times = times.length;
        row.deviation = maxDistance / extent;
        row.note = animated
                ? String.format(Locale.ROOT, "clip %s, %d of %d key times, extent %.4g, moves up to %.2f of it; %s",
                        model.clips().get(0).name(), times.length, keys.length, extent, motion / extent, worst)
                : String.format(Locale.ROOT, "no animation: rest pose, extent %.4g; %s", extent, worst);
        row.failed = !(row.deviation <= TOLERANCE);
        return row;
    }

    /** Null when the evaluator placed the same meshes on the same nodes, in the same order, as the importer. */
    private static String samePlacements(Model model, IndependentLbs ref) {
        List<String> ours = model.instances().stream()
                .map(i -> model.node(i.node()).id() + ":" + i.mesh().id() + (i.isSkinned() ? " (skinned)" : ""))
                .collect(Collectors.toList());
        List<String> theirs = ref.placements().stream()
                .map(p -> p.nodeId + ":" + p.geometryId + (p.skinned ? " (skinned)" : ""))
                .collect(Collectors.toList());
        if (!ours.equals(theirs)) {
            return "placed meshes differ: importer " + ours + ", evaluator " + theirs;
        }
        for (int g = 0; g < ours.size(); g++) {
            if (model.instances().get(g).mesh().positionCount() != ref.placements().get(g).positionCount()) {
                return "position counts differ on " + ours.get(g);
            }
        }
        if (ref.clipName() != null && !ref.clipName().equals(model.clips().get(0).name())) {
            return "first clip: importer " + model.clips().get(0).name() + ", evaluator " + ref.clipName();
        }
        return null;
    }

    private static double[] flatten(double[][] perMesh) {
        return Stream.of(perMesh).flatMapToDouble(java.util.Arrays::stream).toArray();
    }

    /**
     * How far any position moved from the first checked pose: shows that a file's comparison
     * involves motion (a file that never moves would prove little about animation).
     */
    private static double largestMove(double[][] pose, double[] first) {
        if (first == null) {
            return 0;
        }
        double[] now = flatten(pose);
        double max = 0;
        for (int i = 0; i < now.length; i += 3) {
            max = Math.max(max, Math.sqrt(sq(now[i] - first[i]) + sq(now[i + 1] - first[i + 1])
                    + sq(now[i + 2] - first[i + 2])));
        }
        return max;
    }

    /** All key times when there are few, else {@value #MAX_TIMES} evenly spread, first and last included. */
    private static double[] sample(double[] keys) {
        if (keys.length <= MAX_TIMES) {
            return keys;
        }
        double[] s = new double[MAX_TIMES];
        for (int i = 0; i < MAX_TIMES; i++) {
            s[i] = keys[(int) Math.round(i * (keys.length - 1) / (double) (MAX_TIMES - 1))];
        }
        return s;
    }

    private static double sq(double x) {
        return x * x;
    }
}
