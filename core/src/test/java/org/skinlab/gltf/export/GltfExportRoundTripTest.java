package org.skinlab.gltf.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.stream.Collectors;
import java.util.stream.Stream;

import com.fasterxml.jackson.databind.JsonNode;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.animation.AnimationSampler;
import org.skinlab.animation.LocalPose;
import org.skinlab.animation.Pose;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.gltf.GltfImporter;
import org.skinlab.importer.ModelImporter;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.MeshInstance;
import org.skinlab.model.Model;
import org.skinlab.model.Morph;
import org.skinlab.skinning.CentresOfRotation;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.testing.TestPaths;

/**
 * Every bundled asset ({@code assets/**}{@code /*.dae}, {@code *.glb}) and the skinned characters of
 * the third-party corpus (skipped, saying so, when absent) exported with lbs, dqs and cor, read back
 * with skinlab's glTF importer and compared with the original model:
 * <ul>
 * <li>per placed mesh: vertex and triangle counts; per skinned mesh: palette size, and every
 *     vertex's influences (joint and normalised weight, within {@value #WEIGHT_TOLERANCE});</li>
 * <li>clip names and durations (within {@value #WEIGHT_TOLERANCE} s);</li>
 * <li>LBS-posed world positions of every vertex at three times of each clip (start, middle, and
 *     0.3719 of the way, which no asset keys), the original's moved into Y-up metres as the export's
 *     root node moves them; the largest distance over the model's size (the diagonal of its posed
 *     bounding box at the start). Copied glTF tracks: at most {@value #POSE_TOLERANCE} (float
 *     rounding of recovered cubic tangents and re-normalised weights is 1e-7). Resampled COLLADA
 *     clips: the same bound at every time, because the assets and the corpus's characters key whole
 *     matrices LINEAR (exact at the union of key times, and slerp/lerp between them as glTF's LINEAR
 *     is) or, where not, are resampled at 60 Hz (the measured deviations are printed);</li>
 * <li>{@code _COR_CENTER}, read with {@link ExportedGlb} (the importer ignores it), equal to
 *     skinlab's centres for the original within {@value #CENTRE_TOLERANCE} of the size, and to the
 *     centres skinlab computes from the re-imported file within {@value #RECOMPUTED_TOLERANCE} (its
 *     weights are the export's floats, renormalised once more);</li>
 * <li>the {@code SKINLAB_skinning} object on every skinned primitive, exactly as specified, listed
 *     in {@code extensionsUsed} and not required.</li>
 * </ul>
 */
class GltfExportRoundTripTest {
    static final double WEIGHT_TOLERANCE = 1e-6;
    static final double POSE_TOLERANCE = 1e-5;
    static final double RESAMPLED_TOLERANCE = 1e-3;
    static final double CENTRE_TOLERANCE = 1e-6;
    static final double RECOMPUTED_TOLERANCE = 1e-4;
    /** The corpus's skinned files (SOURCES.md, categories S and K). */
    static final List<String> CORPUS = List.of("S01_cowboy.dae", "S02_bob_lamp.dae", "S03_stormtrooper.dae",
            "S11_box_nested_animation.dae", "S12_library_animation_clips.dae", "S13_letter_f_animated.dae",
            "S14_two_skinned_cubes.dae", "S15_leg_control_bones.dae", "S16_suzanne_lines.dae", "S17_trion_scene.dae",
            "K01_simple_bone.dae");

    private static final EnumSet<SkinningMethod> METHODS = EnumSet.of(SkinningMethod.LBS, SkinningMethod.DQS,
            SkinningMethod.COR);

    @Test
    void bundledAssetsRoundTrip() throws Exception {
        List<Path> files;
        try (Stream<Path> s = Files.walk(TestPaths.root().resolve("assets"))) {
            files = s.filter(p -> p.toString().endsWith(".dae") || p.toString().endsWith(".glb")).sorted()
                    .collect(Collectors.toList());
        }
        assertTrue(files.size() >= 20, "expected the bundled assets, found " + files);
        checkAll(files);
    }

