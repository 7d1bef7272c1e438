package org.skinlab.desktop.eval;

import java.util.EnumMap;
import java.util.Map;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.model.Model;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * One pose of a model deformed by every skinning method at once, for comparing them: per
 * geometry and method the points as {@link SkinnedModel#skin} writes them, and per method all
 * geometries' points together in the scene (the file's up axis and unit made Y-up metres,
 * {@code AssetInfo.toYUpMeters}), where distances between methods are measured.
 */
final class PosedMethods {
    private static final SkinningMethod[] METHODS = SkinningMethod.values();

    private final SkinnedModel skinned;
    private final Matrix4f toScene;
    private final float[][][] posed;
    private final float[][] scene;
    private final float[] normals;
    private final int points;
    private final Vector3f p = new Vector3f();

    PosedMethods(Model model, SkinnedModel skinned) {
        this.skinned = skinned;
        toScene = model.asset().toYUpMeters(new Matrix4f());
        int n = skinned.geometries().size();
        posed = new float[n][METHODS.length][];
        int total = 0;
        int largest = 0;
        for (int g = 0; g < n; g++) {
            int count = skinned.geometries().get(g).pointCount();
            for (int m = 0; m < METHODS.length; m++) {
                posed[g][m] = new float[3 * count];
            }
            total += count;
            largest = Math.max(largest, count);
        }
        points = total;
        scene = new float[METHODS.length][3 * total];
        normals = new float[3 * largest];
    }

    /** Poses clip time {@code time} (slerp) and deforms every geometry with every method. */
    void pose(float time) {
        skinned.pose(time, RotationInterpolation.SLERP);
        for (int m = 0; m < METHODS.length; m++) {
            int o = 0;
            for (int g = 0; g < posed.length; g++) {
                float[] out = posed[g][m];
                skinned.skin(g, METHODS[m], out, normals);
                for (int i = 0; i < out.length; i += 3) {
                    toScene.transformPosition(p.set(out[i], out[i + 1], out[i + 2]));
                    scene[m][o++] = p.x;
                    scene[m][o++] = p.y;
                    scene[m][o++] = p.z;
                }
            }
        }
    }

    /** Geometry {@code g}'s points per method (for the joint measures). */
    Map<SkinningMethod, float[]> geometry(int g) {
        Map<SkinningMethod, float[]> map = new EnumMap<>(SkinningMethod.class);
        for (int m = 0; m < METHODS.length; m++) {
            map.put(METHODS[m], posed[g][m]);
        }
        return map;
    }

    /** All points of method {@code m} in the scene, 3 floats each. */
    float[] scene(SkinningMethod m) {
        return scene[m.ordinal()];
    }

    /** Points in the scene per method. */
    int points() {
        return points;
    }

    /** The scene bounds of method {@code m}'s points: {min x, y, z} and {max x, y, z}. */
    double[][] bounds(SkinningMethod m) {
        double[] min = {Double.MAX_VALUE, Double.MAX_VALUE, Double.MAX_VALUE};
        double[] max = {-Double.MAX_VALUE, -Double.MAX_VALUE, -Double.MAX_VALUE};
        float[] s = scene[m.ordinal()];
        for (int i = 0; i < points; i++) {
            for (int c = 0; c < 3; c++) {
                min[c] = Math.min(min[c], s[3 * i + c]);
                max[c] = Math.max(max[c], s[3 * i + c]);
            }
        }
        return new double[][] {min, max};
    }
}
