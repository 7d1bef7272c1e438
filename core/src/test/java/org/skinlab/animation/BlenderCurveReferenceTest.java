package org.skinlab.animation;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.List;
import java.util.stream.Collectors;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import org.junit.jupiter.api.Test;
import org.skinlab.collada.Fixtures;
import org.skinlab.model.ImportWarning;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * Our BEZIER evaluation between keys against Blender's own, on a file Blender 3.4 exported with
 * smooth curves: {@code fixtures/animation/blender-curves.dae} and Blender's deformed cubes of the
 * original scene (not a re-import) at 43 times, keys and in between, in
 * {@code blender-curves.json}. Both are made by {@code assets/src/make_curve_reference.py}
 * (docs/animation.md, "Checked against Blender"). One bone rotating about one axis (a
 * {@code rotationX.ANGLE} channel whose tangent values Blender writes in radians) and one bone
 * translating ({@code location.X}, tangents in the value's own unit), each with a 0.5 m cube
 * weighted fully to it: linear blend skinning with one influence is the joint's rigid transform,
 * so the cube's vertices show the sampled curve directly.
 */
class BlenderCurveReferenceTest {
    /**
     * Of each cube's extent (0.866 m). Blender evaluates its F-curves in float and solves the
     * Bezier's time cubic with its own root finder, the file's times and tangents carry 7
     * significant digits, and so do the JSON's positions: measured 1.8e-6 of the extent (1.5 um)
     * at worst, over 43 times (docs/animation.md). 1e-5 leaves a margin of 5 and is still 100,000
     * times smaller than the error of reading Blender's radian tangents as degrees (1.4 of the
     * extent, {@link #withoutTheRadianRuleThePosesMatchOnlyAtKeys}).
     */
    private static final double TOLERANCE = 1e-5;

    private static final String FILE = "animation/blender-curves.dae";

    private static JsonNode reference() {
        try (InputStream in = BlenderCurveReferenceTest.class.getResourceAsStream(
                "/fixtures/animation/blender-curves.json")) {
            return new ObjectMapper().readTree(in);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    private static String fixtureText() {
        try (InputStream in = BlenderCurveReferenceTest.class.getResourceAsStream("/fixtures/" + FILE)) {
            return new String(in.readAllBytes(), StandardCharsets.UTF_8);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }

    /**
     * Largest distance of any vertex from Blender's, relative to its cube's extent, over all times
     * or only over the key times of each cube's own rig.
     */
    private static double worstRelativeError(Model model, JsonNode ref, boolean keysOnly) {
        SkinnedModel skinned = SkinnedModel.of(model);
        List<SkinnedGeometry> geometries = skinned.geometries();
        JsonNode meshes = ref.get("meshes");
        assertEquals(meshes.size(), geometries.size(), "one placed cube per reference mesh");
        JsonNode times = ref.get("times");
        double worst = 0;
        for (int k = 0; k < times.size(); k++) {
            double t = times.get(k).asDouble();
            skinned.pose((float) t, RotationInterpolation.SLERP);
            for (JsonNode mesh : meshes) {
                if (keysOnly && !isKeyTime(mesh.get("key_times"), t)) {
                    continue;
                }
                int g = geometryIndex(geometries, mesh.get("geometry").asText());
                SkinnedGeometry geometry = geometries.get(g);
                float[] pos = new float[3 * geometry.pointCount()];
                float[] nrm = new float[3 * geometry.pointCount()];
                float[] bySource = new float[3 * geometry.positionCount()];
                skinned.skin(g, SkinningMethod.LBS, pos, nrm);
                geometry.positionsInSourceOrder(pos, bySource);
                JsonNode expected = mesh.get("positions").get(k);
                assertEquals(bySource.length, expected.size(), "one xyz per POSITION entry");
                double extent = mesh.get("extent").asDouble();
                for (int i = 0; i < bySource.length; i += 3) {
                    double dx = bySource[i] - expected.get(i).asDouble();
                    double dy = bySource[i + 1] - expected.get(i + 1).asDouble();
                    double dz = bySource[i + 2] - expected.get(i + 2).asDouble();
                    worst = Math.max(worst, Math.sqrt(dx * dx + dy * dy + dz * dz) / extent);
                }
            }
        }
        return worst;
    }

    private static boolean isKeyTime(JsonNode keyTimes, double t) {
        for (JsonNode k : keyTimes) {
            if (Math.abs(k.asDouble() - t) < 1e-6) {
                return true;
            }
        }
        return false;
    }

    private static int geometryIndex(List<SkinnedGeometry> geometries, String meshId) {
        for (int g = 0; g < geometries.size(); g++) {
            if (meshId.equals(geometries.get(g).mesh().id())) {
                return g;
            }
        }
        throw new AssertionError("no placed geometry " + meshId);
    }

    @Test
    void bezierPosesMatchBlenderAtAndBetweenKeys() {
        JsonNode ref = reference();
        assertEquals("radians", ref.get("channels").get(0).get("tangent_unit").asText(),
                "the fixture carries Blender's radian tangents (what this test is about)");
        Model model = Fixtures.resource(FILE);
        double worst = worstRelativeError(model, ref, false);
        System.out.printf("blender-curves.dae: worst %.2e of the extent over %d times%n", worst,
                ref.get("times").size());
        assertTrue(worst <= TOLERANCE, () -> String.format("%.3g of the extent from Blender", worst));
    }

    @Test
    void theRadianTangentsAreRecognisedWithOneWarning() {
        Model model = Fixtures.resource(FILE);
        List<ImportWarning> radians = model.warnings().stream().filter(w -> w.message().contains("radians"))
                .collect(Collectors.toList());
        assertEquals(1, radians.size(), model.warnings()::toString);
        assertTrue(radians.get(0).message().startsWith("1 BEZIER track(s)"), radians.get(0)::toString);
        assertTrue(radians.get(0).element().contains("rotation_euler_X-sampler"), radians.get(0)::toString);
    }

    @Test
    void withoutTheRadianRuleThePosesMatchOnlyAtKeys() {
        // The same file with another authoring tool: the rule does not apply, the radian tangent
        // values are read as degrees (handles squashed almost flat onto the keys' angles), and the
        // rotating cube leaves Blender's path between keys while the keys themselves still match.
        JsonNode ref = reference();
        String text = fixtureText();
        assertTrue(text.contains("<authoring_tool>Blender 3.4.1</authoring_tool>"));
        Model model = Fixtures.read("not-blender.dae",
                text.replace("<authoring_tool>Blender 3.4.1</authoring_tool>", "<authoring_tool>Other</authoring_tool>"));
        assertTrue(model.warnings().stream().noneMatch(w -> w.message().contains("radians")), model.warnings()::toString);
        double atKeys = worstRelativeError(model, ref, true);
        double between = worstRelativeError(model, ref, false);
        System.out.printf("blender-curves.dae read without the radian rule: worst %.2e of the extent at keys, "
                + "%.2e between keys%n", atKeys, between);
        assertTrue(atKeys <= TOLERANCE, () -> String.format("keys: %.3g", atKeys));
        assertTrue(between > 0.1, () -> String.format("between keys: %.3g", between));
    }
}
