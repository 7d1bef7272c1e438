package org.skinlab.desktop.eval;

import java.util.Arrays;
import java.util.EnumSet;

import org.joml.Matrix4f;
import org.joml.Vector3f;
import org.skinlab.animation.RotationInterpolation;
import org.skinlab.model.Mesh;
import org.skinlab.model.Model;
import org.skinlab.model.Skin;
import org.skinlab.skinning.NormalTransform;
import org.skinlab.skinning.SkinnedGeometry;
import org.skinlab.skinning.SkinnedModel;
import org.skinlab.skinning.SkinningMethod;

/**
 * Whether an asset's {@code .glb} holds the same scene as its {@code .dae} (assets/README.md: each
 * is Blender's glTF export of the same scene): the triangles, the skins' joints and the first clip's
 * length, and where LBS puts the points at a few clip times, both imported and skinned through
 * core ({@link SkinnedModel}) and brought to the same frame (Y-up metres by each file's own
 * {@code AssetInfo}: the .dae is Z-up, the .glb Y-up).
 *
 * <p>Points are paired by bind position, not by index: glTF splits a position into one vertex per
 * normal and drops positions no triangle uses, and COLLADA's weights belong to positions, so any
 * .dae point at a position poses alike. Each .glb point is paired with the nearest .dae point at
 * bind (a search in a window of x sorted, exact); the measure is the largest distance between
 * paired points over the clip times, in millionths of the model's size (the diagonal of the .dae's
 * bind box). Both files hold the same floats (the .dae's as text with 6-7 significant digits), so
 * a faithful export lands within {@link #TOLERANCE_PPM} (core's AssetTwinsTest holds every method
 * to it at and between every key); a broken one (a moved vertex, another weight, a key off)
 * lands orders of magnitude away.
 */
final class AssetTwins {
    /** The largest distance a faithful twin may have, in millionths of the model's size. */
    static final double TOLERANCE_PPM = 10;
    /** Bind positions this close (millionths of the size) are the same position. */
    static final double SAME_POSITION_PPM = 1;
    /** The clip times compared, as fractions of the first clip: its ends, its middle and two between keys. */
    static final double[] CLIP_FRACTIONS = {0, 0.3, 0.5, 0.7, 1};

    /**
     * What the two files hold, .dae first.
     *
     * @param triangles    every mesh's triangles
     * @param joints       every skin's joints
     * @param clipSeconds  the first clip's length (0 without a clip)
     * @param unpaired     .glb points with no .dae point at their bind position
     * @param maxDistancePpm the largest distance between paired points at {@link #CLIP_FRACTIONS},
     *                     in millionths of the model's size
     */
    record Comparison(long[] triangles, int[] joints, double[] clipSeconds, int glbPoints, int unpaired,
            double maxDistancePpm) {

        /** The same triangles, joints and clip length, and every point within the tolerance. */
        boolean agrees() {
            return triangles[0] == triangles[1] && joints[0] == joints[1]
                    && Math.abs(clipSeconds[0] - clipSeconds[1]) <= 1e-6 && unpaired == 0
                    && maxDistancePpm <= TOLERANCE_PPM;
        }
    }

    private AssetTwins() {
    }

    static Comparison compare(Model dae, Model glb) {
        SkinnedModel daeSkin = lbs(dae);
        SkinnedModel glbSkin = lbs(glb);
        Matrix4f daeUp = dae.asset().toYUpMeters(new Matrix4f());
        Matrix4f glbUp = glb.asset().toYUpMeters(new Matrix4f());
        float[] daeBind = upright(daeUp, bind(daeSkin));
        float[] glbBind = upright(glbUp, bind(glbSkin));
        double size = diagonal(daeBind);
        int[] pair = new int[glbBind.length / 3];
        int unpaired = pairByPosition(glbBind, daeBind, SAME_POSITION_PPM * 1e-6 * size, pair);

        double[] clip = {clipSeconds(dae), clipSeconds(glb)};
        float[] daePosed = new float[daeBind.length];
        float[] glbPosed = new float[glbBind.length];
        double worst = 0;
        for (double f : CLIP_FRACTIONS) {
            float[] a = upright(daeUp, posed(daeSkin, (float) (clipStart(dae) + f * clip[0]), daePosed));
            float[] b = upright(glbUp, posed(glbSkin, (float) (clipStart(glb) + f * clip[0]), glbPosed));
            for (int i = 0; i < pair.length; i++) {
                worst = Math.max(worst, distance(b, i, a, pair[i]));
            }
        }
        return new Comparison(new long[] {triangles(dae), triangles(glb)}, new int[] {joints(dae), joints(glb)},
                clip, pair.length, unpaired, size > 0 ? 1e6 * worst / size : 0);
    }