    /**
     * The importer's fixtures: glTF files with CUBICSPLINE and STEP tracks, morph targets animated with
     * a skin, eight influences, textures, quantized and sparse accessors; COLLADA files with BEZIER
     * curves and rotate-angle stacks, which are resampled at 60 Hz.
     */
    @Test
    void importerFixturesRoundTrip() throws Exception {
        List<Path> files;
        Path resources = TestPaths.root().resolve("core/src/test/resources");
        try (Stream<Path> s = Stream.concat(Files.list(resources.resolve("gltf")),
                Files.list(resources.resolve("fixtures/animation")))) {
            files = s.filter(p -> p.toString().matches(".*\\.(gltf|glb|dae)")).sorted().collect(Collectors.toList());
        }
        assertTrue(files.size() >= 15, "expected the importer's fixtures, found " + files);
        checkAll(files);
    }

    @Test
    void corpusSkinnedCharactersRoundTrip() throws Exception {
        Path corpus = TestPaths.corpusOrSkip();
        List<Path> files = new ArrayList<>();
        for (String f : CORPUS) {
            files.add(TestPaths.corpusFile(f).orElseThrow());
        }
        checkAll(files);
    }

    private static void checkAll(List<Path> files) throws Exception {
        System.out.println("| file | meshes | vertices | clips | bytes | pose dev (TRS) | pose dev (file) | centre dev"
                + " | recomputed centre dev |");
        System.out.println("|---|---:|---:|---:|---:|---:|---:|---:|---:|");
        List<String> failures = new ArrayList<>();
        for (Path f : files) {
            try {
                check(f);
            } catch (AssertionError e) {
                failures.add(f.getFileName() + ": " + e.getMessage());
            }
        }
        assertTrue(failures.isEmpty(), String.join("\n", failures));
    }

    private static void check(Path file) throws Exception {
        Model original = ModelImporter.read(file);
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        ExportResult result = GltfExporter.write(original, METHODS, bytes);
        byte[] glb = bytes.toByteArray();
        assertEquals(glb.length, result.bytes(), "bytes reported");
        Model back = GltfImporter.read(new ByteArrayInputStream(glb), file.getFileName() + ".glb", null);
        ExportedGlb exported = new ExportedGlb(glb);
        String name = file.getFileName().toString();

        assertEquals(original.instances().size(), result.meshes(), "one glTF mesh per placed mesh");
        assertEquals(original.instances().size(), back.instances().size(), "placed meshes read back");
        MeshInstance[] backOf = matchInstances(original, back);
        double size = size(original);
        int vertices = 0;
        for (int i = 0; i < backOf.length; i++) {
            MeshInstance a = original.instances().get(i);
            MeshInstance b = backOf[i];
            vertices += a.mesh().vertexCount();
            assertEquals(a.mesh().vertexCount(), b.mesh().vertexCount(), "vertices of mesh " + i);
            assertEquals(a.mesh().triangleCount(), b.mesh().triangleCount(), "triangles of mesh " + i);
            assertEquals(a.isSkinned(), b.isSkinned(), "mesh " + i + " skinned");
        }
        assertEquals(vertices, result.vertices(), "vertices reported");
        checkMaterials(original, backOf);
        checkExtension(exported, original, backOf);
        double[] centreDev = checkSkins(original, back, backOf, exported, size);
        assertEquals(original.clips().stream().map(AnimationClip::name).collect(Collectors.toList()),
                back.clips().stream().map(AnimationClip::name).collect(Collectors.toList()), "clip names");
        for (int c = 0; c < original.clips().size(); c++) {
            assertEquals(original.clips().get(c).duration(), back.clips().get(c).duration(), WEIGHT_TOLERANCE,
                    "duration of clip " + original.clips().get(c).name());
        }
        double[] poseDev = checkPoses(original, back, backOf, size);
        System.out.printf(Locale.ROOT, "| %s | %d | %d | %d | %d | %.2e | %.2e | %.2e | %.2e |%n", name,
                result.meshes(), result.vertices(), result.clips(), result.bytes(), poseDev[0], poseDev[1], centreDev[0],
                centreDev[1]);
        double tolerance = resampledDensely(original) ? RESAMPLED_TOLERANCE : POSE_TOLERANCE;
        assertTrue(!(poseDev[0] > tolerance), "LBS poses deviate from the clip sampled as TRS by " + poseDev[0]
                + " of the size");
        assertTrue(poseDev[1] <= tolerance, "LBS poses deviate from the file's transforms by " + poseDev[1]
                + " of the size");
        assertTrue(centreDev[0] <= CENTRE_TOLERANCE, "_COR_CENTER deviates by " + centreDev[0] + " of the size");
        assertTrue(centreDev[1] <= RECOMPUTED_TOLERANCE, "recomputed centres deviate by " + centreDev[1]);
    }

