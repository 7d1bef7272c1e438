package org.skinlab.gltf;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.api.Test;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.model.AnimationClip;
import org.skinlab.model.Interpolation;
import org.skinlab.model.Model;
import org.skinlab.model.MorphWeightChannel;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * Animations through the model's own sampler, against the specification's formulas evaluated
 * here (glTF 2.0, Appendix C "Interpolation"): LINEAR, STEP, and CUBICSPLINE's Hermite spline
 * {@code p(s) = (2s^3 - 3s^2 + 1) v_k + td (s^3 - 2s^2 + s) b_k + (-2s^3 + 3s^2) v_k+1
 * + td (s^3 - s^2) a_k+1}.
 */
class GltfAnimationTest {
    private static final float EPS = 1e-5f;

    private static Model oneChannel(String path, String interpolation, String outputType, double[] times,
            double... output) throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("SCALAR", times);
        f.floats(outputType, output);
        return GltfFixture.read(f.gltf("\"nodes\":[{\"name\":\"n\"}],\"scenes\":[{\"nodes\":[0]}],"
                + "\"animations\":[{\"name\":\"walk\",\"channels\":[{\"sampler\":0,\"target\":{\"node\":0,"
                + "\"path\":\"" + path + "\"}}],\"samplers\":[{\"input\":0,\"output\":1,\"interpolation\":\""
                + interpolation + "\"}]}]"));
    }

    private static Vector3f translationAt(Model model, float t) {
        SkinnedModel skinned = SkinnedModel.of(model);
        skinned.pose(t, RotationInterpolation.SLERP);
        return skinned.pose().world(0, new Matrix4f()).getTranslation(new Vector3f());
    }

    @Test
    void cubicSplineFollowsTheHermiteFormula() throws Exception {
        double[] times = {0, 2, 3};
        // Per key: in-tangent a, value v, out-tangent b (VEC3; only x varies).
        double[][] abv = {{0, 1, 4}, {-2, 3, 1}, {5, 0, 0}}; // (a, v, b) per key
        double[] out = new double[27];
        for (int k = 0; k < 3; k++) {
            for (int e = 0; e < 3; e++) {
                out[9 * k + 3 * e] = abv[k][e];
                out[9 * k + 3 * e + 1] = 0.5 * abv[k][e];
            }
        }
        Model model = oneChannel("translation", "CUBICSPLINE", "VEC3", times, out);
        assertEquals(Interpolation.BEZIER, model.clips().get(0).channels().get(0).track().interpolation(0));
        for (float t : new float[] {0f, 0.3f, 1f, 1.7f, 2f, 2.25f, 2.5f, 2.9f, 3f}) {
            int k = t < 2f ? 0 : 1;
            double td = times[k + 1] - times[k];
            double s = (t - times[k]) / td;
            double expected = (2 * s * s * s - 3 * s * s + 1) * abv[k][1] + td * (s * s * s - 2 * s * s + s) * abv[k][2]
                    + (-2 * s * s * s + 3 * s * s) * abv[k + 1][1] + td * (s * s * s - s * s) * abv[k + 1][0];
            Vector3f p = translationAt(model, t);
            assertEquals(expected, p.x, EPS, "x at t=" + t);
            assertEquals(0.5 * expected, p.y, EPS, "y at t=" + t);
        }
    }

    @Test
    void linearAndStep() throws Exception {
        double[] times = {0, 1};
        Model linear = oneChannel("translation", "LINEAR", "VEC3", times, 0, 0, 0, 4, 2, 0);
        Model step = oneChannel("translation", "STEP", "VEC3", times, 0, 0, 0, 4, 2, 0);
        assertEquals(1f, translationAt(linear, 0.25f).x, EPS);
        assertEquals(0f, translationAt(step, 0.99f).x, EPS);
        assertEquals(4f, translationAt(step, 1f).x, EPS);
        AnimationClip clip = linear.clips().get(0);
        assertEquals("walk", clip.name());
        assertEquals(0f, clip.start());
        assertEquals(1f, clip.end());
    }

    @Test
    void rotationKeysAreNormalisedWithAWarning() throws Exception {
        Model model = oneChannel("rotation", "LINEAR", "VEC4", new double[] {0, 1}, 0, 0, 0, 2, 0, 0, 1, 1);
        float[] values = model.clips().get(0).channels().get(0).track().values();
        assertEquals(1f, values[3], EPS);
        assertEquals((float) Math.sqrt(0.5), values[7], EPS);
        assertEquals("/animations/0/samplers/0/output", model.warnings().get(0).element());
    }

    private static String morphWeights(double... weights) {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0); // 0
        f.floats("VEC3", 0, 0, 1, 0, 0, 1, 0, 0, 1); // 1
        f.floats("SCALAR", 0, 1); // 2
        f.floats("SCALAR", weights); // 3
        return f.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},\"targets\":[{\"POSITION\":1},"
                + "{\"POSITION\":1}]}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],\"animations\":[{"
                + "\"channels\":[{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"weights\"}}],"
                + "\"samplers\":[{\"input\":2,\"output\":3}]}]");
    }

    @Test
    void weightsChannelsAnimateTheNodesMorphWeights() throws Exception {
        Model model = GltfFixture.read(morphWeights(0, 0, 1, 0.5));
        AnimationClip clip = model.clips().get(0);
        assertTrue(clip.channels().isEmpty());
        assertEquals(1f, clip.end());
        assertEquals(List.of(), model.warnings());
        MorphWeightChannel c = clip.morphWeights().get(0);
        assertEquals(0, c.instance());
        assertEquals(0, c.weightOffset());
        assertEquals(2, c.weightCount());
        assertEquals("/animations/0/channels/0", c.target());
        // Both targets move every vertex by +1 in z: at t = 0.5 the weights are (0.5, 0.25), z = 0.75.
        SkinnedModel skinned = new SkinnedModel(model, clip, NormalTransform.INVERSE_TRANSPOSE);
        skinned.pose(0.5f, RotationInterpolation.SLERP);
        float[] points = new float[9];
        skinned.skin(0, SkinningMethod.LBS, points, new float[9]);
        assertEquals(0.75f, points[2], EPS);
        assertEquals(0.75f, points[5], EPS);
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(morphWeights(0, 1, 0.5)));
        assertEquals("test.gltf: /animations/0/samplers/0/output: accessor 3 has 3 elements but 2 keys of 2 targets"
                + " need 4", e.getMessage());
    }

    /**
     * CUBICSPLINE weights, by the specification's Hermite spline: keys at 0 and 1 s with values 0
     * and 1, out-tangent 2 at the first key, in-tangent 0 at the second; at s = 0.5,
     * p = (s^3 - 2s^2 + s) 2 + (-2s^3 + 3s^2) 1 = 0.25 + 0.5 = 0.75, the target's offset (z + 1)
     * times 0.75.
     */
    @Test
    void cubicSplineWeightsFollowTheHermiteSpline() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0); // 0
        f.floats("VEC3", 0, 0, 1, 0, 0, 1, 0, 0, 1); // 1
        f.floats("SCALAR", 0, 1); // 2
        f.floats("SCALAR", 0, 0, 2, 0, 1, 0); // 3: (in, value, out) per key
        Model model = GltfFixture.read(f.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0},"
                + "\"targets\":[{\"POSITION\":1}]}]}],\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],"
                + "\"animations\":[{\"channels\":[{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"weights\"}}],"
                + "\"samplers\":[{\"input\":2,\"output\":3,\"interpolation\":\"CUBICSPLINE\"}]}]"));
        SkinnedModel skinned = new SkinnedModel(model, model.clips().get(0), NormalTransform.INVERSE_TRANSPOSE);
        float[] points = new float[9];
        for (SkinningMethod method : SkinningMethod.values()) {
            skinned.pose(0.5f, RotationInterpolation.SLERP);
            skinned.skin(0, method, points, new float[9]);
            assertEquals(0.75f, points[8], EPS, method.toString());
        }
    }

    /**
     * Morph normals by hand: base normal (0, 0, 1) at every vertex, one target with NORMAL offset
     * (1, 0, -1) and no position offset; weight 0 -> 1 over [0, 1] s (LINEAR). At t = 0.5,
     * n = (0, 0, 1) + 0.5 (1, 0, -1) = (0.5, 0, 0.5), renormalised (0.7071, 0, 0.7071); at t = 1,
     * (1, 0, 0). The static node is the identity, so every method gives the morphed normal.
     */
    @Test
    void targetNormalsMorphTheNormals() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("VEC3", 0, 0, 0, 1, 0, 0, 0, 1, 0); // 0 positions
        f.floats("VEC3", 0, 0, 1, 0, 0, 1, 0, 0, 1); // 1 normals
        f.floats("VEC3", 0, 0, 0, 0, 0, 0, 0, 0, 0); // 2 position offsets
        f.floats("VEC3", 1, 0, -1, 1, 0, -1, 1, 0, -1); // 3 normal offsets
        f.floats("SCALAR", 0, 1); // 4
        f.floats("SCALAR", 0, 1); // 5
        Model model = GltfFixture.read(f.gltf("\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0,"
                + "\"NORMAL\":1},\"targets\":[{\"POSITION\":2,\"NORMAL\":3}]}],\"weights\":[1]}],"
                + "\"nodes\":[{\"mesh\":0}],\"scenes\":[{\"nodes\":[0]}],"
                + "\"animations\":[{\"channels\":[{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"weights\"}}],"
                + "\"samplers\":[{\"input\":4,\"output\":5}]}]"));
        assertEquals(List.of(), model.warnings());
        assertTrue(model.morphs().get(0).morphsNormals());
        float[] still = model.morphs().get(0).result().normals();
        assertEquals(1f, still[0], EPS, "the mesh's weight 1 gives (1, 0, 0)");
        assertEquals(0f, still[2], EPS);
        SkinnedModel skinned = new SkinnedModel(model, model.clips().get(0), NormalTransform.INVERSE_TRANSPOSE);
        float half = (float) Math.sqrt(0.5);
        for (SkinningMethod method : SkinningMethod.values()) {
            float[] normals = new float[9];
            skinned.pose(0.5f, RotationInterpolation.SLERP);
            skinned.skin(0, method, new float[9], normals);
            for (int v = 0; v < 3; v++) {
                assertEquals(half, normals[3 * v], EPS, method + " vertex " + v);
                assertEquals(0f, normals[3 * v + 1], EPS);
                assertEquals(half, normals[3 * v + 2], EPS);
            }
            skinned.pose(0f, RotationInterpolation.SLERP);
            skinned.skin(0, method, new float[9], normals);
            assertEquals(1f, normals[2], EPS, method + " at t = 0: the base normal");
        }
    }

    @Test
    void weightsOnANodeWithoutMorphTargetsAreRefused() {
        GltfException e = assertThrows(GltfException.class,
                () -> oneChannel("weights", "LINEAR", "SCALAR", new double[] {0, 1}, 0, 1));
        assertEquals("/animations/0/channels/0/target/path", e.path());
    }

    @Test
    void twoChannelsOnOneTargetAreRefused() throws Exception {
        GltfFixture f = new GltfFixture();
        f.floats("SCALAR", 0, 1);
        f.floats("VEC3", 0, 0, 0, 1, 1, 1);
        String channel = "{\"sampler\":0,\"target\":{\"node\":0,\"path\":\"scale\"}}";
        GltfException e = assertThrows(GltfException.class, () -> GltfFixture.read(f.gltf("\"nodes\":[{}],"
                + "\"scenes\":[{\"nodes\":[0]}],\"animations\":[{\"channels\":[" + channel + "," + channel
                + "],\"samplers\":[{\"input\":0,\"output\":1}]}]")));
        assertEquals("/animations/0/channels/1/target", e.path());
    }

    @Test
    void repeatedTimesAreJumpsWithAWarning() throws Exception {
        Model model = oneChannel("translation", "LINEAR", "VEC3", new double[] {0, 1, 1, 2}, 0, 0, 0, 1, 0, 0, 5, 0, 0,
                6, 0, 0);
        assertEquals(0.5f, translationAt(model, 0.5f).x, EPS);
        assertEquals(5.5f, translationAt(model, 1.5f).x, EPS);
        assertEquals("/animations/0/samplers/0/input", model.warnings().get(0).element());
    }

    @Test
    void decreasingTimesAreRefused() {
        GltfException e = assertThrows(GltfException.class,
                () -> oneChannel("translation", "LINEAR", "VEC3", new double[] {1, 0}, 0, 0, 0, 1, 1, 1));
        assertEquals("test.gltf: /accessors/0: key time 1 is 0.0: times must be non-negative and increase",
                e.getMessage());
    }
}
