package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.stream.Stream;
import java.util.zip.GZIPInputStream;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.model.ImportException;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.testing.TestPaths;

/**
 * Our glTF import and LBS against three.js' GLTFLoader (an independent reader and skinner): every
 * vertex of every triangle mesh, in world space, at rest and for every clip at its key times and
 * the midpoints between them, from the references {@code bench/threejs/gltf-reference.mjs} wrote
 * (docs/references.md, "glTF: three.js"). Files: our synthetic fixtures
 * ({@code core/src/test/resources/gltf}, made by {@code tools/gltf/make-fixtures.py}), our assets'
 * {@code .glb} and, when present, third-party samples ({@link GltfSamples}).
 *
 * <p>Tolerance: 1e-4 of the model's size (the diagonal of its rest bounding box, as three.js
 * computed it), the bound. Both sides skin in float32 with different summation orders and
 * quaternion paths; the references are rounded to 7 significant digits.
 *
 * <p>Pairing: three.js makes one mesh per primitive and traverses the scene depth first, a node's
 * primitives before its children; the model has one placed mesh per node with a mesh, in the same
 * depth-first order, whose vertices are its primitives' vertices in order (primitives with equal
 * attributes share theirs); each vertex is compared through the position it was welded to
 * ({@link Mesh#vertexPositions()}), so the comparison covers every glTF vertex and the welding.
 * Rotations are slerped, as three.js (and the specification) do.
 */
class ThreeJsAgreementTest {
    private static final double TOLERANCE = 1e-4;
    private static final ObjectMapper JSON = new ObjectMapper();

    static Stream<String> fixtures() throws IOException {
        try (Stream<Path> files = Files.list(fixtureFolder())) {
            return files.map(p -> p.getFileName().toString()).filter(ThreeJsAgreementTest::isGltf).sorted()
                    .toList().stream();
        }
    }

    /**
     * The assets' references: a reference whose .glb is missing skips, saying so;
     * {@link #everyAssetGlbHasAReference} fails for a .glb without one.
     */
    static Stream<String> assets() throws IOException {
        return referenceNames(assetReferences());
    }

    static Stream<String> samples() throws IOException {
        return referenceNames(fixtureFolder().resolve("threejs/samples"));
    }

