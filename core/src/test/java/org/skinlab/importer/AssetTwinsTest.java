package org.skinlab.importer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.model.ImportException;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;
import org.skinlab.testing.TestPaths;

/**
 * Each asset's {@code .glb} (Blender's glTF export of the same scene, assets/README.md) poses like
 * its {@code .dae}: every point of the glTF mesh, posed with LBS, DQS and CoR through the core's
 * own path ({@link SkinnedModel#pose}, the scalar skinners), lands where the COLLADA point at the
 * same bind position lands, within 1e-5 of the model's size, at every key and at two times
 * between each pair of keys (the middle and 0.37 of the way). Both are first brought to the same
 * frame: Y-up metres by their own {@code AssetInfo} ({@code toYUpMeters}, the up-axis and unit part
 * of {@code ModelFraming}): the .dae is Z-up, the .glb Y-up.
 *
 * <p>Points are paired by bind position, not by index: glTF splits a position into one vertex per
 * normal (the cylinders' cap rims) and keeps only positions that triangles use (the humanoid's
 * loose position 25 is not in the .glb). Weights belong to positions in COLLADA, so any COLLADA
 * point at a position poses alike.
 *
 * <p>Why 1e-5 holds: both files hold the same float data (the .dae's matrices as text with 6-7
 * significant digits, the .glb's TRS as binary floats), the keys are the same (the glTF export
 * samples exactly the .dae's key frames), and between keys both interpolate translation,
 * rotation (SLERP here) and scale the same way once the .dae's key matrices are decomposed.
 */
class AssetTwinsTest {
    private static final double TOLERANCE = 1e-5;

    @ParameterizedTest(name = "{0}")
    @CsvSource({"cylinders/cylinder-twist-low, 1.0", "cylinders/cylinder-twist-high, 1.0",
        "cylinders/cylinder-bend, 1.0", "cylinders/cylinder-twist-full, 0.25", "cylinders/cylinder-bend-full, 0.25",
        "characters/humanoid-walk, 0.125", "creatures/tentacle-wave, 0.125", "stretch/limb-stretch, 0.25",
        "twist/arm-twist, 0.125"})
    void glbPosesLikeItsDaeWithEveryMethodAtAndBetweenKeys(String asset, double keySpacing)
            throws IOException, ImportException {
        Model dae = ModelImporter.read(TestPaths.asset(asset + ".dae"));
        Model glb = ModelImporter.read(TestPaths.asset(asset + ".glb"));
        SkinnedModel daeSkin = SkinnedModel.of(dae);
        SkinnedModel glbSkin = SkinnedModel.of(glb);
        assertEquals(1, daeSkin.geometries().size(), "one mesh in the .dae");
        assertEquals(1, glbSkin.geometries().size(), "one mesh in the .glb");
        SkinnedGeometry daeGeometry = daeSkin.geometries().get(0);
        SkinnedGeometry glbGeometry = glbSkin.geometries().get(0);
        Matrix4f daeUp = dae.asset().toYUpMeters(new Matrix4f());
        Matrix4f glbUp = glb.asset().toYUpMeters(new Matrix4f());
        float[] daeBind = upright(daeUp, daeGeometry.positionArray());
        float[] glbBind = upright(glbUp, glbGeometry.positionArray());
        double size = diagonal(daeBind);
        int[] twin = pairByPosition(glbBind, daeBind, 1e-6 * size);

        float duration = dae.clips().get(0).duration();
        assertEquals(duration, glb.clips().get(0).duration(), 1e-6, "same clip length");
        List<Float> times = times(duration, keySpacing);
        float[] daePosed = new float[daeBind.length];
        float[] glbPosed = new float[glbBind.length];
        float[] daeNormals = new float[daeBind.length];
        float[] glbNormals = new float[glbBind.length];
        for (SkinningMethod method : SkinningMethod.values()) {
            double worst = 0;
            for (float t : times) {
                daeSkin.pose(t, RotationInterpolation.SLERP);
                glbSkin.pose(t, RotationInterpolation.SLERP);
                daeSkin.skin(0, method, daePosed, daeNormals);
                glbSkin.skin(0, method, glbPosed, glbNormals);
                float[] a = upright(daeUp, daePosed);
                float[] b = upright(glbUp, glbPosed);
                for (int i = 0; i < twin.length; i++) {
                    double d = distance(b, i, a, twin[i]);
                    worst = Math.max(worst, d);
                    if (d > TOLERANCE * size) {
                        throw new AssertionError(String.format("%s %s t=%s: .glb point %d is %.3g m (%.3g of the "
                                + "size) from .dae point %d", asset, method.key(), t, i, d, d / size, twin[i]));
                    }
                }
            }
            System.out.printf("%-32s %s: worst %.2e of the size over %d times%n", asset, method.key(), worst / size,
                    times.size());
        }
    }

    /** Every key, the middle between keys and 0.37 of the way. */
    private static List<Float> times(float duration, double spacing) {
        List<Float> times = new ArrayList<>();
        int keys = (int) Math.round(duration / spacing);
        for (int k = 0; k <= keys; k++) {
            times.add((float) (k * spacing));
            if (k < keys) {
                times.add((float) ((k + 0.5) * spacing));
                times.add((float) ((k + 0.37) * spacing));
            }
        }
        assertTrue(times.size() >= 13, "at least 5 keys and the times between them");
        return times;
    }

    /** For every glTF point, a COLLADA point at the same bind position (within {@code within}). */
    private static int[] pairByPosition(float[] glb, float[] dae, double within) {
        int[] twin = new int[glb.length / 3];
        for (int i = 0; i < twin.length; i++) {
            int best = -1;
            double bestDistance = Double.MAX_VALUE;
            for (int j = 0; j < dae.length / 3; j++) {
                double d = distance(glb, i, dae, j);
                if (d < bestDistance) {
                    bestDistance = d;
                    best = j;
                }
            }
            if (bestDistance > within) {
                throw new AssertionError(String.format(".glb point %d has no .dae point at its bind position "
                        + "(nearest %.3g m away)", i, bestDistance));
            }
            twin[i] = best;
        }
        return twin;
    }

    private static float[] upright(Matrix4f toScene, float[] xyz) {
        float[] out = new float[xyz.length];
        Vector3f p = new Vector3f();
        for (int i = 0; i < xyz.length; i += 3) {
            toScene.transformPosition(p.set(xyz[i], xyz[i + 1], xyz[i + 2]));
            out[i] = p.x;
            out[i + 1] = p.y;
            out[i + 2] = p.z;
        }
        return out;
    }

    private static double diagonal(float[] xyz) {
        double[] lo = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] hi = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        for (int i = 0; i < xyz.length; i++) {
            lo[i % 3] = Math.min(lo[i % 3], xyz[i]);
            hi[i % 3] = Math.max(hi[i % 3], xyz[i]);
        }
        return Math.sqrt(Math.pow(hi[0] - lo[0], 2) + Math.pow(hi[1] - lo[1], 2) + Math.pow(hi[2] - lo[2], 2));
    }

    private static double distance(float[] a, int i, float[] b, int j) {
        double dx = a[3 * i] - b[3 * j];
        double dy = a[3 * i + 1] - b[3 * j + 1];
        double dz = a[3 * i + 2] - b[3 * j + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