    private static long triangles(Model m) {
        return m.meshes().stream().mapToLong(Mesh::triangleCount).sum();
    }

    private static int joints(Model m) {
        return m.skins().stream().mapToInt(Skin::jointCount).sum();
    }

    private static double clipSeconds(Model m) {
        return m.clips().isEmpty() ? 0 : m.clips().get(0).duration();
    }

    private static double clipStart(Model m) {
        return m.clips().isEmpty() ? 0 : m.clips().get(0).start();
    }

    /** Every geometry's bind points, one after the other. */
    /** The model with its first clip, bound for LBS alone: what the comparison skins with. */
    private static SkinnedModel lbs(Model model) {
        return new SkinnedModel(model, model.clips().isEmpty() ? null : model.clips().get(0),
                NormalTransform.INVERSE_TRANSPOSE, EnumSet.of(SkinningMethod.LBS));
    }

    private static float[] bind(SkinnedModel model) {
        int n = 0;
        for (SkinnedGeometry g : model.geometries()) {
            n += 3 * g.pointCount();
        }
        float[] all = new float[n];
        int at = 0;
        for (SkinnedGeometry g : model.geometries()) {
            System.arraycopy(g.positionArray(), 0, all, at, 3 * g.pointCount());
            at += 3 * g.pointCount();
        }
        return all;
    }

    /** Every geometry's points skinned with LBS at clip time {@code t}, into {@code into}. */
    private static float[] posed(SkinnedModel model, float t, float[] into) {
        model.pose(t, RotationInterpolation.SLERP);
        int at = 0;
        for (int g = 0; g < model.geometries().size(); g++) {
            int n = 3 * model.geometries().get(g).pointCount();
            float[] positions = new float[n];
            model.skin(g, SkinningMethod.LBS, positions, new float[n]);
            System.arraycopy(positions, 0, into, at, n);
            at += n;
        }
        return into;
    }

    /**
     * For each point of {@code glb}, the nearest point of {@code dae} into {@code pair}: among the
     * .dae points whose x lies within {@code within} (sorted by x, so the window is found by binary
     * search), else, for a point with none that near, by a search of all. Returns how many had
     * none within {@code within}.
     */
    static int pairByPosition(float[] glb, float[] dae, double within, int[] pair) {
        int m = dae.length / 3;
        Integer[] order = new Integer[m];
        for (int j = 0; j < m; j++) {
            order[j] = j;
        }
        Arrays.sort(order, (p, q) -> Float.compare(dae[3 * p], dae[3 * q]));
        float[] xs = new float[m];
        for (int k = 0; k < m; k++) {
            xs[k] = dae[3 * order[k]];
        }
        int unpaired = 0;
        for (int i = 0; i < pair.length; i++) {
            double x = glb[3 * i];
            int best = -1;
            double bestDistance = Double.MAX_VALUE;
            for (int k = firstAtLeast(xs, x - within); k < m && xs[k] <= x + within; k++) {
                double d = distance(glb, i, dae, order[k]);
                if (d < bestDistance) {
                    bestDistance = d;
                    best = order[k];
                }
            }
            if (bestDistance > within) {
                unpaired++;
                for (int j = 0; j < m; j++) {
                    double d = distance(glb, i, dae, j);
                    if (d < bestDistance) {
                        bestDistance = d;
                        best = j;
                    }
                }
            }
            pair[i] = best;
        }
        return unpaired;
    }

    private static int firstAtLeast(float[] sorted, double x) {
        int lo = 0;
        int hi = sorted.length;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (sorted[mid] < x) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
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
        return xyz.length == 0 ? 0
                : Math.sqrt(Math.pow(hi[0] - lo[0], 2) + Math.pow(hi[1] - lo[1], 2) + Math.pow(hi[2] - lo[2], 2));
    }

    private static double distance(float[] a, int i, float[] b, int j) {
        double dx = a[3 * i] - b[3 * j];
        double dy = a[3 * i + 1] - b[3 * j + 1];
        double dz = a[3 * i + 2] - b[3 * j + 2];
        return Math.sqrt(dx * dx + dy * dy + dz * dz);
    }
}