    private static Stream<String> referenceNames(Path folder) throws IOException {
        try (Stream<Path> files = Files.list(folder)) {
            return files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".json") || n.endsWith(".json.gz"))
                    .map(n -> n.substring(0, n.lastIndexOf(".json"))).sorted().toList().stream();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("fixtures")
    void fixtureAgreesWithThreeJs(String name) throws IOException, ImportException {
        Path file = fixtureFolder().resolve(name);
        report(name, agreement(file, reference(fixtureFolder().resolve("threejs"), name)));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("assets")
    void assetGlbAgreesWithThreeJs(String name) throws IOException, ImportException {
        List<Path> files = assetGlbs().stream().filter(p -> p.getFileName().toString().equals(name)).toList();
        assertEquals(1, files.size(), () -> "assets/**/" + name + " should be one file (the assets' .glb export, "
                + "assets/src), found " + files);
        report(name, agreement(files.get(0), reference(assetReferences(), name)));
    }

    @Test
    void everyAssetGlbHasAReference() throws IOException {
        for (Path glb : assetGlbs()) {
            String name = glb.getFileName().toString();
            assertTrue(Files.exists(assetReferences().resolve(name + ".json"))
                    || Files.exists(assetReferences().resolve(name + ".json.gz")), () -> glb
                    + " has no three.js reference: run sh bench/threejs/make-gltf-references.sh");
        }
    }

    private static Path assetReferences() {
        return TestPaths.root().resolve("assets/reference/threejs");
    }

    private static List<Path> assetGlbs() throws IOException {
        try (Stream<Path> files = Files.walk(TestPaths.root().resolve("assets"))) {
            return files.filter(p -> p.getFileName().toString().endsWith(".glb")).sorted().toList();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("samples")
    void sampleAgreesWithThreeJs(String name) throws IOException, ImportException {
        Path file = GltfSamples.fileOrSkip(name);
        report(name, agreement(file, reference(fixtureFolder().resolve("threejs/samples"), name)));
    }

    private static Path fixtureFolder() {
        return TestPaths.root().resolve("core/src/test/resources/gltf");
    }

    private static boolean isGltf(String name) {
        return name.endsWith(".gltf") || name.endsWith(".glb");
    }

    /** {@code folder/name.json}, or its gzipped form; a missing reference is a failure. */
    private static JsonNode reference(Path folder, String name) throws IOException {
        Path plain = folder.resolve(name + ".json");
        Path zipped = folder.resolve(name + ".json.gz");
        assertTrue(Files.exists(plain) || Files.exists(zipped), () -> "no three.js reference for " + name + " in "
                + folder + ": run sh bench/threejs/make-gltf-references.sh");
        if (Files.exists(plain)) {
            return JSON.readTree(plain.toFile());
        }
        try (InputStream in = new GZIPInputStream(Files.newInputStream(zipped))) {
            return JSON.readTree(in);
        }
    }

    /** What one file's comparison found: the worst distance and where. */
    record Agreement(int vertices, int times, double size, double worst, String where) {
    }

    static Agreement agreement(Path file, JsonNode ref) throws IOException, ImportException {
        Model model = GltfImporter.read(file);
        double size = ref.get("size").asDouble();
        assertTrue(size > 0, "the reference has a size");
        Comparison c = new Comparison(file.getFileName().toString(), size);
        List<List<JsonNode>> rest = placedMeshes(ref.get("rest"));
        assertEquals(rest.size(), model.instances().size(), file + ": placed meshes (three.js nodes with meshes)");
        c.compare(new SkinnedModel(model, null, NormalTransform.INVERSE_TRANSPOSE), rest, -1, "rest");
        int vertices = rest.stream().mapToInt(ThreeJsAgreementTest::vertexCount).sum();
        int times = 1;
        for (JsonNode clip : ref.get("clips")) {
            int index = clip.get("index").asInt();
            assertTrue(index < model.clips().size(), () -> file + ": three.js has clip " + index + " ("
                    + clip.get("name").asText() + "), the model has " + model.clips().size() + " clips");
            SkinnedModel skinned = new SkinnedModel(model, model.clips().get(index), NormalTransform.INVERSE_TRANSPOSE);
            List<List<JsonNode>> meshes = placedMeshes(clip.get("meshes"));
            JsonNode clipTimes = clip.get("times");
            for (int k = 0; k < clipTimes.size(); k++) {
                float t = (float) clipTimes.get(k).asDouble();
                skinned.pose(t, RotationInterpolation.SLERP);
                c.compare(skinned, meshes, k, "clip " + index + " (" + clip.get("name").asText() + ") t=" + t);
            }
            times += clipTimes.size();
        }
        return new Agreement(vertices, times, size, c.worst, c.where);
    }

    /** Per placed mesh (consecutive entries of one node), its primitives with distinct vertices. */
    private static List<List<JsonNode>> placedMeshes(JsonNode entries) {
        List<List<JsonNode>> groups = new ArrayList<>();
        int node = Integer.MIN_VALUE;
        for (JsonNode e : entries) {
            if (e.get("node").asInt() != node) {
                node = e.get("node").asInt();
                groups.add(new ArrayList<>());
            }
            List<JsonNode> group = groups.get(groups.size() - 1);
            String attributes = e.get("attributes").asText();
            if (group.stream().noneMatch(g -> g.get("attributes").asText().equals(attributes))) {
                group.add(e);
            }
        }
        return groups;
    }

    private static int vertexCount(List<JsonNode> group) {
        return group.stream().mapToInt(e -> e.get("vertices").asInt()).sum();
    }

    /** Compares posed models with the reference, keeping the worst distance. */
    private static final class Comparison {
        final String file;
        final double size;
        double worst;
        String where = "";

        Comparison(String file, double size) {
            this.file = file;
            this.size = size;
        }

        /** {@code k}: index of the time in each entry's positions, or -1 for the rest entries' one array. */
        void compare(SkinnedModel skinned, List<List<JsonNode>> meshes, int k, String when) {
            for (int g = 0; g < meshes.size(); g++) {
                SkinnedGeometry geometry = skinned.geometries().get(g);
                Mesh mesh = geometry.mesh();
                assertEquals(vertexCount(meshes.get(g)), mesh.vertexCount(),
                        () -> file + ": vertices of the placed mesh of " + describe(meshes.get(0)));
                float[] points = new float[3 * geometry.pointCount()];
                float[] normals = new float[3 * geometry.pointCount()];
                float[] ours = new float[3 * geometry.positionCount()];
                skinned.skin(g, SkinningMethod.LBS, points, normals);
                geometry.positionsInSourceOrder(points, ours);
                // Welded vertices share a position: each glTF vertex is compared through its own.
                int[] positionOfVertex = mesh.vertexPositions();
                int base = 0;
                for (JsonNode primitive : meshes.get(g)) {
                    JsonNode theirs = k < 0 ? primitive.get("positions") : primitive.get("positions").get(k);
                    for (int i = 0; i < theirs.size(); i += 3) {
                        int o = 3 * positionOfVertex[base + i / 3];
                        double d = distance(ours, o, theirs, i);
                        if (!(d <= worst) || where.isEmpty()) { // NaN too: it becomes the worst and fails
                            worst = d;
                            where = String.format("%s, %s, vertex %d: ours (%.6g, %.6g, %.6g), three.js (%s, %s, %s)",
                                    when, describe(List.of(primitive)), i / 3, ours[o], ours[o + 1], ours[o + 2],
                                    theirs.get(i), theirs.get(i + 1), theirs.get(i + 2));
                        }
                    }
                    base += primitive.get("vertices").asInt();
                }
            }
        }

        private static double distance(float[] ours, int o, JsonNode theirs, int i) {
            double dx = ours[o] - theirs.get(i).asDouble();
            double dy = ours[o + 1] - theirs.get(i + 1).asDouble();
            double dz = ours[o + 2] - theirs.get(i + 2).asDouble();
            return Math.sqrt(dx * dx + dy * dy + dz * dz);
        }

        private static String describe(List<JsonNode> group) {
            JsonNode e = group.get(0);
            return "node " + e.get("node").asInt() + " mesh " + e.get("mesh").asInt() + " primitive "
                    + e.get("primitive").asInt();
        }
    }

    private static void report(String name, Agreement a) {
        System.out.printf("three.js agreement | %s | %d | %d | %.3g | %.2e | %s%n", name,
                a.vertices(), a.times(), a.size(), a.worst() / a.size(), a.where());
        assertTrue(a.worst() <= TOLERANCE * a.size(), () -> String.format(
                "%s: %.3g from three.js (%.2e of the size %.4g; allowed %.0e) at %s", name, a.worst(),
                a.worst() / a.size(), a.size(), TOLERANCE, a.where()));
    }
}