    /**
     * Whether some clip is resampled every 1/60 s (a channel on a COLLADA stack that is not one whole
     * LINEAR or STEP matrix, or a BEZIER or HERMITE key there): between those samples glTF's LINEAR
     * interpolation stands in for the curve, which the looser tolerance allows for.
     */
    private static boolean resampledDensely(Model model) {
        for (AnimationClip clip : model.clips()) {
            for (org.skinlab.model.AnimationChannel c : clip.channels()) {
                org.skinlab.model.Node n = model.node(c.node());
                if (NodeLayout.isTrsStack(n.transforms())) {
                    continue;
                }
                boolean wholeMatrix = n.transforms().size() == 1 && c.valueCount() == 16;
                for (int k = 0; k < c.track().keyCount(); k++) {
                    org.skinlab.model.Interpolation i = c.track().interpolation(k);
                    if (!wholeMatrix || i == org.skinlab.model.Interpolation.BEZIER
                            || i == org.skinlab.model.Interpolation.HERMITE) {
                        return true;
                    }
                }
            }
            for (org.skinlab.model.MorphWeightChannel w : clip.morphWeights()) {
                for (int k = 0; k < w.track().keyCount(); k++) {
                    org.skinlab.model.Interpolation i = w.track().interpolation(k);
                    if (i == org.skinlab.model.Interpolation.HERMITE || i == org.skinlab.model.Interpolation.BEZIER
                            && w.weightOffset() != 0) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /**
     * Each drawn part's material read back: the base colour (alpha from COLLADA's opacity), texture
     * image bytes and coordinate transform (within 1e-6), and for glTF input alpha mode, cutoff and
     * sidedness as read; a part bound to no material stays so.
     */
    private static void checkMaterials(Model original, MeshInstance[] backOf) throws IOException {
        boolean gltf = original.source().endsWith(".glb") || original.source().endsWith(".gltf");
        for (int i = 0; i < backOf.length; i++) {
            MeshInstance a = original.instances().get(i);
            List<org.skinlab.model.MeshPart> partsA = a.mesh().parts().stream().filter(p -> p.triangleCount() > 0)
                    .collect(Collectors.toList());
            List<org.skinlab.model.MeshPart> partsB = backOf[i].mesh().parts();
            assertEquals(partsA.size(), partsB.size(), "primitives of mesh " + i);
            for (int p = 0; p < partsA.size(); p++) {
                org.skinlab.model.Material ma = a.material(partsA.get(p).material()).material();
                org.skinlab.model.Material mb = backOf[i].material(partsB.get(p).material()).material();
                String where = "mesh " + i + " part " + p + " (" + ma.name() + ")";
                if (ma == org.skinlab.model.Material.DEFAULT) {
                    assertTrue(mb == org.skinlab.model.Material.DEFAULT, where + " stays unbound");
                    continue;
                }
                assertEquals(ma.name(), mb.name(), where);
                float[] colour = ma.shading() == org.skinlab.model.Material.Shading.CONSTANT ? ma.emission() : ma.diffuse();
                float[] back = mb.shading() == org.skinlab.model.Material.Shading.CONSTANT ? mb.emission() : mb.diffuse();
                if (colour != null) {
                    for (int c = 0; c < 3; c++) {
                        assertEquals(Math.max(0f, Math.min(1f, colour[c])), back[c], 1e-6, where + " colour " + c);
                    }
                }
                assertEquals(ma.shading() == org.skinlab.model.Material.Shading.CONSTANT,
                        mb.shading() == org.skinlab.model.Material.Shading.CONSTANT, where + " unlit");
                org.skinlab.model.Texture ta = ma.baseTexture();
                org.skinlab.model.Texture tb = mb.baseTexture();
                byte[] image = ta == null ? null : ta.image().isEmbedded() ? ta.image().bytes()
                        : ta.image().file() != null && Files.isRegularFile(ta.image().file())
                        ? Files.readAllBytes(ta.image().file()) : null;
                if (image != null && MaterialExport.mediaType(image) != null) {
                    assertTrue(tb != null, where + " keeps its texture");
                    assertTrue(java.util.Arrays.equals(image, tb.image().bytes()), where + " image bytes");
                    float[] xa = ta.transform().values();
                    float[] xb = tb.transform().values();
                    for (int k = 0; k < 6; k++) {
                        assertEquals(xa[k], xb[k], 1e-6, where + " texture transform " + k);
                    }
                }
                if (gltf) {
                    assertEquals(ma.alphaMode(), mb.alphaMode(), where + " alpha mode");
                    assertEquals(ma.alphaCutoff(), mb.alphaCutoff(), 0f, where + " alpha cutoff");
                    assertEquals(ma.doubleSided(), mb.doubleSided(), where + " double-sided");
                    assertEquals(ma.opacity(), mb.opacity(), 1e-6, where + " opacity");
                }
            }
        }
    }

    /** Per original instance, the re-imported instance drawing the mesh the export wrote for it (mesh i). */
    private static MeshInstance[] matchInstances(Model original, Model back) {
        MeshInstance[] result = new MeshInstance[original.instances().size()];
        for (MeshInstance b : back.instances()) {
            String id = back.morphOf(b).map(Morph::base).orElse(b.mesh()).id();
            int m = Integer.parseInt(id.substring("/meshes/".length()));
            assertEquals(null, result[m], "mesh " + m + " placed twice");
            result[m] = b;
        }
        return result;
    }

    private static void checkExtension(ExportedGlb glb, Model original, MeshInstance[] backOf) {
        JsonNode used = glb.json.get("extensionsUsed");
        boolean skinned = original.instances().stream().anyMatch(MeshInstance::isSkinned);
        assertEquals(skinned, used != null && used.toString().contains("\"SKINLAB_skinning\""), "extensionsUsed: " + used);
        assertFalse(glb.json.has("extensionsRequired"), "nothing is required");
        for (int m = 0; m < original.instances().size(); m++) {
            for (JsonNode p : glb.json.get("meshes").get(m).get("primitives")) {
                JsonNode ext = p.path("extensions").path("SKINLAB_skinning");
                if (!original.instances().get(m).isSkinned()) {
                    assertTrue(ext.isMissingNode(), "static mesh " + m + " has no SKINLAB_skinning");
                    continue;
                }
                assertEquals("{\"methods\":[\"lbs\",\"dqs\",\"cor\"],\"attributes\":{\"cor\":\"_COR_CENTER\"},"
                        + "\"version\":1}", ext.toString(), "mesh " + m);
                assertEquals(p.get("attributes").get("POSITION").asInt() >= 0, true);
            }
        }
    }

    /** Influences per vertex; returns the centre deviations (shipped vs original, recomputed vs shipped). */
    private static double[] checkSkins(Model original, Model back, MeshInstance[] backOf, ExportedGlb glb,
            double size) {
        double centre = 0;
        double recomputed = 0;
        for (int i = 0; i < backOf.length; i++) {
            MeshInstance a = original.instances().get(i);
            if (!a.isSkinned()) {
                continue;
            }
            SkinnedGeometry ga = SkinnedGeometry.of(a, original.nodes());
            SkinnedGeometry gb = SkinnedGeometry.of(backOf[i], back.nodes());
            // The skin's joints in order, then the skeleton's transformed non-joint ancestors, which no
            // vertex is bound to (NodeLayout.withTransformedAncestors): the influence check below
            // finds any vertex bound to one.
            assertTrue(gb.jointCount() >= ga.jointCount(), "palette of mesh " + i);
            for (int j = 0; j < ga.jointCount(); j++) {
                if (ga.jointNode(j) >= 0) {
                    assertEquals(original.node(ga.jointNode(j)).name(), back.node(gb.jointNode(j)).name(),
                            "joint " + j + " of mesh " + i);
                }
            }
            int vc = a.mesh().vertexCount();
            for (int v = 0; v < vc; v++) {
                Map<Integer, Double> wa = influences(ga, v);
                Map<Integer, Double> wb = influences(gb, v);
                assertEquals(wa.keySet(), wb.keySet(), "joints of vertex " + v + " of mesh " + i);
                for (Map.Entry<Integer, Double> e : wa.entrySet()) {
                    assertEquals(e.getValue(), wb.get(e.getKey()), WEIGHT_TOLERANCE,
                            "weight of joint " + e.getKey() + " at vertex " + v + " of mesh " + i);
                }
            }
            int accessor = glb.json.get("meshes").get(i).get("primitives").get(0).get("attributes").get("_COR_CENTER")
                    .asInt();
            float[] shipped = glb.floats(accessor, 3);
            assertEquals(3 * vc, shipped.length, "_COR_CENTER count of mesh " + i);
            float[] ours = CentresOfRotation.compute(ga, CentresOfRotation.Parameters.DEFAULT,
                    CentresOfRotation.Progress.NONE);
            float[] again = CentresOfRotation.compute(gb, CentresOfRotation.Parameters.DEFAULT,
                    CentresOfRotation.Progress.NONE);
            for (int v = 0; v < vc; v++) {
                centre = Math.max(centre, distance(shipped, 3 * v, ours, 3 * v) / size);
                recomputed = Math.max(recomputed, distance(shipped, 3 * v, again, 3 * v) / size);
            }
        }
        return new double[] {centre, recomputed};
    }

    private static Map<Integer, Double> influences(SkinnedGeometry g, int point) {
        Map<Integer, Double> w = new HashMap<>();
        int k = g.influencesPerPoint();
        for (int a = 0; a < k; a++) {
            float weight = g.weightArray()[k * point + a];
            if (weight > 0f) {
                w.merge(g.jointArray()[k * point + a], (double) weight, Double::sum);
            }
        }
        return w;
    }

    /**
     * The largest distance of an LBS-posed vertex at three times of each clip (or at rest), over the
     * size: [0] against the original posed from its clip sampled into translation, rotation and
     * scale ({@link AnimationSampler#sampleLocal}, what glTF can hold), [1] against the original
     * posed from the file's own transforms ({@link SkinnedModel#pose(float, RotationInterpolation)},
     * which keeps a key matrix's shear).
     */
    private static double[] checkPoses(Model original, Model back, MeshInstance[] backOf, double size) {
        Matrix4f toYUp = original.asset().toYUpMeters(new Matrix4f());
        double[] worst = new double[2];
        int clips = Math.max(1, original.clips().size());
        for (int c = 0; c < clips; c++) {
            AnimationClip ca = original.clips().isEmpty() ? null : original.clips().get(c);
            AnimationClip cb = back.clips().isEmpty() ? null : back.clips().get(c);
            SkinnedModel sa = new SkinnedModel(original, ca, NormalTransform.INVERSE_TRANSPOSE,
                    EnumSet.of(SkinningMethod.LBS));
            SkinnedModel sb = new SkinnedModel(back, cb, NormalTransform.INVERSE_TRANSPOSE,
                    EnumSet.of(SkinningMethod.LBS));
            LocalPose local = sa.skeleton().newLocalPose();
            Pose values = sa.skeleton().newPose();
            float duration = ca == null ? 0f : ca.duration();
            if (original.hasMorphWeightAnimation()) {
                worst[0] = Double.NaN; // pose(LocalPose) poses the skeleton only, not the morph weights
            }
            for (float d : new float[] {0f, duration / 2, duration * 0.3719f}) {
                float t = (ca == null ? 0f : ca.start()) + d;
                sb.pose(d, RotationInterpolation.SLERP);
                for (int form = original.hasMorphWeightAnimation() ? 1 : 0; form < 2; form++) {
                    if (form == 0) {
                        // pose(LocalPose) leaves morph weights as they are: pose(t) sets them first.
                        sa.pose(t, RotationInterpolation.SLERP);
                        sa.sampler().sampleLocal(t, RotationInterpolation.SLERP, values, local);
                        sa.pose(local);
                    } else {
                        sa.pose(t, RotationInterpolation.SLERP);
                    }
                    for (int i = 0; i < backOf.length; i++) {
                        int j = back.instances().indexOf(backOf[i]);
                        SkinnedGeometry ga = sa.geometries().get(i);
                        SkinnedGeometry gb = sb.geometries().get(j);
                        float[] pa = new float[3 * ga.pointCount()];
                        float[] pb = new float[3 * gb.pointCount()];
                        sa.skin(i, SkinningMethod.LBS, pa, new float[pa.length]);
                        sb.skin(j, SkinningMethod.LBS, pb, new float[pb.length]);
                        Vector3f v = new Vector3f();
                        for (int k = 0; k < ga.vertexCount(); k++) {
                            toYUp.transformPosition(v.set(pa[3 * k], pa[3 * k + 1], pa[3 * k + 2]));
                            double dx = v.x - pb[3 * k];
                            double dy = v.y - pb[3 * k + 1];
                            double dz = v.z - pb[3 * k + 2];
                            worst[form] = Math.max(worst[form], Math.sqrt(dx * dx + dy * dy + dz * dz) / size);
                        }
                    }
                }
            }
        }
        return worst;
    }

    /** The diagonal of the bounding box of the LBS-posed vertices at the first clip's start, in Y-up metres. */
    private static double size(Model model) {
        SkinnedModel s = new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0),
                NormalTransform.INVERSE_TRANSPOSE, EnumSet.of(SkinningMethod.LBS));
        Matrix4f toYUp = model.asset().toYUpMeters(new Matrix4f());
        float[] min = {Float.MAX_VALUE, Float.MAX_VALUE, Float.MAX_VALUE};
        float[] max = {-Float.MAX_VALUE, -Float.MAX_VALUE, -Float.MAX_VALUE};
        Vector3f v = new Vector3f();
        for (int g = 0; g < s.geometries().size(); g++) {
            float[] p = new float[3 * s.geometries().get(g).pointCount()];
            s.skin(g, SkinningMethod.LBS, p, new float[p.length]);
            for (int k = 0; k < s.geometries().get(g).vertexCount(); k++) {
                toYUp.transformPosition(v.set(p[3 * k], p[3 * k + 1], p[3 * k + 2]));
                min[0] = Math.min(min[0], v.x);
                min[1] = Math.min(min[1], v.y);
                min[2] = Math.min(min[2], v.z);
                max[0] = Math.max(max[0], v.x);
                max[1] = Math.max(max[1], v.y);
                max[2] = Math.max(max[2], v.z);
            }
        }
        return Math.sqrt(Math.pow(max[0] - min[0], 2) + Math.pow(max[1] - min[1], 2) + Math.pow(max[2] - min[2], 2));
    }

    private static double distance(float[] a, int i, float[] b, int j) {
        double dx = a[i] - b[j];
        double dy = a[i + 1] - b[j + 1];
        double dz = a[i + 2] - b[j + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }

    @Test
    void methodsOutsideLbsDqsCorAreRefused() {
        org.junit.jupiter.api.Assertions.assertThrows(IllegalArgumentException.class, () -> GltfExporter.write(
                ModelImporter.read(TestPaths.asset("cylinders/cylinder-bend.glb")), EnumSet.of(SkinningMethod.BFDQS),
                new ByteArrayOutputStream()));
    }

    static byte[] export(Path file) throws IOException, org.skinlab.model.ImportException {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream();
        GltfExporter.write(ModelImporter.read(file), METHODS, bytes);
        return bytes.toByteArray();
    }
}
