package org.skinlab.mixer;

import java.util.List;

import org.joml.Quaternionf;
import org.skinlab.animation.AnimationHelper;
import org.skinlab.animation.LocalPose;

/**
 * How a layer's clips combine onto the pose below it ({@link #layer}: the rules of
 * {@link Layer} and {@link LayerMode}), through the two operations poses are blended with, on one
 * node's translation, rotation and scale in {@link LocalPose}'s layout ({@link #mix},
 * {@link #add}). Holds scratch: one per thread.
 *
 * <p>Rotations are slerped along the shorter arc as {@link AnimationHelper#slerp} does (the same
 * nlerp below its threshold), but with {@link AnimationHelper#acosFast} and
 * {@link AnimationHelper#sinFast}: the blend runs once per node per clip per step, and
 * {@code Math.acos} with three {@code Math.sin} cost more than all the rest of it.
 */
final class Blend {
    private final Quaternionf q1 = new Quaternionf();
    private final Quaternionf q2 = new Quaternionf();
    private final float[] delta = new float[4];
    /** One node's accumulation of a layer's clips. */
    private final float[] accumulated = new float[LocalPose.STRIDE];

    /**
     * Blends a layer's clips ({@code active}, each sampled into its local pose) onto {@code dest},
     * node by node, with the layer's weight times the mask's ({@code mask} null: 1 everywhere).
     */
    void layer(List<ClipState> active, LayerMode mode, double weight, float[] mask, float[] rest, float[] dest) {
        int nodes = rest.length / LocalPose.STRIDE;
        float[] acc = accumulated;
        for (int j = 0; j < nodes; j++) {
            double m = mask == null ? weight : weight * mask[j];
            if (m == 0) {
                continue;
            }
            int o = LocalPose.STRIDE * j;
            if (mode == LayerMode.ADDITIVE) {
                for (int i = 0; i < active.size(); i++) {
                    ClipState s = active.get(i);
                    if (s.weight > 0 && s.clip.sampler.animates(j)) {
                        add(s.local.array(), o, s.reference.array(), o, s.weight * m, dest, o);
                    }
                }
                continue;
            }
            if (active.size() == 1) {
                // One clip: no accumulation; the rest fills what its weight leaves.
                ClipState s = active.get(0);
                if (s.weight >= 1 && s.clip.sampler.animates(j)) {
                    mix(dest, o, s.local.array(), o, m, dest, o);
                    continue;
                }
            }
            double cumulative = 0;
            for (int i = 0; i < active.size(); i++) {
                ClipState s = active.get(i);
                if (!(s.weight > 0) || !s.clip.sampler.animates(j)) {
                    continue;
                }
                if (cumulative == 0) {
                    System.arraycopy(s.local.array(), o, acc, 0, LocalPose.STRIDE);
                    cumulative = s.weight;
                } else {
                    cumulative += s.weight;
                    mix(acc, 0, s.local.array(), o, s.weight / cumulative, acc, 0);
                }
            }
            if (cumulative == 0) {
                continue;
            }
            if (cumulative < 1) {
                mix(acc, 0, rest, o, 1 - cumulative, acc, 0);
            }
            mix(dest, o, acc, 0, m, dest, o);
        }
    }

    /**
     * {@code dest = a + t (b - a)} for translation and scale, the slerp from a to b along the
     * shortest arc for rotation ({@link AnimationHelper#slerp}); {@code dest} may be {@code a}.
     */
    void mix(float[] a, int ao, float[] b, int bo, double t, float[] dest, int d) {
        if (t >= 1) {
            System.arraycopy(b, bo, dest, d, 10);
            return;
        }
        float u = (float) t;
        for (int c = 0; c < 3; c++) {
            dest[d + c] = a[ao + c] + u * (b[bo + c] - a[ao + c]);
            dest[d + 7 + c] = a[ao + 7 + c] + u * (b[bo + 7 + c] - a[ao + 7 + c]);
        }
        slerp(a[ao + 3], a[ao + 4], a[ao + 5], a[ao + 6], b[bo + 3], b[bo + 4], b[bo + 5], b[bo + 6], u, dest, d + 3);
    }

    /** The slerp from a to b by u along the shorter arc into {@code dest[o .. o + 3]}. */
    private static void slerp(double ax, double ay, double az, double aw, double bx, double by, double bz, double bw,
            float u, float[] dest, int o) {
        double dot = ax * bx + ay * by + az * bz + aw * bw;
        double sign = dot < 0 ? -1 : 1;
        double cos = Math.min(1.0, Math.abs(dot));
        double wa;
        double wb;
        if (cos > AnimationHelper.SLERP_NLERP_THRESHOLD) {
            wa = 1 - u;
            wb = sign * u;
        } else {
            double angle = AnimationHelper.acosFast(cos);
            // sin(angle) from the cosine: exact enough below the nlerp threshold (1 - cos^2 >= 2e-7).
            double sin = Math.sqrt(1 - cos * cos);
            wa = AnimationHelper.sinFast((1 - u) * angle) / sin;
            wb = sign * AnimationHelper.sinFast(u * angle) / sin;
        }
        double x = wa * ax + wb * bx;
        double y = wa * ay + wb * by;
        double z = wa * az + wb * bz;
        double w = wa * aw + wb * bw;
        if (cos > AnimationHelper.SLERP_NLERP_THRESHOLD) {
            double len = Math.sqrt(x * x + y * y + z * z + w * w);
            x /= len;
            y /= len;
            z /= len;
            w /= len;
        }
        dest[o] = (float) x;
        dest[o + 1] = (float) y;
        dest[o + 2] = (float) z;
        dest[o + 3] = (float) w;
    }

    /**
     * Adds the difference of {@code value} from {@code reference} to {@code dest} by weight w:
     * {@code dest.r = dest.r * slerp(identity, conj(ref.r) * value.r, w)},
     * {@code dest.t += w (value.t - ref.t)}, {@code dest.s += w (value.s - ref.s)}.
     */
    void add(float[] value, int vo, float[] reference, int ro, double w, float[] dest, int d) {
        float u = (float) w;
        for (int c = 0; c < 3; c++) {
            dest[d + c] += u * (value[vo + c] - reference[ro + c]);
            dest[d + 7 + c] += u * (value[vo + 7 + c] - reference[ro + 7 + c]);
        }
        // delta = conj(ref) * value
        q1.set(-reference[ro + 3], -reference[ro + 4], -reference[ro + 5], reference[ro + 6])
                .mul(value[vo + 3], value[vo + 4], value[vo + 5], value[vo + 6]);
        if (u != 1f) {
            float[] r = delta;
            slerp(0, 0, 0, 1, q1.x, q1.y, q1.z, q1.w, u, r, 0);
            q1.set(r[0], r[1], r[2], r[3]);
        }
        q2.set(dest[d + 3], dest[d + 4], dest[d + 5], dest[d + 6]).mul(q1);
        dest[d + 3] = q2.x;
        dest[d + 4] = q2.y;
        dest[d + 5] = q2.z;
        dest[d + 6] = q2.w;
    }
}
