package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;
import java.util.zip.GZIPInputStream;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.MethodSource;
import org.skinlab.animation.LocalPose;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.mixer.Layer;
import org.skinlab.mixer.Mixer;
import org.skinlab.model.ImportException;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.testing.TestPaths;

/**
 * Blended clips and additive layers against three.js r187's {@code AnimationMixer}: every vertex,
 * in world space, for each case of the references {@code bench/threejs/blend-reference.mjs} wrote
 * ({@code assets/reference/threejs/blends}: weighted pairs of clips with weights summing to 1 and
 * to less, clips that animate different joints, additive clips with reference times, at key times
 * and between them). Our side: a {@link Mixer} whose base layer plays the case's weighted set and
 * one additive layer per additive clip, every clip at the case's time looped within its own
 * duration, then LBS. Files: our character {@code humanoid-moves.glb} and, when the samples folder
 * has it, the Khronos Fox ({@link GltfSamples}; skipped, saying so, when absent).
 *
 * <p>Tolerance: 1e-5 of the model's size (the diagonal of its rest bounding box), the issue's
 * bound; the references hold 7 significant digits. Vertices are paired as in
 * {@link ThreeJsAgreementTest} (each glTF vertex through the position it was welded to).
 */
class ThreeJsBlendAgreementTest {
    private static final double TOLERANCE = 1e-5;
    private static final ObjectMapper JSON = new ObjectMapper();

    static Stream<String> references() throws IOException {
        try (Stream<Path> files = Files.list(folder())) {
            return files.map(p -> p.getFileName().toString()).filter(n -> n.endsWith(".blends.json.gz")).sorted()
                    .toList().stream();
        }
    }

    private static Path folder() {
        return TestPaths.root().resolve("assets/reference/threejs/blends");
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("references")
    void blendsAgreeWithThreeJs(String name) throws IOException, ImportException {
        JsonNode ref;
        try (InputStream in = new GZIPInputStream(Files.newInputStream(folder().resolve(name)))) {
            ref = JSON.readTree(in);
        }
        String fileName = ref.get("file").asText();
        Path file = asset(fileName);
        if (file == null) {
            file = GltfSamples.fileOrSkip(fileName);
        }
        Model model = GltfImporter.read(file);
        SkinnedModel skinned = new SkinnedModel(model, null, NormalTransform.INVERSE_TRANSPOSE,
                EnumSet.of(SkinningMethod.LBS));
        double size = ref.get("size").asDouble();
        List<JsonNode> meshes = new ArrayList<>();
        ref.get("meshes").forEach(meshes::add);
        double worst = 0;
        String where = "";
        LocalPose local = skinned.skeleton().newLocalPose();
        for (JsonNode c : ref.get("cases")) {
            Mixer mixer = new Mixer(model, skinned.skeleton());
            Map<String, Double> weights = new LinkedHashMap<>();
            c.get("blend").forEach(b -> weights.put(b.get("clip").asText(), b.get("weight").asDouble()));
            mixer.base().setClipWeights(weights);
            for (JsonNode a : c.get("additive")) {
                Layer layer = mixer.addLayer("additive " + a.get("clip").asText());
                layer.play(a.get("clip").asText());
                layer.setAdditive(a.get("refTime").asDouble());
                layer.setWeight(a.get("weight").asDouble());
            }
            double time = c.get("time").asDouble();
            for (Layer l : mixer.layers()) {
                l.setTime(time);
            }
            mixer.evaluate(RotationInterpolation.SLERP, local);
            skinned.pose(local);
            JsonNode theirs = c.get("positions");
            String when = c.get("blend") + " + " + c.get("additive") + " at " + time;
            int offset = 0;
            int g = -1;
            int node = Integer.MIN_VALUE;
            List<String> seen = new ArrayList<>();
            float[] ours = null;
            int[] positionOfVertex = null;
            int base = 0;
            for (JsonNode m : meshes) {
                int vertices = m.get("vertices").asInt();
                if (m.get("node").asInt() != node) {
                    node = m.get("node").asInt();
                    g++;
                    seen.clear();
                    base = 0;
                    SkinnedGeometry geometry = skinned.geometries().get(g);
                    Mesh mesh = geometry.mesh();
                    float[] points = new float[3 * geometry.pointCount()];
                    ours = new float[3 * geometry.positionCount()];
                    skinned.skin(g, SkinningMethod.LBS, points, new float[points.length]);
                    geometry.positionsInSourceOrder(points, ours);
                    positionOfVertex = mesh.vertexPositions();
                }
                // Primitives with the same attributes share their vertices in our mesh (as ThreeJsAgreementTest).
                if (!seen.contains(m.get("attributes").asText())) {
                    seen.add(m.get("attributes").asText());
                    for (int i = 0; i < vertices; i++) {
                        int o = 3 * positionOfVertex[base + i];
                        double dx = ours[o] - theirs.get(offset + 3 * i).asDouble();
                        double dy = ours[o + 1] - theirs.get(offset + 3 * i + 1).asDouble();
                        double dz = ours[o + 2] - theirs.get(offset + 3 * i + 2).asDouble();
                        double d = Math.sqrt(dx * dx + dy * dy + dz * dz);
                        if (!(d <= worst)) {
                            worst = d;
                            where = when + ", mesh " + g + " vertex " + i;
                        }
                    }
                    base += vertices;
                }
                offset += 3 * vertices;
            }
            assertEquals(theirs.size(), offset, name + ": positions in the reference");
        }
        double w = worst;
        String at = where;
        System.out.printf("three.js blend agreement | %s | %d cases | %.2e of the size %.4g | %s%n", name,
                ref.get("cases").size(), w / size, size, at);
        assertTrue(w <= TOLERANCE * size, () -> String.format("%s: %.3g from three.js (%.2e of the size; allowed %.0e)"
                + " at %s", name, w, w / size, TOLERANCE, at));
    }

    /** Our asset of that file name, or null when it is not one of ours. */
    private static Path asset(String fileName) throws IOException {
        try (Stream<Path> files = Files.walk(TestPaths.root().resolve("assets"))) {
            return files.filter(p -> p.getFileName().toString().equals(fileName) && !p.toString().contains("reference"))
                    .findFirst().orElse(null);
        }
    }
}
